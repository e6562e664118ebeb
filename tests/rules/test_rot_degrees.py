from __future__ import annotations

from typing import Callable, List, Tuple

import pytest

from launch_linter.model import Diagnostic

Lint = Callable[..., List[Tuple[str, int]]]
LintDiagnostics = Callable[..., Tuple[Diagnostic, ...]]

RULE = "rot_degrees"


def launch(args: str, pkg: str = "tf2_ros") -> str:
    return (
        f'<launch>\n<node pkg="{pkg}" type="static_transform_publisher" name="t" '
        f'args="{args}"/>\n</launch>'
    )


def test_study_fig_4a_135_degrees_about_x(lint_diagnostics: LintDiagnostics) -> None:
    # Fig. 4(a): "the laser is rotated 135 degrees by x", written as roll 135.
    (found,) = lint_diagnostics(launch("0 0 0.3 0 0 135 base_link laser 100", "tf"), RULE)
    assert found.line == 2
    assert "roll 135" in found.message and "2.35619 rad" in found.message


def test_negative_degrees_are_reported(lint_diagnostics: LintDiagnostics) -> None:
    # anchors.md (e): PhysFrame missed -90 0 -90 because it only looked at positive values.
    (found,) = lint_diagnostics(launch("0 0 0 -90 0 -90 camera_link camera_optical"), RULE)
    assert "yaw -90" in found.message and "roll -90" in found.message
    assert "-1.5708 rad" in found.message


@pytest.mark.parametrize(
    "angles", ["1.5708 0 0", "-1.57 0 -1.57", "3.14159 3.14159 0", "6.2831 0 0", "0 0 -6.28"]
)
def test_radians_pass(lint: Lint, angles: str) -> None:
    assert lint(launch(f"0 0 0 {angles} a b"), RULE) == []


@pytest.mark.parametrize("angles", ["9.42478 0 0", "0 7.853982 0", "0 0 -4.712389"])
def test_radian_multiples_of_half_pi_pass(lint: Lint, angles: str) -> None:
    assert lint(launch(f"0 0 0 {angles} a b"), RULE) == []


@pytest.mark.parametrize("angles", ["90 0 0", "0 45 0", "0 0 180", "11 0 0", "0 7 0"])
def test_degrees_are_reported(lint: Lint, angles: str) -> None:
    assert lint(launch(f"0 0 0 {angles} a b"), RULE) == [(RULE, 2)]


def test_quaternions_are_not_angles(lint: Lint) -> None:
    assert lint(launch("0 0 0 0 0 90 1 a b"), RULE) == []


def test_unresolved_rotation_is_silent(lint: Lint) -> None:
    xml = """<launch>
  <arg name="yaw"/>
  <node pkg="tf2_ros" type="static_transform_publisher" name="t"
        args="0 0 0 $(arg yaw) 0 90 a b"/>
</launch>"""
    assert lint(xml, RULE) == []
    assert lint(xml, RULE, {"yaw": "0"}) == [(RULE, 3)]
