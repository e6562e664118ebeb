from __future__ import annotations

from pathlib import Path

import pytest

from launch_linter import LintOptions, lint_paths

RULE = "ros2_missing_keyword"
TEMPLATE = """from launch import LaunchDescription
from launch_ros.actions import {cls}
from launch_ros.descriptions import ComposableNode


def generate_launch_description():
    return LaunchDescription([
        {call},
    ])
"""
LIFECYCLE = "LifecycleNode(package='lidar', executable='lidar_node', name='lidar'{extra})"
CONTAINER = ("ComposableNodeContainer(name='container', package='rclcpp_components', "
             "executable='component_container'{extra}, composable_node_descriptions=[])")


def _found(tmp_path: Path, cls: str, call: str, distro: str | None) -> list[tuple[int, str, str]]:
    path = tmp_path / "lifecycle.launch.py"
    path.write_text(TEMPLATE.format(cls=cls, call=call), encoding="utf-8")
    result = lint_paths([str(path)], LintOptions(package_paths=(), ros_distro=distro))
    return [(d.line, d.severity.value, d.message) for d in result.diagnostics if d.rule == RULE]


@pytest.mark.parametrize("distro", ["galactic", "humble", "jazzy", "rolling"])
@pytest.mark.parametrize(("cls", "call"), [("LifecycleNode", LIFECYCLE),
                                           ("ComposableNodeContainer", CONTAINER)])
def test_error_without_namespace_from_galactic_on(tmp_path: Path, distro: str, cls: str,
                                                  call: str) -> None:
    ((line, level, message),) = _found(tmp_path, cls, call.format(extra=""), distro)
    assert (line, level) == (8, "error")
    assert f"{cls}(...) without namespace=" in message
    assert distro.capitalize() in message


@pytest.mark.parametrize("distro", ["humble", None, "foxy"])
def test_silent_with_both_keywords(tmp_path: Path, distro: str | None) -> None:
    call = LIFECYCLE.format(extra=", namespace=''")
    assert _found(tmp_path, "LifecycleNode", call, distro) == []


@pytest.mark.parametrize("distro", ["foxy", "eloquent", "dashing"])
def test_silent_on_foxy_and_before(tmp_path: Path, distro: str) -> None:
    assert _found(tmp_path, "LifecycleNode", LIFECYCLE.format(extra=""), distro) == []


@pytest.mark.parametrize("distro", [None, "noetic"])
def test_info_without_a_ros2_target(tmp_path: Path, distro: str | None) -> None:
    ((_, level, message),) = _found(tmp_path, "LifecycleNode", LIFECYCLE.format(extra=""),
                                    distro)
    assert level == "info"
    assert "Galactic and later" in message


def test_both_keywords_named_when_both_are_missing(tmp_path: Path) -> None:
    call = "LifecycleNode(package='lidar', executable='lidar_node')"
    ((_, _, message),) = _found(tmp_path, "LifecycleNode", call, "humble")
    assert "without name= and namespace=" in message


def test_unknown_keyword_arguments_are_not_judged(tmp_path: Path) -> None:
    # **options unknown: the call's keywords are not known, nothing is said.
    call = "LifecycleNode(package='lidar', executable='lidar_node', **OPTIONS)"
    assert _found(tmp_path, "LifecycleNode", call, "humble") == []


def test_a_plain_node_needs_neither(tmp_path: Path) -> None:
    assert _found(tmp_path, "Node", "Node(package='lidar', executable='lidar_node')",
                  "humble") == []


def test_foxy_keywords_are_named(tmp_path: Path) -> None:
    call = ("LifecycleNode(package='lidar', node_executable='lidar_node', node_name='lidar', "
            "node_namespace='/')")
    ((_, level, message),) = _found(tmp_path, "LifecycleNode", call, "humble")
    assert level == "error"
    assert ("without name= and namespace= (node_executable, node_name, node_namespace= "
            "removed after Foxy)") in message
