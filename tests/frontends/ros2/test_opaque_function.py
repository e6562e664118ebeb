"""OpaqueFunction: a body that builds and returns plain actions is read like the file;
otherwise an info says why (the function is never run)."""

from __future__ import annotations

from launch_linter.engine import lint_text

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
