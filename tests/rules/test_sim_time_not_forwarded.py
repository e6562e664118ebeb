"""sim_time_not_forwarded: a ROS 2 launch file passes use_sim_time on to some of what it
starts and not to a tf node it starts (fault, then fixed); sim_time_mismatch's evidence
of an include not followed that is given use_sim_time true."""

from __future__ import annotations

import time
from pathlib import Path

from launch_linter.engine import LintOptions, lint_paths

RULE = "sim_time_not_forwarded"
RULES = frozenset({RULE, "sim_time_mismatch"})


def run(tmp_path: Path, name: str, text: str,
        args: dict[str, str] | None = None) -> list[tuple[str, int, str]]:
    path = tmp_path / name
    path.write_text(text)
    options = LintOptions(package_paths=(), select=RULES, args=args or {})
    return [(d.rule, d.line, d.severity.value)
            for d in lint_paths([str(path)], options).diagnostics]


NAV = ("from launch import LaunchDescription\n"                                  # 1
       "from launch.actions import DeclareLaunchArgument, IncludeLaunchDescription\n"
       "from launch.conditions import IfCondition, UnlessCondition\n"
       "from launch.launch_description_sources import PythonLaunchDescriptionSource\n"
       "from launch.substitutions import LaunchConfiguration\n"                  # 5
       "from launch_ros.actions import Node, SetParameter\n"
       "def generate_launch_description():\n"
       "    sim = LaunchConfiguration('use_sim_time')\n"
       "    return LaunchDescription([\n"
       "        DeclareLaunchArgument('use_sim_time', default_value='false'),\n"   # 10
       "        IncludeLaunchDescription(\n"
       "            PythonLaunchDescriptionSource('/nowhere/nav2_bringup_launch.py'),\n"
       "            launch_arguments={{'use_sim_time': sim}}.items()),\n"
       "        {rviz}\n"                                                         # 14
       "    ])\n")
RVIZ = "Node(package='rviz2', executable='rviz2'{extra}),"


def test_turtlebot3_456_rviz2_left_out_of_what_the_file_passes_on(tmp_path: Path) -> None:
    fault = NAV.format(rviz=RVIZ.format(extra=""))
    # Whatever the value: the default (false) gives the structural finding at info ...
    assert run(tmp_path, "n.launch.py", fault) == [(RULE, 14, "info")]
    # ... and true makes the include not followed clock evidence: sim_time_mismatch's
    # warning, once (the structural finding leaves the node to it).
    assert run(tmp_path, "n.launch.py", fault, {"use_sim_time": "true"}) == [
        ("sim_time_mismatch", 14, "warning")]
    fixed = NAV.format(rviz=RVIZ.format(extra=", parameters=[{'use_sim_time': sim}]"))
    assert run(tmp_path, "n.launch.py", fixed) == []
    assert run(tmp_path, "n.launch.py", fixed, {"use_sim_time": "true"}) == []


def test_what_gives_the_node_use_sim_time_otherwise_or_may_do_so(tmp_path: Path) -> None:
    # A literal value, SetParameter in its scope, a parameter file the linter cannot read
    # (it may set it), a condition exclusive with the include's: all silent.
    for rviz in (RVIZ.format(extra=", parameters=[{'use_sim_time': True}]"),
                 "SetParameter(name='use_sim_time', value=sim), " + RVIZ.format(extra=""),
                 RVIZ.format(extra=", parameters=['/nowhere/rviz.yaml']"),
                 RVIZ.format(extra=", parameters=[LaunchConfiguration('params')]")):
        assert run(tmp_path, "n.launch.py", NAV.format(rviz=rviz)) == [], rviz
    exclusive = NAV.replace(
        "launch_arguments={{'use_sim_time': sim}}.items()),",
        "launch_arguments={{'use_sim_time': sim}}.items(),\n"
        "            condition=IfCondition(LaunchConfiguration('nav'))),").format(
        rviz=RVIZ.format(extra=", condition=UnlessCondition(LaunchConfiguration('nav'))"))
    assert run(tmp_path, "n.launch.py", exclusive) == []
    # A node the file starts that is no tf node (a teleop) is not reported.
    teleop = "Node(package='teleop_twist_keyboard', executable='teleop_twist_keyboard'),"
    assert run(tmp_path, "n.launch.py", NAV.format(rviz=teleop)) == []


def test_a_literal_include_argument_is_not_passing_the_configuration_on(
        tmp_path: Path) -> None:
    literal = NAV.replace("{{'use_sim_time': sim}}", "{{'use_sim_time': 'false'}}")
    assert run(tmp_path, "n.launch.py", literal.format(rviz=RVIZ.format(extra=""))) == []


def test_an_include_followed_is_not_clock_evidence_its_nodes_are(tmp_path: Path) -> None:
    """The included file may ignore the argument: when it is read, its nodes say what
    runs on simulated time."""
    (tmp_path / "inner.launch.py").write_text(
        "from launch import LaunchDescription\n"
        "from launch_ros.actions import Node\n"
        "def generate_launch_description():\n"
        "    return LaunchDescription([Node(package='demo_nodes_cpp', executable='talker')])\n")
    followed = NAV.replace("'/nowhere/nav2_bringup_launch.py'",
                           f"'{tmp_path / 'inner.launch.py'}'")
    fault = followed.format(rviz=RVIZ.format(extra=""))
    assert run(tmp_path, "n.launch.py", fault, {"use_sim_time": "true"}) == [
        (RULE, 14, "info")]


XML = ('<launch>\n'
       '  <arg name="use_sim_time" default="false"/>\n'
       '  <node pkg="robot_state_publisher" exec="robot_state_publisher">\n'
       '    <param name="use_sim_time" value="$(var use_sim_time)"/>\n'
       '  </node>\n'
       '  <node pkg="joint_state_publisher" exec="joint_state_publisher"{jsp}\n'
       '</launch>\n')


def test_xml_joint_state_publisher_beside_robot_state_publisher(tmp_path: Path) -> None:
    fault = XML.format(jsp="/>")
    assert run(tmp_path, "d.launch.xml", fault) == [(RULE, 6, "info")]
    fixed = XML.format(jsp='>\n    <param name="use_sim_time" value="$(var use_sim_time)"/>'
                           '\n  </node>')
    assert run(tmp_path, "d.launch.xml", fixed) == []


def test_ros1_has_one_global_use_sim_time(tmp_path: Path) -> None:
    ros1 = ('<launch><arg name="use_sim_time" default="false"/>'
            '<node pkg="robot_state_publisher" type="robot_state_publisher" name="rsp">'
            '<param name="use_sim_time" value="$(arg use_sim_time)"/></node>'
            '<node pkg="rviz" type="rviz" name="rviz"/></launch>')
    assert run(tmp_path, "a.launch", ros1) == []


def test_twenty_thousand_forwarded_parameters_and_include_arguments(tmp_path: Path) -> None:
    count = 20_000
    params = ", ".join(f"'p{i}': LaunchConfiguration('p{i}')" for i in range(count))
    arguments = ", ".join(f"'a{i}': LaunchConfiguration('a{i}')" for i in range(count))
    text = NAV.replace("{{'use_sim_time': sim}}", f"{{{{'use_sim_time': sim, {arguments}}}}}")
    text = text.format(rviz=RVIZ.format(extra=f", parameters=[{{{params}}}]"))
    started = time.process_time()
    assert run(tmp_path, "n.launch.py", text) == [(RULE, 14, "info")]
    assert time.process_time() - started < 30
