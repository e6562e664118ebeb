"""Converting the beliefs that the study's artifact published into our beliefs format.

The artifact (PhysFrame, ``linter_rules{,_2,_5,_10}.py``) lists beliefs per z threshold
(1, 2, 5, 10) without their counts, computed with p0 = 0.85. What can be known is kept:
``n`` and ``e`` are 0, which the rules read as "not published", and ``z`` is the highest
threshold whose list holds the belief, a lower bound of the artifact's own score. So
``--beliefs study --min-z T`` gives exactly the artifact's list for threshold T.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import Any

from launch_linter.mining.beliefs import belief_order, beliefs_document
from launch_linter.model.beliefs import BELIEF_CLASSES
from launch_linter.model.diagnostic import Belief

STUDY_MATURE_COMMITS = 30


class StudyFormatError(ValueError):
    """The study's beliefs file does not have the expected shape."""


def _key(value: Any, cls: str) -> tuple[str, ...] | str:
    """A signature ``[parent, child]`` for the ``sig_`` classes, a node name otherwise."""
    if cls.startswith("sig_"):
        if isinstance(value, list) and len(value) == 2 and all(isinstance(v, str) for v in value):
            return (value[0], value[1])
    elif isinstance(value, str):
        return value
    raise StudyFormatError(f"{cls}: unexpected key {value!r}")


def _belief(cls: str, entry: Any, z: float) -> Belief:
    if cls.endswith("_implication"):
        if not isinstance(entry, list) or len(entry) != 2:
            raise StudyFormatError(
                f"{cls}: an implication is [antecedent, consequent], not {entry!r}"
            )
        return Belief(cls, _key(entry[0], cls), _key(entry[1], cls), 0, 0, z)
    return Belief(cls, _key(entry, cls), None, 0, 0, z)


def study_beliefs(data: Mapping[str, Any]) -> list[Belief]:
    """Every belief of every threshold, once, with z = the highest threshold that lists it."""
    thresholds = data.get("thresholds")
    if not isinstance(thresholds, dict) or not thresholds:
        raise StudyFormatError("no 'thresholds' object")
    best: dict[tuple[str, Any, Any], Belief] = {}
    for level in sorted(thresholds, key=float):
        classes = thresholds[level]
        if not isinstance(classes, dict):
            raise StudyFormatError(f"threshold {level}: expected an object of classes")
        for cls, entries in classes.items():
            if cls not in BELIEF_CLASSES or not isinstance(entries, list):
                raise StudyFormatError(f"threshold {level}: unknown class or list {cls!r}")
            for entry in entries:
                belief = _belief(cls, entry, float(level))
                best[(cls, belief.antecedent, belief.consequent)] = belief
    return sorted(best.values(), key=belief_order)


def study_document(data: Mapping[str, Any], source: str, created: str) -> dict[str, Any]:
    """The study's beliefs as a ``launch-linter-beliefs/1`` document."""
    beliefs: Sequence[Belief] = study_beliefs(data)
    p0 = data.get("p0_used_by_source", 0.85)
    if not isinstance(p0, (int, float)):
        raise StudyFormatError("'p0_used_by_source' must be a number")
    return beliefs_document(
        beliefs,
        float(p0),
        STUDY_MATURE_COMMITS,
        {
            "corpus": source,
            "files": 0,
            "transforms": 0,
            "created": created,
            "counts": (
                "not published: n and e are 0; z is the highest threshold (1, 2, 5, 10) "
                "whose list in the artifact holds the belief, a lower bound of its score"
            ),
        },
    )
