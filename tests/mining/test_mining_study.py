from __future__ import annotations

import json
from typing import Any

import pytest

from launch_linter.beliefs_files import load_beliefs
from launch_linter.mining.beliefs import dumps_document
from launch_linter.mining.stats import z_score
from launch_linter.mining.study import StudyFormatError, study_beliefs, study_document
from launch_linter.model.beliefs import BELIEF_CLASSES, BeliefSet

CLASSES: dict[str, list[Any]] = {c: [] for c in BELIEF_CLASSES}


def levels(**lists: dict[str, list[Any]]) -> dict[str, Any]:
    return {"p0_used_by_source": 0.85,
            "thresholds": {level[1:]: {**CLASSES, **classes} for level, classes in lists.items()}}


STUDY = levels(
    t1={"sig_implication": [[["a", "b"], ["c", "d"]], [["c", "d"], ["a", "b"]]],
        "name_null_rot": ["n1", "n2", ""]},
    t2={"sig_implication": [[["a", "b"], ["c", "d"]]], "name_null_rot": ["n1"]},
    t5={"name_null_rot": ["n1"]},
    t10={},
)


def test_z_is_the_highest_threshold_that_lists_the_belief() -> None:
    found = {(b.cls, b.antecedent, b.consequent): (b.n, b.e, b.z) for b in study_beliefs(STUDY)}
    assert found == {
        ("sig_implication", ("a", "b"), ("c", "d")): (0, 0, 2.0),
        ("sig_implication", ("c", "d"), ("a", "b")): (0, 0, 1.0),
        ("name_null_rot", "n1", None): (0, 0, 5.0),
        ("name_null_rot", "n2", None): (0, 0, 1.0),
        ("name_null_rot", "", None): (0, 0, 1.0),
    }


def test_each_threshold_gives_back_its_list() -> None:
    document = json.loads(dumps_document(study_document(STUDY, "study", "2025-01-01T00:00:00Z")))
    assert document["p0"] == 0.85
    for level, classes in STUDY["thresholds"].items():
        loaded = BeliefSet.from_json(document, "study", float(level))
        for cls, entries in classes.items():
            got = [b.antecedent if b.consequent is None else (b.antecedent, b.consequent)
                   for b in loaded.of_class(cls)]
            expected = [tuple(e) if isinstance(e, list) and cls.startswith("sig_null") else
                        (tuple(e[0]), tuple(e[1])) if cls == "sig_implication" else
                        e for e in entries]
            assert sorted(got, key=str) == sorted(expected, key=str)


@pytest.mark.parametrize("bad", [
    {},
    {"thresholds": {"1": {"nope": []}}},
    {"thresholds": {"1": {"sig_implication": [["a", "b"]]}}},
    {"thresholds": {"1": {"sig_null_rot": [["a", "b", "c"]]}}},
])
def test_malformed_study_files_are_refused(bad: dict[str, Any]) -> None:
    with pytest.raises(StudyFormatError):
        study_beliefs(bad)


def test_shipped_study_beliefs_load() -> None:
    study = load_beliefs("study", 1.0)
    assert study.p0 == 0.85
    assert all(b.n == 0 and b.e == 0 and b.z in (1.0, 2.0, 5.0, 10.0) for b in study.beliefs)
    # The artifact's counts per threshold (sig/name implication, null disp, null rot).
    counts = {z: tuple(len(load_beliefs("study", z).of_class(c)) for c in BELIEF_CLASSES)
              for z in (1.0, 2.0, 5.0, 10.0)}
    assert counts == {1.0: (64, 95, 10, 9, 599, 780), 2.0: (8, 9, 0, 0, 583, 763),
                      5.0: (0, 0, 0, 0, 76, 97), 10.0: (0, 0, 0, 0, 11, 7)}


def test_shipped_bundled_beliefs_are_consistent() -> None:
    bundled = load_beliefs("bundled", float("-inf"))
    assert bundled.beliefs and bundled.p0 == 0.9
    for belief in bundled.beliefs:
        assert belief.n >= 2 and 0 <= belief.e <= belief.n
        assert belief.z == pytest.approx(z_score(belief.n, belief.e, bundled.p0), abs=1e-4)
        if belief.cls.endswith("_implication"):
            assert belief.e >= 1 and belief.consequent is not None
        else:
            assert belief.consequent is None
    assert len(load_beliefs("bundled", 1.0).beliefs) < len(bundled.beliefs)
