from __future__ import annotations

import json
from pathlib import Path

import pytest

from launch_linter import LintOptions, lint_paths
from launch_linter.knowledge import KnowledgeError, bundled, parse_entry
from launch_linter.rules.ros2_param_type import written_type

RULE = "ros2_param_type"
LAUNCH = """from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='robot_localization', executable='{executable}', name='filter',
             parameters=['{file}'{extra}]),
    ])
"""


def _found(tmp_path: Path, params: str, executable: str = "ekf_node", extra: str = ""
           ) -> list[tuple[str, int, str]]:
    (tmp_path / "params.yaml").write_text(params, encoding="utf-8")
    launch = tmp_path / "filter.launch.py"
    launch.write_text(LAUNCH.format(executable=executable, file=tmp_path / "params.yaml",
                                    extra=extra), encoding="utf-8")
    result = lint_paths([str(launch)], LintOptions(package_paths=()))
    return [(Path(d.path).name, d.line, d.message) for d in result.diagnostics
            if d.rule == RULE]


@pytest.mark.parametrize(("line", "given"), [("frequency: 30", "an integer"),
                                             ("two_d_mode: 1", "an integer"),
                                             ("sensor_timeout: true", "a bool")])
def test_a_value_of_another_type_kills_the_node(tmp_path: Path, line: str, given: str) -> None:
    params = f"filter:\n  ros__parameters:\n    {line}\n"
    ((name, at, message),) = _found(tmp_path, params)
    assert (name, at) == ("params.yaml", 3)
    assert f"rclcpp reads as {given}" in message


@pytest.mark.parametrize("line", ["frequency: 30.0", "frequency: 3.0e1", "two_d_mode: true",
                                  "map_frame: map", "frequency: '30.0'", "other: 30"])
def test_the_declared_type_or_an_unlisted_parameter_is_silent(tmp_path: Path,
                                                              line: str) -> None:
    assert _found(tmp_path, f"filter:\n  ros__parameters:\n    {line}\n") == []


def test_navsat_transform_frequency(tmp_path: Path) -> None:
    params = "filter:\n  ros__parameters:\n    frequency: 30\n    delay: 3.0\n"
    ((_, at, message),) = _found(tmp_path, params, "navsat_transform_node")
    assert at == 3 and "write it as 30.0" in message


def test_a_key_for_another_node_gives_this_one_nothing(tmp_path: Path) -> None:
    assert _found(tmp_path, "other_node:\n  ros__parameters:\n    frequency: 30\n") == []


def test_only_the_last_setting_counts(tmp_path: Path) -> None:
    params = "filter:\n  ros__parameters:\n    frequency: 30\n"
    assert _found(tmp_path, params, extra=", {'frequency': 30.0}") == []


def test_an_unknown_program_is_not_judged(tmp_path: Path) -> None:
    params = "filter:\n  ros__parameters:\n    frequency: 30\n"
    assert _found(tmp_path, params, "some_other_node") == []


def test_written_type() -> None:
    assert [written_type(v) for v in ("30", "-2", "30.0", ".5", "1.0e-3", "true", "map",
                                      "1e3", "inf")] == [
        "integer", "integer", "double", "double", "double", "bool", None, None, None]


def test_knowledge_parameter_types_are_checked() -> None:
    entry = {"id": "x", "kind": "node", "ros": [2],
             "match": {"package": "p", "executables": ["e"]},
             "parameter_types": {"rate": "float"},
             "sources": [{"repository": "o/r", "package": "p", "file": "f", "ref": "main",
                          "commit": "0" * 40, "lines": "1"}]}
    with pytest.raises(KnowledgeError, match="parameter_types"):
        parse_entry(json.loads(json.dumps(entry)), "test", "test")
    entry["parameter_types"] = {"rate": "double"}
    assert parse_entry(entry, "test", "test").parameter_types == (("rate", "double"),)


def test_bundled_types_name_ros2_nodes() -> None:
    typed = [e for e in bundled().entries if e.parameter_types]
    assert {e.id for e in typed} >= {"robot_localization_filter", "navsat_transform"}
    assert all(2 in e.ros for e in typed)
