from __future__ import annotations

from typing import Callable, List, Tuple

from launch_linter.model import Diagnostic

Lint = Callable[..., List[Tuple[str, int]]]
LintDiagnostics = Callable[..., Tuple[Diagnostic, ...]]

RULE = "self_transform"


def test_same_parent_and_child(lint: Lint) -> None:
    xml = """<launch>
  <node pkg="tf2_ros" type="static_transform_publisher" name="a"
        args="0 0 0 0 0 0 base_link base_link"/>
</launch>"""
    assert lint(xml, RULE) == [(RULE, 2)]


def test_leading_slash_is_the_same_frame(lint_diagnostics: LintDiagnostics) -> None:
    xml = """<launch>
  <node pkg="tf" type="static_transform_publisher" name="a"
        args="0 0 0 0 0 0 /laser laser 100"/>
</launch>"""
    (found,) = lint_diagnostics(xml, RULE)
    assert found.line == 2 and found.column == 3
    assert "'laser'" in found.message
    assert found.node == "a"


def test_different_frames_pass(lint: Lint) -> None:
    xml = """<launch>
  <node pkg="tf2_ros" type="static_transform_publisher" name="a"
        args="0 0 0 0 0 0 base_link laser"/>
</launch>"""
    assert lint(xml, RULE) == []


def test_unresolved_frame_is_silent(lint: Lint) -> None:
    xml = """<launch>
  <arg name="frame"/>
  <node pkg="tf2_ros" type="static_transform_publisher" name="a"
        args="0 0 0 0 0 0 $(arg frame) $(arg frame)"/>
</launch>"""
    assert lint(xml, RULE) == []
    assert lint(xml, RULE, {"frame": "odom"}) == [(RULE, 3)]


def test_resolved_through_args(lint: Lint) -> None:
    xml = """<launch>
  <arg name="parent" default="map"/>
  <arg name="child" default="/map"/>
  <node pkg="tf" type="static_transform_publisher" name="a"
        args="0 0 0 0 0 0 $(arg parent) $(arg child) 100"/>
</launch>"""
    assert lint(xml, RULE) == [(RULE, 4)]
    assert lint(xml, RULE, {"child": "odom"}) == []


def test_only_static_transform_publishers(lint: Lint) -> None:
    xml = """<launch>
  <node pkg="my_pkg" type="static_transform_publisher" name="a"
        args="0 0 0 0 0 0 base_link base_link"/>
</launch>"""
    assert lint(xml, RULE) == []
