"""ros2_include_arg_misspelt: an include argument that the included files neither declare
nor read, spelt like one they declare; reported even where part of the include is unseen."""

from __future__ import annotations

import time
from pathlib import Path

from launch_linter import LintOptions, lint_paths

RULE = "ros2_include_arg_misspelt"
CHILD = ('<launch>\n<arg name="params_file" default="default.yaml"/>\n'
         '<node pkg="nav2_amcl" exec="amcl" name="amcl"><param from="$(var params_file)"/>'
         '</node>\n{extra}</launch>\n')


def lint(tmp_path: Path, main: str, extra: str = "") -> list[tuple[int, str]]:
    (tmp_path / "child.launch.xml").write_text(CHILD.format(extra=extra), encoding="utf-8")
    (tmp_path / "main.launch.xml").write_text(main, encoding="utf-8")
    result = lint_paths([str(tmp_path / "main.launch.xml")], LintOptions(package_paths=(), ros=2))
    return [(d.line, d.message) for d in result.diagnostics if d.rule == RULE]


def main_passing(name: str) -> str:
    return ('<launch>\n<include file="$(dirname)/child.launch.xml">\n'
            f'  <arg name="{name}" value="robot.yaml"/>\n</include>\n</launch>\n')


def test_a_name_one_word_short_of_a_declared_one(tmp_path: Path) -> None:
    """turtlebot3#694: `params` passed to nav2_bringup, which declares `params_file`."""
    [(line, message)] = lint(tmp_path, main_passing("params"))
    assert line == 3 and "declares 'params_file'" in message


def test_a_name_spelt_alike(tmp_path: Path) -> None:
    assert [line for line, _ in lint(tmp_path, main_passing("param_file"))] == [3]


def test_the_declared_name_is_silent(tmp_path: Path) -> None:
    assert lint(tmp_path, main_passing("params_file")) == []


def test_a_name_unlike_every_declared_one_is_not_this_rule(tmp_path: Path) -> None:
    assert lint(tmp_path, main_passing("rate")) == []


def test_reported_even_where_part_of_the_include_is_unseen(tmp_path: Path) -> None:
    # An include the linter cannot follow makes the include's arguments unknown to
    # ros2_unused_include_arg; the declared spelling still says which one was meant.
    unseen = '<include file="$(find-pkg-share not_installed)/launch/x.launch.xml"/>\n'
    assert [line for line, _ in lint(tmp_path, main_passing("params"), unseen)] == [3]


def test_two_names_one_word_apart_are_ambiguous_and_silent(tmp_path: Path) -> None:
    # `frame` beside both `base_frame` and `frame_id`: no one spelling is meant.
    child = ('<launch>\n<arg name="base_frame" default="a"/><arg name="frame_id" default="b"/>'
             '\n<include file="$(find-pkg-share not_installed)/launch/x.launch.xml"/>'
             '\n</launch>\n')
    (tmp_path / "child.launch.xml").write_text(child, encoding="utf-8")
    (tmp_path / "main.launch.xml").write_text(main_passing("frame"), encoding="utf-8")
    result = lint_paths([str(tmp_path / "main.launch.xml")], LintOptions(package_paths=(), ros=2))
    assert [d for d in result.diagnostics if d.rule == RULE] == []


def test_twenty_thousand_unused_arguments_of_an_unseen_include_stay_bounded(
        tmp_path: Path) -> None:
    # Only the first 32 arguments nothing uses are compared with the declared names.
    declared = "".join(f'<arg name="argument_{i}" default="x"/>' for i in range(20_000))
    (tmp_path / "child.launch.xml").write_text(
        f'<launch>{declared}<include file="$(find-pkg-share not_installed)/x.launch.xml"/>'
        '</launch>', encoding="utf-8")
    passed = "".join(f'<arg name="argument{i}" value="1"/>' for i in range(20_000))
    (tmp_path / "main.launch.xml").write_text(
        f'<launch><include file="$(dirname)/child.launch.xml">{passed}</include></launch>',
        encoding="utf-8")
    started = time.process_time()
    result = lint_paths([str(tmp_path / "main.launch.xml")], LintOptions(package_paths=(), ros=2))
    assert sum(d.rule == RULE for d in result.diagnostics) == 32
    assert time.process_time() - started < 60
