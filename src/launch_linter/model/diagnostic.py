"""Diagnostics: what a rule reports, where, and on which belief it rests."""

from __future__ import annotations

from dataclasses import dataclass
from enum import Enum


class Severity(str, Enum):
    ERROR = "error"
    WARNING = "warning"
    INFO = "info"

    @property
    def rank(self) -> int:
        return {"error": 3, "warning": 2, "info": 1}[self.value]


class Category(str, Enum):
    MUST = "must"
    MAY_SEMANTIC = "may_semantic"
    MAY_IMPLIED = "may_implied"
    TF = "tf"
    LAUNCH = "launch"


@dataclass(frozen=True, order=True)
class Location:
    path: str
    line: int
    column: int


@dataclass(frozen=True)
class Problem:
    """What a front-end (or the suppression pass) noticed, before the engine stamps it.

    It names its rule by id only: the rule registry owns category and severity, so the
    front-ends never decide either.
    """

    rule: str
    path: str
    line: int
    column: int
    message: str
    node: str | None = None
    related: tuple[Location, ...] = ()


@dataclass(frozen=True)
class Belief:
    """A mined MAY-Implied belief: ``if`` (signature or name) implies ``then``."""

    cls: str
    antecedent: tuple[str, ...] | str
    consequent: tuple[str, ...] | str | None
    n: int
    e: int
    z: float

    def to_json(self) -> dict[str, object]:
        def enc(v: tuple[str, ...] | str | None) -> object:
            return list(v) if isinstance(v, tuple) else v

        return {
            "class": self.cls,
            "if": enc(self.antecedent),
            "then": enc(self.consequent),
            "n": self.n,
            "e": self.e,
            "z": round(self.z, 4),
        }


@dataclass(frozen=True)
class Diagnostic:
    rule: str
    category: Category
    severity: Severity
    path: str
    line: int
    column: int
    message: str
    node: str | None = None
    related: tuple[Location, ...] = ()
    belief: Belief | None = None

    @property
    def sort_key(self) -> tuple[str, int, int, str, str]:
        return (self.path, self.line, self.column, self.rule, self.message)

    def to_json(self) -> dict[str, object]:
        return {
            "rule": self.rule,
            "category": self.category.value,
            "severity": self.severity.value,
            "path": self.path,
            "line": self.line,
            "column": self.column,
            "message": self.message,
            "node": self.node,
            "related": [
                {"path": r.path, "line": r.line, "column": r.column} for r in self.related
            ],
            "belief": self.belief.to_json() if self.belief else None,
        }
