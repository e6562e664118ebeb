"""Counting MAY-Implied beliefs from transforms (pure: no I/O, no SQL).

The six classes and what ``n`` and ``e`` count (the study's Table III):

- ``sig_implication`` / ``name_implication``, per file: for an antecedent A (a signature
  ``(parent, child)`` or a node name) and a consequent B that shares a file with A at least
  once, ``n`` = files with A, ``e`` = files with both A and B.
- ``sig_null_disp`` / ``name_null_disp`` and ``sig_null_rot`` / ``name_null_rot``, per
  transform: for an antecedent A, ``n`` = transforms with A whose displacement (rotation)
  is known, ``e`` = those where it is zero.

Only resolved values count: a transform whose signature (name) is unresolved adds nothing
to the signature (name) classes, one whose displacement is unknown adds nothing to the
``null_disp`` classes.
"""

from __future__ import annotations

import json
from collections import Counter, defaultdict
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass
from typing import Any, Tuple, Union

from launch_linter.mining.stats import z_score
from launch_linter.model.beliefs import BELIEF_CLASSES, BELIEF_FORMAT
from launch_linter.model.diagnostic import Belief

MIN_SUPPORT = 2
"""Beliefs with fewer cases than this are not stored: one file proves no convention."""

Key = Union[Tuple[str, ...], str]

IMPLICATION_CLASSES = ("sig_implication", "name_implication")


@dataclass(frozen=True)
class MinedTransform:
    """What the miner needs of one stored transform."""

    file: int
    """The distinct file (content) the transform is written in."""
    signature: tuple[str, str] | None
    name: str | None
    null_displacement: bool | None
    null_rotation: bool | None


def _implications(cls: str, files: Iterable[set[Key]], p0: float) -> list[Belief]:
    with_a: Counter[Key] = Counter()
    with_both: Counter[tuple[Key, Key]] = Counter()
    for keys in files:
        ordered = sorted(keys, key=str)
        with_a.update(ordered)
        for a in ordered:
            for b in ordered:
                if a != b:
                    with_both[(a, b)] += 1
    return [
        Belief(cls, a, b, with_a[a], e, z_score(with_a[a], e, p0))
        for (a, b), e in with_both.items()
        if with_a[a] >= MIN_SUPPORT
    ]


def _nulls(cls: str, cases: Iterable[tuple[Key, bool]], p0: float) -> list[Belief]:
    n: Counter[Key] = Counter()
    e: Counter[Key] = Counter()
    for key, is_null in cases:
        n[key] += 1
        if is_null:
            e[key] += 1
    return [
        Belief(cls, key, None, count, e[key], z_score(count, e[key], p0))
        for key, count in n.items()
        if count >= MIN_SUPPORT
    ]


def usable_name(name: str | None) -> str | None:
    """A node name the name classes can use: resolved and not empty."""
    return name if name else None


def mine(transforms: Iterable[MinedTransform], p0: float) -> list[Belief]:
    """Every belief with ``n ≥ 2``, in :func:`belief_order`."""
    signatures: dict[int, set[Key]] = defaultdict(set)
    names: dict[int, set[Key]] = defaultdict(set)
    sig_disp: list[tuple[Key, bool]] = []
    sig_rot: list[tuple[Key, bool]] = []
    name_disp: list[tuple[Key, bool]] = []
    name_rot: list[tuple[Key, bool]] = []
    for t in transforms:
        name = usable_name(t.name)
        if t.signature is not None:
            signatures[t.file].add(t.signature)
            if t.null_displacement is not None:
                sig_disp.append((t.signature, t.null_displacement))
            if t.null_rotation is not None:
                sig_rot.append((t.signature, t.null_rotation))
        if name is not None:
            names[t.file].add(name)
            if t.null_displacement is not None:
                name_disp.append((name, t.null_displacement))
            if t.null_rotation is not None:
                name_rot.append((name, t.null_rotation))
    found = [
        *_implications("sig_implication", signatures.values(), p0),
        *_implications("name_implication", names.values(), p0),
        *_nulls("sig_null_disp", sig_disp, p0),
        *_nulls("name_null_disp", name_disp, p0),
        *_nulls("sig_null_rot", sig_rot, p0),
        *_nulls("name_null_rot", name_rot, p0),
    ]
    return sorted(found, key=belief_order)


def belief_order(belief: Belief) -> tuple[int, float, int, str, str]:
    """Class (in the rules table's order), strongest first, then by key for stability."""
    return (
        BELIEF_CLASSES.index(belief.cls),
        -belief.z,
        -belief.n,
        encode_key(belief.antecedent),
        encode_key(belief.consequent),
    )


def encode_key(key: Key | None) -> str:
    """A key as compact JSON text (a signature is a list, a name a string)."""
    if key is None:
        return ""
    return json.dumps(list(key) if isinstance(key, tuple) else key, ensure_ascii=False,
                      separators=(",", ":"))


def decode_key(text: str) -> Key:
    """The inverse of :func:`encode_key` for a key that is present."""
    value = json.loads(text)
    if isinstance(value, list):
        return tuple(str(v) for v in value)
    return str(value)


def belief_entry(belief: Belief) -> dict[str, Any]:
    """One entry of a beliefs file; the null classes have no ``then``."""
    def plain(key: Key) -> list[str] | str:
        return list(key) if isinstance(key, tuple) else key

    entry: dict[str, Any] = {"class": belief.cls, "if": plain(belief.antecedent)}
    if belief.consequent is not None:
        entry["then"] = plain(belief.consequent)
    entry.update(n=belief.n, e=belief.e, z=round(belief.z, 4))
    return entry


def beliefs_document(
    beliefs: Sequence[Belief], p0: float, mature_commits: int, source: Mapping[str, Any]
) -> dict[str, Any]:
    """A ``launch-linter-beliefs/1`` document."""
    return {
        "format": BELIEF_FORMAT,
        "p0": p0,
        "mature_commits": mature_commits,
        "source": dict(source),
        "beliefs": [belief_entry(b) for b in beliefs],
    }



def dumps_document(document: Mapping[str, Any]) -> str:
    """The document as JSON text with one belief per line (small, readable diffs)."""
    head = json.dumps(
        {k: v for k, v in document.items() if k != "beliefs"}, ensure_ascii=False, indent=1
    )
    lines = [head[: head.rindex("}")].rstrip() + ",", ' "beliefs": [']
    entries = [json.dumps(b, ensure_ascii=False) for b in document.get("beliefs", [])]
    lines.extend(f"  {text}," for text in entries[:-1])
    lines.extend(f"  {text}" for text in entries[-1:])
    lines.append(" ]")
    lines.append("}")
    return "\n".join(lines) + "\n"
