"""OpaqueFunction: a body that builds and returns plain actions is read like the file;
otherwise an info says why (the function is never run)."""

from __future__ import annotations

import gc
from pathlib import Path

from launch_linter.engine import lint_text
from launch_linter.frontends.dispatch import load_tree
from launch_linter.frontends.ros1 import LoadOptions
from launch_linter.workspace.packages import PackageIndex

HEADER = """from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, OpaqueFunction
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node
import yaml
"""

PLAIN = HEADER + """

def launch_setup(context, *args, **kwargs):
    frame = LaunchConfiguration('frame').perform(context)
    tf = Node(package='tf2_ros', executable='static_transform_publisher',
             arguments=['--frame-id', frame, '--child-frame-id', 'laser'])
    return [tf]


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('frame', default_value='base_link'),
        OpaqueFunction(function=launch_setup),
    ])
"""

UNKNOWN_LOOP = HEADER + """

def launch_setup(context):
    with open('/robot.yaml') as f:
        cfg = yaml.safe_load(f)
    nodes = []
    for name in cfg:
        nodes.append(Node(package='tf2_ros', executable='static_transform_publisher',
             arguments=['--frame-id', 'base_link', '--child-frame-id', name]))
    return nodes


def generate_launch_description():
    return LaunchDescription([OpaqueFunction(function=launch_setup)])
"""

NO_RETURN = HEADER + """

def launch_setup(context):
    Node(package='tf2_ros', executable='static_transform_publisher',
             arguments=['--frame-id', 'base_link', '--child-frame-id', 'imu'])


def generate_launch_description():
    return LaunchDescription([OpaqueFunction(function=launch_setup)])
"""


def test_plain_actions_are_interpreted_with_the_launch_arguments() -> None:
    result = lint_text(PLAIN, "a_launch.py")
    assert [(t.parent, t.child) for t in result.transforms] == [("base_link", "laser")]
    assert not [d for d in result.diagnostics if d.rule == "unresolved"]


def test_a_loop_over_an_unknown_value_says_why() -> None:
    result = lint_text(UNKNOWN_LOOP, "b_launch.py")
    assert result.transforms == ()
    (info,) = [d for d in result.diagnostics if d.rule == "unresolved"]
    assert info.line == 12 and info.severity.value == "info"
    assert "OpaqueFunction launch_setup()" in info.message and "yaml.safe_load" in info.message


def test_actions_built_but_not_returned_say_so() -> None:
    result = lint_text(NO_RETURN, "c_launch.py")
    assert result.transforms == ()
    (info,) = [d for d in result.diagnostics if d.rule == "unresolved"]
    assert "builds launch actions but returns none" in info.message


def test_a_log_message_returned_alone_is_not_the_actions_built() -> None:
    # stereolabs/zed-ros2-wrapper: an early return of a LogInfo; the nodes built later are
    # not seen, which the info still says.
    text = HEADER + """from launch.actions import LogInfo


def launch_setup(context):
    tf = Node(package='tf2_ros', executable='static_transform_publisher',
              arguments=['--frame-id', 'a', '--child-frame-id', 'b'])
    return [LogInfo(msg='starting')]


def generate_launch_description():
    return LaunchDescription([OpaqueFunction(function=launch_setup)])
"""
    result = lint_text(text, "d_launch.py")
    (info,) = [d for d in result.diagnostics if d.rule == "unresolved"]
    assert "builds launch actions but returns none" in info.message


def test_a_list_of_arguments_rebound_under_an_unknown_if_is_one_or_the_other() -> None:
    # husarion/rosbot_xl_ros spawn.launch.py: ``rpy`` is one of two 3-item lists; the
    # arguments are 8 either way, never 11 (both lists at once).
    text = HEADER + """

def launch_setup(context):
    camera_model = context.perform_substitution(LaunchConfiguration('camera_model'))
    rpy = ['1.57', '-1.57', '0']
    if camera_model.startswith('zed'):
        rpy = ['0', '0', '0']
    return [Node(package='tf2_ros', executable='static_transform_publisher',
                 arguments=['0', '0', '0'] + rpy + ['a', 'b'])]


def generate_launch_description():
    return LaunchDescription([DeclareLaunchArgument('camera_model'),
                              OpaqueFunction(function=launch_setup)])
"""
    result = lint_text(text, "e_launch.py")
    assert not [d for d in result.diagnostics if d.rule == "bad_arity"]
    assert [d for d in result.diagnostics if d.rule == "unresolved"]


FIXABLE = """from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='tf2_ros', executable='static_transform_publisher',
             arguments=['--frame-id', '/base_link', '--child-frame-id', 'laser']),
    ])
"""


def test_reading_and_checking_leave_no_reference_cycle(tmp_path: Path) -> None:
    # The function's scopes hold its action, whose function holds them back: until the
    # tree is read. Left to the garbage collector, such cycles cost a tenth of the ROS 2
    # front-end's time over the corpus (docs/performance.md).
    path = tmp_path / "a_launch.py"
    path.write_text(PLAIN, encoding="utf-8")
    options = LoadOptions(packages=PackageIndex([]))
    load_tree(str(path), options)  # the imports and caches of a first read
    lint_text(FIXABLE, "f_launch.py")
    gc.collect()
    gc.disable()
    try:
        tree = load_tree(str(path), options)
        assert [(t.parent_written, t.child_written) for t in tree.transforms] == [
            ("base_link", "laser")]
        del tree
        assert gc.collect() == 0
        # A fix located in a file reads its string literals (``fix_python``).
        assert [d.fix is not None for d in lint_text(FIXABLE, "f_launch.py").diagnostics] == [
            True]
        assert gc.collect() == 0
    finally:
        gc.enable()
