"""ros2_schema: an action attribute or nested tag that launch refuses."""

from __future__ import annotations

from typing import Callable, List, Tuple

Lint = Callable[..., List[Tuple[str, int]]]

GOOD = """<launch>
  <node pkg="tf2_ros" exec="static_transform_publisher" namespace="r"
        args="--frame-id a --child-frame-id b"/>
</launch>
"""


def test_misspelled_attribute_is_an_error(lint: Lint) -> None:
    bad = GOOD.replace("namespace=", "namespce=")
    assert lint(bad, "ros2_schema") == [("ros2_schema", 2)]


def test_accepted_attributes_are_silent(lint: Lint) -> None:
    assert lint(GOOD, "ros2_schema") == []


def test_ros1_files_are_not_checked(lint: Lint) -> None:
    ros1 = '<launch><node pkg="tf" type="static_transform_publisher" name="x" ns="a"' \
           ' args="0 0 0 0 0 0 a b 100"/></launch>'
    assert lint(ros1, "ros2_schema") == []
