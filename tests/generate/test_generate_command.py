"""``launch-linter generate``: options, errors, and a reproducible file."""

from __future__ import annotations

import json
import os
from pathlib import Path

import pytest
from standalone_helpers import BELIEFS, Generated

from launch_linter.beliefs_files import load_beliefs
from launch_linter.cli import main
from launch_linter.model.beliefs import BELIEF_CLASSES


def _read(path: Path) -> Generated:
    return Generated(path, path.read_text(encoding="utf-8"), "", 0.0)


def test_generate_writes_an_executable_file_and_says_so(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    out = tmp_path / "lint.py"
    assert main(["generate", "-o", str(out)]) == 0
    assert os.access(out, os.X_OK)
    assert f"wrote {out}:" in capsys.readouterr().err
    generated = _read(out).assigned("GENERATED")
    assert generated["beliefs"] == "bundled" and generated["min_z"] == 1.0
    assert generated["beliefs_count"] == len(load_beliefs("bundled", 1.0).beliefs)
    assert generated["command"] == "launch-linter generate --beliefs bundled --min-z 1.0"


def test_the_file_does_not_depend_on_its_name_or_the_time(tmp_path: Path) -> None:
    first, second = tmp_path / "a.py", tmp_path / "b.py"
    assert main(["generate", "--beliefs", "study", "--min-z", "2", "-o", str(first)]) == 0
    assert main(["generate", "--beliefs", "study", "--min-z", "2", "-o", str(second)]) == 0
    assert first.read_bytes() == second.read_bytes()


def test_classes_choose_the_tables_that_are_filled(tmp_path: Path, beliefs_file: Path) -> None:
    out = tmp_path / "lint.py"
    args = ["generate", "--beliefs", str(beliefs_file), "--min-z", "0", "-o", str(out)]
    assert main([*args, "--class", "name_null_rot", "--class", "sig_implication"]) == 0
    generated = _read(out)
    header = generated.assigned("GENERATED")
    assert header["classes"] == ("sig_implication", "name_null_rot")
    assert header["command"].endswith("--class sig_implication --class name_null_rot")
    for cls in BELIEF_CLASSES:
        rows = generated.assigned(cls.upper())
        expected = [b for b in BELIEFS["beliefs"] if b["class"] == cls]
        assert len(rows) == (len(expected) if header["classes"].count(cls) else 0), cls
    assert "# Not selected when generating (--class), so empty." in generated.text


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (["--class", "sig_implication,nonsense"], "unknown belief class(es): nonsense"),
        (["--beliefs", "/no/such/file.json"], "cannot read beliefs file"),
        (["--min-z", "nan"], "--min-z must be a number"),
    ],
)
def test_mistakes_exit_2(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], args: list[str], message: str
) -> None:
    out = tmp_path / "lint.py"
    assert main(["generate", *args, "-o", str(out)]) == 2
    assert message in capsys.readouterr().err
    assert not out.exists()


def test_an_unwritable_output_exits_2(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["generate", "-o", str(tmp_path / "no" / "such" / "dir.py")]) == 2
    assert "cannot write" in capsys.readouterr().err


def test_a_malformed_beliefs_file_exits_2(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    bad = tmp_path / "bad.json"
    bad.write_text(json.dumps({"format": "something else"}), encoding="utf-8")
    assert main(["generate", "--beliefs", str(bad), "-o", str(tmp_path / "x.py")]) == 2
    assert "launch-linter-beliefs/1" in capsys.readouterr().err
