from __future__ import annotations

from typing import Callable, List, Tuple

import pytest

from launch_linter.model import Diagnostic

Lint = Callable[..., List[Tuple[str, int]]]
LintDiagnostics = Callable[..., Tuple[Diagnostic, ...]]

RULE = "bad_arity"


def launch(pkg: str, args: str) -> str:
    return (
        f'<launch>\n<node pkg="{pkg}" type="static_transform_publisher" name="t" '
        f'args="{args}"/>\n</launch>'
    )


def test_tf2_ros_given_a_period(lint_diagnostics: LintDiagnostics) -> None:
    # anchors.md (e): PhysFrame modelled this as a valid base_link -> laser transform.
    (found,) = lint_diagnostics(launch("tf2_ros", "0 0 0.2 0 0 0 base_link laser 100"), RULE)
    assert found.line == 2
    assert "child '100'" in found.message and "remove the period" in found.message


def test_tf_without_a_period(lint_diagnostics: LintDiagnostics) -> None:
    (found,) = lint_diagnostics(launch("tf", "0 0 0.2 0 0 0 base_link laser"), RULE)
    assert "add a period" in found.message


def test_tf_quaternion_without_a_period(lint: Lint) -> None:
    assert lint(launch("tf", "0 0 0.2 0 0 0 1 base_link laser"), RULE) == [(RULE, 2)]


@pytest.mark.parametrize(
    ("pkg", "args"),
    [
        ("tf2_ros", "0 0 0 0 0 0 0 1 base_link laser 100"),
        ("tf2_ros", "0 0 0 base_link laser"),
        ("tf", "0 0 0 0 0 0 0 0 1 base_link laser 100"),
        ("tf", "base_link laser"),
    ],
)
def test_counts_the_program_rejects(lint: Lint, pkg: str, args: str) -> None:
    assert lint(launch(pkg, args), RULE) == [(RULE, 2)]


@pytest.mark.parametrize(
    ("pkg", "args"),
    [
        ("tf2_ros", "0 0 0.2 0 0 0 base_link laser"),
        ("tf2_ros", "0 0 0.2 0 0 0 1 base_link laser"),
        ("tf2_ros", "/my_transform_param"),
        ("tf", "0 0 0.2 0 0 0 base_link laser 100"),
        ("tf", "0 0 0.2 0 0 0 1 base_link laser 100"),
        ("tf2_ros", "0 0 0.2 0 0 0 base_link laser __name:=t"),
    ],
)
def test_valid_counts(lint: Lint, pkg: str, args: str) -> None:
    assert lint(launch(pkg, args), RULE) == []


def test_arguments_across_lines(lint: Lint) -> None:
    xml = """<launch>
  <node pkg="tf2_ros" type="static_transform_publisher" name="t"
        args="0 0 0.2
              0 0 0
              base_link laser
              100"/>
</launch>"""
    assert lint(xml, RULE) == [(RULE, 2)]


def test_unresolved_count_is_silent(lint: Lint) -> None:
    xml = """<launch>
  <arg name="rot"/>
  <node pkg="tf2_ros" type="static_transform_publisher" name="t"
        args="0 0 0.2 $(arg rot) base_link laser"/>
</launch>"""
    assert lint(xml, RULE) == []
    assert lint(xml, RULE, {"rot": "0 0 0"}) == []
    assert lint(xml, RULE, {"rot": "0 0"}) == [(RULE, 3)]


def test_study_fig_4b_tf_without_period(lint: Lint) -> None:
    # Fig. 4(b)'s first node uses pkg tf with no period: tf prints its usage and exits.
    xml = launch("tf", "0.0 0.365 0.2 -1.57 0.0 0.0 base base_wheel_left")
    assert lint(xml, RULE) == [(RULE, 2)]


def test_study_fig_4c_missing_space(lint: Lint) -> None:
    # Fig. 4(c): "/base_footprint/base_link 10" has one frame too few for tf.
    xml = launch("tf", "0.0 0.0 0.0 0.0 0.0 0.0 /base_footprint/base_link 10")
    assert lint(xml, RULE) == [(RULE, 2)]
