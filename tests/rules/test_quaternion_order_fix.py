from __future__ import annotations

from typing import Callable, List, Tuple

from launch_linter.engine import lint_text
from launch_linter.fix import apply_edits
from launch_linter.model import Diagnostic

Lint = Callable[..., List[Tuple[str, int]]]
LintDiagnostics = Callable[..., Tuple[Diagnostic, ...]]

RULE = "quaternion_order"
NODE = """<launch>
  <node pkg="tf2_ros" type="static_transform_publisher" name="a"
        args="{}"/>
</launch>"""


def test_one_zero_zero_zero_is_reported_as_info(lint_diagnostics: LintDiagnostics) -> None:
    (found,) = lint_diagnostics(NODE.format("0.2 0 0.1 1 0 0 0 base_link laser"), RULE)
    assert found.severity.value == "info" and "half turn about x" in found.message
    assert found.fix is not None and found.fix.applicability.value == "unsafe"


def test_the_fix_reorders_w_first(lint_diagnostics: LintDiagnostics) -> None:
    text = NODE.format("0.2 0 0.1 -1.0 0 0 0 base_link laser")
    (found,) = lint_diagnostics(text, RULE)
    assert found.fix is not None
    after, _ = apply_edits(text.encode(), [found.fix])
    assert after.decode() == NODE.format("0.2 0 0.1 0 0 0 -1 base_link laser")
    assert lint_text(after.decode(), "test.launch").diagnostics == ()


def test_other_quaternions_and_ypr_pass(lint: Lint) -> None:
    for args in ("0 0 0 0 0 0 1 a b", "0 0 0 0 0 1 0 a b", "0 0 0 1 0 0 a b",
                 "0 0 0 0.7071068 0 0 0.7071068 a b"):
        assert lint(NODE.format(args), RULE) == [], args
