from __future__ import annotations

import re

from launch_linter import LintOptions, lint_text
from launch_linter.beliefs_files import load_beliefs
from launch_linter.model import Diagnostic
from launch_linter.model.beliefs import BeliefSet
from launch_linter.model.diagnostic import Belief
from launch_linter.rules import RULES_BY_ID

RULE = "name_null_rot"
LASER = Belief(RULE, "base_link_to_laser", None, 14, 14, 1.2472)


def node(name: str, args: str) -> str:
    return f'  <node pkg="tf" type="static_transform_publisher" name="{name}" args="{args}"/>'


def launch(*lines: str) -> str:
    return "<launch>\n" + "\n".join(lines) + "\n</launch>\n"


def run(xml: str, *beliefs: Belief) -> tuple[Diagnostic, ...]:
    options = LintOptions(package_paths=(), select=frozenset({RULE}),
                          beliefs=BeliefSet("test", 0.0, beliefs))
    return lint_text(xml, "test.launch", options).diagnostics


def test_rotation_under_a_name_that_usually_has_none() -> None:
    xml = launch(node("base_link_to_laser", "0.2 0 0.15 3.1416 0 0 base_link laser 100"))
    (found,) = run(xml, LASER)
    assert (found.rule, found.line, found.node, found.belief) == (RULE, 2, "base_link_to_laser",
                                                                  LASER)
    assert "ypr (3.1416, 0, 0)" in found.message and "n=14, e=14, z=1.25" in found.message


def test_no_rotation_or_other_name_is_fine() -> None:
    assert run(launch(node("base_link_to_laser", "0.2 0 0.15 0 0 0 base_link laser 100")),
               LASER) == ()
    assert run(launch(node("laser_tf", "0.2 0 0.15 1 0 0 base_link laser 100")), LASER) == ()


def test_unresolved_rotation_or_name_is_skipped() -> None:
    xml = launch('  <arg name="yaw"/>',
                 node("base_link_to_laser", "0 0 0 $(arg yaw) 0 0 base_link laser 100"))
    assert run(xml, LASER) == ()
    anon = launch(node("$(anon base_link_to_laser)", "0 0 0 1 0 0 base_link laser 100"))
    assert run(anon, LASER) == ()


def test_study_belief_without_counts() -> None:
    study = Belief(RULE, "base_link_to_laser", None, 0, 0, 10.0)
    (found,) = run(launch(node("base_link_to_laser", "0 0 0 1 0 0 base_link laser 100")), study)
    assert "z ≥ 10, counts not published" in found.message


def test_documented_example_with_the_bundled_beliefs() -> None:
    doc = RULES_BY_ID[RULE].doc
    example, use_instead = re.findall(r"```xml\n(.*?)```", doc, re.S)[:2]
    options = LintOptions(package_paths=(), select=frozenset({RULE}),
                          beliefs=load_beliefs("bundled", 1.0))
    assert [d.rule for d in lint_text(example, "example.launch", options).diagnostics] == [RULE]
    assert lint_text(use_instead, "example.launch", options).diagnostics == ()
