from __future__ import annotations

import ast
import time
from pathlib import Path

import pytest

from launch_linter import LintOptions, lint_paths
from launch_linter.frontends.ros2_python.string_truth import string_truth_problems

RULE = "py_string_as_bool"
HEAD = """from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, OpaqueFunction, Shutdown
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node
"""

TEXT_TESTED = """
def launch_gz(context):
    on_exit_shutdown = LaunchConfiguration('on_exit_shutdown').perform(context)
    if on_exit_shutdown:
        return [Shutdown()]
    return []


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('on_exit_shutdown', default_value='false'),
        OpaqueFunction(function=launch_gz),
    ])
"""

OBJECT_TESTED = """
def generate_launch_description():
    start_servo = LaunchConfiguration('start_servo')
    nodes = [DeclareLaunchArgument('start_servo', default_value='false')]
    if start_servo:
        nodes.append(Node(package='moveit_servo', executable='servo_node_main'))
    return LaunchDescription(nodes)
"""


def _lint(tmp_path: Path, body: str) -> list[tuple[int, str]]:
    path = tmp_path / "demo.launch.py"
    path.write_text(HEAD + body, encoding="utf-8")
    options = LintOptions(package_paths=(), select=frozenset({RULE}))
    return [(d.line, d.severity.value) for d in lint_paths([str(path)], options).diagnostics]


def test_the_text_of_a_switch_tested_for_truth_is_reported(tmp_path: Path) -> None:
    assert _lint(tmp_path, TEXT_TESTED) == [(8, "warning")]


def test_the_text_compared_is_silent(tmp_path: Path) -> None:
    fixed = TEXT_TESTED.replace("if on_exit_shutdown:", "if on_exit_shutdown.lower() == 'true':")
    assert _lint(tmp_path, fixed) == []


@pytest.mark.parametrize("test", [
    "if not LaunchConfiguration('on_exit_shutdown').perform(context):",
    "if context.launch_configurations['on_exit_shutdown']:",
    "if bool(context.launch_configurations.get('on_exit_shutdown')):",
    "if True and on_exit_shutdown:",
])
def test_every_form_of_the_read_and_the_test(tmp_path: Path, test: str) -> None:
    assert len(_lint(tmp_path, TEXT_TESTED.replace("if on_exit_shutdown:", test))) == 1


@pytest.mark.parametrize("change", [
    # Not a switch: testing a path or a name for being empty is what `if x:` is for.
    ("default_value='false'", "default_value=''"),
    # Assigned twice: the second assignment may turn the text into a bool.
    ("    if on_exit_shutdown:",
     "    on_exit_shutdown = on_exit_shutdown == 'true'\n    if on_exit_shutdown:"),
])
def test_what_may_be_meant_is_not_judged(tmp_path: Path, change: tuple[str, str]) -> None:
    assert _lint(tmp_path, TEXT_TESTED.replace(*change)) == []


def test_a_launch_configuration_object_tested_for_truth_is_reported(tmp_path: Path) -> None:
    assert _lint(tmp_path, OBJECT_TESTED) == [(9, "warning")]


def test_an_object_in_a_conditional_expression_and_a_comparison(tmp_path: Path) -> None:
    body = """
def generate_launch_description():
    level = 'info' if not LaunchConfiguration('debug') else 'debug'
    mode = '--fast' if LaunchConfiguration('headless') == 'true' else ''
    return LaunchDescription([Node(package='a', executable='b', arguments=[level, mode])])
"""
    assert _lint(tmp_path, body) == [(7, "warning"), (8, "warning")]


def test_an_object_given_to_a_condition_is_silent(tmp_path: Path) -> None:
    body = OBJECT_TESTED.replace(
        "    if start_servo:\n        nodes.append(Node(package='moveit_servo', "
        "executable='servo_node_main'))",
        "    nodes.append(Node(package='moveit_servo', executable='servo_node_main',\n"
        "                      condition=IfCondition(start_servo)))",
    ).replace("from launch_ros.actions import Node",
              "from launch_ros.actions import Node\nfrom launch.conditions import IfCondition")
    assert _lint(tmp_path, body) == []


def test_twenty_thousand_functions_and_arguments_are_read_in_linear_time() -> None:
    # Hostile: every loop over the file's nodes (declarations, scopes, tests) at 20,000.
    declared = "".join(
        f"    DeclareLaunchArgument('switch_{i}', default_value='false')\n" for i in range(20_000)
    )
    functions = "".join(
        f"def f_{i}(context):\n    s = LaunchConfiguration('switch_{i}').perform(context)\n"
        f"    if s:\n        return []\n" for i in range(20_000)
    )
    tree = ast.parse(f"def g():\n{declared}\n{functions}")
    started = time.perf_counter()
    problems = string_truth_problems(tree)
    assert len(problems) == 20_000
    assert time.perf_counter() - started < 60
