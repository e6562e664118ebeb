"""``transforms``: each edge once, with the entry points that publish it (text and JSON)."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from launch_linter.cli import main

PART = ('<launch>\n  <arg name="z" default="0"/>\n'
        '  <node pkg="tf" type="static_transform_publisher" name="laser_tf" '
        'args="0 0 $(arg z) 0 0 0 base_link laser 100"/>\n</launch>\n')


def entry(z: str | None = None) -> str:
    passed = f'<arg name="z" value="{z}"/>' if z is not None else ""
    return f'<launch>\n  <include file="$(dirname)/part.launch">{passed}</include>\n</launch>\n'


@pytest.fixture()
def folder(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    (tmp_path / "part.launch").write_text(PART)
    (tmp_path / "robot.launch").write_text(entry())
    (tmp_path / "sim.launch").write_text(entry())
    (tmp_path / "tall.launch").write_text(entry("1.5"))
    monkeypatch.chdir(tmp_path)
    return tmp_path


def test_each_edge_once_with_its_entry_points(
    folder: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    assert main(["transforms", "."]) == 0
    lines = capsys.readouterr().out.splitlines()
    # robot.launch and sim.launch include part.launch alike: one edge; tall.launch gives
    # it other values: its own edge.
    assert len(lines) == 2, lines
    assert lines[0].startswith("part.launch:3:3: /laser_tf (tf) base_link -> laser t=(0, 0, 0)")
    assert lines[0].endswith("[in robot.launch, sim.launch]")
    assert "t=(0, 0, 1.5)" in lines[1] and lines[1].endswith("[in tall.launch]")
    assert main(["transforms", ".", "--format", "json"]) == 0
    document = json.loads(capsys.readouterr().out)
    assert [t["entry_points"] for t in document["transforms"]] == [
        ["robot.launch", "sim.launch"], ["tall.launch"]]
    assert document["transforms"][0]["root"] == "robot.launch"


def test_one_entry_point_is_not_named(folder: Path, capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["transforms", "robot.launch"]) == 0
    (line,) = capsys.readouterr().out.splitlines()
    assert "[in " not in line
