from __future__ import annotations

from typing import Callable, List, Tuple

import pytest
from robot_ws import ws_lint

RULE = "rep105_order"
Lint = Callable[..., List[Tuple[str, int]]]


def static(parent: str, child: str) -> str:
    return (f'<launch><node pkg="tf2_ros" type="static_transform_publisher" name="t" '
            f'args="0 0 0 0 0 0 {parent} {child}"/></launch>')


@pytest.mark.parametrize("parent, child", [("odom", "map"), ("base_link", "odom"),
                                           ("base_footprint", "map"), ("map", "earth")])
def test_inverted(lint: Lint, parent: str, child: str) -> None:
    assert lint(static(parent, child), RULE) == [(RULE, 1)]


@pytest.mark.parametrize("parent, child", [("map", "odom"), ("odom", "base_footprint"),
                                           ("earth", "map"), ("base_link", "base_footprint"),
                                           ("base_link", "laser")])
def test_in_order_or_outside_the_chain(lint: Lint, parent: str, child: str) -> None:
    assert lint(static(parent, child), RULE) == []


def test_found_in_an_included_file() -> None:
    (found,) = ws_lint("demo_bringup/launch/cameras.launch", RULE)
    assert found.path.endswith("camera_driver.launch") and found.node == "odom_in_map"
