from __future__ import annotations

from pathlib import Path

import pytest

from launch_linter import LintOptions, lint_paths
from launch_linter.rules.use_sim_time_misspelt import near_miss

RULE = "use_sim_time_misspelt"
XML = """<launch>
  <node pkg="robot_state_publisher" exec="robot_state_publisher" name="rsp">
    <param name="{name}" value="{value}"/>
  </node>
</launch>
"""
PY = """from launch import LaunchDescription
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    sim = {{"{name}": LaunchConfiguration("sim", default="true")}}
    return LaunchDescription([
        Node(package="rviz2", executable="rviz2", parameters=[sim]),
    ])
"""


def _found(tmp_path: Path, text: str, file: str) -> list[tuple[int, str]]:
    path = tmp_path / file
    path.write_text(text, encoding="utf-8")
    result = lint_paths([str(path)], LintOptions(package_paths=()))
    return [(d.line, d.severity.value) for d in result.diagnostics if d.rule == RULE]


@pytest.mark.parametrize("name", ["use_sime_time", "use_sim_tim", "use_simtime",
                                  "Use_Sim_Time", "use_sym_tme"])
def test_a_misspelt_name_is_a_warning_at_its_line(tmp_path: Path, name: str) -> None:
    assert _found(tmp_path, XML.format(name=name, value="true"), "a.launch.xml") == [
        (3, "warning")]


@pytest.mark.parametrize(("name", "value"), [("use_sim_time", "true"),
                                             ("use_sime_time", "false"),
                                             ("use_sim_timestep", "true"),
                                             ("use_sim_times", "true"),
                                             ("sim_time", "true"),
                                             ("use_time", "true")])
def test_the_right_name_a_false_value_or_another_parameter_is_silent(
        tmp_path: Path, name: str, value: str) -> None:
    assert _found(tmp_path, XML.format(name=name, value=value), "a.launch.xml") == []


def test_a_value_from_a_launch_argument(tmp_path: Path) -> None:
    assert _found(tmp_path, PY.format(name="use_sime_time"), "a.launch.py") == [(7, "warning")]
    assert _found(tmp_path, PY.format(name="use_sim_time"), "a.launch.py") == []


def test_near_miss() -> None:
    assert [near_miss(n) for n in ("use_sime_time", "usesimtime", "use_sim_time",
                                   "use_sim_time_x", "publish_tf", "")] == [
        True, True, False, False, False, False]


def test_a_ros1_node_is_left_out(tmp_path: Path) -> None:
    ros1 = ('<launch>\n  <node pkg="robot_state_publisher" type="robot_state_publisher" '
            'name="rsp">\n    <param name="use_sime_time" value="true"/>\n  </node>\n</launch>\n')
    assert _found(tmp_path, ros1, "a.launch") == []
