from __future__ import annotations

from typing import Callable, List, Tuple

import pytest

from launch_linter.model import Diagnostic, Severity

Lint = Callable[..., List[Tuple[str, int]]]
LintDiagnostics = Callable[..., Tuple[Diagnostic, ...]]

RULE = "bad_quaternion"


def launch(quaternion: str, pkg: str = "tf2_ros") -> str:
    period = " 100" if pkg == "tf" else ""
    return (
        f'<launch>\n<node pkg="{pkg}" type="static_transform_publisher" name="t" '
        f'args="0 0 0 {quaternion} base_link laser{period}"/>\n</launch>'
    )


def test_zero_quaternion(lint_diagnostics: LintDiagnostics) -> None:
    # anchors.md (e): PhysFrame did not flag the quaternion 0 0 0 0.
    (found,) = lint_diagnostics(launch("0 0 0 0"), RULE)
    assert found.line == 2 and found.severity is Severity.ERROR
    assert "zero" in found.message and "0 0 0 1" in found.message


@pytest.mark.parametrize("quaternion", ["0 0 0 2", "1 0 0 1", "0 0 0.1 0.9"])
def test_dropped_by_tf2(lint_diagnostics: LintDiagnostics, quaternion: str) -> None:
    (found,) = lint_diagnostics(launch(quaternion, "tf"), RULE)
    assert found.severity is Severity.ERROR


def test_suggests_the_normalised_quaternion(lint_diagnostics: LintDiagnostics) -> None:
    (found,) = lint_diagnostics(launch("0 0 1 1"), RULE)
    assert "0 0 0.7071068 0.7071068" in found.message


def test_slightly_off_unit_is_info(lint_diagnostics: LintDiagnostics) -> None:
    (found,) = lint_diagnostics(launch("0 0 0.707 0.707"), RULE)
    assert found.severity is Severity.INFO


@pytest.mark.parametrize(
    "quaternion", ["0 0 0 1", "0 0 0 -1", "0.70710678 0 0 0.70710678", "0.5 -0.5 0.5 -0.5"]
)
def test_unit_quaternions_pass(lint: Lint, quaternion: str) -> None:
    assert lint(launch(quaternion), RULE) == []


def test_ypr_is_not_a_quaternion(lint: Lint) -> None:
    assert lint(launch("0 0 0"), RULE) == []


def test_tf2_ros_period_misread_is_left_to_bad_arity(lint: Lint) -> None:
    xml = launch("0 0 0").replace("laser", "laser 100")
    assert lint(xml, RULE) == []


def test_unresolved_rotation_is_silent(lint: Lint) -> None:
    xml = """<launch>
  <arg name="qw"/>
  <node pkg="tf2_ros" type="static_transform_publisher" name="t"
        args="0 0 0 0 0 0 $(arg qw) base_link laser"/>
</launch>"""
    assert lint(xml, RULE) == []
    assert lint(xml, RULE, {"qw": "0"}) == [(RULE, 3)]


def test_not_on_a_word_bad_number_rejects(lint: Lint) -> None:
    # One root cause, one finding: "nan" is bad_number's; the norm of it is no advice.
    assert lint(launch("nan 0 0 1", "tf"), "bad_number") == [("bad_number", 2)]
    assert lint(launch("nan 0 0 1", "tf"), RULE) == []


def test_the_study_profile_reports_both() -> None:
    from launch_linter import LintOptions, lint_text

    result = lint_text(launch("nan 0 0 1", "tf"), "t.launch",
                       LintOptions(package_paths=(), profile="study"))
    assert {d.rule for d in result.diagnostics} >= {"bad_number", RULE}
