"""A xacro command run through another program (``env_run <config> xacro ...``, which
sources a configuration first): the environment variables the expansion reads as unset
may be set, so what they decide is not known and the structure is not judged."""

from __future__ import annotations

from pathlib import Path

from launch_linter import LintOptions, lint_paths
from launch_linter.frontends.robot.describe import xacro_wrapper
from launch_linter.model.diagnostic import Diagnostic

ROBOT = ('<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">'
         '<link name="base_link"/><link name="pack"/>'
         '<xacro:if value="$(optenv PACK 0)"><joint name="j" type="fixed">'
         '<parent link="base_link"/><child link="pack"/></joint></xacro:if></robot>')


def _lint(tmp_path: Path, command: str) -> tuple[Diagnostic, ...]:
    (tmp_path / "robot.urdf.xacro").write_text(ROBOT, encoding="utf-8")
    (tmp_path / "robot.launch").write_text(
        f'<launch><param name="robot_description" command="{command}"/>'
        '<node pkg="robot_state_publisher" type="robot_state_publisher" name="rsp"/>'
        '</launch>', encoding="utf-8")
    options = LintOptions(package_paths=(), select=frozenset({"urdf_root", "unresolved"}))
    return lint_paths([str(tmp_path / "robot.launch")], options).diagnostics


def test_without_a_wrapper_the_unset_variable_decides(tmp_path: Path) -> None:
    (found,) = _lint(tmp_path, "xacro $(dirname)/robot.urdf.xacro")
    assert found.rule == "urdf_root" and found.severity.value == "error"


def test_a_wrapper_may_set_the_variable(tmp_path: Path) -> None:
    command = "$(dirname)/env_run $(dirname)/config $(find xacro)/xacro $(dirname)/robot.urdf.xacro"
    (said,) = _lint(tmp_path, command)
    assert said.rule == "unresolved" and "env_run" in said.message and "PACK" in said.message


def test_which_programs_wrap_xacro() -> None:
    def words(text: str) -> list[tuple[str, bool]]:
        return [(w, True) for w in text.split()]

    assert xacro_wrapper(words("env_run cfg /opt/ros/share/xacro/xacro r.xacro")) == "env_run"
    assert xacro_wrapper(words("rosrun xacro xacro r.xacro")) is None
    assert xacro_wrapper(words("python /opt/xacro.py r.xacro")) is None
    assert xacro_wrapper(words("xacro r.xacro")) is None
    assert xacro_wrapper(words("cat r.urdf")) is None


def test_xacro_named_by_an_unresolved_word_is_no_wrapper() -> None:
    assert xacro_wrapper([("FindExecutable(name='xacro')", False), ("r.xacro", True)]) is None
    assert xacro_wrapper([("$(find-exec xacro)", False), ("r.xacro", True)]) is None


def test_a_wrapper_of_a_description_without_variables_changes_nothing(tmp_path: Path) -> None:
    (tmp_path / "plain.urdf.xacro").write_text(
        '<robot name="r"><link name="a"/><link name="b"/></robot>', encoding="utf-8")
    (tmp_path / "robot.launch").write_text(
        '<launch><param name="robot_description" command="$(dirname)/env_run cfg '
        'xacro $(dirname)/plain.urdf.xacro"/>'
        '<node pkg="robot_state_publisher" type="robot_state_publisher" name="rsp"/>'
        '</launch>', encoding="utf-8")
    options = LintOptions(package_paths=(), select=frozenset({"urdf_root", "unresolved"}))
    (found,) = lint_paths([str(tmp_path / "robot.launch")], options).diagnostics
    assert found.rule == "urdf_root"
