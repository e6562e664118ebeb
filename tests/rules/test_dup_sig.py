from __future__ import annotations

from pathlib import Path
from typing import Callable, List, Tuple

from launch_linter import LintOptions, lint_paths
from launch_linter.model import Diagnostic, Location

Lint = Callable[..., List[Tuple[str, int]]]
LintDiagnostics = Callable[..., Tuple[Diagnostic, ...]]
LintTree = Callable[..., Tuple[Diagnostic, ...]]

RULE = "dup_sig"


def node(name: str, args: str, attrs: str = "", pkg: str = "tf2_ros") -> str:
    return (
        f'<node pkg="{pkg}" type="static_transform_publisher" name="{name}" '
        f'args="{args}" {attrs}/>'
    )


def test_same_pair_twice(lint_diagnostics: LintDiagnostics) -> None:
    xml = "\n".join([
        "<launch>",
        node("a", "0 0 0 0 0 0 base_link laser"),
        node("b", "0 0 1 0 0 0 base_link laser"),
        "</launch>",
    ])
    (found,) = lint_diagnostics(xml, RULE)
    assert found.line == 3 and found.node == "b"
    assert found.related == (Location("test.launch", 2, 1),)
    assert "different values" in found.message


def test_identical_copy_is_called_redundant(lint_diagnostics: LintDiagnostics) -> None:
    xml = "\n".join([
        "<launch>",
        node("a", "0 0 0 0 0 0 base_link laser"),
        node("b", "0 0 0 0 0 0 base_link laser"),
        "</launch>",
    ])
    (found,) = lint_diagnostics(xml, RULE)
    assert "redundant" in found.message


def test_slash_normalised_pairs_are_the_same(lint: Lint) -> None:
    # anchors.md (e): PhysFrame did not see /base_link and base_link as one frame.
    xml = "\n".join([
        "<launch>",
        node("a", "0 0 0 0 0 0 /base_link laser3"),
        node("b", "0 0 0 0 0 0 base_link laser3"),
        "</launch>",
    ])
    assert lint(xml, RULE) == [(RULE, 3)]


def test_namespaces_do_not_rename_frames(lint: Lint) -> None:
    xml = "\n".join([
        "<launch>",
        '<group ns="r1">', node("tf", "0 0 0 0 0 0 base laser"), "</group>",
        '<group ns="r2">', node("tf", "0 0 0 0 0 0 base laser"), "</group>",
        "</launch>",
    ])
    assert lint(xml, RULE) == [(RULE, 6)]


def test_reversed_pair_is_not_a_duplicate(lint: Lint) -> None:
    xml = "\n".join([
        "<launch>",
        node("a", "0 0 0 0 0 0 map odom"),
        node("b", "0 0 0 0 0 0 odom map"),
        "</launch>",
    ])
    assert lint(xml, RULE) == []


def test_exclusive_conditions_are_not_duplicates(lint: Lint) -> None:
    xml = "\n".join([
        "<launch>",
        '<arg name="sim"/>',
        '<group if="$(arg sim)">', node("a", "0 0 0 0 0 0 map odom"), "</group>",
        '<group unless="$(arg sim)">', node("b", "0 0 1 0 0 0 map odom"), "</group>",
        "</launch>",
    ])
    assert lint(xml, RULE) == []
    assert lint(xml, RULE, {"sim": "true"}) == []


def test_unresolved_frame_is_silent(lint: Lint) -> None:
    xml = "\n".join([
        "<launch>",
        '<arg name="child"/>',
        node("a", "0 0 0 0 0 0 map odom"),
        node("b", "0 0 0 0 0 0 map $(arg child)"),
        "</launch>",
    ])
    assert lint(xml, RULE) == []
    assert lint(xml, RULE, {"child": "odom"}) == [(RULE, 4)]


def test_per_file_only(lint_tree: LintTree) -> None:
    child = "<launch>\n" + node("b", "0 0 0 0 0 0 base laser") + "\n</launch>\n"
    root = "\n".join([
        "<launch>",
        node("a", "0 0 0 0 0 0 base laser"),
        '<include file="$(dirname)/child.launch"/>',
        "</launch>",
    ])
    assert lint_tree({"child.launch": child, "root.launch": root}, "root.launch", RULE) == ()


def test_file_included_twice_is_not_its_own_duplicate(lint_tree: LintTree) -> None:
    child = "<launch>\n" + node("b", "0 0 0 0 0 0 base laser") + "\n</launch>\n"
    root = "\n".join([
        "<launch>",
        '<include file="$(dirname)/child.launch" ns="r1"/>',
        '<include file="$(dirname)/child.launch" ns="r2"/>',
        "</launch>",
    ])
    assert lint_tree({"child.launch": child, "root.launch": root}, "root.launch", RULE) == ()


def test_study_fig_4c(lint_diagnostics: LintDiagnostics) -> None:
    # Fig. 4(c): the same camera transform (and name) three times.
    xml = "\n".join([
        "<launch>",
        node("map_to_odom", "0.0 0.0 0.0 0.0 0.0 0.0 /map /base_footprint 10", pkg="tf"),
        node("base_footprint_2_base_link", "0.0 0.0 0.0 0.0 0.0 0.0 /base_footprint/base_link 10",
             pkg="tf"),
        node("base_link_2_oamera_link", "0.0 0.0 0.0 0.0 0.0 0.0 /base_link /camera_link 10",
             pkg="tf"),
        node("base_link_2_oamera_link", "0.0 0.0 0.0 0.0 0.0 0.0 /base_link /camera_link 10",
             pkg="tf"),
        node("base_link_2_oamera_link", "0.0 0.0 0.0 0.0 0.0 0.0 /base_link /camera_link 10",
             pkg="tf"),
        "</launch>",
    ])
    found = lint_diagnostics(xml, RULE)
    assert [d.line for d in found] == [5, 6]
    assert all(d.related == (Location("test.launch", 4, 1),) for d in found)


def test_reported_once_when_the_file_is_also_included(tmp_path: Path) -> None:
    child = "\n".join([
        "<launch>", node("a", "0 0 0 0 0 0 base laser"), node("b", "0 0 1 0 0 0 base laser"),
        "</launch>",
    ])
    (tmp_path / "child.launch").write_text(child, encoding="utf-8")
    (tmp_path / "root.launch").write_text(
        '<launch>\n<include file="$(dirname)/child.launch"/>\n</launch>\n', encoding="utf-8"
    )
    options = LintOptions(package_paths=(), select=frozenset({RULE}))
    found = lint_paths([str(tmp_path)], options).diagnostics
    assert [(d.path.endswith("child.launch"), d.line) for d in found] == [(True, 3)]
