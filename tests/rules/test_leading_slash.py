from __future__ import annotations

from typing import Callable, List, Tuple

from launch_linter.model import Diagnostic, Severity

Lint = Callable[..., List[Tuple[str, int]]]
LintDiagnostics = Callable[..., Tuple[Diagnostic, ...]]

RULE = "leading_slash"


def launch(parent: str, child: str) -> str:
    return (
        '<launch>\n<node pkg="tf" type="static_transform_publisher" name="t" '
        f'args="0 0 0 0 0 0 {parent} {child} 100"/>\n</launch>'
    )


def test_one_info_per_frame(lint_diagnostics: LintDiagnostics) -> None:
    found = lint_diagnostics(launch("/base_link", "/laser"), RULE)
    assert [(d.line, d.severity) for d in found] == [(2, Severity.INFO)] * 2
    assert {d.message.split(" ")[0] for d in found} == {"parent", "child"}
    assert any("write 'laser'" in d.message for d in found)


def test_only_the_slashed_frame(lint_diagnostics: LintDiagnostics) -> None:
    (found,) = lint_diagnostics(launch("base_link", "/laser"), RULE)
    assert found.message.startswith("child frame '/laser'")


def test_no_slash_passes(lint: Lint) -> None:
    assert lint(launch("base_link", "robot/laser"), RULE) == []


def test_slash_before_a_substitution_is_known(lint: Lint) -> None:
    xml = """<launch>
  <arg name="robot"/>
  <node pkg="tf" type="static_transform_publisher" name="t"
        args="0 0 0 0 0 0 /$(arg robot)/base_link laser 100"/>
</launch>"""
    assert lint(xml, RULE) == [(RULE, 3)]


def test_slash_from_an_arg_value(lint: Lint) -> None:
    xml = """<launch>
  <arg name="frame" default="/map"/>
  <node pkg="tf" type="static_transform_publisher" name="t"
        args="0 0 0 0 0 0 $(arg frame) odom 100"/>
</launch>"""
    assert lint(xml, RULE) == [(RULE, 3)]
    assert lint(xml, RULE, {"frame": "map"}) == []
