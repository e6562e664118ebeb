from __future__ import annotations

import tracemalloc
from typing import Callable, List, Tuple

from launch_linter.model import Diagnostic, Location

Lint = Callable[..., List[Tuple[str, int]]]
LintDiagnostics = Callable[..., Tuple[Diagnostic, ...]]

RULE = "int_suffix"


def launch(*nodes: tuple[str, str, str]) -> str:
    lines = [
        f'<node pkg="tf2_ros" type="static_transform_publisher" name="{name}" '
        f'args="0.1 0 0 0 0 0 {parent} {child}"/>'
        for name, parent, child in nodes
    ]
    return "\n".join(["<launch>", *lines, "</launch>"])


def test_study_fig_4b_missing_2(lint_diagnostics: LintDiagnostics) -> None:
    xml = launch(
        ("static_transform_publisher1", "base", "wheel_left"),
        ("static_transform_publisher1", "base", "wheel_right"),
        ("static_transform_publisher3", "base", "wheel_center"),
    )
    (found,) = lint_diagnostics(xml, RULE)
    assert found.line == 4
    assert "static_transform_publisher2" in found.message
    assert found.related == (Location("test.launch", 2, 1),)


def test_frames_are_grouped_separately(lint_diagnostics: LintDiagnostics) -> None:
    xml = launch(("a", "base", "sonar1"), ("b", "base", "sonar3"), ("c", "base", "sonar4"))
    (found,) = lint_diagnostics(xml, RULE)
    assert found.line == 3 and "child frames" in found.message and "sonar2" in found.message


def test_unrelated_stems_are_never_pooled(lint: Lint) -> None:
    # anchors.md (e): PhysFrame pooled cam1, laser3, imu5 and reported 2 and 4 missing.
    xml = launch(("t1", "base", "cam1"), ("t2", "base", "laser3"), ("t3", "base", "imu5"))
    assert lint(xml, RULE) == []


def test_sparse_series_is_not_reported(lint: Lint) -> None:
    # AprilTag ids: 8, 17, 26, 35 leave more numbers out than they hold.
    xml = launch(*[(f"map_tag_{n}", "map", f"tag_{n}") for n in (8, 17, 26, 35)])
    assert lint(xml, RULE) == []


def test_complete_series_passes(lint: Lint) -> None:
    xml = launch(("tf1", "base", "a"), ("tf2", "base", "b"), ("tf3", "base", "c"))
    assert lint(xml, RULE) == []


def test_single_suffix_is_no_series(lint: Lint) -> None:
    xml = launch(("tf1", "base", "a"), ("tf1", "base", "b"))
    assert lint(xml, RULE) == []


def test_zero_padding_is_kept(lint_diagnostics: LintDiagnostics) -> None:
    xml = launch(("a", "base", "cam01"), ("b", "base", "cam03"))
    (found,) = lint_diagnostics(xml, RULE)
    assert "cam02" in found.message


def test_series_is_per_file(lint_tree: Callable[..., tuple[Diagnostic, ...]]) -> None:
    child = launch(("tf3", "base", "b"), ("tf4", "base", "c"))
    root = launch(("tf1", "base", "a")).replace(
        "</launch>", '<include file="$(dirname)/child.launch"/>\n</launch>'
    )
    found = lint_tree({"child.launch": child, "root.launch": root}, "root.launch", RULE)
    assert found == ()


def test_unresolved_member_makes_the_series_unknown(lint: Lint) -> None:
    xml = launch(
        ("tf1", "base", "a"), ("tf$(arg n)", "base", "b"), ("tf3", "base", "c")
    ).replace("<launch>", '<launch>\n<arg name="n"/>')
    assert lint(xml, RULE) == []
    assert lint(xml, RULE, {"n": "5"}) == [(RULE, 5)]


def test_a_huge_gap_is_counted_not_listed(lint: Lint) -> None:
    # Listing the ten million numbers between the two would take hundreds of megabytes:
    # the gap is counted first (and is too wide to be a series).
    xml = launch(("tf_1", "base", "a"), ("tf_10000000", "base", "b"))
    tracemalloc.start()
    try:
        assert lint(xml, RULE) == []
        peak = tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()
    assert peak < 50 * 1024 * 1024


def test_a_suffix_of_thousands_of_digits_is_no_series(lint: Lint) -> None:
    # Python refuses to read an integer of more than 4,300 digits: such a name must not
    # crash the rule, and no numbering of that length is a series anybody wrote.
    long_suffix = "7" * 5000
    xml = launch(("tf_1", "base", "a"), (f"tf_{long_suffix}", "base", "b"),
                 ("tf_2", "base", "c"))
    assert lint(xml, RULE) == []


def test_eighteen_digits_still_make_a_series(lint: Lint) -> None:
    start = 10**17
    xml = launch(*((f"tf_{start + n}", "base", child) for n, child in ((0, "a"), (1, "b"),
                                                                      (3, "c"))))
    assert [rule for rule, _ in lint(xml, RULE)] == [RULE]
