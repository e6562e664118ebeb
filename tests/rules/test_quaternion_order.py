from __future__ import annotations

from typing import Callable, List, Tuple

import pytest
from robot_ws import ws_lint

RULE = "quaternion_order"
Lint = Callable[..., List[Tuple[str, int]]]


def static(rotation: str) -> str:
    return (f'<launch><node pkg="tf2_ros" type="static_transform_publisher" name="t" '
            f'args="0 0 0 {rotation} base_link imu_link"/></launch>')


@pytest.mark.parametrize("rotation", ["1 0 0 0", "-1 0 0 0", "1.0 0.0 0.0 0.0"])
def test_w_first_identity(lint: Lint, rotation: str) -> None:
    assert lint(static(rotation), RULE) == [(RULE, 1)]


@pytest.mark.parametrize("rotation", ["0 0 0 1", "0 0 0.7071 0.7071", "0 0 3.14159",
                                      "0.7071 0 0 0.7071"])
def test_other_rotations(lint: Lint, rotation: str) -> None:
    assert lint(static(rotation), RULE) == []


def test_in_the_workspace() -> None:
    (found,) = ws_lint("demo_bringup/launch/cameras.launch", RULE)
    assert found.node == "imu_tf"
