"""xacro's processing order per distribution and call (``xacro_order``)."""

from __future__ import annotations

from hypothesis import given
from hypothesis import strategies as st

from launch_linter.frontends.robot.xacro_order import (
    legacy_include_refusal,
    legacy_order,
    property_needed,
)


def test_the_legacy_order_per_distribution_and_option() -> None:
    assert legacy_order({"ROS_DISTRO": "kinetic"}, ())
    assert legacy_order({"ROS_DISTRO": "indigo"}, ("-o", "out.urdf"))
    assert not legacy_order({"ROS_DISTRO": "kinetic"}, ("--inorder",))
    assert not legacy_order({"ROS_DISTRO": "lunar"}, ("-i",))
    assert not legacy_order({"ROS_DISTRO": "jade"}, ("--check-order",))
    assert not legacy_order({"ROS_DISTRO": "melodic"}, ())
    assert legacy_order({"ROS_DISTRO": "melodic"}, ("--legacy",))
    assert not legacy_order({"ROS_DISTRO": "noetic"}, ("--legacy",))
    assert not legacy_order({}, ())


def test_the_names_an_expression_needs() -> None:
    assert property_needed("arm") == "arm"
    assert property_needed("prefix + '_arm'") == "prefix"
    assert property_needed("pi / 2") is None
    assert property_needed("'fixed'") is None
    assert property_needed("[x for x in y]") is None  # binds a name of its own
    assert property_needed("lambda a: a") is None
    assert property_needed("(") is None  # not Python: nothing claimed


@given(st.text(max_size=200))
def test_any_file_name_is_judged_without_an_exception(text: str) -> None:
    refusal = legacy_include_refusal(text)
    assert refusal is None or "${" in text
