"""sim_clock_not_bridged: Gazebo Sim started, nodes on use_sim_time true, no /clock bridge
(found; silent with the bridge, with Gazebo classic, and without nodes on sim time; open
when a node the knowledge base does not know could bridge the clock)."""

from __future__ import annotations

import time
from pathlib import Path

from launch_linter.engine import LintOptions, lint_paths

RULE = "sim_clock_not_bridged"

HEAD = ("from launch import LaunchDescription\n"                                  # 1
        "from launch.actions import GroupAction, IncludeLaunchDescription\n"
        "from launch.launch_description_sources import PythonLaunchDescriptionSource\n"
        "from launch_ros.actions import Node\n"
        "from launch_ros.substitutions import FindPackageShare\n"                 # 5
        "def generate_launch_description():\n"
        "    return LaunchDescription([\n"
        "        IncludeLaunchDescription(PythonLaunchDescriptionSource(\n"       # 8
        "            [FindPackageShare('{sim}'), '/launch/{launch}'])),\n"
        "        Node(package='robot_state_publisher', executable='robot_state_publisher',\n"
        "             parameters=[{{'use_sim_time': {sim_time}}}]),\n"             # 11
        "        {extra}\n"
        "    ])\n")
BRIDGE = ("Node(package='ros_gz_bridge', executable='parameter_bridge', "
          "arguments=['/clock@rosgraph_msgs/msg/Clock[gz.msgs.Clock']),")


def run(tmp_path: Path, sim: str = "ros_gz_sim", launch: str = "gz_sim.launch.py",
        sim_time: str = "True", extra: str = "") -> list[tuple[int, str, str]]:
    path = tmp_path / "sim.launch.py"
    path.write_text(HEAD.format(sim=sim, launch=launch, sim_time=sim_time, extra=extra))
    options = LintOptions(package_paths=(), select=frozenset({RULE}))
    return [(d.line, d.severity.value, d.message)
            for d in lint_paths([str(path)], options).diagnostics]


def test_gz_sim_without_a_clock_bridge(tmp_path: Path) -> None:
    ((line, level, message),) = run(tmp_path)
    assert (line, level) == (8, "info")
    assert "nothing in the launch tree bridges" in message
    assert "robot_state_publisher/robot_state_publisher" in message


def test_ignition_spawner_alone_is_evidence(tmp_path: Path) -> None:
    spawner = "Node(package='ros_ign_gazebo', executable='create'),"
    found = run(tmp_path, sim="ros_ign_gazebo", launch="ign_gazebo.launch.py", extra=spawner)
    assert [line for line, _, _ in found] == [8]


def test_silent_with_the_bridge(tmp_path: Path) -> None:
    assert run(tmp_path, extra=BRIDGE) == []


def test_silent_with_gazebo_classic(tmp_path: Path) -> None:
    assert run(tmp_path, sim="gazebo_ros", launch="gazebo.launch.py") == []


def test_silent_without_nodes_on_sim_time(tmp_path: Path) -> None:
    assert run(tmp_path, sim_time="False") == []


def test_ros_gz_sim_launch_starts_a_bridge(tmp_path: Path) -> None:
    assert run(tmp_path, launch="ros_gz_sim.launch.py") == []


def test_unknown_node_leaves_the_tree_open(tmp_path: Path) -> None:
    ((_, _, message),) = run(tmp_path, extra="Node(package='my_pkg', executable='sim_glue'),")
    assert "not decided" in message and "my_pkg/sim_glue" in message


def test_unknown_include_leaves_the_tree_open(tmp_path: Path) -> None:
    include = ("IncludeLaunchDescription(PythonLaunchDescriptionSource("
               "[FindPackageShare('my_pkg'), '/launch/bridges.launch.py'])),")
    ((_, _, message),) = run(tmp_path, extra=include)
    assert "not decided" in message


def test_twenty_thousand_nodes(tmp_path: Path) -> None:
    node = ("Node(package='robot_state_publisher', executable='robot_state_publisher',"
            " parameters=[{'use_sim_time': True}]),")
    # Four groups: the front-end follows at most 10,000 items of one list.
    many = "".join("GroupAction([" + node * 5_000 + "])," for _ in range(4))
    started = time.process_time()
    ((_, _, message),) = run(tmp_path, extra=many)
    assert "and 19998 more" in message
    assert time.process_time() - started < 60
