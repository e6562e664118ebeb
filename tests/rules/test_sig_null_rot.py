from __future__ import annotations

import re

import pytest

from launch_linter import LintOptions, lint_text
from launch_linter.beliefs_files import load_beliefs
from launch_linter.model import Diagnostic
from launch_linter.model.beliefs import BeliefSet
from launch_linter.model.diagnostic import Belief
from launch_linter.rules import RULES_BY_ID

RULE = "sig_null_rot"
FOOTPRINT = Belief(RULE, ("base_footprint", "base_link"), None, 24, 24, 1.633)


def node(name: str, args: str, pkg: str = "tf2_ros") -> str:
    return f'  <node pkg="{pkg}" type="static_transform_publisher" name="{name}" args="{args}"/>'


def launch(*lines: str) -> str:
    return "<launch>\n" + "\n".join(lines) + "\n</launch>\n"


def run(xml: str, *beliefs: Belief) -> tuple[Diagnostic, ...]:
    options = LintOptions(package_paths=(), select=frozenset({RULE}),
                          beliefs=BeliefSet("test", 0.0, beliefs))
    return lint_text(xml, "test.launch", options).diagnostics


def test_rotation_where_none_is_usual() -> None:
    (found,) = run(launch(node("fp", "0 0 0.1 1.5708 0 0 base_footprint base_link")), FOOTPRINT)
    assert (found.rule, found.line, found.node, found.belief) == (RULE, 2, "fp", FOOTPRINT)
    assert "(base_footprint → base_link)" in found.message
    assert "ypr (1.5708, 0, 0)" in found.message and "n=24, e=24, z=1.63" in found.message


def test_quaternion_rotation_is_reported_as_written() -> None:
    (found,) = run(launch(node("fp", "0 0 0 0 0 0.7071 0.7071 base_footprint base_link")),
                   FOOTPRINT)
    assert "quaternion (0, 0, 0.7071, 0.7071)" in found.message


@pytest.mark.parametrize("args", [
    "0 0 0.1 0 0 0 base_footprint base_link",
    "0 0 0.1 0 0 0 1 base_footprint base_link",
    "0 0 0.1 0 0 0 -1 /base_footprint base_link",
])
def test_identity_rotations_are_fine(args: str) -> None:
    assert run(launch(node("fp", args)), FOOTPRINT) == ()


def test_unresolved_rotation_is_skipped() -> None:
    xml = launch('  <arg name="yaw"/>', node("fp", "0 0 0 $(arg yaw) 0 0 base_footprint base_link"))
    assert run(xml, FOOTPRINT) == ()


def test_documented_example_with_the_bundled_beliefs() -> None:
    doc = RULES_BY_ID[RULE].doc
    example, use_instead = re.findall(r"```xml\n(.*?)```", doc, re.S)[:2]
    options = LintOptions(package_paths=(), select=frozenset({RULE}),
                          beliefs=load_beliefs("bundled", 1.0))
    assert [d.rule for d in lint_text(example, "example.launch", options).diagnostics] == [RULE]
    assert lint_text(use_instead, "example.launch", options).diagnostics == ()
