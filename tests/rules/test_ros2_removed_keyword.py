from __future__ import annotations

from pathlib import Path

import pytest

from launch_linter import LintOptions, lint_paths

RULE = "ros2_removed_keyword"
FOXY = """from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='tf2_ros', node_executable='static_transform_publisher',
             node_name='laser_tf', arguments=['0', '0', '0.2', '0', '0', '0', 'base', 'laser']),
    ])
"""


def _found(
    tmp_path: Path, distro: str | None, rules: tuple[str, ...] = (RULE,)
) -> list[tuple[str, str, str]]:
    path = tmp_path / "foxy.launch.py"
    path.write_text(FOXY, encoding="utf-8")
    result = lint_paths([str(path)], LintOptions(package_paths=(), ros_distro=distro))
    return [(d.rule, d.severity.value, d.message) for d in result.diagnostics if d.rule in rules]


@pytest.mark.parametrize("distro", ["galactic", "humble", "jazzy", "rolling"])
def test_error_after_foxy_naming_the_replacement(tmp_path: Path, distro: str) -> None:
    ((rule, level, message),) = _found(tmp_path, distro)
    assert (rule, level) == (RULE, "error")
    assert "node_executable= (now executable=)" in message
    assert "node_name= (now name=)" in message
    assert distro.capitalize() in message


@pytest.mark.parametrize("distro", ["foxy", "eloquent", None])
def test_silent_on_foxy_or_when_the_keywords_are_the_only_evidence(
    tmp_path: Path, distro: str | None
) -> None:
    assert _found(tmp_path, distro) == []


@pytest.mark.parametrize("distro", ["melodic", "noetic"])
def test_a_ros1_target_says_nothing_of_the_ros2_distribution(tmp_path: Path, distro: str) -> None:
    # A mixed repository linted with --ros-distro noetic: its ROS 2 files are judged as
    # with no target given, not as if Noetic were a distribution after Foxy.
    assert _found(tmp_path, distro) == []


def test_the_keywords_are_evidence_of_foxy(tmp_path: Path) -> None:
    # Positional arguments are Foxy's only form: with the keywords as evidence and no
    # distribution given, ros2_positional_args says nothing.
    assert _found(tmp_path, None, ("ros2_positional_args",)) == []
    assert [f[1] for f in _found(tmp_path, "humble", ("ros2_positional_args",))] == ["info"]


def test_modern_keywords_are_fine(tmp_path: Path) -> None:
    path = tmp_path / "ok.launch.py"
    path.write_text(FOXY.replace("node_executable", "executable").replace("node_name", "name"))
    result = lint_paths([str(path)], LintOptions(package_paths=(), ros_distro="humble"))
    assert [d for d in result.diagnostics if d.rule == RULE] == []


FLAGS = FOXY.replace("arguments=['0', '0', '0.2', '0', '0', '0', 'base', 'laser']",
                     "arguments=['--z', '0.2', '--frame-id', 'base', '--child-frame-id', 'laser']")


def _found_in(tmp_path: Path, text: str, distro: str | None) -> list[tuple[str, str]]:
    path = tmp_path / "mixed.launch.py"
    path.write_text(text, encoding="utf-8")
    result = lint_paths([str(path)], LintOptions(package_paths=(), ros_distro=distro))
    return [(d.rule, d.message) for d in result.diagnostics
            if d.rule in (RULE, "ros2_bad_flag")]


def test_foxy_keywords_with_humble_flags_report_the_refused_keyword(tmp_path: Path) -> None:
    assert FLAGS != FOXY
    ((rule, message),) = _found_in(tmp_path, FLAGS, None)
    assert rule == RULE
    assert "node_executable= (now executable=)" in message
    assert "flags at line 7 arrived in Humble" in message


def test_foxy_keywords_with_flags_on_foxy_given_are_the_flags_mistake(tmp_path: Path) -> None:
    assert [rule for rule, _ in _found_in(tmp_path, FLAGS, "foxy")] == ["ros2_bad_flag"]


def test_the_fixed_keyword_is_silent(tmp_path: Path) -> None:
    fixed = FLAGS.replace("node_executable", "executable").replace("node_name", "name")
    assert _found_in(tmp_path, fixed, None) == []
