from __future__ import annotations

from typing import Callable, List, Tuple

import pytest

from launch_linter.model import Diagnostic, Severity

Lint = Callable[..., List[Tuple[str, int]]]
LintDiagnostics = Callable[..., Tuple[Diagnostic, ...]]

RULE = "bad_number"


def launch(args: str, pkg: str = "tf2_ros") -> str:
    return (
        f'<launch>\n<node pkg="{pkg}" type="static_transform_publisher" name="t" '
        f'args="{args}"/>\n</launch>'
    )


def test_junk_reads_as_zero(lint_diagnostics: LintDiagnostics) -> None:
    (found,) = lint_diagnostics(launch("0 0 0 pi/2 0 0 a b"), RULE)
    assert found.line == 2
    assert "yaw 'pi/2'" in found.message and "as 0" in found.message


def test_numeric_prefix_is_read(lint_diagnostics: LintDiagnostics) -> None:
    (found,) = lint_diagnostics(launch("0 0 0 1,57 0 0 a b"), RULE)
    assert found.message.endswith("reads only its numeric start, 1")


def test_each_bad_number_is_reported(lint_diagnostics: LintDiagnostics) -> None:
    found = lint_diagnostics(launch("0.1m 0 0 0 0 0 a b x100", "tf"), RULE)
    assert [d.message.split("'")[0] for d in found] == ["period_ms ", "x "]


@pytest.mark.parametrize(
    "args", ["0 0 0 0 0 0 a b", "-1e-3 +2. .5 1E2 0 0 a b", "0 0 0 0 0 0 1 a b"]
)
def test_numbers_pass(lint: Lint, args: str) -> None:
    assert lint(launch(args), RULE) == []


def test_quaternion_slots_are_named(lint_diagnostics: LintDiagnostics) -> None:
    (found,) = lint_diagnostics(launch("0 0 0 0 0 0 w a b"), RULE)
    assert found.message.startswith("qw 'w'")


def test_unresolved_number_is_silent(lint: Lint) -> None:
    xml = """<launch>
  <arg name="x"/>
  <node pkg="tf2_ros" type="static_transform_publisher" name="t"
        args="$(arg x) 0 0 0 0 0 a b"/>
</launch>"""
    assert lint(xml, RULE) == []
    assert lint(xml, RULE, {"x": "ten"}) == [(RULE, 3)]


def test_trailing_separator_is_info(lint_diagnostics: LintDiagnostics) -> None:
    # Found in the corpus: comma-separated args ("1.5707963, 0.0, 0.0"); atof reads them
    # as meant: the robot gets what was meant, so this is style (info; the study: warning).
    found = lint_diagnostics(launch("0 0 0 1.5707963, 0.0, 0 a b"), RULE)
    assert [(d.severity, d.message.split(" ")[0]) for d in found] == [
        (Severity.INFO, "pitch"), (Severity.INFO, "yaw")
    ]
    assert "reads 1.5708 as meant" in found[1].message


def test_non_finite_is_an_error(lint_diagnostics: LintDiagnostics) -> None:
    (found,) = lint_diagnostics(launch("1e999 0 0 0 0 0 a b"), RULE)
    assert found.severity is Severity.ERROR and "inf" in found.message
