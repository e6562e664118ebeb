from __future__ import annotations

import json

import pytest

from launch_linter.mining.beliefs import (
    MinedTransform,
    belief_entry,
    beliefs_document,
    decode_key,
    dumps_document,
    encode_key,
    mine,
)
from launch_linter.mining.stats import z_score
from launch_linter.model.beliefs import BeliefSet
from launch_linter.model.diagnostic import Belief


def t(file: int, parent: str | None, child: str | None, name: str | None = None,
      disp: bool | None = True, rot: bool | None = True) -> MinedTransform:
    signature = (parent, child) if parent is not None and child is not None else None
    return MinedTransform(file, signature, name, disp, rot)


def find(beliefs: list[Belief], cls: str, antecedent: object, consequent: object = None) -> Belief:
    (found,) = [b for b in beliefs if b.cls == cls and b.antecedent == antecedent
                and b.consequent == consequent]
    return found


def test_signature_implication_counts_files() -> None:
    rows = [
        # files 1-3 have a→b and c→d; file 4 has a→b only; file 5 has c→d twice.
        t(1, "a", "b"), t(1, "c", "d"),
        t(2, "a", "b"), t(2, "c", "d"),
        t(3, "a", "b"), t(3, "c", "d"), t(3, "a", "b"),
        t(4, "a", "b"),
        t(5, "c", "d"), t(5, "c", "d"),
    ]
    beliefs = mine(rows, 0.9)
    ab_cd = find(beliefs, "sig_implication", ("a", "b"), ("c", "d"))
    assert (ab_cd.n, ab_cd.e) == (4, 3)
    assert ab_cd.z == pytest.approx(z_score(4, 3, 0.9))
    cd_ab = find(beliefs, "sig_implication", ("c", "d"), ("a", "b"))
    assert (cd_ab.n, cd_ab.e) == (4, 3)


def test_implications_only_for_pairs_that_meet_and_antecedents_seen_twice() -> None:
    rows = [t(1, "a", "b"), t(1, "c", "d"), t(2, "a", "b"), t(3, "x", "y"), t(3, "a", "b")]
    beliefs = [b for b in mine(rows, 0.9) if b.cls == "sig_implication"]
    # a→b is in 3 files: beliefs (a→b ⇒ c→d) 3/1 and (a→b ⇒ x→y) 3/1; c→d and x→y are
    # each in one file only, so nothing is believed of them; x→y never meets c→d.
    assert {(b.antecedent, b.consequent, b.n, b.e) for b in beliefs} == {
        (("a", "b"), ("c", "d"), 3, 1),
        (("a", "b"), ("x", "y"), 3, 1),
    }


def test_name_implication_and_unresolved_names_are_skipped() -> None:
    rows = [
        t(1, "a", "b", "n1"), t(1, "c", "d", "n2"),
        t(2, "a", "b", "n1"), t(2, "c", "d", None),  # name unresolved: counts for nothing
        t(3, "a", "b", ""),  # an empty name is no name
    ]
    beliefs = mine(rows, 0.9)
    n1_n2 = find(beliefs, "name_implication", "n1", "n2")
    assert (n1_n2.n, n1_n2.e) == (2, 1)
    assert not [b for b in beliefs if b.antecedent == ""]


def test_null_classes_count_transforms() -> None:
    rows = [
        t(1, "map", "odom", "m", disp=True, rot=True),
        t(1, "map", "odom", "m", disp=False, rot=True),  # same file, counted again
        t(2, "map", "odom", "m", disp=True, rot=False),
        t(3, "map", "odom", "m", disp=None, rot=None),  # unknown values are not cases
    ]
    beliefs = mine(rows, 0.9)
    disp = find(beliefs, "sig_null_disp", ("map", "odom"))
    rot = find(beliefs, "sig_null_rot", ("map", "odom"))
    assert (disp.n, disp.e) == (3, 2)
    assert (rot.n, rot.e) == (3, 2)
    assert (find(beliefs, "name_null_disp", "m").n, find(beliefs, "name_null_rot", "m").e) == (3, 2)
    assert disp.z == pytest.approx((2 / 3 - 0.9) / (0.09 / 3) ** 0.5)


def test_unresolved_signature_counts_for_names_only() -> None:
    rows = [t(1, None, None, "x", disp=False), t(2, None, None, "x", disp=False)]
    beliefs = mine(rows, 0.9)
    assert {b.cls for b in beliefs} == {"name_null_disp", "name_null_rot"}
    assert find(beliefs, "name_null_disp", "x").e == 0


def test_null_beliefs_need_two_cases_and_keep_negative_scores() -> None:
    beliefs = mine([t(1, "a", "b", disp=False), t(2, "a", "b", disp=False), t(3, "c", "d")], 0.9)
    assert find(beliefs, "sig_null_disp", ("a", "b")).z == pytest.approx(z_score(2, 0))
    assert not [b for b in beliefs if b.antecedent == ("c", "d")]


def test_order_is_by_class_then_strength() -> None:
    rows = [t(f, "a", "b", disp=f != 0) for f in range(10)] + [
        t(f, "c", "d", disp=True) for f in range(20)
    ]
    beliefs = mine(rows, 0.9)
    classes = [b.cls for b in beliefs]
    order = ["sig_implication", "name_implication", "sig_null_disp", "name_null_disp",
             "sig_null_rot", "name_null_rot"]
    assert classes == sorted(classes, key=order.index)
    disp = [b for b in beliefs if b.cls == "sig_null_disp"]
    # z(20, 20) = 1.49 before z(10, 9) = 0
    assert [b.antecedent for b in disp] == [("c", "d"), ("a", "b")]


def test_keys_round_trip() -> None:
    for key in [("base_link", "laser"), "map_to_odom", ("ü", "\"q\"")]:
        assert decode_key(encode_key(key)) == key
    assert encode_key(None) == ""


def test_document_follows_the_contract_and_loads() -> None:
    beliefs = [
        Belief("sig_implication", ("base_frame", "nav"), ("base_link", "base_stabilized"),
               42, 42, z_score(42, 42)),
        Belief("name_null_rot", "map_to_odom", None, 30, 29, z_score(30, 29)),
    ]
    document = beliefs_document(beliefs, 0.9, 30, {"corpus": "c", "files": 2, "transforms": 3,
                                                   "created": "2025-01-01T00:00:00Z"})
    assert belief_entry(beliefs[0]) == {
        "class": "sig_implication", "if": ["base_frame", "nav"],
        "then": ["base_link", "base_stabilized"], "n": 42, "e": 42, "z": 2.1602,
    }
    assert "then" not in belief_entry(beliefs[1])
    text = dumps_document(document)
    assert json.loads(text) == document
    loaded = BeliefSet.from_json(json.loads(text), "test", 1.0)
    assert [(b.cls, b.antecedent, b.consequent, b.n, b.e) for b in loaded.beliefs] == [
        ("sig_implication", ("base_frame", "nav"), ("base_link", "base_stabilized"), 42, 42),
        ("name_null_rot", "map_to_odom", None, 30, 29),
    ]
    assert BeliefSet.from_json(json.loads(text), "test", 2.0).of_class("name_null_rot") == ()


def test_empty_document_is_valid_json() -> None:
    document = beliefs_document([], 0.9, 30, {"corpus": "c"})
    assert json.loads(dumps_document(document))["beliefs"] == []
