"""ros2_positional_args: the deprecated old-style arguments in ROS 2 launch files."""

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


def test_positional_ypr_and_quaternion(lint: Lint) -> None:
    xml = (
        "<launch>\n"
        f'  <node {TF} name="a" args="0 0 0.2 0 0 0 base_link laser"/>\n'
        f'  <node {TF} name="b" args="0 0 0 0 0 0 1 map odom"/>\n'
        "</launch>"
    )
    assert lint(xml, "ros2_positional_args") == [
        ("ros2_positional_args", 2), ("ros2_positional_args", 3),
    ]


def test_the_message_gives_the_flags(lint_diagnostics: LintDiagnostics) -> None:
    xml = f'<launch><node {TF} name="a" args="0.1 0 0.2 1.57 0 0 base_link laser"/></launch>'
    (diagnostic,) = lint_diagnostics(xml, "ros2_positional_args")
    assert diagnostic.severity.value == "info"
    assert "Foxy and Galactic" in diagnostic.message and "Rolling" in diagnostic.message
    assert diagnostic.message.endswith(
        "--x 0.1 --y 0 --z 0.2 --yaw 1.57 --pitch 0 --roll 0 --frame-id base_link "
        "--child-frame-id laser"
    )


def test_flags_and_ros1_files_are_fine(lint: Lint) -> None:
    ros2 = f'<launch><node {TF} name="a" args="--z 0.2 --frame-id b --child-frame-id l"/></launch>'
    ros1 = ('<launch><node pkg="tf2_ros" type="static_transform_publisher" name="a" '
            'args="0 0 0.2 0 0 0 base_link laser"/></launch>')
    assert lint(ros2, "ros2_positional_args") == []
    assert lint(ros1, "ros2_positional_args") == []


def test_python_launch_file() -> None:
    text = (
        "from launch import LaunchDescription\n"
        "from launch_ros.actions import Node\n"
        "def generate_launch_description():\n"
        "    return LaunchDescription([\n"
        "        Node(package='tf2_ros', executable='static_transform_publisher',\n"
        "             arguments=['0', '0', '0', '0', '0', '0', 'map', 'odom']),\n"
        "    ])\n"
    )
    diagnostics = run_rule(text, "ros2_positional_args", path="tf.launch.py")
    assert [(d.rule, d.line, d.column) for d in diagnostics] == [("ros2_positional_args", 5, 9)]


POSITIONAL = f'<launch><node {TF} name="a" args="0 0 0.2 0 0 0 base_link laser"/></launch>'
FLAGS = f'<launch><node {TF} name="a" args="--z 0.2 --frame-id b --child-frame-id l"/></launch>'


def _levels(text: str, rule: str, distro: str | None, profile: str = "default") -> list[str]:
    from launch_linter import LintOptions, lint_text

    options = LintOptions(package_paths=(), ros_distro=distro, profile=profile)
    found = lint_text(text, "t.launch.xml", options).diagnostics
    return [d.severity.value for d in found if d.rule == rule]


@pytest.mark.parametrize(
    ("distro", "levels"),
    [("foxy", []), ("galactic", []), ("humble", ["info"]), ("jazzy", ["info"]),
     ("kilted", ["info"]), ("rolling", ["error"]), (None, ["info"])],
)
def test_level_follows_the_target_distribution(distro: str | None, levels: list[str]) -> None:
    assert _levels(POSITIONAL, "ros2_positional_args", distro) == levels


def test_messages_name_the_distribution() -> None:
    from launch_linter import LintOptions, lint_text

    for distro, word in (("rolling", "Rolling"), ("humble", "Humble")):
        options = LintOptions(package_paths=(), ros_distro=distro)
        (found,) = [d for d in lint_text(POSITIONAL, "t.launch.xml", options).diagnostics
                    if d.rule == "ros2_positional_args"]
        assert word in found.message


def test_the_study_profile_keeps_the_warning() -> None:
    assert _levels(POSITIONAL, "ros2_positional_args", None, "study") == ["warning"]
    assert _levels(POSITIONAL, "ros2_positional_args", "foxy", "study") == ["warning"]


@pytest.mark.parametrize("distro", ["foxy", "galactic"])
def test_flags_are_an_error_before_humble(distro: str) -> None:
    assert _levels(FLAGS, "ros2_bad_flag", distro) == ["error"]


@pytest.mark.parametrize("distro", [None, "humble", "rolling"])
def test_flags_are_fine_from_humble(distro: str | None) -> None:
    assert _levels(FLAGS, "ros2_bad_flag", distro) == []
