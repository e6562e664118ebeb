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


SPLIT = """from launch import LaunchDescription
from launch_ros.actions import ComposableNodeContainer, Node
from launch_ros.descriptions import ComposableNode


def generate_launch_description():
    return LaunchDescription([
        Node(
            package='joy',
            node_executable='joy_node',
        ),
        ComposableNodeContainer(
            package='rclcpp_components', name='container', namespace='',
            executable='component_container',
            composable_node_descriptions=[
                ComposableNode(
                    package='ublox_gps',
                    node_plugin='ublox_node::UbloxNode',
                    node_name='ublox_gps_node'),
            ],
        ),
    ])
"""


def _lines(tmp_path: Path, text: str, distro: str | None = "galactic"
           ) -> list[tuple[int, str, str]]:
    path = tmp_path / "split.launch.py"
    path.write_text(text, encoding="utf-8")
    result = lint_paths([str(path)], LintOptions(package_paths=(), ros_distro=distro))
    return [(d.line, d.severity.value, d.message) for d in result.diagnostics if d.rule == RULE]


def test_reported_at_the_keyword_that_must_change_and_for_composable_nodes(
    tmp_path: Path,
) -> None:
    # The keyword's line, not the call's: the word a maintainer edits (teleop_twist_joy#26).
    # ComposableNode(node_plugin=...) is refused from Galactic on too (ublox#126).
    found = _lines(tmp_path, SPLIT)
    assert [(line, level) for line, level, _ in found] == [(10, "error"), (18, "error")]
    assert "Node keyword(s) node_executable= (now executable=)" in found[0][2]
    assert ("ComposableNode keyword(s) node_plugin= (now plugin=), node_name= (now name=)"
            in found[1][2])


def test_composable_node_keywords_of_today_are_silent(tmp_path: Path) -> None:
    fixed = SPLIT.replace("node_executable", "executable").replace(
        "node_plugin", "plugin").replace("node_name", "name")
    assert _lines(tmp_path, fixed) == []


def test_composable_node_foxy_keywords_are_read_on_foxy(tmp_path: Path) -> None:
    # On Foxy the old keywords still work: no finding, and the component keeps its name.
    assert _lines(tmp_path, SPLIT, "foxy") == []


def test_a_helper_function_reports_at_its_call(tmp_path: Path) -> None:
    helper = '''from launch import LaunchDescription
from launch_ros.actions import Node


def make(executable):
    return Node(package='joy',
                node_executable=executable)


def generate_launch_description():
    return LaunchDescription([
        make('joy_node'),
        make('teleop_node'),
    ])
'''
    assert [line for line, _, _ in _lines(tmp_path, helper)] == [12, 13]


def test_a_call_with_20000_keywords_is_read_once(tmp_path: Path) -> None:
    # Hostile: the keywords of one call are walked once to find the first old one.
    many = ", ".join(f"k{i}='v'" for i in range(20_000))
    text = SPLIT.replace("node_executable='joy_node',", f"{many}, node_executable='joy_node',")
    found = _lines(tmp_path, text)
    assert [line for line, _, _ in found] == [10, 18]


OPAQUE = """from launch import LaunchDescription
from launch.actions import OpaqueFunction
from launch_ros.actions import Node


def launch_setup(context):
    return [Node(package='joy',
                 node_executable='joy_node')]


def generate_launch_description():
    return LaunchDescription([OpaqueFunction(function=launch_setup)])
"""


def test_in_an_opaque_function_the_keyword_is_an_error_too(tmp_path: Path) -> None:
    # The function runs when ros2 launch visits it: the Node it builds raises there as
    # anywhere (was: an info "in OpaqueFunction launch_setup(): ...", the tree opened).
    path = tmp_path / "opaque.launch.py"
    path.write_text(OPAQUE, encoding="utf-8")
    result = lint_paths([str(path)], LintOptions(package_paths=(), ros_distro="humble"))
    found = [(d.rule, d.severity.value, d.line) for d in result.diagnostics]
    assert found == [(RULE, "error", 8)]


def test_in_an_opaque_function_the_new_keyword_is_silent(tmp_path: Path) -> None:
    path = tmp_path / "opaque.launch.py"
    path.write_text(OPAQUE.replace("node_executable", "executable"), encoding="utf-8")
    result = lint_paths([str(path)], LintOptions(package_paths=(), ros_distro="humble"))
    assert [d.rule for d in result.diagnostics] == []


BRANCHED = """import os

from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    if os.getenv('ROS_DISTRO') == 'eloquent':
        node = Node(package='joy', node_executable='joy_node')
    else:
        node = Node(package='joy', executable='joy_node')
    return LaunchDescription([
        node,
        Node(package='tf2_ros', executable='static_transform_publisher',
             arguments=['0', '0', '0', '0', '0', '0', 'base', 'laser']),
    ])
"""


def test_keywords_under_an_undecided_branch_are_no_evidence_of_foxy(tmp_path: Path) -> None:
    # With no distribution given, a branch for Eloquent does not make the file Foxy's:
    # the positional form stays "set --ros-distro to know" (info), not Foxy's only form.
    path = tmp_path / "branched.launch.py"
    path.write_text(BRANCHED, encoding="utf-8")
    result = lint_paths([str(path)], LintOptions(package_paths=()))
    assert [(d.rule, d.severity.value) for d in result.diagnostics
            if d.rule in (RULE, "ros2_positional_args")] == [("ros2_positional_args", "info")]


def test_keywords_under_a_branch_the_distribution_decides_are_judged(tmp_path: Path) -> None:
    path = tmp_path / "branched.launch.py"
    path.write_text(BRANCHED, encoding="utf-8")
    for distro, expected in (("humble", []), ("eloquent", [])):
        result = lint_paths([str(path)], LintOptions(package_paths=(), ros_distro=distro))
        assert [d.rule for d in result.diagnostics if d.rule == RULE] == expected
    galactic = BRANCHED.replace("'eloquent'", "'galactic'")
    path.write_text(galactic, encoding="utf-8")
    result = lint_paths([str(path)], LintOptions(package_paths=(), ros_distro="galactic"))
    assert [(d.rule, d.line) for d in result.diagnostics if d.rule == RULE] == [(RULE, 9)]
