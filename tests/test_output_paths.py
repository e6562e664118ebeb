"""Paths in every format: relative to the current folder when the file is under it,
absolute otherwise, however the path was given."""

from __future__ import annotations

import json
import os
from pathlib import Path

import pytest

from launch_linter.cli import main
from launch_linter.model.paths import shown_path

ROBOT = ('<launch>\n  <include file="$(dirname)/part.launch"/>\n</launch>\n')
PART = ('<launch>\n  <node pkg="tf" type="static_transform_publisher" name="a" '
        'args="0 0 0 0 0 0 /a b 100"/>\n</launch>\n')


def test_shown_path(tmp_path: Path) -> None:
    inside = tmp_path / "pkg" / "a.launch"
    assert shown_path(str(inside), str(tmp_path)) == os.path.join("pkg", "a.launch")
    assert shown_path(str(tmp_path / "pkg" / ".." / "b"), str(tmp_path)) == "b"
    assert shown_path(str(tmp_path.parent / "x"), str(tmp_path)) == str(tmp_path.parent / "x")


@pytest.fixture()
def project(tmp_path: Path) -> Path:
    (tmp_path / "pkg" / "launch").mkdir(parents=True)
    (tmp_path / "pkg" / "launch" / "robot.launch").write_text(ROBOT)
    (tmp_path / "pkg" / "launch" / "part.launch").write_text(PART)
    return tmp_path


def _paths(capsys: pytest.CaptureFixture[str], argv: list[str]) -> set[str]:
    main(["check", *argv, "--format", "json", "--exit-zero", "--fail-on", "info"])
    document = json.loads(capsys.readouterr().out)
    return {d["path"] for d in document["diagnostics"]} | {f["path"] for f in document["files"]}


def test_same_paths_however_the_folder_is_named(
    project: Path, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.chdir(project / "pkg")
    expected = {os.path.join("launch", "robot.launch"), os.path.join("launch", "part.launch")}
    assert _paths(capsys, ["."]) == expected
    assert _paths(capsys, [str(project / "pkg")]) == expected
    assert _paths(capsys, ["../pkg/launch"]) == expected
    # Run from a subfolder: the files above it are shown absolute, never "../".
    monkeypatch.chdir(project / "pkg" / "launch")
    assert _paths(capsys, [".."]) == {"robot.launch", "part.launch"}
    monkeypatch.chdir(project / "pkg" / "launch")
    outside = project / "other"
    outside.mkdir()
    (outside / "o.launch").write_text(PART)
    assert _paths(capsys, ["../../other"]) == {str(outside / "o.launch")}
    main(["check", "../../other", "--exit-zero"])
    assert capsys.readouterr().out.startswith(f"{outside / 'o.launch'}:2:3: info:")
