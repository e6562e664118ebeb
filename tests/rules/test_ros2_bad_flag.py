"""ros2_bad_flag: flags the ROS 2 static_transform_publisher rejects or misreads."""

from __future__ import annotations

from typing import Callable, List, Tuple

import pytest

from launch_linter import LintOptions, lint_text
from launch_linter.model import Diagnostic

Lint = Callable[..., List[Tuple[str, int]]]
LintDiagnostics = Callable[..., Tuple[Diagnostic, ...]]


def run_rule(text: str, rule: str, path: str) -> tuple[Diagnostic, ...]:
    """The diagnostics of ``rule`` alone for launch text ``text`` read as ``path``."""
    options = LintOptions(package_paths=(), select=frozenset({rule}))
    return lint_text(text, path, options).diagnostics


TF = 'pkg="tf2_ros" exec="static_transform_publisher"'


def node(args: str) -> str:
    return f'<launch>\n  <node {TF} name="t" args="{args}"/>\n</launch>'


@pytest.mark.parametrize(("args", "expected"), [
    ("--x 1 --yaw_deg 90 --frame-id a --child-frame-id b", "unknown flag '--yaw_deg'"),
    ("--frame_id a --child-frame-id b", "did you mean '--frame-id'?"),
    ("-- yaw 1 --frame-id a --child-frame-id b", "without the space"),
    ("--x 1 0 0 0 0 0 0 a b", "Cannot specify both new-style (flags) and old-style"),
    ("--roll 1 --qw 1 --frame-id a --child-frame-id b", "both quaternion and Euler"),
    ("--qz 1 --frame-id a --child-frame-id b", "not unit length"),
    ("--x 1 --child-frame-id b", "'Frame id must not be empty'"),
])
def test_mistakes(lint_diagnostics: LintDiagnostics, args: str, expected: str) -> None:
    diagnostics = lint_diagnostics(node(args), "ros2_bad_flag")
    assert any(expected in d.message for d in diagnostics)
    assert {(d.line, d.severity.value) for d in diagnostics} == {(2, "error")}


@pytest.mark.parametrize("args", [
    "--x -0.1 --y 2 --z 0.3 --roll 0 --pitch 0 --yaw 1.57 --frame-id a --child-frame-id b",
    "--qx 0 --qy 0 --qz 0.7071068 --qw 0.7071068 --frame-id a --child-frame-id b",
    "--qz 0.7071068 --qw 0.7071068 --frame-id a --child-frame-id b",
    "--frame-id a --child-frame-id b --ros-args -r __node:=t",
])
def test_correct_flags(lint: Lint, args: str) -> None:
    assert lint(node(args), "ros2_bad_flag") == []


def test_every_mistake_of_one_node_is_reported(lint: Lint) -> None:
    found = lint(node("--x 1 --yaw_deg 90"), "ros2_bad_flag")
    assert found == [("ros2_bad_flag", 2)] * 3


def test_an_unknown_argument_list_is_not_judged(lint: Lint) -> None:
    text = (
        "from launch import LaunchDescription\n"
        "from launch_ros.actions import Node\n"
        "from my_pkg import tf_arguments\n"
        "def generate_launch_description():\n"
        "    return LaunchDescription([Node(package='tf2_ros',\n"
        "        executable='static_transform_publisher', arguments=tf_arguments())])\n"
    )
    assert run_rule(text, "ros2_bad_flag", path="tf.launch.py") == ()
