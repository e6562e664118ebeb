"""ROS 2 Python launch files, read as a syntax tree and never run."""

from __future__ import annotations

from pathlib import Path

import pytest
from ros2_helpers import Load, by_name, rules

from launch_linter import LintOptions, lint_paths
from launch_linter.model.launch import FileStatus

HEADER = """\
import os

from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import (DeclareLaunchArgument, GroupAction, IncludeLaunchDescription,
                            OpaqueFunction, RegisterEventHandler, TimerAction)
from launch.conditions import IfCondition, LaunchConfigurationEquals, UnlessCondition
from launch.event_handlers import OnProcessExit
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import (LaunchConfiguration, PathJoinSubstitution,
                                  ThisLaunchFileDir)
from launch_ros.actions import ComposableNodeContainer, LoadComposableNodes, Node
from launch_ros.actions import PushRosNamespace
from launch_ros.descriptions import ComposableNode
from launch_ros.substitutions import FindPackageShare

"""
HEADER_LINES = HEADER.count("\n")


def tf(arguments: str, extra: str = "") -> str:
    return (f"Node(package='tf2_ros', executable='static_transform_publisher'{extra}, "
            f"arguments={arguments})")


def launch_file(body: str) -> str:
    return HEADER + "def generate_launch_description():\n" + body


def test_a_node_with_a_list_of_arguments(load: Load) -> None:
    tree = load({"a.launch.py": launch_file(
        "    return LaunchDescription([\n"
        "        " + tf("['--x', '0.1', '--frame-id', 'base_link', '--child-frame-id', 'laser']",
                        ", name='laser_tf', namespace='robot'") + ",\n"
        "    ])\n"
    )}, "a.launch.py")
    (transform,) = tree.transforms
    assert (transform.line, transform.column) == (HEADER_LINES + 3, 9)
    assert (transform.name, transform.namespace) == ("laser_tf", "/robot")
    assert (transform.parent, transform.child, transform.translation) == (
        "base_link", "laser", (0.1, 0.0, 0.0),
    )
    assert (transform.ros_version, transform.launch_format) == (2, "ros2-python")
    assert transform.args_written.startswith("['--x'")
    assert tree.problems == ()


def test_arguments_and_configurations(load: Load) -> None:
    files = {"a.launch.py": launch_file(
        "    child = LaunchConfiguration('child')\n"
        "    node = " + tf("['--frame-id', LaunchConfiguration('parent', default='odom'), "
                           "'--child-frame-id', child]", ", name='t'") + "\n"
        "    return LaunchDescription([\n"
        "        DeclareLaunchArgument('child', default_value='base_link'),\n"
        "        node,\n"
        "    ])\n"
    )}
    (transform,) = load(files, "a.launch.py").transforms
    assert (transform.parent, transform.child) == ("odom", "base_link")
    (transform,) = load(files, "a.launch.py", args={"child": "body"}).transforms
    assert transform.child == "body"


def test_lists_loops_helpers_and_strings(load: Load) -> None:
    tree = load({"a.launch.py": launch_file(
        "    ld = LaunchDescription()\n"
        "    for side, y in (('left', 0.3), ('right', -0.3)):\n"
        "        ld.add_action(wheel(side, y))\n"
        "    extra = [wheel(s, 0.0) for s in ['front']]\n"
        "    extra += [" + tf("'0 0 0 0 0 0 base_link mast'.split()", ", name='mast_tf'") + "]\n"
        "    for action in extra:\n"
        "        ld.add_action(action)\n"
        "    return ld\n"
        "\n"
        "def wheel(side, y):\n"
        "    frame = f'wheel_{side}_link'\n"
        "    return " + tf("['--y', str(y), '--frame-id', 'base_link', '--child-frame-id', frame]",
                          ", name='%s_tf' % side") + "\n"
    )}, "a.launch.py")
    nodes = by_name(tree)
    assert set(nodes) == {"left_tf", "right_tf", "front_tf", "mast_tf"}
    assert (nodes["right_tf"].child, nodes["right_tf"].translation) == (
        "wheel_right_link", (0.0, -0.3, 0.0),
    )
    assert nodes["mast_tf"].child == "mast"
    assert [i.kind for i in nodes["mast_tf"].arg_issues] == ["positional"]


def test_arguments_in_one_string(load: Load) -> None:
    tree = load({"a.launch.py": launch_file(
        "    return LaunchDescription([" + tf("['0 0 0.2 0 0 0 base_link laser']") + "])\n"
    )}, "a.launch.py")
    (transform,) = tree.transforms
    assert [i.kind for i in transform.arg_issues] == ["single_string", "positional"]
    assert (transform.parent, transform.child) == ("base_link", "laser")
    assert transform.args == "'0 0 0.2 0 0 0 base_link laser'"


def test_arguments_given_as_a_string_instead_of_a_list(load: Load) -> None:
    tree = load({"a.launch.py": launch_file(
        "    return LaunchDescription([" + tf("'0 0 0 0 0 0 a b'") + "])\n"
    )}, "a.launch.py")
    (transform,) = tree.transforms
    assert transform.form == "unknown" and "arity" in transform.unresolved
    assert ("roslaunch_error", HEADER_LINES + 2) in rules(tree)


def test_a_number_in_the_arguments_is_a_launch_error(load: Load) -> None:
    tree = load({"a.launch.py": launch_file(
        "    return LaunchDescription([" + tf("['--z', 0.2, '--frame-id', 'a', "
                                              "'--child-frame-id', 'b']") + "])\n"
    )}, "a.launch.py")
    assert tree.transforms[0].translation == (0.0, 0.0, 0.2)
    assert rules(tree) == [("roslaunch_error", HEADER_LINES + 2)]


def test_a_number_as_a_launch_configuration_default_is_its_text(load: Load) -> None:
    # launch's LaunchConfiguration turns each item of ``default`` that is neither text nor a
    # substitution into text with str() (kiss-icp's odometry.launch.py: default=0.1).
    tree = load({"a.launch.py": launch_file(
        "    z = LaunchConfiguration('z', default=0.5)\n"
        "    on = LaunchConfiguration('on', default=True)\n"
        "    return LaunchDescription([Node(package='tf2_ros',\n"
        "        executable='static_transform_publisher', condition=IfCondition(on),\n"
        "        arguments=['--z', z, '--frame-id', 'a', '--child-frame-id', 'b'])])\n"
    )}, "a.launch.py")
    assert tree.transforms[0].translation == (0.0, 0.0, 0.5)
    assert rules(tree) == []


def test_a_number_given_to_another_substitution_is_still_a_launch_error(load: Load) -> None:
    tree = load({"a.launch.py": launch_file(
        "    from launch.substitutions import EnvironmentVariable\n"
        "    z = EnvironmentVariable('Z', default_value=0.5)\n"
        "    return LaunchDescription([" + tf("['--z', z, '--frame-id', 'a', "
                                              "'--child-frame-id', 'b']") + "])\n"
    )}, "a.launch.py")
    assert rules(tree) == [("roslaunch_error", HEADER_LINES + 3)]


def test_unknown_values_are_unresolved_with_their_line(load: Load) -> None:
    tree = load({"a.launch.py": launch_file(
        "    from my_robot.frames import laser_frame\n"
        "    args = ['--frame-id', 'base', '--child-frame-id', laser_frame()]\n"
        "    return LaunchDescription([\n"
        "        " + tf("args", ", name='a'") + ",\n"
        "        " + tf("compute_arguments()", ", name='b'") + ",\n"
        "    ])\n"
    )}, "a.launch.py")
    nodes = by_name(tree)
    assert nodes["a"].unresolved_names == ("child",)
    assert nodes["a"].parent == "base"
    (reason,) = nodes["a"].unresolved_reasons
    assert reason.startswith(f"laser_frame(): line {HEADER_LINES + 3}:")
    assert set(nodes["b"].unresolved) == {"translation", "rotation", "parent", "child", "arity"}
    assert f"line {HEADER_LINES + 6}: compute_arguments()" in nodes["b"].unresolved_reasons[0]
    # compute_arguments is bound nowhere in the file: a NameError (py_name_error) too.
    assert sorted(r for r, _ in rules(tree)) == ["py_name_error", "unresolved", "unresolved"]


def test_an_if_on_an_unknown_value_gives_exclusive_conditions(load: Load) -> None:
    tree = load({"a.launch.py": launch_file(
        "    nodes = []\n"
        "    if os.environ.get('USE_LIDAR') == '1':\n"
        "        nodes.append(" + tf("['--frame-id', 'a', '--child-frame-id', 'lidar']",
                                     ", name='x'") + ")\n"
        "    else:\n"
        "        nodes.append(" + tf("['--frame-id', 'a', '--child-frame-id', 'camera']",
                                     ", name='x'") + ")\n"
        "    return LaunchDescription(nodes)\n"
    )}, "a.launch.py")
    first, second = tree.transforms
    assert (first.child, second.child) == ("lidar", "camera")
    assert first.condition.excludes(second.condition)
    assert "os.environ.get('USE_LIDAR') == '1'" in first.condition.describe()


def test_a_static_if_is_decided(load: Load) -> None:
    tree = load({"a.launch.py": launch_file(
        "    simulate = False\n"
        "    nodes = [" + tf("['--frame-id', 'a', '--child-frame-id', 'b']", ", name='t'") + "]\n"
        "    if simulate:\n"
        "        nodes = []\n"
        "    return LaunchDescription(nodes)\n"
    )}, "a.launch.py")
    assert [t.name for t in tree.transforms] == ["t"]
    assert tree.transforms[0].condition.always


def test_conditions_and_groups(load: Load) -> None:
    tree = load({"a.launch.py": launch_file(
        "    return LaunchDescription([\n"
        "        DeclareLaunchArgument('mode', default_value='sim'),\n"
        "        GroupAction([\n"
        "            PushRosNamespace('r1'),\n"
        "            " + tf("['--frame-id', 'a', '--child-frame-id', 'b']",
                            ", name='in_group'") + ",\n"
        "        ]),\n"
        "        " + tf("['--frame-id', 'a', '--child-frame-id', 'c']",
                        ", name='sim', condition=LaunchConfigurationEquals('mode', 'sim')") + ",\n"
        "        " + tf("['--frame-id', 'a', '--child-frame-id', 'd']",
                        ", name='real', condition=UnlessCondition(LaunchConfiguration("
                        "'real'))") + ",\n"
        "        " + tf("['--frame-id', 'a', '--child-frame-id', 'e']",
                        ", name='not_real', condition=IfCondition(LaunchConfiguration("
                        "'real'))") + ",\n"
        "    ])\n"
    )}, "a.launch.py")
    nodes = by_name(tree)
    assert nodes["in_group"].namespace == "/r1"
    assert nodes["sim"].namespace == "/" and nodes["sim"].condition.always
    assert nodes["real"].condition.excludes(nodes["not_real"].condition)


def test_includes_of_every_form(load: Load) -> None:
    package = '<package format="3"><name>robot</name></package>'
    tree = load({
        "ws/robot/package.xml": package,
        "ws/robot/launch/b.launch.xml": (
            '<launch><arg name="frame"/><node pkg="tf2_ros" exec="static_transform_publisher" '
            'name="from_xml" args="--frame-id base --child-frame-id $(var frame)"/></launch>'
        ),
        "ws/robot/launch/c.launch.py": launch_file(
            "    return LaunchDescription([" + tf(
                "['--frame-id', 'base', '--child-frame-id', LaunchConfiguration('frame')]",
                ", name='from_py'") + "])\n"
        ),
        "a.launch.py": launch_file(
            "    share = get_package_share_directory('robot')\n"
            "    return LaunchDescription([\n"
            "        IncludeLaunchDescription(\n"
            "            PathJoinSubstitution([FindPackageShare('robot'), 'launch', "
            "'b.launch.xml']),\n"
            "            launch_arguments={'frame': 'gps'}.items()),\n"
            "        IncludeLaunchDescription(PythonLaunchDescriptionSource(\n"
            "            os.path.join(share, 'launch', 'c.launch.py')),\n"
            "            launch_arguments=[('frame', 'imu')]),\n"
            "        IncludeLaunchDescription(PythonLaunchDescriptionSource(\n"
            "            [ThisLaunchFileDir(), '/missing.launch.py'])),\n"
            "    ])\n"
        ),
    }, "a.launch.py", packages=("ws",))
    nodes = by_name(tree)
    assert (nodes["from_xml"].child, nodes["from_xml"].launch_format) == ("gps", "ros2-xml")
    assert (nodes["from_py"].child, nodes["from_py"].path) == ("imu",
                                                                "ws/robot/launch/c.launch.py")
    assert [(r, "not found" in d.message) for (r, _), d in zip(rules(tree), tree.problems)] == [
        ("roslaunch_error", True),
    ]


def test_opaque_function_reads_configurations_when_it_runs(load: Load) -> None:
    tree = load({"a.launch.py": launch_file(
        "    return LaunchDescription([\n"
        "        DeclareLaunchArgument('robot', default_value='r2'),\n"
        "        OpaqueFunction(function=setup),\n"
        "    ])\n"
        "\n"
        "def setup(context, *args, **kwargs):\n"
        "    robot = LaunchConfiguration('robot').perform(context)\n"
        "    camera = context.launch_configurations.get('camera', 'cam')\n"
        "    if robot == 'r2':\n"
        "        return [" + tf("['--frame-id', robot + '_base', '--child-frame-id', camera]",
                                ", name='t'") + "]\n"
        "    return []\n"
    )}, "a.launch.py")
    (transform,) = tree.transforms
    assert (transform.parent, transform.child) == ("r2_base", "cam")
    assert transform.condition.always


def test_composable_nodes(load: Load) -> None:
    tree = load({"a.launch.py": launch_file(
        "    tool = ComposableNode(package='tf2_ros',\n"
        "                          plugin='tf2_ros::StaticTransformBroadcasterNode',\n"
        "                          name='tool_tf',\n"
        "                          parameters=[{'frame_id': 'flange', 'child_frame_id': 'tool',\n"
        "                                       'translation': {'z': 0.1}, 'rotation.w': 1}])\n"
        "    bare = ComposableNode(package='tf2_ros',\n"
        "                          plugin='tf2_ros::StaticTransformBroadcasterNode')\n"
        "    return LaunchDescription([\n"
        "        ComposableNodeContainer(name='c', namespace='', package='rclcpp_components',\n"
        "            executable='component_container', composable_node_descriptions=[tool]),\n"
        "        LoadComposableNodes(target_container='c', composable_node_descriptions=[bare]),\n"
        "    ])\n"
    )}, "a.launch.py")
    tool, bare = tree.transforms
    assert (tool.line, tool.parent, tool.child, tool.translation) == (
        HEADER_LINES + 2, "flange", "tool", (0.0, 0.0, 0.1),
    )
    assert tool.arg_issues == ()
    assert (bare.name, bare.parent_written, bare.child_written) == (None, "/frame", "/child")
    assert [i.kind for i in bare.arg_issues] == ["default_frames"]


def test_event_handlers_and_timers(load: Load) -> None:
    tree = load({"a.launch.py": launch_file(
        "    first = Node(package='demo_nodes_cpp', executable='talker')\n"
        "    return LaunchDescription([\n"
        "        first,\n"
        "        RegisterEventHandler(OnProcessExit(target_action=first, on_exit=[\n"
        "            " + tf("['--frame-id', 'a', '--child-frame-id', 'b']", ", name='later'") + "\n"
        "        ])),\n"
        "        TimerAction(period=2.0, actions=[\n"
        "            " + tf("['--frame-id', 'a', '--child-frame-id', 'c']", ", name='timed'") + "\n"
        "        ]),\n"
        "    ])\n"
    )}, "a.launch.py")
    nodes = by_name(tree)
    assert not nodes["later"].condition.always
    assert nodes["timed"].condition.always


def test_old_keyword_names(load: Load) -> None:
    tree = load({"a.launch.py": launch_file(
        "    return LaunchDescription([Node(package='tf2_ros', "
        "node_executable='static_transform_publisher', node_name='old', "
        "arguments=['--frame-id', 'a', '--child-frame-id', 'b'])])\n"
    )}, "a.launch.py")
    assert [t.name for t in tree.transforms] == ["old"]


def test_nothing_in_the_file_runs(load: Load, tmp_path: Path) -> None:
    marker = tmp_path / "ran"
    tree = load({"a.launch.py": (
        "import os\n"
        "import subprocess\n"
        f"open({str(marker)!r}, 'w').write('module')\n"
        f"os.system('touch {marker}')\n"
        "def generate_launch_description():\n"
        f"    subprocess.run(['touch', {str(marker)!r}])\n"
        f"    __import__('os').system('touch {marker}')\n"
        "    while True:\n"
        "        pass\n"
    )}, "a.launch.py")
    assert not marker.exists()
    assert tree.status is FileStatus.OK


def test_work_is_bounded(load: Load) -> None:
    tree = load({"a.launch.py": (
        "def generate_launch_description():\n"
        "    nodes = []\n"
        "    for i in range(10**9):\n"
        "        nodes.append(i)\n"
        "    return recurse(0)\n"
        "def recurse(n):\n"
        "    return recurse(n + 1)\n"
    )}, "a.launch.py")
    assert tree.transforms == ()
    assert [r for r, _ in rules(tree)] == ["unresolved"]
    deep = "x = " + "(" * 5000 + "1" + ")" * 5000 + "\n"
    tree = load({"b.launch.py": deep}, "b.launch.py")
    assert tree.status is FileStatus.PARSE_ERROR


def test_loops_over_unknown_values_that_launch_nodes_are_reported(load: Load) -> None:
    tree = load({"a.launch.py": launch_file(
        "    ld = LaunchDescription()\n"
        "    for frame in load_frames():\n"
        "        ld.add_action(" + tf("['--frame-id', 'a', '--child-frame-id', frame]") + ")\n"
        "    return ld\n"
    )}, "a.launch.py")
    assert tree.transforms == ()
    # load_frames is bound nowhere in the file: Python raises NameError there as well.
    assert sorted(rules(tree)) == [("py_name_error", HEADER_LINES + 3),
                                   ("unresolved", HEADER_LINES + 3)]


def test_a_bracket_never_closed_is_reported_where_it_opens(load: Load) -> None:
    # ROS 2 runs launch files with Python 3.10+, whose parser names the open bracket; the
    # parser of Python 3.8 and 3.9 named the next statement instead (line 4 here).
    source = ("def generate_launch_description():\n"
              "    args = []\n"
              "    args.append(\n"
              "    x = [1, 2]\n"
              "    return args\n")
    tree = load({"a.launch.py": source}, "a.launch.py")
    assert tree.status is FileStatus.PARSE_ERROR and rules(tree) == [("parse_error", 3)]
    # Brackets all closed: the parser's own place stands.
    tree = load({"b.launch.py": "def f(:\n    pass\nx = (1)\n"}, "b.launch.py")
    assert rules(tree) == [("parse_error", 1)]


def test_syntax_errors_and_missing_entry_point(load: Load) -> None:
    tree = load({"a.launch.py": "def generate_launch_description(:\n"}, "a.launch.py")
    assert tree.status is FileStatus.PARSE_ERROR and rules(tree) == [("parse_error", 1)]
    tree = load({"b.launch.py": "x = 1\n"}, "b.launch.py")
    assert rules(tree) == [("unresolved", 1)]


def test_comments_and_element_lines(load: Load) -> None:
    tree = load({"a.launch.py": launch_file(
        "    return LaunchDescription([\n"
        "        # launch-linter: disable=ros2_positional_args\n"
        "        " + tf("['0', '0', '0', '0', '0', '0', 'a', 'b']") + ",\n"
        "    ])\n"
    )}, "a.launch.py")
    assert (HEADER_LINES + 3, " launch-linter: disable=ros2_positional_args") in [
        (c.line, c.text) for c in tree.comments
    ]
    assert ("a.launch.py", HEADER_LINES + 4) in tree.element_lines


def test_a_helper_call_is_where_its_transform_is(load: Load, tmp_path: Path) -> None:
    tree = load({"a.launch.py": launch_file(
        "    return LaunchDescription([\n"
        "        laser('front_tf'),\n"
        "        laser('rear_tf'),\n"
        "    ])\n"
        "\n"
        "def laser(name):\n"
        "    return " + tf("['--frame-id', 'base_link', '--child-frame-id', 'laser']",
                          ", name=name") + "\n"
    )}, "a.launch.py")
    assert [(t.name, t.line, t.column) for t in tree.transforms] == [
        ("front_tf", HEADER_LINES + 3, 9), ("rear_tf", HEADER_LINES + 4, 9),
    ]
    options = LintOptions(package_paths=(), select=frozenset({"dup_sig"}))
    result = lint_paths([str(tmp_path / "a.launch.py")], options)
    assert [d.line for d in result.diagnostics] == [HEADER_LINES + 4]


def test_text_bombs_are_refused(load: Load) -> None:
    tree = load({"a.launch.py": launch_file(
        "    a = 'x' * 90000\n"
        "    b = a.replace('x', a)\n"
        "    c = '%999999999d' % 1\n"
        "    d = f'{a}{a}{a}'\n"
        "    e = ''.join([a, a, a])\n"
        "    f = '{}{}{}'.format(a, a, a)\n"
        "    return LaunchDescription([" + tf("['--frame-id', 'base', '--child-frame-id', "
                                              "b + c + d + e + f]") + "])\n"
    )}, "a.launch.py")
    (transform,) = tree.transforms
    assert transform.unresolved_names == ("child",)
    assert "too long" in transform.unresolved_reasons[0]


def test_comments_and_statement_lines_only_in_files_that_hold_a_directive() -> None:
    from launch_linter.frontends.ros2_python import read_python

    source = b"# a plain comment\nx = 1\n"
    plain = read_python("/a.launch.py", source)
    assert (plain.comments, plain.element_lines) == ((), ())
    marked = read_python("/a.launch.py", b"# launch-linter: disable=dup_name\n" + source)
    assert marked.comments == ((1, " launch-linter: disable=dup_name"), (2, " a plain comment"))
    assert marked.element_lines == (3,)


def test_reading_a_python_launch_file_leaves_no_reference_cycles(tmp_path: Path) -> None:
    import gc

    launch = tmp_path / "a.launch.py"
    launch.write_text(
        "from launch import LaunchDescription\n"
        "from launch_ros.actions import Node\n"
        "def helper(name):\n"
        "    return Node(package='tf2_ros', executable='static_transform_publisher',\n"
        "                arguments=['0', '0', '0', '0', '0', '0', 'base', name])\n"
        "def generate_launch_description():\n"
        "    return LaunchDescription([helper(n) for n in ['a', 'b']])\n"
    )
    lint_paths([str(launch)], LintOptions())  # imports, caches
    gc.collect()
    gc.disable()
    try:
        result = lint_paths([str(launch)], LintOptions())
        assert len(result.transforms) == 2
        assert gc.collect() == 0
    finally:
        gc.enable()


def test_parameter_and_log_dir_substitutions_are_unresolved(load: Load) -> None:
    tree = load({"a.launch.py": HEADER
        + "from launch_ros.substitutions import Parameter\n"
        + "from launch.substitutions import LaunchLogDir\n"
        + launch_file("    return LaunchDescription([\n        "
                      + tf("['--frame-id', Parameter('base'), '--child-frame-id', 'laser']",
                           ", cwd=LaunchLogDir()")
                      + "])\n").replace(HEADER, "", 1)}, "a.launch.py")
    (transform,) = tree.transforms
    assert "parent" in transform.unresolved and transform.child == "laser"
    assert [rule for rule, _ in rules(tree)] == ["unresolved"]


def test_launch_testing_entry_point(load: Load) -> None:
    tree = load({"test_a.py": HEADER + "import launch_testing\n\n"
        "def generate_test_description():\n"
        "    node = " + tf("['--frame-id', 'map', '--child-frame-id', 'odom']") + "\n"
        "    return LaunchDescription([node, launch_testing.actions.ReadyToTest()]), {'n': node}\n"
    }, "test_a.py")
    assert [(t.parent, t.child) for t in tree.transforms] == [("map", "odom")]
    assert tree.problems == ()


def test_launch_pytest_fixture_with_a_pytest_fixture_argument(load: Load) -> None:
    tree = load({"test_b.py": HEADER + "import launch_pytest\nimport pytest\n"
        "from launch.actions import ExecuteProcess\n\n"
        "@pytest.fixture\n"
        "def proc():\n"
        "    return ExecuteProcess(cmd=['ros2', 'run', 'tf2_ros', 'static_transform_publisher',"
        " '--frame-id', 'map', '--child-frame-id', 'odom'])\n\n"
        "@launch_pytest.fixture(scope='module')\n"
        "def launch_description(proc):\n"
        "    return LaunchDescription([proc, launch_pytest.actions.ReadyToTest()])\n"
    }, "test_b.py")
    (transform,) = tree.transforms
    assert (transform.package, transform.parent, transform.child) == ("tf2_ros", "map", "odom")


def test_a_script_is_an_info_not_an_error(load: Load) -> None:
    tree = load({"tool.launch.py": "import sys\nprint(sys.argv)\n"}, "tool.launch.py")
    assert rules(tree) == [("unresolved", 1)]
    assert tree.status is FileStatus.OK


def test_execute_process_ros2_run_is_a_node_outside_the_pushed_namespace(load: Load) -> None:
    tree = load({"a.launch.py": HEADER + "from launch.actions import ExecuteProcess\n"
        + launch_file(
            "    return LaunchDescription([GroupAction([PushRosNamespace('r'), ExecuteProcess(\n"
            "        cmd=['ros2', 'run', 'tf2_ros', 'static_transform_publisher', '0', '0', '0',"
            " '0', '0', '0', 'a', 'b']),\n"
            "        ExecuteProcess(cmd=['ls', '-l'])])])\n").replace(HEADER, "", 1)},
        "a.launch.py")
    (transform,) = tree.transforms
    assert (transform.namespace, transform.parent, transform.child) == ("/", "a", "b")


def test_launch_pytest_fixture_that_yields(load: Load) -> None:
    tree = load({"test_c.py": HEADER + "import launch_pytest\n\n"
        "@launch_pytest.fixture\n"
        "def launch_description():\n"
        "    frames = ['map', 'odom']\n"
        "    yield LaunchDescription([" + tf("['--frame-id', frames[0], '--child-frame-id',"
                                            " frames[1]]") + "])\n"
        "    print('cleanup')\n"
    }, "test_c.py")
    assert [(t.parent, t.child) for t in tree.transforms] == [("map", "odom")]


def test_script_style_file_reads_what_it_serves(load: Load) -> None:
    tree = load({"run.launch.py": HEADER + "import sys\nfrom launch import LaunchService\n\n"
        "def main(argv=sys.argv[1:]):\n"
        "    ld = LaunchDescription([" + tf("['--frame-id', 'map', '--child-frame-id', 'odom']")
        + "])\n"
        "    ls = LaunchService(argv=argv)\n"
        "    ls.include_launch_description(ld)\n"
        "    return ls.run()\n\n"
        "if __name__ == '__main__':\n"
        "    sys.exit(main())\n"
    }, "run.launch.py")
    assert [(t.parent, t.child) for t in tree.transforms] == [("map", "odom")]


def test_path_substitution_division_and_find_share_find(load: Load) -> None:
    package = '<package format="3"><name>robot</name></package>'
    inner = (
        '<launch><arg name="frame"/><node pkg="tf2_ros" exec="static_transform_publisher" '
        'name="tf_$(var frame)" args="--frame-id base --child-frame-id $(var frame)"/></launch>')
    tree = load({
        "ws/robot/package.xml": package,
        "ws/robot/launch/b.launch.xml": inner,
        "a.launch.py": (
            "from launch.substitutions import PathSubstitution\n" + HEADER
            + "share = FindPackageShare(package='robot').find('robot')\n\n\n"
            + "def generate_launch_description():\n"
            "    return LaunchDescription([\n"
            "        IncludeLaunchDescription(\n"
            "            PathSubstitution(FindPackageShare('robot')) / 'launch' / 'b.launch.xml',\n"
            "            launch_arguments={'frame': 'gps'}.items()),\n"
            "        IncludeLaunchDescription(\n"
            "            PathJoinSubstitution([FindPackageShare('robot'), 'launch']) / "
            "'b.launch.xml',\n"
            "            launch_arguments={'frame': 'imu'}.items()),\n"
            "        IncludeLaunchDescription(os.path.join(share, 'launch', 'b.launch.xml'),\n"
            "            launch_arguments={'frame': 'gnss'}.items()),\n"
            "    ])\n"
        ),
    }, "a.launch.py", packages=("ws",))
    assert sorted(str(t.child) for t in tree.transforms) == ["gnss", "gps", "imu"]
    assert tree.problems == ()


@pytest.mark.parametrize(("cmd", "expected"), [
    ("cmd=['ros2 run tf2_ros static_transform_publisher --frame-id a --child-frame-id b'],"
     " shell=True", [("a", "b")]),
    ("cmd=['ros2', 'run tf2_ros', \"static_transform_publisher --frame-id 'a' "
     "--child-frame-id b\"], shell=True", [("a", "b")]),
    ("cmd=[FindExecutable(name='ros2'), 'run', 'tf2_ros', 'static_transform_publisher',"
     " '--frame-id', 'a', '--child-frame-id', 'b']", [("a", "b")]),
    # A shell expands $X, runs two commands or reads a value's spaces: not read.
    ("cmd=['ros2 run tf2_ros static_transform_publisher --frame-id $X --child-frame-id b'],"
     " shell=True", []),
    ("cmd=['ros2 run tf2_ros static_transform_publisher --frame-id a --child-frame-id b;"
     " ls'], shell=True", []),
    ("cmd=['ros2 run tf2_ros static_transform_publisher', LaunchConfiguration('a')],"
     " shell=True", []),
    ("cmd=['ros2 run tf2_ros static_transform_publisher --frame-id a --child-frame-id b']",
     []),
])
def test_execute_process_ros2_run_in_a_shell(load: Load, cmd: str,
                                             expected: list[tuple[str, str]]) -> None:
    tree = load({"a.launch.py": HEADER + "from launch.actions import ExecuteProcess\n"
        "from launch.substitutions import FindExecutable, LaunchConfiguration\n"
        + launch_file(f"    return LaunchDescription([ExecuteProcess({cmd})])\n").replace(
            HEADER, "", 1)}, "a.launch.py")
    assert [(t.parent, t.child) for t in tree.transforms] == expected


NOT_UTF8 = (b"from launch import LaunchDescription\n"
            b"from launch_ros.actions import Node\n"
            b"def generate_launch_description():\n"
            b"    # \xc6\xf4\xb6\xaf (GBK)\n"
            b"    return LaunchDescription([Node(package='tf2_ros',\n"
            b"        executable='static_transform_publisher',\n"
            b"        arguments=['0', '0', '0', '0', '0', '0', %s, 'laser'])])\n")


def test_bytes_python_compiles_are_read_as_python_reads_them(tmp_path: Path) -> None:
    """launch compiles a Python launch file's bytes (SourceFileLoader): CPython accepts
    bytes that are not UTF-8 inside a comment, and a declared coding (samples8:
    guyuehome/originbot's camera_internal.launch.py, a GBK comment, was a parse_error)."""
    options = LintOptions(package_paths=())
    comment = tmp_path / "comment.launch.py"
    comment.write_bytes(NOT_UTF8 % b"'base_link'")
    declared = tmp_path / "declared.launch.py"
    declared.write_bytes(b"# -*- coding: latin-1 -*-\n" + NOT_UTF8 % b"'caf\xe9'")
    for path in (comment, declared):
        result = lint_paths([str(path)], options)
        assert [d.rule for d in result.diagnostics if d.rule == "parse_error"] == []
        assert result.files[0].transforms == 1
    # In a string without a declaration, Python refuses the bytes too.
    literal = tmp_path / "literal.launch.py"
    literal.write_bytes(NOT_UTF8 % b"'caf\xe9'")
    found = lint_paths([str(literal)], options).diagnostics
    assert [(d.rule, d.message) for d in found if d.rule == "parse_error"] == [
        ("parse_error", "not UTF-8 text: invalid continuation byte")]
