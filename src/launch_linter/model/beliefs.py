"""Mined MAY-Implied beliefs, as the rules read them (format ``launch-linter-beliefs/1``)."""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping

from launch_linter.model.diagnostic import Belief
from launch_linter.model.record import Record, _set

TYPE_CHECKING = False  # typing is not imported at run time: start-up (docs/performance.md)
if TYPE_CHECKING:
    from typing import Any

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
    _decode: Callable[[], BeliefSet] | None
    _origin: str | None
    _count: int | None

    __slots__ = ("source", "min_z", "beliefs", "p0", "_index", "_decode", "_origin", "_count")
    _private = ("_index", "_decode", "_origin", "_count")

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
        _set(self, "_decode", None)
        _set(self, "_origin", None)
        _set(self, "_count", None)

    @staticmethod
    def stored(source: str, min_z: float, origin: str,
               decode: Callable[[], BeliefSet]) -> BeliefSet:
        """The set ``decode()`` gives, decoded when ``beliefs`` or ``p0`` is first read.
        ``origin`` names the content it is decoded from (a digest of the file's bytes):
        the results cache keys a run on it, so a run answered by the cache never decodes
        the bundled file (a 260 KB JSON document, a twentieth of the start-up)."""
        stored = BeliefSet.__new__(BeliefSet)
        _set(stored, "source", source)
        _set(stored, "min_z", min_z)
        _set(stored, "_index", {})
        _set(stored, "_decode", decode)
        _set(stored, "_origin", origin)
        _set(stored, "_count", None)
        return stored

    def __getattr__(self, name: str) -> Any:
        # Called only for an attribute not found: ``beliefs`` and ``p0`` of a stored set
        # not decoded yet (their slots are empty until then).
        try:
            decode = object.__getattribute__(self, "_decode")
        except AttributeError:
            decode = None
        if decode is None or name not in ("beliefs", "p0"):
            raise AttributeError(f"{type(self).__name__!r} object has no attribute {name!r}")
        decoded = decode()
        _set(self, "beliefs", decoded.beliefs)
        _set(self, "p0", decoded.p0)
        _set(self, "_decode", None)
        return getattr(self, name)

    @property
    def origin(self) -> str | None:
        """What a stored set is decoded from (None: a set built in memory)."""
        return self._origin

    @property
    def count(self) -> int:
        """How many beliefs: without decoding a stored set when the count is known."""
        if self._decode is not None and self._count is not None:
            return self._count
        return len(self.beliefs)

    def know_count(self, count: int) -> None:
        """Tell a stored set not decoded yet its count (remembered for its ``origin`` and
        ``min_z`` by the results cache)."""
        if self._decode is not None:
            _set(self, "_count", count)

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
