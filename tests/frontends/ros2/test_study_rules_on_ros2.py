"""The study's rules and the mined beliefs apply unchanged to ROS 2 transforms."""

from __future__ import annotations

from pathlib import Path

import pytest

from launch_linter import LintOptions, lint_paths, lint_text
from launch_linter.model.beliefs import BeliefSet

PAIRS = [("base_link", "laser"), ("base_link", "laser"), ("/odom", "odom"),
         ("base_link", "imu_link")]


def xml(pairs: list[tuple[str, str]], yaw: str = "0") -> str:
    nodes = "".join(
        f'  <node pkg="tf2_ros" exec="static_transform_publisher" name="tf{i}"\n'
        f'        args="--yaw {yaw} --frame-id {parent} --child-frame-id {child}"/>\n'
        for i, (parent, child) in enumerate(pairs)
    )
    return f"<launch>\n{nodes}</launch>\n"


def yaml(pairs: list[tuple[str, str]], yaw: str = "0") -> str:
    nodes = "".join(
        f"- node:\n    pkg: tf2_ros\n    exec: static_transform_publisher\n    name: tf{i}\n"
        f"    args: '--yaw {yaw} --frame-id {parent} --child-frame-id {child}'\n"
        for i, (parent, child) in enumerate(pairs)
    )
    return "launch:\n" + nodes


def python(pairs: list[tuple[str, str]], yaw: str = "0") -> str:
    nodes = "".join(
        f"        Node(package='tf2_ros', executable='static_transform_publisher',"
        f" name='tf{i}',\n             arguments=['--yaw', '{yaw}', '--frame-id', '{parent}',"
        f" '--child-frame-id', '{child}']),\n"
        for i, (parent, child) in enumerate(pairs)
    )
    return ("from launch import LaunchDescription\nfrom launch_ros.actions import Node\n"
            "def generate_launch_description():\n    return LaunchDescription([\n"
            f"{nodes}    ])\n")


FORMATS = [(xml, "robot.launch.xml", 2), (yaml, "robot.launch.yaml", 5),
           (python, "robot.launch.py", 2)]
"""Writer, file name, and the lines between two consecutive nodes."""


def found(text: str, path: str, select: set[str]) -> list[tuple[str, int]]:
    options = LintOptions(package_paths=(), select=frozenset(select))
    return [(d.rule, d.line) for d in lint_text(text, path, options).diagnostics]


@pytest.mark.parametrize(("write", "path", "step"), FORMATS)
def test_must_rules(write: object, path: str, step: int) -> None:
    assert callable(write)
    first = {"robot.launch.xml": 2, "robot.launch.yaml": 2, "robot.launch.py": 5}[path]
    diagnostics = found(write(PAIRS), path, {"dup_sig", "self_transform", "dup_name",
                                             "leading_slash"})
    assert ("dup_sig", first + step) in diagnostics
    assert ("self_transform", first + 2 * step) in diagnostics
    assert ("leading_slash", first + 2 * step) in diagnostics
    assert not any(rule == "dup_name" for rule, _ in diagnostics)


@pytest.mark.parametrize(("write", "path", "step"), FORMATS)
def test_may_semantic_rules(write: object, path: str, step: int) -> None:
    assert callable(write)
    diagnostics = found(write([("base_link", "imu_link")], yaw="90"), path,
                        {"rot_degrees", "sensor_null"})
    assert [rule for rule, _ in diagnostics] == ["rot_degrees"]
    diagnostics = found(write([("base_link", "imu_link")]), path, {"sensor_null"})
    assert [rule for rule, _ in diagnostics] == ["sensor_null"]


def test_duplicate_node_names_are_info_in_ros2() -> None:
    text = xml([("a", "b")]).replace("tf0", "same") + xml([("a", "c")]).replace("tf0", "same")
    text = text.replace("</launch>\n<launch>\n", "")
    options = LintOptions(package_paths=(), select=frozenset({"dup_name"}))
    (diagnostic,) = lint_text(text, "robot.launch.xml", options).diagnostics
    assert diagnostic.severity.value == "info"


def test_tree_rules_across_formats(tmp_path: Path) -> None:
    (tmp_path / "a.launch.xml").write_text(
        '<launch>\n  <include file="$(dirname)/b.launch.py"/>\n'
        '  <node pkg="tf2_ros" exec="static_transform_publisher" name="x"\n'
        '        args="--frame-id map --child-frame-id laser"/>\n</launch>\n',
        encoding="utf-8",
    )
    (tmp_path / "b.launch.py").write_text(python([("base_link", "laser")]), encoding="utf-8")
    options = LintOptions(package_paths=(), select=frozenset({"multiple_parents"}))
    (diagnostic,) = lint_paths([str(tmp_path / "a.launch.xml")], options).diagnostics
    assert diagnostic.rule == "multiple_parents" and diagnostic.line == 3


@pytest.mark.parametrize(("write", "path", "step"), FORMATS)
def test_mined_beliefs(write: object, path: str, step: int) -> None:
    assert callable(write)
    beliefs = BeliefSet.from_json({
        "format": "launch-linter-beliefs/1",
        "beliefs": [{"class": "sig_null_rot", "if": ["base_link", "laser"], "n": 30, "e": 30,
                     "z": 3.0}],
    }, "test")
    options = LintOptions(package_paths=(), beliefs=beliefs,
                          select=frozenset({"sig_null_rot"}))
    result = lint_text(write([("base_link", "laser")], yaw="1.57"), path, options)
    (diagnostic,) = result.diagnostics
    assert diagnostic.belief is not None and diagnostic.belief.n == 30
