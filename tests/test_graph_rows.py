"""``graph`` of a folder with many distinct trees (a manipulator with many variants:
ros2_kortex gave ten clusters side by side, 9,675 x 2,575 pixels): the clusters are dealt
into rows, the deepest together, so that the picture has about a screen's shape."""

from __future__ import annotations

from pathlib import Path

import pytest

from launch_linter.engine import LintOptions, lint_paths
from launch_linter.graph.model import build_graph
from launch_linter.graph.render import cluster_rows, rankdir, to_dot

NODE = ('  <node pkg="tf" type="static_transform_publisher" name="{name}" '
        'args="0 0 0.1 0 0 0 {parent} {child} 100"/>\n')


def _chains(folder: Path, count: int, depth: int) -> None:
    for tree in range(count):
        nodes = "".join(NODE.format(name=f"n{tree}_{i}", parent=f"t{tree}_{i}",
                                    child=f"t{tree}_{i + 1}") for i in range(depth))
        (folder / f"variant{tree}.launch").write_text(f"<launch>\n{nodes}</launch>\n")


def test_many_deep_trees_are_laid_in_rows(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    _chains(tmp_path, 24, 6)
    monkeypatch.chdir(tmp_path)
    graph = build_graph(lint_paths(["."], LintOptions()))
    assert len(graph.clusters) == 24
    direction = rankdir(graph)
    rows = cluster_rows(graph, direction)
    assert len(rows) > 1 and sorted(i for row in rows for i in row) == list(range(24))
    dot = to_dot(graph)
    assert f"rankdir={direction}" in dot
    # One invisible edge to the root of every cluster after the first row.
    assert dot.count("[style=invis, weight=0];") == sum(len(row) for row in rows[1:])


def test_the_deepest_trees_share_a_row(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    _chains(tmp_path, 4, 2)
    (tmp_path / "deep.launch").write_text("<launch>\n" + "".join(
        NODE.format(name=f"d{i}", parent=f"d{i}", child=f"d{i + 1}") for i in range(14))
        + "</launch>\n")
    (tmp_path / "deep2.launch").write_text("<launch>\n" + "".join(
        NODE.format(name=f"e{i}", parent=f"e{i}", child=f"e{i + 1}") for i in range(14))
        + "</launch>\n")
    monkeypatch.chdir(tmp_path)
    graph = build_graph(lint_paths(["."], LintOptions()))
    titles = graph.clusters
    rows = cluster_rows(graph, rankdir(graph))
    first = [titles[i].split(":")[0] for i in rows[0]]
    assert first[:2] == ["deep.launch", "deep2.launch"]


def test_a_few_trees_stay_side_by_side(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    _chains(tmp_path, 3, 3)
    monkeypatch.chdir(tmp_path)
    graph = build_graph(lint_paths(["."], LintOptions()))
    assert len(cluster_rows(graph, rankdir(graph))) == 1
    assert "style=invis" not in to_dot(graph)
