"""ros2_param_empty_list: `[]` in the parameter file of an rclcpp node (rclcpp's
parameter_value_from throws 'No parameter value set'; rclpy does not)."""

from __future__ import annotations

import time
from pathlib import Path

from launch_linter.engine import LintOptions, lint_paths
from launch_linter.workspace.client_library import client_library

RULE = "ros2_param_empty_list"

LAUNCH = ("import os\n"
          "from launch import LaunchDescription\n"
          "from launch.conditions import IfCondition\n"
          "from launch_ros.actions import Node\n"
          "def generate_launch_description():\n"
          "    here = os.path.dirname(__file__)\n"
          "    return LaunchDescription([\n"
          "        Node(package='bridge', executable='bridge_node'{extra},\n"
          "             parameters=[os.path.join(here, 'bridge.yaml')]),\n"
          "    ])\n")
RCLCPP = ("<package format='3'><name>bridge</name><depend>rclcpp</depend>"
          "<export><build_type>ament_cmake</build_type></export></package>")
PARAMS = "bridge:\n  ros__parameters:\n    rate: 2.0\n    exclude: []\n"


def run(tmp_path: Path, params: str = PARAMS, manifest: str = RCLCPP,
        extra: str = ", name='bridge'") -> list[tuple[str, int, str]]:
    (tmp_path / "package.xml").write_text(manifest)
    (tmp_path / "bridge.yaml").write_text(params)
    path = tmp_path / "bridge.launch.py"
    path.write_text(LAUNCH.format(extra=extra))
    options = LintOptions(package_paths=(str(tmp_path),), select=frozenset({RULE}))
    return [(Path(d.path).name, d.line, d.severity.value)
            for d in lint_paths([str(path)], options).diagnostics]


def test_an_empty_list_for_an_rclcpp_node_is_an_error_at_its_key(tmp_path: Path) -> None:
    assert run(tmp_path) == [("bridge.yaml", 4, "error")]


def test_a_nested_empty_list_and_a_wildcard_section_are_reported(tmp_path: Path) -> None:
    params = "/**:\n  ros__parameters:\n    filter:\n      topics: []\n"
    assert run(tmp_path, params, extra="") == [("bridge.yaml", 4, "error")]


def test_a_list_with_an_item_is_silent(tmp_path: Path) -> None:
    assert run(tmp_path, PARAMS.replace("[]", "['/debug']")) == []


def test_a_section_for_another_node_is_silent(tmp_path: Path) -> None:
    # rclcpp converts only the sections that match the node (parameter_map_from).
    assert run(tmp_path, PARAMS.replace("bridge:", "other:")) == []


def test_a_node_of_unknown_name_is_judged_only_through_a_wildcard(tmp_path: Path) -> None:
    assert run(tmp_path, extra="") == []


def test_a_python_package_is_not_judged(tmp_path: Path) -> None:
    # rclpy reads the untyped value as "not set" without raising.
    python = RCLCPP.replace("ament_cmake", "ament_python").replace("rclcpp", "rclpy")
    assert run(tmp_path, manifest=python) == []
    both = RCLCPP.replace("<depend>rclcpp</depend>",
                          "<depend>rclcpp</depend><exec_depend>rclpy</exec_depend>")
    assert run(tmp_path, manifest=both) == []


def test_a_node_under_a_condition_is_not_judged(tmp_path: Path) -> None:
    assert run(tmp_path, extra=", name='bridge', condition=IfCondition('false')") == []


def test_client_library_needs_rclcpp_and_ament_cmake(tmp_path: Path) -> None:
    manifest = tmp_path / "package.xml"
    manifest.write_text(RCLCPP)
    assert client_library(str(manifest)) == "rclcpp"
    manifest.write_text(RCLCPP.replace("<depend>rclcpp</depend>", ""))
    assert client_library(str(manifest)) is None
    manifest.write_text("<package")
    assert client_library(str(manifest)) is None


def test_twenty_thousand_empty_lists_and_dependencies_stay_fast(tmp_path: Path) -> None:
    params = "bridge:\n  ros__parameters:\n" + "".join(
        f"    p{i}: []\n" for i in range(20_000))
    manifest = RCLCPP.replace("<depend>rclcpp</depend>", "<depend>rclcpp</depend>" + "".join(
        f"<depend>d{i}</depend>" for i in range(20_000)))
    started = time.process_time()
    found = run(tmp_path, params, manifest)
    assert time.process_time() - started < 30
    assert found and {(name, level) for name, _, level in found} == {("bridge.yaml", "error")}
