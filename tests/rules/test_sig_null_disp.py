from __future__ import annotations

import re

from launch_linter import LintOptions, lint_text
from launch_linter.beliefs_files import load_beliefs
from launch_linter.model import Diagnostic
from launch_linter.model.beliefs import BeliefSet
from launch_linter.model.diagnostic import Belief
from launch_linter.rules import RULES_BY_ID

RULE = "sig_null_disp"
WORLD_MAP = Belief(RULE, ("world", "map"), None, 15, 15, 1.291)


def node(name: str, args: str, pkg: str = "tf") -> str:
    return f'  <node pkg="{pkg}" type="static_transform_publisher" name="{name}" args="{args}"/>'


def launch(*lines: str) -> str:
    return "<launch>\n" + "\n".join(lines) + "\n</launch>\n"


def run(xml: str, *beliefs: Belief) -> tuple[Diagnostic, ...]:
    options = LintOptions(package_paths=(), select=frozenset({RULE}),
                          beliefs=BeliefSet("test", 0.0, beliefs))
    return lint_text(xml, "test.launch", options).diagnostics


def test_displacement_where_none_is_usual() -> None:
    (found,) = run(launch(node("w", "2 1 0 0 0 0 world map 100")), WORLD_MAP)
    assert (found.rule, found.line, found.node, found.belief) == (RULE, 2, "w", WORLD_MAP)
    assert "(world → map)" in found.message and "(2, 1, 0)" in found.message
    assert "n=15, e=15, z=1.29" in found.message


def test_zero_displacement_is_fine() -> None:
    assert run(launch(node("w", "0 0 0 0.3 0 0 world map 100")), WORLD_MAP) == ()
    assert run(launch(node("w", "-0.0 0 0 0 0 0 1 /world map", "tf2_ros")), WORLD_MAP) == ()


def test_every_transform_is_judged() -> None:
    xml = launch('  <group ns="a">', node("w", "1 0 0 0 0 0 world map 100"), "  </group>",
                 node("w", "0 0 1 0 0 0 /world map 100"))
    assert [d.line for d in run(xml, WORLD_MAP)] == [3, 5]


def test_unresolved_displacement_is_skipped() -> None:
    xml = launch('  <arg name="x"/>', node("w", "$(arg x) 0 0 0 0 0 world map 100"))
    assert run(xml, WORLD_MAP) == ()
    assert len(run(xml.replace('<arg name="x"/>', '<arg name="x" default="3"/>'), WORLD_MAP)) == 1


def test_other_signatures_and_classes_are_ignored() -> None:
    xml = launch(node("w", "2 1 0 0 0 0 map world 100"))
    assert run(xml, WORLD_MAP) == ()
    assert run(launch(node("w", "2 1 0 0 0 0 world map 100")),
               Belief("sig_null_rot", ("world", "map"), None, 15, 15, 1.291)) == ()


def test_documented_example_with_the_bundled_beliefs() -> None:
    doc = RULES_BY_ID[RULE].doc
    example, use_instead = re.findall(r"```xml\n(.*?)```", doc, re.S)[:2]
    options = LintOptions(package_paths=(), select=frozenset({RULE}),
                          beliefs=load_beliefs("bundled", 1.0))
    assert [d.rule for d in lint_text(example, "example.launch", options).diagnostics] == [RULE]
    assert lint_text(use_instead, "example.launch", options).diagnostics == ()
