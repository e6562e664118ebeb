from __future__ import annotations

import re
from pathlib import Path

from launch_linter import LintOptions, lint_paths, lint_text
from launch_linter.beliefs_files import load_beliefs
from launch_linter.model import Diagnostic
from launch_linter.model.beliefs import BeliefSet
from launch_linter.model.diagnostic import Belief
from launch_linter.rules import RULES_BY_ID

RULE = "sig_implication"
CAMERA = Belief(RULE, ("camera_link", "camera_rotated"), ("camera_rotated", "world"),
                10, 10, 1.0541)
CAMERA_TOO = Belief(RULE, ("camera_link", "camera_rotated"), ("base_link", "camera_link"),
                    12, 11, 0.7698)


def node(name: str, args: str) -> str:
    return f'  <node pkg="tf" type="static_transform_publisher" name="{name}" args="{args}"/>'


def launch(*lines: str) -> str:
    return "<launch>\n" + "\n".join(lines) + "\n</launch>\n"


def run(xml: str, *beliefs: Belief, path: str = "test.launch") -> tuple[Diagnostic, ...]:
    options = LintOptions(package_paths=(), select=frozenset({RULE}),
                          beliefs=BeliefSet("test", 0.0, beliefs))
    return lint_text(xml, path, options).diagnostics


ROTATION = node("cam_rot", "0 0 0 0 0 -1.57 camera_link camera_rotated 100")
MOUNT = node("cam_mount", "0.3 0 1 0 0 0 camera_rotated world 100")


def test_antecedent_without_consequent() -> None:
    xml = launch(node("other", "0 0 0 0 0 0 map odom 100"), ROTATION)
    (found,) = run(xml, CAMERA)
    assert (found.rule, found.line, found.node) == (RULE, 3, "cam_rot")
    assert found.belief == CAMERA
    assert "(camera_link → camera_rotated)" in found.message
    assert "(camera_rotated → world)" in found.message
    assert "n=10, e=10, z=1.05" in found.message
    assert found.to_json()["belief"] == {
        "class": RULE, "if": ["camera_link", "camera_rotated"], "then": ["camera_rotated", "world"],
        "n": 10, "e": 10, "z": 1.0541,
    }


def test_consequent_present_is_fine() -> None:
    assert run(launch(ROTATION, MOUNT), CAMERA) == ()
    # Frame ids compare without their leading slash.
    slashed = node("cam_mount", "0.3 0 1 0 0 0 /camera_rotated /world 100")
    assert run(launch(ROTATION, slashed), CAMERA) == ()


def test_reported_once_at_the_first_antecedent() -> None:
    again = node("cam_rot2", "0 0 0 0 0 -1.57 /camera_link camera_rotated 100")
    (found,) = run(launch(ROTATION, again), CAMERA)
    assert found.line == 2


def test_each_missing_consequent_is_reported() -> None:
    found = run(launch(ROTATION), CAMERA, CAMERA_TOO)
    assert sorted(d.belief.consequent for d in found if d.belief) == [
        ("base_link", "camera_link"), ("camera_rotated", "world")]


def test_without_beliefs_nothing_is_said() -> None:
    assert run(launch(ROTATION)) == ()
    other_class = Belief("name_implication", "cam_rot", "cam_mount", 10, 10, 1.05)
    assert run(launch(ROTATION), other_class) == ()


def test_file_with_unresolved_frames_is_not_judged() -> None:
    # The transform with an unknown child could be (camera_rotated → world).
    xml = launch('  <arg name="frame"/>', ROTATION,
                 node("cam_mount", "0.3 0 1 0 0 0 camera_rotated $(arg frame) 100"))
    assert run(xml, CAMERA) == ()
    resolved = xml.replace('<arg name="frame"/>', '<arg name="frame" default="world"/>')
    assert run(resolved, CAMERA) == ()
    wrong = xml.replace('<arg name="frame"/>', '<arg name="frame" default="map"/>')
    assert len(run(wrong, CAMERA)) == 1


def test_scope_is_the_file_not_the_tree(tmp_path: Path) -> None:
    (tmp_path / "child.launch").write_text(launch(MOUNT))
    (tmp_path / "root.launch").write_text(
        launch(ROTATION, '  <include file="$(dirname)/child.launch"/>'))
    options = LintOptions(package_paths=(), select=frozenset({RULE}),
                          beliefs=BeliefSet("test", 0.0, (CAMERA,)))
    (found,) = lint_paths([str(tmp_path / "root.launch")], options).diagnostics
    assert found.path.endswith("root.launch") and found.line == 2


def test_study_beliefs_say_that_counts_are_unknown() -> None:
    study = Belief(RULE, CAMERA.antecedent, CAMERA.consequent, 0, 0, 2.0)
    (found,) = run(launch(ROTATION), study)
    assert "z ≥ 2, counts not published" in found.message


def test_documented_example_with_the_bundled_beliefs() -> None:
    doc = RULES_BY_ID[RULE].doc
    example, use_instead = re.findall(r"```xml\n(.*?)```", doc, re.S)[:2]
    options = LintOptions(package_paths=(), select=frozenset({RULE}),
                          beliefs=load_beliefs("bundled", 1.0))
    assert [d.rule for d in lint_text(example, "example.launch", options).diagnostics] == [RULE]
    assert lint_text(use_instead, "example.launch", options).diagnostics == ()
