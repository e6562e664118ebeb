from __future__ import annotations

import csv
import importlib.util
import shutil
from pathlib import Path
from typing import TYPE_CHECKING, Any

import pytest
from evaluation_helpers import launch, node

from launch_linter.cli import main
from launch_linter.evaluation import chart
from launch_linter.evaluation import evaluate as evaluate_module
from launch_linter.evaluation.evaluate import EvaluationError, evaluate
from launch_linter.evaluation.history import FIXED, PERSISTING
from launch_linter.evaluation.table import CSV_COLUMNS, TOTAL_STUDY_RULES
from launch_linter.evaluation.thresholds import render_thresholds

if TYPE_CHECKING:  # the folder's conftest (tests/conftest.py is ``conftest`` too at run time)
    from conftest import MakeDb

MAP_ODOM = node("map_to_odom", "0 0 0 0 0 0 map odom 100")
MAP_ODOM_ROTATED = node("map_to_odom", "0 0 0 0.5 0 0 map odom 100")
LASER = node("laser_tf", "0.1 0 0.2 0 0 0 base_link laser 100")
CAMERA_DEGREES = node("cam_tf", "0.1 0 0.2 90 0 0 base_link camera 100")
CAMERA = node("cam_tf", "0.1 0 0.2 1.57 0 0 base_link camera 100")
LASER_SLASH = node("laser_tf", "0.1 0 0.2 0 0 0 /base_link laser 100")
SELF = node("self_tf", "0 0 0 0 0 0 base_link base_link 100")
IMU = node("imu_tf", "0 0 0.1 0 0 0 base_link imu_link 100")


def corpus_rows() -> list[dict[str, Any]]:
    # three distinct contents (the miner counts each content once) that agree on map_to_odom
    mature = [
        {"repo": f"m/{name}", "path": "launch/tf.launch",
         "text": launch(MAP_ODOM, LASER, node(f"{name}_tf", f"0 0 0 0 0 0 {name} x 100"))}
        for name in ("one", "two", "three")
    ]
    return [
        *mature,
        # a fault in a mature repository is not evaluated, but its history is followed
        {"repo": "m/one", "path": "launch/old.launch", "text": launch(MAP_ODOM, LASER_SLASH),
         "commit": "c0", "latest": False, "head_paths": ["launch/tf.launch"]},
        {"repo": "m/four", "path": "launch/x.launch", "text": launch(SELF)},
        # immature: one file with three faults, one version earlier with a rot_degrees
        # fault fixed since; one file with one fault; one clean file
        {"repo": "i/one", "path": "launch/a.launch", "commits": 5,
         "text": launch(MAP_ODOM_ROTATED, SELF, CAMERA)},
        {"repo": "i/one", "path": "launch/a.launch", "commits": 5, "commit": "c0",
         "latest": False, "text": launch(MAP_ODOM_ROTATED, SELF, CAMERA_DEGREES)},
        {"repo": "i/two", "path": "launch/b.launch", "commits": 5, "text": launch(SELF, IMU)},
        {"repo": "i/three", "path": "launch/c.launch", "commits": 5, "text": launch(IMU)},
    ]


def test_table_counts_on_a_mined_database(make_db: MakeDb) -> None:
    _, db = make_db(corpus_rows())
    evaluation = evaluate(str(db), 1.0)
    table = evaluation.table
    rows = {row.rule: row for row in table.fault_rows}
    assert table.files == 3 and table.repos == 3
    assert (rows["self_transform"].faults, rows["self_transform"].files) == (2, 2)
    assert rows["name_null_rot"].files == 1 and rows["sig_null_rot"].files == 1
    assert rows["rot_degrees"].files == 0  # fixed in the latest version
    # i/one has map_to_odom without laser_tf, which the mature files always have with it
    assert rows["name_implication"].files == 1 and rows["sig_implication"].files == 1
    assert rows[TOTAL_STUDY_RULES].faults == 6
    assert rows[TOTAL_STUDY_RULES].files == 2  # not the 6 of the rows' sum
    assert evaluation.scope.immature_repos == 3
    assert {b.cls for b in evaluation.scope.beliefs.beliefs} >= {"name_null_rot", "sig_null_rot"}


def test_history_counts_fixed_and_persisting(make_db: MakeDb) -> None:
    _, db = make_db(corpus_rows())
    history = evaluate(str(db), 1.0).history
    assert history.rules["rot_degrees"].outcomes[FIXED] == 1
    assert history.rules["rot_degrees"].immature[FIXED] == 1
    assert history.rules["self_transform"].outcomes[PERSISTING] == 1
    assert history.rules["name_null_rot"].outcomes[PERSISTING] == 1
    # the renamed file of a mature repository is followed to its HEAD path
    assert history.rules["leading_slash"].outcomes[FIXED] == 1
    assert history.rules["leading_slash"].immature[FIXED] == 0
    assert history.earlier_versions == 2


def test_threshold_moves_only_the_belief_rules(make_db: MakeDb) -> None:
    _, db = make_db(corpus_rows())
    low, high = evaluate(str(db), 1.0), evaluate(str(db), 5.0)
    rows_low = {r.rule: r for r in low.table.fault_rows}
    rows_high = {r.rule: r for r in high.table.fault_rows}
    assert rows_high["name_null_rot"].faults == 0 and len(high.scope.beliefs.beliefs) == 0
    assert rows_high["self_transform"] == rows_low["self_transform"]
    text = render_thresholds([low, high])
    assert "| name_null_rot | 1 / 1 (33.33%) | 0 / 0 (0.00%) | 65 / 61 (0.72%) |" in text
    assert "| name_null_rot | 0 / 1 | 0 / 0 |" in text  # history: fixed / persisting
    # p0 = 0.5: z(n, n) = sqrt(n), so z >= 5 needs 25 agreeing cases; these have 3
    assert "(1 for z ≥ 1, 25 for z ≥ 5)" in text and "has z = 1.73" in text


def test_command_writes_every_output(make_db: MakeDb, tmp_path: Path,
                                     capsys: pytest.CaptureFixture[str]) -> None:
    pytest.importorskip("matplotlib", reason="the chart needs the plot extra")
    _, db = make_db(corpus_rows())
    out = tmp_path / "out"
    assert main(["evaluate", "--db", str(db), "--out", str(out)]) == 0
    assert sorted(p.name for p in out.iterdir()) == [
        "history.md", "rules.png", "table.csv", "table.md"
    ]
    assert (out / "rules.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    with open(out / "table.csv", encoding="utf-8", newline="") as handle:
        rows = list(csv.DictReader(handle))
    assert tuple(rows[0]) == CSV_COLUMNS
    self_row = next(r for r in rows if r["rule"] == "self_transform")
    assert (self_row["faults"], self_row["files"], self_row["percent_files"]) == ("2", "2", "66.67")
    history = (out / "history.md").read_text(encoding="utf-8")
    assert "| rot_degrees | 1 | 1 | 1 | 0 | 0 | 100% | 1 | 1 | 0 |" in history
    assert "2 files (66.7%) with a fault" in capsys.readouterr().out


def test_without_matplotlib_everything_but_the_chart_is_written_and_one_line_says_why(
    make_db: MakeDb, tmp_path: Path, capsys: pytest.CaptureFixture[str],
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    # As a plain install (no plot extra) finds it: matplotlib not installed.
    monkeypatch.setattr(chart, "chart_available", lambda: False)
    monkeypatch.setattr(evaluate_module, "chart_available", lambda: False)
    _, db = make_db(corpus_rows())
    out = tmp_path / "out"
    assert main(["evaluate", "--db", str(db), "--out", str(out)]) == 0
    assert sorted(p.name for p in out.iterdir()) == ["history.md", "table.csv", "table.md"]
    captured = capsys.readouterr()
    assert "rules.png" not in captured.out and "2 files (66.7%) with a fault" in captured.out
    hints = [line for line in captured.err.splitlines() if "rules.png" in line]
    assert hints == [
        "launch-linter: rules.png not drawn: it needs matplotlib "
        "(pip install 'launch-linter[plot]')"
    ]


def test_the_chart_is_looked_up_not_imported() -> None:
    assert chart.chart_available() == (importlib.util.find_spec("matplotlib") is not None)


def test_beliefs_option_replaces_the_mined_beliefs(make_db: MakeDb, tmp_path: Path) -> None:
    _, db = make_db(corpus_rows())
    evaluation = evaluate(str(db), 1.0, "none")
    assert {r.rule: r for r in evaluation.table.fault_rows}["name_null_rot"].faults == 0


def test_errors_are_reported_not_raised(make_db: MakeDb, tmp_path: Path,
                                        capsys: pytest.CaptureFixture[str]) -> None:
    root, db = make_db(corpus_rows())
    missing = tmp_path / "missing.db"
    assert main(["evaluate", "--db", str(missing), "--out", str(tmp_path / "o")]) == 2
    assert "no such database" in capsys.readouterr().err
    shutil.rmtree(root)
    with pytest.raises(EvaluationError, match="not a folder here"):
        evaluate(str(db), 1.0)
    assert main(["evaluate", "--db", str(db), "--out", str(tmp_path / "o")]) == 2


def test_a_changed_corpus_file_is_not_linted(make_db: MakeDb) -> None:
    root, db = make_db(corpus_rows())
    changed = next((root / "files").glob("*.launch"))
    changed.write_text(launch(IMU), encoding="utf-8")
    evaluation = evaluate(str(db), 1.0)
    assert any("changed since it was mined" in why for _, why in evaluation.scope.not_linted)
