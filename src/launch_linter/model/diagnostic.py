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


class Applicability(str, Enum):
    """ruff's model: a safe fix keeps the meaning the author intended; an unsafe one may
    change what the launch file does and wants a human to look."""

    SAFE = "safe"
    UNSAFE = "unsafe"


@dataclass(frozen=True)
class TokenEdit:
    """Replace the argument words ``tokens[start:end]`` with ``text`` ("" deletes them
    and the blank before them)."""

    start: int
    end: int
    text: str


@dataclass(frozen=True)
class Edit:
    """A replacement of the bytes ``[start, end)`` of the file ``path``.

    ``expected``: the text those bytes held when the edit was located (a fix is applied
    only where they still do)."""

    path: str
    start: int
    end: int
    content: str
    expected: str | None = None

    def to_json(self) -> dict:  # type: ignore[type-arg]
        return {"path": self.path, "start": self.start, "end": self.end, "content": self.content}


@dataclass(frozen=True)
class Fix:
    """How to fix a diagnostic: edits of the argument words ``tokens`` as written (what a
    rule knows), turned into byte ``edits`` of the file once it has been located there.

    ``safe_from_distro``: an unsafe fix that is safe when the target ROS 2 distribution
    (``--ros-distro``) is this one or newer."""

    applicability: Applicability
    message: str
    tokens: tuple[str, ...] = ()
    token_edits: tuple[TokenEdit, ...] = ()
    edits: tuple[Edit, ...] = ()
    safe_from_distro: str | None = None

    def to_json(self) -> dict:  # type: ignore[type-arg]
        return {
            "applicability": self.applicability.value,
            "message": self.message,
            "edits": [e.to_json() for e in self.edits],
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
    fix: Fix | None = None

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
            "fix": self.fix.to_json() if self.fix and self.fix.edits else None,
        }
