"""py_string_as_bool, value-based criterion: a launch argument's boolean text (its value
resolved as launch would) tested for truth in Python."""

from __future__ import annotations

import time
from pathlib import Path

from launch_linter.engine import LintOptions, lint_paths

RULE = "py_string_as_bool"
FILE = """from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, OpaqueFunction
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def setup(context):
{body}
    return [Node(package='filters', executable='filter', parameters=[{{'output_frame': frame}}])]


def generate_launch_description():
    return LaunchDescription([DeclareLaunchArgument('flag', default_value='{default}'),
                              OpaqueFunction(function=setup)])
"""


def run(tmp_path: Path, body: str, default: str = "false",
        args: dict[str, str] | None = None) -> list[tuple[int, str]]:
    path = tmp_path / "flag.launch.py"
    path.write_text(FILE.format(body=body, default=default))
    options = LintOptions(package_paths=(), select=frozenset({RULE}), args=args or {})
    return [(d.line, d.severity.value) for d in lint_paths([str(path)], options).diagnostics]


IF_TEST = """    if LaunchConfiguration('flag').perform(context):
        frame = 'lidar'
    else:
        frame = ''"""


def test_boolean_text_tested_by_if_is_a_warning(tmp_path: Path) -> None:
    assert run(tmp_path, IF_TEST) == [(8, "warning")]
    assert run(tmp_path, IF_TEST, default="True") == [(8, "warning")]
    assert run(tmp_path, IF_TEST, default="", args={"flag": "false"}) == [(8, "warning")]


def test_ternary_and_not_are_truth_tests(tmp_path: Path) -> None:
    ternary = "    frame = 'lidar' if LaunchConfiguration('flag').perform(context) else ''"
    negated = ("    frame = 'lidar'\n"
               "    if not context.launch_configurations['flag']:\n"
               "        frame = ''")
    assert run(tmp_path, ternary) == [(8, "warning")]
    assert run(tmp_path, negated) == [(9, "warning")]


def test_compared_text_and_other_texts_are_silent(tmp_path: Path) -> None:
    compared = ("    frame = 'lidar' if LaunchConfiguration('flag').perform(context).lower() "
                "== 'true' else ''")
    assert run(tmp_path, compared) == []
    # A file name or prefix tested for being non-empty, on purpose.
    assert run(tmp_path, IF_TEST, default="") == []
    assert run(tmp_path, IF_TEST, default="params.yaml") == []
    # 0/1 are numbers' texts as often as booleans: not judged.
    assert run(tmp_path, IF_TEST, default="0") == []


def test_unknown_value_is_silent(tmp_path: Path) -> None:
    body = IF_TEST.replace("'flag'", "'undeclared'")
    assert run(tmp_path, body) == []


def test_twenty_thousand_truth_tests(tmp_path: Path) -> None:
    # Every test is judged where it is evaluated, once; the interpreter's step bound
    # still ends a file too long to follow.
    body = "    frame = ''\n" + "".join(
        "    if LaunchConfiguration('flag').perform(context):\n        frame = 'lidar'\n"
        for _ in range(20_000))
    started = time.process_time()
    found = run(tmp_path, body)
    assert time.process_time() - started < 60
    assert all(level == "warning" for _, level in found)
