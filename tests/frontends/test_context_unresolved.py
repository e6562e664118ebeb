"""Errors the file alone cannot decide are unresolved info; the study's profile keeps them."""

from __future__ import annotations

from pathlib import Path

import pytest

from launch_linter import LintOptions, lint_paths

STP = '<node pkg="tf" type="static_transform_publisher" name="t" args="0 0 0 0 0 0 a b 100"/>'


def _rules(tmp_path: Path, name: str, text: str, **options: object) -> list[tuple[str, str]]:
    path = tmp_path / name
    path.write_text(text, encoding="utf-8")
    result = lint_paths([str(path)], LintOptions(package_paths=(), **options))  # type: ignore[arg-type]
    return [(d.rule, d.severity.value) for d in result.diagnostics
            if d.rule in ("roslaunch_error", "unresolved")]


@pytest.mark.parametrize("reference", [
    '$(optenv EXPOSE)',
    '$(arg expose)',
])
def test_a_param_from_the_environment(tmp_path: Path, reference: str) -> None:
    text = (f'<launch>\n  <arg name="expose" default="$(optenv EXPOSE)"/>\n'
            f'  <param name="e" type="int" value="{reference}"/>\n  {STP}\n</launch>\n')
    assert _rules(tmp_path, "a.launch", text) == [("unresolved", "info")]
    assert _rules(tmp_path, "a.launch", text, profile="study") == [("roslaunch_error", "error")]
    # Given with --env, the value is known and the error is real.
    assert _rules(tmp_path, "a.launch", text, env={"EXPOSE": ""}) == [
        ("roslaunch_error", "error")]


def test_a_namespace_from_the_environment(tmp_path: Path) -> None:
    text = (f'<launch>\n  <group ns="$(optenv UAV_NAME)">\n    {STP}\n  </group>\n</launch>\n')
    assert _rules(tmp_path, "a.launch", text) == [("unresolved", "info")]
    assert _rules(tmp_path, "a.launch", text, env={"UAV_NAME": "uav1"}) == []
    assert _rules(tmp_path, "a.launch", text, profile="study") == [("roslaunch_error", "error")]


def test_an_error_without_the_environment_stays(tmp_path: Path) -> None:
    text = f'<launch>\n  <param name="e" type="int" value="abc"/>\n  {STP}\n</launch>\n'
    assert _rules(tmp_path, "a.launch", text) == [("roslaunch_error", "error")]


def test_an_include_under_home_in_ros2(tmp_path: Path) -> None:
    text = ("import os\nfrom launch import LaunchDescription\n"
            "from launch.actions import IncludeLaunchDescription\n"
            "from launch.launch_description_sources import PythonLaunchDescriptionSource\n\n\n"
            "def generate_launch_description():\n    return LaunchDescription([\n"
            "        IncludeLaunchDescription(PythonLaunchDescriptionSource(\n"
            "            os.path.expanduser('~/ws/robot.launch.py'))),\n    ])\n")
    assert _rules(tmp_path, "a.launch.py", text) == [("unresolved", "info")]
    assert _rules(tmp_path, "a.launch.py", text, profile="study") == [("roslaunch_error", "error")]


def test_an_include_from_an_environment_variable_in_ros2(tmp_path: Path) -> None:
    # Judged FALSE as an error (navigation2's costmap test: TEST_LAUNCH_DIR set by CMake).
    text = ("import os\nfrom launch import LaunchDescription\n"
            "from launch.actions import IncludeLaunchDescription\n"
            "from launch.launch_description_sources import PythonLaunchDescriptionSource\n\n\n"
            "def generate_launch_description():\n    return LaunchDescription([\n"
            "        IncludeLaunchDescription(PythonLaunchDescriptionSource(os.path.join(\n"
            "            os.getenv('TEST_LAUNCH_DIR', ''), 'server.launch.py'))),\n    ])\n")
    assert _rules(tmp_path, "a.launch.py", text) == [("unresolved", "info")]
    assert _rules(tmp_path, "a.launch.py", text, env={"TEST_LAUNCH_DIR": str(tmp_path)}) == [
        ("roslaunch_error", "error")]
    assert _rules(tmp_path, "a.launch.py", text, profile="study") == [("roslaunch_error", "error")]


@pytest.mark.parametrize("body", [
    "def main():\n    pass\n\n\nif __name__ == '__main__':\n    main()\n",
    "@launch_this\ndef main():\n    pass\n",
])
def test_a_python_file_that_is_not_a_launch_file(tmp_path: Path, body: str) -> None:
    # better_launch scripts and programs (judged FALSE as roslaunch_error): info.
    assert _rules(tmp_path, "t.launch.py", body) == [("unresolved", "info")]
