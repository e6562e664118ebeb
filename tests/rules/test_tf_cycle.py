from __future__ import annotations

from typing import Callable, List, Tuple

from hypothesis import given, settings
from hypothesis import strategies as st

from launch_linter import LintOptions, lint_text
from launch_linter.model import Diagnostic

Lint = Callable[..., List[Tuple[str, int]]]
LintDiagnostics = Callable[..., Tuple[Diagnostic, ...]]
LintTree = Callable[..., Tuple[Diagnostic, ...]]

RULE = "tf_cycle"


def run_rule(xml: str, rule: str) -> tuple[Diagnostic, ...]:
    options = LintOptions(package_paths=(), select=frozenset({rule}))
    return lint_text(xml, "test.launch", options).diagnostics


def node(name: str, parent: str, child: str, attrs: str = "") -> str:
    return (
        f'<node pkg="tf2_ros" type="static_transform_publisher" name="{name}" '
        f'args="0 0 0 0 0 0 {parent} {child}" {attrs}/>'
    )


def launch(*nodes: str, args: str = "") -> str:
    return "\n".join(["<launch>", *([args] if args else []), *nodes, "</launch>"])


def test_two_frame_loop(lint_diagnostics: LintDiagnostics) -> None:
    (found,) = lint_diagnostics(launch(node("a", "map", "odom"), node("b", "/odom", "map")), RULE)
    assert found.line == 3 and [r.line for r in found.related] == [2]
    assert "map -> odom -> map" in found.message and "may" not in found.message


def test_longer_loop_reported_once_at_the_closing_transform(
    lint_diagnostics: LintDiagnostics,
) -> None:
    xml = launch(
        node("a", "a", "b"), node("c", "c", "a"), node("x", "base", "laser"), node("b", "b", "c")
    )
    (found,) = lint_diagnostics(xml, RULE)
    assert found.line == 5
    assert sorted(r.line for r in found.related) == [2, 3]
    assert "a -> b -> c -> a" in found.message


def test_two_separate_loops(lint: Lint) -> None:
    xml = launch(node("a", "a", "b"), node("b", "b", "a"), node("c", "c", "d"), node("d", "d", "c"))
    assert lint(xml, RULE) == [(RULE, 3), (RULE, 5)]


def test_tree_passes(lint: Lint) -> None:
    xml = launch(node("a", "map", "odom"), node("b", "odom", "base"), node("c", "map", "gps"))
    assert lint(xml, RULE) == []


def test_diamond_is_not_a_loop(lint: Lint) -> None:
    # Two parents for d (multiple_parents' business), but no loop.
    xml = launch(node("a", "a", "b"), node("b", "a", "c"), node("c", "b", "d"), node("d", "c", "d"))
    assert lint(xml, RULE) == []


def test_self_transform_is_not_a_loop(lint: Lint) -> None:
    assert lint(launch(node("a", "map", "map")), RULE) == []


def test_conditional_loop_says_may(lint_diagnostics: LintDiagnostics) -> None:
    xml = launch(
        node("a", "map", "odom"), node("b", "odom", "map", 'if="$(arg x)"'),
        args='<arg name="x"/>',
    )
    (found,) = lint_diagnostics(xml, RULE)
    assert "may form a loop" in found.message


def test_exclusive_conditions_break_the_loop(lint: Lint) -> None:
    xml = launch(
        node("a", "map", "odom", 'unless="$(arg x)"'), node("b", "odom", "map", 'if="$(arg x)"'),
        args='<arg name="x"/>',
    )
    assert lint(xml, RULE) == []


def test_a_compatible_alternative_edge_still_closes_the_loop(lint: Lint) -> None:
    xml = launch(
        node("a", "map", "odom", 'unless="$(arg x)"'),
        node("b", "odom", "map", 'if="$(arg x)"'),
        node("c", "odom", "map"),
        args='<arg name="x"/>',
    )
    assert lint(xml, RULE) == [(RULE, 5)]


def test_across_includes(lint_tree: LintTree) -> None:
    child = launch(node("b", "odom", "map"))
    root = launch(node("a", "map", "odom"), '<include file="$(dirname)/child.launch"/>')
    (found,) = lint_tree({"child.launch": child, "root.launch": root}, "root.launch", RULE)
    assert found.path.endswith("child.launch")
    assert found.related[0].path.endswith("root.launch")


def test_dense_graph_stays_bounded(lint: Lint) -> None:
    frames = [f"f{i}" for i in range(12)]
    nodes = [node(f"{a}_{b}", a, b) for a in frames for b in frames if a != b]
    found = lint(launch(*nodes), RULE)
    assert 0 < len(found) <= 100


def _has_cycle(edges: set[tuple[int, int]]) -> bool:
    """Reference: repeatedly drop frames without a parent; a loop is what remains."""
    remaining = set(edges)
    while True:
        children = {c for _, c in remaining}
        roots = {p for p, _ in remaining} - children
        if not roots:
            return bool(remaining)
        remaining = {(p, c) for p, c in remaining if p not in roots}


@settings(max_examples=60, deadline=None)
@given(st.sets(st.tuples(st.integers(0, 5), st.integers(0, 5)).filter(lambda e: e[0] != e[1]),
               max_size=10))
def test_reports_a_loop_exactly_when_there_is_one(edges: set[tuple[int, int]]) -> None:
    xml = launch(*(node(f"t{p}_{c}", f"f{p}", f"f{c}") for p, c in sorted(edges)))
    found = run_rule(xml, RULE)
    assert bool(found) == _has_cycle(edges)
    assert all(len(d.related) >= 1 for d in found)


LONG = 5_000


def test_a_long_chain_has_no_loop_and_no_recursion_error(lint: Lint) -> None:
    xml = launch(*(node(f"t{i}", f"f{i}", f"f{i + 1}") for i in range(LONG)))
    assert lint(xml, RULE) == []


def test_a_long_loop_is_one_finding_with_a_bounded_message(
    lint_diagnostics: LintDiagnostics,
) -> None:
    xml = launch(*(node(f"t{i}", f"f{i}", f"f{(i + 1) % LONG}") for i in range(LONG)))
    (found,) = lint_diagnostics(xml, RULE)
    assert found.line == LONG + 1 and len(found.related) == 10
    assert f"f0 -> f1 -> f2 -> f3 -> f4 -> and {LONG - 4} more (with line 2" in found.message
    assert f"and {LONG - 6} more)" in found.message and len(found.message) < 400


def test_loops_of_later_frames_of_a_closed_chain_are_found(lint: Lint) -> None:
    # f0 closes the long loop; f2 <-> f3 is a loop of its own among the later frames.
    nodes = [node(f"t{i}", f"f{i}", f"f{(i + 1) % 50}") for i in range(50)]
    nodes.append(node("back", "f3", "f2"))
    assert lint(launch(*nodes), RULE) == [(RULE, 51), (RULE, 52)]


def test_a_conditional_transform_in_a_long_loop(lint_diagnostics: LintDiagnostics) -> None:
    nodes = [node(f"t{i}", f"f{i}", f"f{i + 1}") for i in range(LONG - 1)]
    nodes.append(node("close", f"f{LONG - 1}", "f0", 'if="$(arg x)"'))
    (found,) = lint_diagnostics(launch(*nodes, args='<arg name="x"/>'), RULE)
    assert "may form a loop" in found.message


def test_many_two_frame_loops_in_one_component_stay_bounded(lint: Lint) -> None:
    # A ladder f0 <-> f1 <-> f2 ...: one strongly connected component with many loops.
    nodes = [n for i in range(300)
             for n in (node(f"u{i}", f"f{i}", f"f{i + 1}"), node(f"d{i}", f"f{i + 1}", f"f{i}"))]
    found = lint(launch(*nodes), RULE)
    assert len(found) == 100
