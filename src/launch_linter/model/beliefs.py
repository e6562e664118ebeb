"""Mined MAY-Implied beliefs, as the rules read them (format ``launch-linter-beliefs/1``)."""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

from launch_linter.model.diagnostic import Belief
from launch_linter.model.record import Record, _set

BELIEF_FORMAT = "launch-linter-beliefs/1"
BELIEF_CLASSES = (
    "sig_implication",
    "name_implication",
    "sig_null_disp",
    "name_null_disp",
    "sig_null_rot",
    "name_null_rot",
)


class BeliefFormatError(ValueError):
    """The beliefs file does not follow the contract."""


def _key(value: Any) -> tuple[str, ...] | str:
    if isinstance(value, list):
        return tuple(str(v) for v in value)
    if isinstance(value, str):
        return value
    raise BeliefFormatError(f"belief key must be a string or a list of strings, not {value!r}")


class BeliefSet(Record):
    """Beliefs at or above ``min_z``; ``source`` names where they came from."""

    source: str
    min_z: float
    beliefs: tuple[Belief, ...]
    p0: float
    _index: dict[str, dict[tuple[str, ...] | str, tuple[Belief, ...]]]

    __slots__ = ("source", "min_z", "beliefs", "p0", "_index")
    _private = ("_index",)

    def __init__(
        self,
        source: str,
        min_z: float,
        beliefs: tuple[Belief, ...],
        p0: float = 0.9,
    ) -> None:
        _set(self, "source", source)
        _set(self, "min_z", min_z)
        _set(self, "beliefs", beliefs)
        _set(self, "p0", p0)
        _set(self, "_index", {})

    @staticmethod
    def empty(source: str = "none") -> BeliefSet:
        return BeliefSet(source, 0.0, ())

    @staticmethod
    def from_json(data: Any, source: str, min_z: float = 1.0) -> BeliefSet:
        if not isinstance(data, dict) or data.get("format") != BELIEF_FORMAT:
            raise BeliefFormatError(f"not a {BELIEF_FORMAT} document")
        beliefs: list[Belief] = []
        for entry in data.get("beliefs", []):
            try:
                cls = entry["class"]
                if cls not in BELIEF_CLASSES:
                    raise BeliefFormatError(f"unknown belief class {cls!r}")
                z = float(entry["z"])
                if not math.isfinite(z):
                    raise BeliefFormatError(f"belief z-score {entry['z']!r} is not finite")
                if z < min_z:
                    continue
                then = entry.get("then")
                beliefs.append(
                    Belief(
                        cls,
                        _key(entry["if"]),
                        None if then is None else _key(then),
                        int(entry["n"]),
                        int(entry["e"]),
                        z,
                    )
                )
            except (KeyError, TypeError, ValueError, OverflowError) as exc:
                if isinstance(exc, BeliefFormatError):
                    raise
                raise BeliefFormatError(f"malformed belief {entry!r}: {exc}") from None
        p0 = data.get("p0", 0.9)
        if isinstance(p0, bool) or not isinstance(p0, (int, float)) or not 0.0 < p0 < 1.0:
            raise BeliefFormatError(f"'p0' must be a number between 0 and 1, not {p0!r}")
        return BeliefSet(source, min_z, tuple(beliefs), float(p0))

    def of_class(self, cls: str) -> tuple[Belief, ...]:
        return tuple(b for b in self.beliefs if b.cls == cls)

    def by_antecedent(self, cls: str) -> Mapping[tuple[str, ...] | str, tuple[Belief, ...]]:
        """The beliefs of ``cls`` keyed by antecedent, strongest first (built once per set,
        so that linting many trees does not rescan every belief for each one)."""
        index = self._index.get(cls)
        if index is None:
            grouped: dict[tuple[str, ...] | str, list[Belief]] = {}
            for belief in self.beliefs:
                if belief.cls == cls:
                    grouped.setdefault(belief.antecedent, []).append(belief)
            index = {
                key: tuple(sorted(group, key=lambda b: (-b.z, -b.n)))
                for key, group in grouped.items()
            }
            self._index[cls] = index
        return index

    def restricted(self, classes: tuple[str, ...]) -> BeliefSet:
        return BeliefSet(
            self.source, self.min_z, tuple(b for b in self.beliefs if b.cls in classes), self.p0
        )
