"""component_default_frames: a StaticTransformBroadcasterNode left at /frame -> /child."""

from __future__ import annotations

from typing import Callable, List, Tuple

from launch_linter import LintOptions, lint_text
from launch_linter.model import Diagnostic

Lint = Callable[..., List[Tuple[str, int]]]
LintDiagnostics = Callable[..., Tuple[Diagnostic, ...]]


def run_rule(text: str, rule: str, path: str) -> tuple[Diagnostic, ...]:
    """The diagnostics of ``rule`` alone for launch text ``text`` read as ``path``."""
    options = LintOptions(package_paths=(), select=frozenset({rule}))
    return lint_text(text, path, options).diagnostics


def container(params: str) -> str:
    return (
        "<launch>\n"
        '  <node_container pkg="rclcpp_components" exec="component_container" name="c" '
        'namespace="">\n'
        '    <composable_node pkg="tf2_ros" plugin="tf2_ros::StaticTransformBroadcasterNode"'
        ' name="tf">\n'
        f"{params}"
        "    </composable_node>\n"
        "  </node_container>\n"
        "</launch>"
    )


def test_no_frames(lint_diagnostics: LintDiagnostics) -> None:
    (diagnostic,) = lint_diagnostics(container(""), "component_default_frames")
    assert diagnostic.line == 3
    assert "'/frame' -> '/child'" in diagnostic.message


def test_one_frame_missing(lint_diagnostics: LintDiagnostics) -> None:
    params = '      <param name="frame_id" value="base_link"/>\n'
    (diagnostic,) = lint_diagnostics(container(params), "component_default_frames")
    assert "no child_frame_id parameter" in diagnostic.message
    assert "'base_link' -> '/child'" in diagnostic.message


def test_both_frames_given(lint: Lint) -> None:
    params = ('      <param name="frame_id" value="base_link"/>\n'
              '      <param name="child_frame_id" value="laser"/>\n')
    assert lint(container(params), "component_default_frames") == []


def test_parameters_from_a_file_are_not_judged(lint: Lint) -> None:
    params = '      <param from="$(dirname)/tf.yaml"/>\n'
    assert lint(container(params), "component_default_frames") == []


def test_python_component() -> None:
    text = (
        "from launch import LaunchDescription\n"
        "from launch_ros.actions import ComposableNodeContainer\n"
        "from launch_ros.descriptions import ComposableNode\n"
        "def generate_launch_description():\n"
        "    return LaunchDescription([ComposableNodeContainer(\n"
        "        name='c', namespace='', package='rclcpp_components',\n"
        "        executable='component_container', composable_node_descriptions=[\n"
        "            ComposableNode(package='tf2_ros',\n"
        "                           plugin='tf2_ros::StaticTransformBroadcasterNode',\n"
        "                           parameters=[{'translation.z': 0.2}]),\n"
        "        ])])\n"
    )
    diagnostics = run_rule(text, "component_default_frames", path="a.launch.py")
    assert [d.line for d in diagnostics] == [8]
