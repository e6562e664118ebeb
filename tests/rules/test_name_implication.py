from __future__ import annotations

import re
from pathlib import Path

from launch_linter import LintOptions, lint_paths, lint_text
from launch_linter.beliefs_files import load_beliefs
from launch_linter.model import Diagnostic
from launch_linter.model.beliefs import BeliefSet
from launch_linter.model.diagnostic import Belief
from launch_linter.rules import RULES_BY_ID

RULE = "name_implication"
LINKS = Belief(RULE, "link2_broadcaster", "link1_broadcaster", 11, 11, 1.1055)


def node(name: str, args: str) -> str:
    return f'  <node pkg="tf" type="static_transform_publisher" name="{name}" args="{args}"/>'


def launch(*lines: str) -> str:
    return "<launch>\n" + "\n".join(lines) + "\n</launch>\n"


def run(xml: str, *beliefs: Belief) -> tuple[Diagnostic, ...]:
    options = LintOptions(package_paths=(), select=frozenset({RULE}),
                          beliefs=BeliefSet("test", 0.0, beliefs))
    return lint_text(xml, "test.launch", options).diagnostics


LINK1 = node("link1_broadcaster", "0 0 0.1 0 0 0 base_link link1 100")
LINK2 = node("link2_broadcaster", "0.5 0 0 0 0 0 link1 link2 100")


def test_name_without_its_companion() -> None:
    (found,) = run(launch(LINK2), LINKS)
    assert (found.rule, found.line, found.node) == (RULE, 2, "link2_broadcaster")
    assert found.belief == LINKS
    assert "'link2_broadcaster'" in found.message and "'link1_broadcaster'" in found.message
    assert "n=11, e=11, z=1.11" in found.message


def test_companion_present_is_fine() -> None:
    assert run(launch(LINK1, LINK2), LINKS) == ()
    assert run(launch(LINK1), LINKS) == ()


def test_names_are_compared_without_namespace() -> None:
    grouped = launch('  <group ns="arm">', LINK1, "  </group>", LINK2)
    assert run(grouped, LINKS) == ()


def test_names_from_substitutions_count_once_resolved() -> None:
    xml = launch('  <arg name="i" default="1"/>',
                 node("link$(arg i)_broadcaster", "0 0 0.1 0 0 0 base_link link1 100"), LINK2)
    assert run(xml, LINKS) == ()
    unknown = xml.replace(' default="1"', "")
    assert run(unknown, LINKS) == ()


def test_scope_is_the_file(tmp_path: Path) -> None:
    (tmp_path / "child.launch").write_text(launch(LINK2))
    (tmp_path / "root.launch").write_text(
        launch(LINK1, '  <include file="$(dirname)/child.launch"/>'))
    options = LintOptions(package_paths=(), select=frozenset({RULE}),
                          beliefs=BeliefSet("test", 0.0, (LINKS,)))
    (found,) = lint_paths([str(tmp_path / "root.launch")], options).diagnostics
    assert found.path.endswith("child.launch") and found.line == 2


def test_documented_example_with_the_bundled_beliefs() -> None:
    doc = RULES_BY_ID[RULE].doc
    example, use_instead = re.findall(r"```xml\n(.*?)```", doc, re.S)[:2]
    options = LintOptions(package_paths=(), select=frozenset({RULE}),
                          beliefs=load_beliefs("bundled", 1.0))
    assert [d.rule for d in lint_text(example, "example.launch", options).diagnostics] == [RULE]
    assert lint_text(use_instead, "example.launch", options).diagnostics == ()
