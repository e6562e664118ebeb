"""robot_frame_collision: one robot file included per robot without frame prefixes."""

from __future__ import annotations

from pathlib import Path

from launch_linter.engine import LintOptions, lint_paths

RULE = "robot_frame_collision"
ROBOT = ('<launch>\n<param name="robot_description" value="&lt;robot name=\'r\'&gt;'
         '&lt;joint name=\'j\' type=\'fixed\'&gt;&lt;parent link=\'base_link\'/&gt;'
         '&lt;child link=\'laser\'/&gt;&lt;/joint&gt;&lt;/robot&gt;"/>\n'
         '<node pkg="robot_state_publisher" type="robot_state_publisher" name="rsp"/>\n'
         '</launch>\n')


def run(tmp_path: Path, fleet: str) -> list[tuple[str, str, int]]:
    (tmp_path / "robot.launch").write_text(ROBOT)
    (tmp_path / "fleet.launch").write_text(fleet)
    options = LintOptions(package_paths=(), select=frozenset({RULE}))
    result = lint_paths([str(tmp_path / "fleet.launch")], options)
    return [(d.rule, Path(d.path).name, d.line) for d in result.diagnostics]


def test_two_namespaced_robots_without_a_prefix(tmp_path: Path) -> None:
    fault = ('<launch><group ns="r1"><include file="$(dirname)/robot.launch"/></group>'
             '<group ns="r2"><include file="$(dirname)/robot.launch"/></group></launch>')
    assert run(tmp_path, fault) == [(RULE, "robot.launch", 2)]
    fixed = fault.replace('<group ns="r1">', '<group ns="r1"><param name="tf_prefix" '
                                             'value="r1"/>')
    assert run(tmp_path, fixed) == []


def test_one_robot_is_silent(tmp_path: Path) -> None:
    assert run(tmp_path, '<launch><include file="$(dirname)/robot.launch"/></launch>') == []


def test_a_ros2_frame_prefix_given_to_ros1_publishers_is_no_prefix(tmp_path: Path) -> None:
    """ROS 1 robot_state_publisher reads tf_prefix, not frame_prefix
    (ros/robot_state_publisher#192): the robots' frames still collide."""
    robot = ROBOT.replace('name="rsp"/>', 'name="rsp"><param name="frame_prefix" '
                                          'value="$(arg p)"/></node>')
    (tmp_path / "robot.launch").write_text(robot.replace("<launch>\n", '<launch>\n<arg name="p"/>'))
    fleet = ('<launch><group ns="r1"><include file="$(dirname)/robot.launch">'
             '<arg name="p" value="r1"/></include></group>'
             '<group ns="r2"><include file="$(dirname)/robot.launch">'
             '<arg name="p" value="r2"/></include></group></launch>')
    (tmp_path / "fleet.launch").write_text(fleet)
    options = LintOptions(package_paths=(), select=frozenset({RULE}))
    found = lint_paths([str(tmp_path / "fleet.launch")], options).diagnostics
    assert [(d.rule, Path(d.path).name) for d in found] == [(RULE, "robot.launch")]
    (tmp_path / "robot.launch").write_text(
        robot.replace("<launch>\n", '<launch>\n<arg name="p"/>').replace("frame_prefix",
                                                                         "tf_prefix"))
    assert lint_paths([str(tmp_path / "fleet.launch")], options).diagnostics == ()
