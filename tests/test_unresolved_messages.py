"""Unresolved messages name the first unknown that really blocks the value, each cause
once, without printing the written expression twice or a condition for a variable."""

from __future__ import annotations

from pathlib import Path

from launch_linter.engine import LintOptions, lint_paths
from launch_linter.resolve.value import Hole, blocker, why_unresolved


def test_blocker_is_the_innermost_quoted_unknown() -> None:
    hole = Hole("LaunchConfiguration('urdf')",
                'PathJoinSubstitution([FindPackageShare("d"), f"{base}.urdf.xacro"]): '
                "os.getenv('BASE'): environment variable 'BASE' not given (use --env)")
    assert blocker(hole) == ("os.getenv('BASE')",
                             "environment variable 'BASE' not given (use --env)")
    # A reason in words quotes nothing: the hole itself blocks.
    plain = Hole("$(arg model)", "arg 'model' is not set: give it with --arg")
    assert blocker(plain) == ("$(arg model)", "arg 'model' is not set: give it with --arg")
    assert blocker(Hole("x", "line 5: a: b")) == ("x", "line 5: a: b")


def test_why_unresolved_names_each_cause_once_and_not_the_whole_value_again() -> None:
    whole = Hole("$(find nav2)", "package 'nav2' not found")
    assert why_unresolved((whole,)) == "package 'nav2' not found"
    cause = "set under the condition 'c'"
    twice = (Hole("a", cause), "/", Hole("b", cause))
    assert why_unresolved(twice) == "a, b: set under the condition 'c'"
    nested = ("xacro ", Hole("LaunchConfiguration('urdf')",
                             "os.getenv('BASE'): environment variable 'BASE' not given"))
    assert why_unresolved(nested) == ("os.getenv('BASE'): environment variable 'BASE' not "
                                      "given (in LaunchConfiguration('urdf'))")


def _messages(folder: Path, name: str, text: str, **options: object) -> list[str]:
    (folder / name).write_text(text)
    result = lint_paths([str(folder / name)], LintOptions(**options))  # type: ignore[arg-type]
    return [d.message for d in result.diagnostics if d.rule == "unresolved"]


DESCRIPTION = """import os
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import Command, LaunchConfiguration, PathJoinSubstitution
from launch_ros.actions import Node
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    robot_base = os.getenv('LINOROBOT2_BASE')
    urdf_path = PathJoinSubstitution(
        [FindPackageShare("linorobot2_description"), "urdf/robots", f"{robot_base}.urdf.xacro"])
    return LaunchDescription([
        DeclareLaunchArgument(name='urdf', default_value=urdf_path),
        Node(package='robot_state_publisher', executable='robot_state_publisher',
             parameters=[{'robot_description': Command(['xacro ', LaunchConfiguration('urdf')])}]),
    ])
"""


def test_an_environment_variable_behind_a_default_is_named(tmp_path: Path) -> None:
    package = tmp_path / "linorobot2_description"
    (package / "launch").mkdir(parents=True)
    (package / "package.xml").write_text(
        "<package><name>linorobot2_description</name><export><build_type>ament_cmake"
        "</build_type></export></package>")
    (message,) = _messages(package / "launch", "description.launch.py", DESCRIPTION,
                           package_paths=(str(tmp_path),))
    assert message.startswith("robot description not read: the description file depends on "
                              "os.getenv('LINOROBOT2_BASE'): environment variable "
                              "'LINOROBOT2_BASE' not given (use --env)")
    assert message.count("LaunchConfiguration('urdf')") <= 1


INCLUDE = """from launch import LaunchDescription
from launch.actions import IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import PathJoinSubstitution
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    return LaunchDescription([IncludeLaunchDescription(PythonLaunchDescriptionSource(
        PathJoinSubstitution([FindPackageShare('nav2_bringup'), 'launch', 'x.launch.py'])))])
"""


def test_a_python_include_message_prints_its_expression_once(tmp_path: Path) -> None:
    (message,) = _messages(tmp_path, "inc.launch.py", INCLUDE)
    assert message.count("PathJoinSubstitution(") == 1
    assert message.endswith("not followed: FindPackageShare('nav2_bringup'): package "
                            "'nav2_bringup' not found under the package path")


BRANCHES = """import os
from launch import LaunchDescription
from launch.actions import IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch_ros.actions import Node


def generate_launch_description():
    LDS_MODEL = os.environ['LDS_MODEL']
    LDS_LAUNCH_FILE = '/hlds_laser.launch.py'
    if LDS_MODEL == 'LDS-01':
        lidar_pkg_dir = '/opt/a'
    else:
        lidar_pkg_dir = '/opt/b'
        LDS_LAUNCH_FILE = '/ld08.launch.py'
    robots = os.environ['ROBOTS']
    if len(robots) == 0:
        robots_list = []
    else:
        robots_list = robots.split(',')
    ld = LaunchDescription([IncludeLaunchDescription(
        PythonLaunchDescriptionSource([lidar_pkg_dir, LDS_LAUNCH_FILE]))])
    for robot in robots_list:
        ld.add_action(Node(package='tf2_ros', executable='static_transform_publisher',
                           arguments=['0', '0', '0', '0', '0', '0', 'map', robot]))
    return ld
"""


def test_variables_set_under_an_unknown_condition_are_named_by_themselves(
    tmp_path: Path,
) -> None:
    include, loop = _messages(tmp_path, "robot.launch.py", BRANCHES)
    # Both unknowns have one cause, said once, with what really blocks the condition.
    assert include.startswith("include file 'lidar_pkg_dirLDS_LAUNCH_FILE' not followed: "
                              "lidar_pkg_dir, LDS_LAUNCH_FILE: line 11: set under the "
                              "condition \"LDS_MODEL == 'LDS-01'\" (os.environ['LDS_MODEL']:")
    assert include.count("set under") == 1
    # "the loop over robots_list", not "the loop over len(robots) == 0".
    assert loop.startswith("the loop over robots_list (set under the condition "
                           "'len(robots) == 0'")




TWO_NODES = """from launch import LaunchDescription
from launch.substitutions import Command, LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    description = {'robot_description': Command(['xacro ', LaunchConfiguration('model')])}
    return LaunchDescription([
        Node(package='robot_state_publisher', executable='robot_state_publisher',
             parameters=[description]),
        Node(package='controller_manager', executable='ros2_control_node',
             parameters=[description]),
        Node(package='joint_state_publisher', executable='joint_state_publisher',
             parameters=[description]),
    ])
"""


def test_one_description_given_to_several_nodes_is_reported_once(tmp_path: Path) -> None:
    messages = _messages(tmp_path, "bringup.launch.py", TWO_NODES)
    described = [m for m in messages if m.startswith("robot description not read")]
    assert len(described) == 1, messages
    assert "LaunchConfiguration('model')" in described[0]


PART = """<launch>
  <arg name="model"/>
  <node pkg="tf" type="static_transform_publisher" name="t_$(arg model)"
        args="0 0 0 0 0 0 a $(env HOST_FRAME) 100"/>
</launch>
"""

VARIANTS = """<launch>
  <include file="$(dirname)/part.launch"><arg name="model" value="burger"/></include>
  <include file="$(dirname)/part.launch"><arg name="model" value="waffle"/></include>
  <include file="$(dirname)/part.launch"><arg name="model" value="waffle_pi"/></include>
</launch>
"""


def test_included_text_says_its_cause_once_with_the_including_file(tmp_path: Path) -> None:
    (tmp_path / "part.launch").write_text(PART)
    (message,) = _messages(tmp_path, "robot.launch", VARIANTS)
    assert "environment variable 'HOST_FRAME' is not given" in message
    assert message.endswith(f"(included from {tmp_path / 'robot.launch'}:2)")


DISTRO_BRANCH = """import os
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    if os.environ.get('ROS_DISTRO') == 'dashing':
        tf = Node(package='tf2_ros', node_executable='static_transform_publisher',
                  arguments=['--frame-id', 'map', '--child-frame-id', 'odom'])
    else:
        tf = Node(package='tf2_ros', executable='static_transform_publisher',
                  arguments=['--frame-id', 'map', '--child-frame-id', 'odom'])
    return LaunchDescription([tf])
"""


def test_a_branch_for_another_distribution_is_silent_when_the_target_decides_it(
    tmp_path: Path,
) -> None:
    (tmp_path / "tf.launch.py").write_text(DISTRO_BRANCH)

    def rules(**options: object) -> list[str]:
        result = lint_paths([str(tmp_path / "tf.launch.py")],
                            LintOptions(**options))  # type: ignore[arg-type]
        return sorted(d.rule for d in result.diagnostics)

    # Unknown target: the branch is unknown, and the message says on what.
    (message,) = _messages(tmp_path, "tf.launch.py", DISTRO_BRANCH)
    assert "os.environ.get('ROS_DISTRO')" in message
    # --ros-distro decides it: no message about the Dashing-only branch, no refused keyword.
    assert rules(ros_distro="humble") == []
    assert "ros2_removed_keyword" not in rules(ros_distro="jazzy")


NAV_INCLUDE = """import os

from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource


def generate_launch_description():
    nav2_launch_dir = os.path.join(get_package_share_directory('nav2_bringup'), 'launch')
    return LaunchDescription([
        IncludeLaunchDescription(
            PythonLaunchDescriptionSource([nav2_launch_dir, '/navigation_launch.py'])),
    ])
"""


def test_an_include_message_prints_the_written_expression_once(tmp_path: Path) -> None:
    """rosrider: the include's path, quoted whole, holds the expression the blocker is
    in; ``(in EXPRESSION)`` after the reason said it a second time."""
    (message,) = _messages(tmp_path, "nav.launch.py", NAV_INCLUDE)
    assert message.count("os.path.join(") == 1, message
    assert message.endswith("get_package_share_directory('nav2_bringup'): package "
                            "'nav2_bringup' not found under the package path")


SPLIT_CALL = """from launch import LaunchDescription
from launch.actions import IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import PathJoinSubstitution
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    pkg_nav2_bringup = FindPackageShare('nav2_bringup')
    return LaunchDescription([
        IncludeLaunchDescription(PythonLaunchDescriptionSource(PathJoinSubstitution(
            [pkg_nav2_bringup, 'launch', 'navigation_launch.py']))),
    ])
"""


def test_an_expression_written_over_lines_is_quoted_as_one_line(tmp_path: Path) -> None:
    """turtlebot4: ``PathJoinSubstitution(`` then the list on the next line was quoted
    ``PathJoinSubstitution( [pkg_nav2_bringup, ...])``."""
    (message,) = _messages(tmp_path, "nav2.launch.py", SPLIT_CALL)
    assert ('include file "PathJoinSubstitution([pkg_nav2_bringup, \'launch\', '
            '\'navigation_launch.py\'])" not followed') in message


QUOTED_CONDITION = """import os

from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    if 'GAZEBO_MODEL_PATH' in os.environ:
        frame = 'a'
    else:
        frame = 'b'
    return LaunchDescription([
        Node(package='tf2_ros', executable='static_transform_publisher',
             arguments=['--frame-id', 'map', '--child-frame-id', frame]),
    ])
"""


def test_a_condition_holding_quotes_is_quoted_readably(tmp_path: Path) -> None:
    """navigation2_tutorials: ``'GAZEBO_MODEL_PATH' in os.environ`` was quoted in single
    quotes, ``''GAZEBO_MODEL_PATH' in os.environ'``."""
    (message,) = _messages(tmp_path, "gps.launch.py", QUOTED_CONDITION)
    assert "set under the condition \"'GAZEBO_MODEL_PATH' in os.environ\"" in message


LONG_COMMAND = """from launch import LaunchDescription
from launch.actions import OpaqueFunction
from launch.substitutions import Command, FindExecutable, PathJoinSubstitution
from launch_ros.actions import Node


def launch_setup(context):
    content = Command(
        [
            PathJoinSubstitution([FindExecutable(name="xacro")]),
            " ",
            "robot.urdf.xacro",
        ]
    )
    description = {"robot_description": content.perform(context)}
    return [Node(package="robot_state_publisher", executable="robot_state_publisher",
                 parameters=[description])]


def generate_launch_description():
    return LaunchDescription([OpaqueFunction(function=launch_setup)])
"""


def test_an_expression_cut_after_three_lines_says_it_is_cut(tmp_path: Path) -> None:
    """ros2_kortex: ``Command([PathJoinSubstitution([FindExecutable(name="xacro")]),:
    $(command) runs a program`` read as if the expression ended at the comma."""
    messages = _messages(tmp_path, "sim.launch.py", LONG_COMMAND)
    quoted = [m for m in messages if "Command([" in m]
    assert quoted and all('Command([PathJoinSubstitution([FindExecutable(name="xacro")]), ...'
                          in m for m in quoted), messages
