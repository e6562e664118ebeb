"""The study's Fig. 4 and the PhysFrame defects of anchors.md (e), run through every rule.

Each case lists every diagnostic the MUST, MAY-Semantic and tf rules give, so a rule that
starts to fire where it should not (or stops firing) shows up here.
"""

from __future__ import annotations

from collections import Counter

import pytest

from launch_linter import LintOptions, lint_text
from launch_linter.beliefs_files import load_beliefs
from launch_linter.model import Category

CATEGORIES = frozenset({Category.MUST.value, Category.MAY_SEMANTIC.value, Category.TF.value})


def node(name: str, args: str, pkg: str = "tf") -> str:
    return f'<node pkg="{pkg}" type="static_transform_publisher" name="{name}" args="{args}"/>'


def findings(xml: str) -> Counter[tuple[str, int]]:
    options = LintOptions(package_paths=(), select=CATEGORIES)
    return Counter((d.rule, d.line) for d in lint_text(xml, "fig.launch", options).diagnostics)


def launch(*nodes: str) -> str:
    return "\n".join(["<launch>", *nodes, "</launch>"])


def test_fig_4a_wrong_rotation_unit() -> None:
    xml = launch(
        "<!-- the laser is rotated 135 degrees about x relative to the base -->",
        node("base_to_laser", "0.1 0 0.3 0 0 135 base_link laser 100"),
    )
    assert findings(xml) == Counter({("rot_degrees", 3): 1})


def test_fig_4b_duplicated_name_missing_integer_suffix() -> None:
    xml = launch(
        node("static_transform_publisher1", "0.0 0.365 0.2 -1.57 0.0 0.0 base base_wheel_left"),
        node("static_transform_publisher1", "0.0 -0.365 0.2 -1.57 0.0 0.0 base base_wheel_right",
             "tf2_ros"),
        node("static_transform_publisher3", "0.0 -0.365 0.2 -1.57 0.0 0.0 base base_wheel_center",
             "tf2_ros"),
    )
    assert findings(xml) == Counter({
        ("bad_arity", 2): 1,  # pkg tf without a period: tf prints its usage and exits
        ("dup_name", 3): 1,
        ("int_suffix", 4): 1,
        # -1.57 is π/2 rounded (info: the wheels are no sensor frames).
        ("rounded_pi", 2): 1, ("rounded_pi", 3): 1, ("rounded_pi", 4): 1,
    })


def test_fig_4c_copies_and_a_missing_space() -> None:
    camera = "0.0 0.0 0.0 0.0 0.0 0.0 /base_link /camera_link 10"
    xml = launch(
        node("map_to_odom", "0.0 0.0 0.0 0.0 0.0 0.0 /map /base_footprint 10"),
        node("base_footprint_2_base_link", "0.0 0.0 0.0 0.0 0.0 0.0 /base_footprint/base_link 10"),
        node("base_link_2_oamera_link", camera),
        node("base_link_2_oamera_link", camera),
        node("base_link_2_oamera_link", camera),
    )
    assert findings(xml) == Counter({
        ("leading_slash", 2): 2,
        ("bad_arity", 3): 1,
        ("leading_slash", 3): 1,
        ("leading_slash", 4): 2,
        ("leading_slash", 5): 2,
        ("dup_name", 5): 1,
        ("dup_sig", 5): 1,
        ("leading_slash", 6): 2,
        ("dup_name", 6): 1,
        ("dup_sig", 6): 1,
    })


@pytest.mark.parametrize(
    ("xml", "expected"),
    [
        # tf2_ros given a period: read as a quaternion with qw = 0 and child "100".
        (launch(node("t", "0 0 0.2 0 0 0 base_link laser 100", "tf2_ros")),
         {("bad_arity", 2): 1}),
        # -90 0 -90 in degrees: PhysFrame only looked at positive values.
        (launch(node("t", "0 0 0 -90 0 -90 camera_link camera_optical", "tf2_ros")),
         {("rot_degrees", 2): 1}),
        # The zero quaternion was not flagged.
        (launch(node("t", "0 0 0 0 0 0 0 base_link laser", "tf2_ros")),
         {("bad_quaternion", 2): 1}),
        # /base_link and base_link are one frame: the same signature twice.
        (launch(node("a", "0 0 0 0 0 0 /base_link laser3 100"),
                node("b", "0.1 0 0 0 0 0 base_link laser3 100")),
         {("dup_sig", 3): 1, ("leading_slash", 2): 1}),
        # cam1, laser3, imu5 are unrelated stems: no int_suffix.
        (launch(node("t1", "0.1 0 0 0 0 0 base cam1 100"),
                node("t2", "0.1 0 0 0 0 0 base laser3 100"),
                node("t3", "0.1 0 0 0 0 0 base imu5 100")),
         {}),
        # sensor_null could never fire standalone.
        (launch(node("imu_tf", "0 0 0 0 0 0 base_link imu_link 100")),
         {("sensor_null", 2): 1}),
        # $(arg x) in args crashed validate_transforms: here it is only left unjudged.
        (launch('<arg name="x"/>', node("t", "0 0 0 0 0 0 $(arg x) $(arg x) 100")),
         {}),
    ],
)
def test_physframe_defects(xml: str, expected: dict[tuple[str, int], int]) -> None:
    assert findings(xml) == Counter(expected)


def test_null_rotation_is_not_reported_as_a_rotation() -> None:
    # PhysFrame reported map -> odom with zero rotation as "should have null rotation, but
    # it does not"; with the bundled beliefs nothing about its rotation is reported.
    xml = launch(node("map_to_odom", "0 0 0 0 0 0 map odom 100"))
    options = LintOptions(package_paths=(), beliefs=load_beliefs("bundled", 1.0))
    rules = {d.rule for d in lint_text(xml, "fig.launch", options).diagnostics}
    assert not rules & {"sig_null_rot", "name_null_rot", "rot_degrees"}


def test_messages_carry_line_numbers() -> None:
    # PhysFrame printed no line numbers; every diagnostic here has the node's own line.
    xml = launch("", "", node("t", "0 0 0 0 0 0 0 base_link laser", "tf2_ros"))
    options = LintOptions(package_paths=(), select=CATEGORIES)
    (found,) = lint_text(xml, "fig.launch", options).diagnostics
    assert (found.line, found.column) == (4, 1)
