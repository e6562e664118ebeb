from __future__ import annotations

import math

import pytest
from _urdf import link, lint_urdf, robot
from hypothesis import given
from hypothesis import strategies as st

from launch_linter.rules.rounded_pi import rounded_pi

RULE = "rounded_pi"


def _stp(args: str) -> str:
    return ('<launch><node pkg="tf2_ros" type="static_transform_publisher" name="t" '
            f'args="{args}"/></launch>')


@pytest.mark.parametrize("value, meant", [
    (1.57, "π/2"), (-1.57, "-π/2"), (3.14, "π"), (-3.14, "-π"), (1.571, "π/2"),
    (0.785, "π/4"), (4.71, "3π/2"), (6.28, "2π"), (3.142, "π"),
])
def test_roundings_of_pi(value: float, meant: str) -> None:
    found = rounded_pi(value)
    assert found is not None and found[0] == meant


@pytest.mark.parametrize("value", [1.5708, 3.1416, 3.1415, 1.5707963, math.pi / 2, 1.5712,
                                   1.57119, 1.5, 2.0, 0.0, 10.0, 1.56])
def test_precise_or_measured_angles_are_fine(value: float) -> None:
    assert rounded_pi(value) is None


@given(st.integers(min_value=1, max_value=8), st.integers(min_value=5, max_value=12))
def test_five_decimals_and_more_are_never_reported(quarters: int, decimals: int) -> None:
    assert rounded_pi(round(quarters * math.pi / 4, decimals)) is None


@given(st.floats(allow_nan=True, allow_infinity=True))
def test_any_float_is_judged_without_error(value: float) -> None:
    found = rounded_pi(value)
    assert found is None or 1e-4 <= found[1] < 0.01


def test_a_static_transform_yaw(lint_diagnostics) -> None:  # type: ignore[no-untyped-def]
    (found,) = lint_diagnostics(_stp("0 0 0 1.57 0 0 base_link laser"), RULE)
    assert found.severity.value == "warning"
    assert "yaw 1.57 is π/2 rounded (8.0e-04 rad off)" in found.message
    assert "0.80 mm at 1 m" in found.message


def test_three_decimals_are_info(lint_diagnostics) -> None:  # type: ignore[no-untyped-def]
    (found,) = lint_diagnostics(_stp("0 0 0 0 0 1.571 base_link laser"), RULE)
    assert found.severity.value == "info"


def test_precise_values_are_fine(lint) -> None:  # type: ignore[no-untyped-def]
    assert lint(_stp("0 0 0 1.5708 0 -3.1416 base_link laser"), RULE) == []


def test_a_urdf_rpy_with_the_distance_to_the_child_frame() -> None:
    text = robot(link("base_link") + link("camera") + link("optical")
                 + '<joint name="cam" type="fixed"><origin rpy="0 0 3.14"/>'
                 '<parent link="base_link"/><child link="camera"/></joint>'
                 + '<joint name="opt" type="fixed"><origin xyz="0 0.5 0"/>'
                 '<parent link="camera"/><child link="optical"/></joint>')
    (found,) = lint_urdf(text, RULE)
    assert "yaw 3.14 is π rounded" in found.message
    assert "0.80 mm at 'optical' (0.5 m from 'camera')" in found.message


def test_xacro_computed_angles_are_exact() -> None:
    text = robot(link("a") + link("b") + '<joint name="j" type="fixed">'
                 '<origin rpy="${pi/2} 0 ${-pi}"/><parent link="a"/><child link="b"/></joint>')
    assert lint_urdf(text, RULE) == ()


def test_a_rough_orientation_is_info(lint_diagnostics) -> None:  # type: ignore[no-untyped-def]
    (found,) = lint_diagnostics(_stp("0 0 0 4.7 -1 3.14 camera_link camera_rotated"), RULE)
    assert found.severity.value == "info"


def test_a_frame_that_places_a_robot_is_info(lint_diagnostics) -> None:  # type: ignore[no-untyped-def]
    (found,) = lint_diagnostics(_stp("1 0 0 3.14 0 0 world robot_2/base_footprint"), RULE)
    assert found.severity.value == "info"
