from __future__ import annotations

import json
from pathlib import Path

import pytest
from corpus_helpers import MakeCorpus, launch, node

from launch_linter.beliefs_files import load_beliefs
from launch_linter.cli import main
from launch_linter.mining.stats import z_score


def corpus_rows(files: int) -> list[dict[str, object]]:
    """``files`` files that all publish map→odom (null) with base_link→laser, plus one
    file where base_link→laser stands alone with a rotation."""
    rows: list[dict[str, object]] = [
        {"repo": f"o/r{i}", "path": "tf.launch", "text": launch(
            node(f"mo{i}", "0 0 0 0 0 0 map odom 100"),
            node("base_to_laser", f"0.{i + 1} 0 0 0 0 0 base_link laser 100"),
        )}
        for i in range(files)
    ]
    rows.append({"repo": "o/alone", "path": "tf.launch", "text": launch(
        node("base_to_laser", "0 0 0 1 0 0 base_link laser 100"))})
    return rows


@pytest.fixture
def db(make_corpus: MakeCorpus, tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> Path:
    root = make_corpus(corpus_rows(12))
    path = tmp_path / "c.db"
    assert main(["mine", str(root), "--db", str(path), "--jobs", "1"]) == 0
    out = capsys.readouterr().out
    assert "ingested 13 new of 13 files" in out and "0 parse failures" in out
    return path


def test_mine_twice_reports_nothing_new(db: Path, make_corpus: MakeCorpus,
                                        capsys: pytest.CaptureFixture[str]) -> None:
    root = db.parent / "corpus"
    assert main(["mine", str(root), "--db", str(db)]) == 0
    assert "ingested 0 new of 13 files" in capsys.readouterr().out


def test_beliefs_table(db: Path, capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["beliefs", "--db", str(db), "--min-z", "1", "--class", "sig_implication"]) == 0
    lines = capsys.readouterr().out.splitlines()
    assert lines[0].split() == ["class", "z", "n", "e", "if", "then"]
    # map→odom is in 12 files, always with base_link→laser: z(12, 12) = 1.15.
    # base_link→laser is in 13 files, 12 with map→odom: z(13, 12) = 0.2, below the bar.
    assert [line.split() for line in lines[1:]] == [
        ["sig_implication", "1.15", "12", "12", '["map","odom"]', '["base_link","laser"]'],
    ]


def test_beliefs_json_and_file(
    db: Path, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    assert main(["beliefs", "--db", str(db), "--format", "json"]) == 0
    document = json.loads(capsys.readouterr().out)
    assert document["format"] == "launch-linter-beliefs/1" and document["p0"] == 0.9
    assert document["mature_commits"] == 30
    assert document["source"]["files"] == 13 and document["source"]["transforms"] == 25
    rot = next(b for b in document["beliefs"]
               if b["class"] == "sig_null_rot" and b["if"] == ["base_link", "laser"])
    assert (rot["n"], rot["e"], rot["z"]) == (13, 12, round(z_score(13, 12), 4))
    assert "then" not in rot
    out = tmp_path / "beliefs.json"
    assert main(["beliefs", "--db", str(db), "--min-z", "1", "-o", str(out)]) == 0
    assert "wrote" in capsys.readouterr().err
    loaded = load_beliefs(str(out), 1.0)
    # map→odom (12 of 12 files, 12 of 12 null transforms) passes; base_to_laser's 12 of 13
    # null rotations (z = 0.2) do not.
    assert sorted((b.cls, b.antecedent, b.consequent) for b in loaded.beliefs) == [
        ("sig_implication", ("map", "odom"), ("base_link", "laser")),
        ("sig_null_disp", ("map", "odom"), None),
        ("sig_null_rot", ("map", "odom"), None),
    ]


def test_mined_beliefs_drive_check(db: Path, tmp_path: Path,
                                   capsys: pytest.CaptureFixture[str]) -> None:
    beliefs = tmp_path / "beliefs.json"
    assert main(["beliefs", "--db", str(db), "-o", str(beliefs)]) == 0
    target = tmp_path / "robot.launch"
    target.write_text(launch(node("mo", "1 0 0 0 0 0 map odom 100")))
    # These beliefs have z < 2: reported at info by default, so fail on info.
    status = main(["check", str(target), "--beliefs", str(beliefs), "--format", "json",
                   "--select", "may_implied", "--fail-on", "info"])
    document = json.loads(capsys.readouterr().out)
    assert status == 1
    found = {(d["rule"], json.dumps(d["belief"]["if"])) for d in document["diagnostics"]}
    assert found == {("sig_implication", '["map", "odom"]'), ("sig_null_disp", '["map", "odom"]')}
    implication = next(d for d in document["diagnostics"] if d["rule"] == "sig_implication")
    assert implication["belief"] == {"class": "sig_implication", "if": ["map", "odom"],
                                     "then": ["base_link", "laser"], "n": 12, "e": 12,
                                     "z": round(z_score(12, 12), 4)}
    assert "n=12, e=12, z=1.15" in implication["message"]


@pytest.mark.parametrize(
    ("argv", "message"),
    [
        (["beliefs", "--class", "nope"], "unknown belief class"),
        (["beliefs", "--db", "MISSING"], "no such database"),
        (["mine", "CORPUS", "--p0", "1.5"], "p0 must be"),
        (["mine", "CORPUS", "--mature-commits", "-1"], "must not be negative"),
        (["mine", "MISSING", "--db", "x.db"], "does not exist"),
    ],
)
def test_usage_errors(argv: list[str], message: str, db: Path, tmp_path: Path,
                      capsys: pytest.CaptureFixture[str]) -> None:
    argv = [str(db.parent / "corpus") if a == "CORPUS" else
            str(tmp_path / "missing") if a == "MISSING" else a for a in argv]
    if "--db" not in argv:
        argv += ["--db", str(db)]
    assert main(argv) == 2
    assert message in capsys.readouterr().err


def test_beliefs_before_mining_is_an_error(tmp_path: Path,
                                           capsys: pytest.CaptureFixture[str]) -> None:
    empty = tmp_path / "empty.db"
    from launch_linter.mining.store import Store

    Store(str(empty)).close()
    assert main(["beliefs", "--db", str(empty)]) == 2
    assert "nothing mined" in capsys.readouterr().err
