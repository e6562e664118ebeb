"""`launch-linter rules` shows, for a rule without a measured precision, the verdicts
recorded for it in docs/evaluation (per file, each label as written, never a rate), and
the data file it reads says what those files say."""

from __future__ import annotations

import importlib.util
import json
from pathlib import Path
from types import ModuleType

import pytest

from launch_linter import measured

ROOT = Path(__file__).resolve().parents[1]


def script() -> ModuleType:
    spec = importlib.util.spec_from_file_location(
        "verdict_counts", ROOT / "scripts" / "verdict_counts.py")
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_the_recorded_verdicts_are_shown_per_file_and_never_as_a_rate(
        monkeypatch: pytest.MonkeyPatch) -> None:
    verdicts = {"judged_rule": [["a.jsonl", {"TRUE": 3, "FALSE": 1}],
                                ["b.jsonl", {"open, rightly undecided": 2}]]}
    table = {"measured_rule": {"after": {"judged": 40, "precision": 0.95, "true": 38}}}
    monkeypatch.setattr(measured, "_verdicts", lambda: verdicts)
    monkeypatch.setattr(measured, "_table", lambda: table)
    text = measured.precision_text("judged_rule")
    assert text.startswith("not measured on one sample;")
    assert text.endswith("a.jsonl 3 TRUE, 1 FALSE; b.jsonl 2 'open, rightly undecided'")
    assert "different samples and code states, not a rate" in text and "%" not in text
    assert measured.precision_text("unjudged_rule") == "not measured"
    assert measured.precision_text("measured_rule") == "95% of 40 judged"


def test_the_data_file_says_what_the_verdict_files_it_names_say() -> None:
    module = script()
    recounted = module.counts(str(ROOT / "docs" / "evaluation"), module.rule_ids())
    data = json.loads((ROOT / "src" / "launch_linter" / "data" / "verdicts.json").read_text())
    assert data["rules"]
    for rule, files in data["rules"].items():
        found = dict((name, labels) for name, labels in recounted.get(rule, []))
        for name, labels in files:
            assert found.get(name) == labels, (
                f"{rule} in {name}: run python scripts/verdict_counts.py")


def test_rows_are_counted_by_their_rule_or_their_file_s_name(tmp_path: Path) -> None:
    rows = [{"rule": "rule_a (plugin controllers)", "verdict": "TRUE_NEGATIVE"},
            {"rule": "rule_a", "verdict": "TRUE"}, {"rule": "rule_a"},
            {"rule": "not_a_rule", "verdict": "TRUE"}, {"verdict": "FALSE"}]
    (tmp_path / "rule_b_judged.jsonl").write_text(
        "\n".join(json.dumps(r) for r in rows) + "\n")
    assert script().counts(str(tmp_path), {"rule_a", "rule_b"}) == {
        "rule_a": [["rule_b_judged.jsonl", {"TRUE": 1, "TRUE_NEGATIVE": 1}]],
        "rule_b": [["rule_b_judged.jsonl", {"FALSE": 1}]]}
