"""``transforms`` and ``graph`` show the edges nodes publish and the frames they look up."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from launch_linter.cli import main
from launch_linter.engine import LintOptions, lint_paths
from launch_linter.graph.model import build_graph
from launch_linter.graph.render import to_dot

LAUNCH = ('<launch>\n<node pkg="amcl" type="amcl" name="amcl">'
          '<param name="base_frame_id" value="base_footprint"/></node>\n</launch>\n')


def test_transforms_lists_node_edges_and_consumers(tmp_path: Path,
                                                   capsys: pytest.CaptureFixture[str]) -> None:
    path = tmp_path / "a.launch"
    path.write_text(LAUNCH)
    main(["transforms", "--format", "json", str(path)])
    document = json.loads(capsys.readouterr().out)
    (edge,) = document["node_edges"]
    assert (edge["parent"], edge["child"], edge["role"], edge["line"]) == (
        "map", "odom", "localization", 2)
    assert edge["source"] == "node" and edge["knowledge"] == "amcl"
    frames = {(c["frame"], c["parameter"]) for c in document["frame_consumers"]}
    assert frames == {("odom", "odom_frame_id"), ("base_footprint", "base_frame_id")}
    main(["transforms", str(path)])
    out = capsys.readouterr().out
    assert f"{path}:2:1: node amcl/amcl map -> odom  [localization]" in out


def test_graph_draws_node_edges_dashed_and_labelled(tmp_path: Path) -> None:
    path = tmp_path / "a.launch"
    path.write_text(LAUNCH)
    graph = build_graph(lint_paths([str(path)], LintOptions(package_paths=())))
    (edge,) = [e for e in graph.edges if e.source == "node"]
    assert edge.dynamic and edge.label[0] == "node amcl/amcl"
    assert "1 node-published edge" in graph.title
    assert "node amcl/amcl" in to_dot(graph)


def test_transforms_text_keeps_a_frames_controls_inert(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    # A frame parameter is a launch file's words: a newline or a terminal escape in it
    # must not start a forged line or reach the terminal.
    path = tmp_path / "a.launch"
    path.write_text('<launch>\n<node pkg="amcl" type="amcl" name="amcl">'
                    '<param name="base_frame_id" value="base&#10;x:1:1: \x85\u202e"/>'
                    '</node>\n</launch>\n')
    main(["transforms", str(path)])
    lines = capsys.readouterr().out.splitlines()
    (lookup,) = [line for line in lines if "(parameter base_frame_id)" in line]
    assert "\\x0a" in lookup and "\x85" not in lookup and "\u202e" not in lookup
    assert not any(line.startswith("x:1:1:") for line in lines)
