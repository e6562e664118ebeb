from __future__ import annotations

from typing import Callable, List, Tuple

import pytest

from launch_linter.model import Diagnostic

Lint = Callable[..., List[Tuple[str, int]]]
LintDiagnostics = Callable[..., Tuple[Diagnostic, ...]]

RULE = "reversed_name"


def launch(name: str, parent: str, child: str) -> str:
    return (
        f'<launch>\n<node pkg="tf2_ros" type="static_transform_publisher" name="{name}" '
        f'args="0 0 0 0 0 0 {parent} {child}"/>\n</launch>'
    )


@pytest.mark.parametrize(
    "name", ["map_to_odom", "map2odom", "map_2_odom", "map_odom", "MAP_TO_ODOM"]
)
def test_child_then_parent(lint: Lint, name: str) -> None:
    assert lint(launch(name, "odom", "map"), RULE) == [(RULE, 2)]


@pytest.mark.parametrize("name", ["odom_to_map", "odom2map", "odom_map", "tf", "map_to_base"])
def test_parent_then_child_or_other_names(lint: Lint, name: str) -> None:
    assert lint(launch(name, "odom", "map"), RULE) == []


def test_slashes_are_ignored(lint: Lint) -> None:
    assert lint(launch("map_to_odom", "/odom", "/map"), RULE) == [(RULE, 2)]


def test_name_reading_both_ways_is_not_reported(lint: Lint) -> None:
    # parent "a", child "a_a": "a_a_a" is both child_parent and parent_child.
    assert lint(launch("a_a_a", "a", "a_a"), RULE) == []
    assert lint(launch("a_a_a", "a_a", "a"), RULE) == []
    assert lint(launch("a_a_to_a", "a", "a_a"), RULE) == [(RULE, 2)]


def test_message_suggests_the_name(lint_diagnostics: LintDiagnostics) -> None:
    (found,) = lint_diagnostics(launch("laser_to_base_link", "base_link", "laser"), RULE)
    assert "'base_link_to_laser'" in found.message


def test_unresolved_name_is_silent(lint: Lint) -> None:
    xml = """<launch>
  <arg name="n"/>
  <node pkg="tf2_ros" type="static_transform_publisher" name="$(arg n)"
        args="0 0 0 0 0 0 odom map"/>
</launch>"""
    assert lint(xml, RULE) == []
    assert lint(xml, RULE, {"n": "map_to_odom"}) == [(RULE, 3)]
