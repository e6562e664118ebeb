from __future__ import annotations

import re

from launch_linter import LintOptions, lint_text
from launch_linter.beliefs_files import load_beliefs
from launch_linter.model import Diagnostic
from launch_linter.model.beliefs import BeliefSet
from launch_linter.model.diagnostic import Belief
from launch_linter.rules import RULES_BY_ID

RULE = "name_null_disp"
VIRTUAL = Belief(RULE, "virtual_joint_broadcaster_0", None, 14, 14, 1.2472)


def node(name: str, args: str) -> str:
    return f'  <node pkg="tf" type="static_transform_publisher" name="{name}" args="{args}"/>'


def launch(*lines: str) -> str:
    return "<launch>\n" + "\n".join(lines) + "\n</launch>\n"


def run(xml: str, *beliefs: Belief) -> tuple[Diagnostic, ...]:
    options = LintOptions(package_paths=(), select=frozenset({RULE}),
                          beliefs=BeliefSet("test", 0.0, beliefs))
    return lint_text(xml, "test.launch", options).diagnostics


def test_displacement_under_a_name_that_usually_has_none() -> None:
    xml = launch(node("virtual_joint_broadcaster_0", "0 0 0.75 0 0 0 world base_link 100"))
    (found,) = run(xml, VIRTUAL)
    assert (found.rule, found.line, found.belief) == (RULE, 2, VIRTUAL)
    assert "'virtual_joint_broadcaster_0'" in found.message and "(0, 0, 0.75)" in found.message
    assert "n=14, e=14, z=1.25" in found.message


def test_zero_displacement_and_other_names_are_fine() -> None:
    assert run(launch(node("virtual_joint_broadcaster_0", "0 0 0 1 0 0 world base 100")),
               VIRTUAL) == ()
    assert run(launch(node("virtual_joint_broadcaster_1", "0 0 1 0 0 0 world base 100")),
               VIRTUAL) == ()


def test_name_in_a_namespace_still_counts() -> None:
    xml = launch('  <group ns="robot">',
                 node("virtual_joint_broadcaster_0", "1 0 0 0 0 0 world base 100"), "  </group>")
    assert len(run(xml, VIRTUAL)) == 1


def test_unresolved_name_is_skipped() -> None:
    xml = launch('  <arg name="n"/>',
                 node("virtual_joint_broadcaster_$(arg n)", "1 0 0 0 0 0 world base 100"))
    assert run(xml, VIRTUAL) == ()
    assert len(run(xml.replace('<arg name="n"/>', '<arg name="n" default="0"/>'), VIRTUAL)) == 1


def test_documented_example_with_the_bundled_beliefs() -> None:
    doc = RULES_BY_ID[RULE].doc
    example, use_instead = re.findall(r"```xml\n(.*?)```", doc, re.S)[:2]
    options = LintOptions(package_paths=(), select=frozenset({RULE}),
                          beliefs=load_beliefs("bundled", 1.0))
    assert [d.rule for d in lint_text(example, "example.launch", options).diagnostics] == [RULE]
    assert lint_text(use_instead, "example.launch", options).diagnostics == ()
