from __future__ import annotations

from typing import Callable, List, Tuple

import pytest

from launch_linter.model import Diagnostic

Lint = Callable[..., List[Tuple[str, int]]]
LintDiagnostics = Callable[..., Tuple[Diagnostic, ...]]

RULE = "ned_transform"


def launch(args: str) -> str:
    return (
        '<launch>\n<node pkg="tf2_ros" type="static_transform_publisher" name="t" '
        f'args="{args}"/>\n</launch>'
    )


@pytest.mark.parametrize(
    ("args", "problem"),
    [
        ("0 0 0 0 0 0 base_link base_link_ned", "has no rotation"),
        ("0 0 0 0 0 0 1 base_link base_link_ned", "has no rotation"),
        ("0.1 0 0 1.5708 0 3.1416 base_link base_link_ned", "has a displacement"),
        ("1 0 0 0 0 0 map map_NED", "has a displacement and has no rotation"),
        # uuv_simulator 8d9ca306: pi in yaw turns x and y, z stays up (fixed: pi in roll).
        ("0 0 0 3.141592653589793 0 0 rexrov/base_link rexrov/base_link_ned", "z axis"),
        # yaw and roll swapped (ENU -> NED is yaw pi/2, roll pi): z ends horizontal.
        ("0 0 0 3.14 0 1.57 odom odom_ned", "keeps the z axis of its ENU parent 'odom' up"),
        ("0 0 0 0 0 0.7071068 0.7071068 map map_ned", "z axis"),  # a quarter turn in yaw
    ],
)
def test_reported(lint_diagnostics: LintDiagnostics, args: str, problem: str) -> None:
    (found,) = lint_diagnostics(launch(args), RULE)
    assert found.line == 2 and problem in found.message


@pytest.mark.parametrize(
    "args",
    [
        "0 0 0 1.5708 0 3.1416 base_link base_link_ned",
        "0 0 0 0.70710678 0.70710678 0 0 odom odom_ned",
        "0 0 0 0 0 0 base_link ned_frame",
        "1 0 0 0 0 0 base_link_ned base_link",
        "0 0 0 0 0 3.141592653589793 rexrov/base_link rexrov/base_link_ned",  # roll pi
        "0 0 0 0 0 3.14 base_link base_link_ned",  # a rounded pi still turns z down
        "0 0 0 1 0 0 0 map world_ned",  # a half turn about x, as a quaternion
        "0 0 0 3.14159 0 0 base_link_frd base_link_ned",  # an FRD parent's z is down
        "0 0 0 1.5708 0 0 odom_ned imu_ned",  # a NED parent: z stays down
        "0 0 0 1.5708 0 0 camera_optical_frame camera_ned",  # an optical parent
    ],
)
def test_passes(lint: Lint, args: str) -> None:
    assert lint(launch(args), RULE) == []


def test_unresolved_values_are_silent(lint: Lint) -> None:
    xml = """<launch>
  <arg name="x"/>
  <node pkg="tf2_ros" type="static_transform_publisher" name="t"
        args="$(arg x) 0 0 1.5708 0 3.1416 base_link base_link_ned"/>
</launch>"""
    assert lint(xml, RULE) == []
    assert lint(xml, RULE, {"x": "0.2"}) == [(RULE, 3)]
