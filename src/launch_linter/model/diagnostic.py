"""Diagnostics: what a rule reports, where, and on which belief it rests."""

from __future__ import annotations

from enum import Enum

from launch_linter.model.record import OrderedRecord, Record, _set

NO_ELEMENT_AT_ALL = "the file holds no element"
"""What an XML reader's message adds when a file holds no element at all (empty, or only a
prolog or comments), as against a document whose root is left open at its end: expat says
"no element found" for both."""


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


class Location(OrderedRecord):
    path: str
    line: int
    column: int

    __slots__ = ("path", "line", "column")

    def __init__(self, path: str, line: int, column: int) -> None:
        _set(self, "path", path)
        _set(self, "line", line)
        _set(self, "column", column)


DESCRIPTION_NEVER_LOADED = "description_never_loaded"
"""The problem on a robot description's root that nothing loads (the front-end finds it,
the engine reports the findings of that tree at info, the rule of that id says why)."""


class Problem(Record):
    """What a front-end (or the suppression pass) noticed, before the engine stamps it.

    It names its rule by id only: the rule registry owns category and severity, so the
    front-ends never decide either.
    """

    rule: str
    path: str
    line: int
    column: int
    message: str
    node: str | None
    related: tuple[Location, ...]

    __slots__ = ("rule", "path", "line", "column", "message", "node", "related")

    def __init__(
        self,
        rule: str,
        path: str,
        line: int,
        column: int,
        message: str,
        node: str | None = None,
        related: tuple[Location, ...] = (),
    ) -> None:
        _set(self, "rule", rule)
        _set(self, "path", path)
        _set(self, "line", line)
        _set(self, "column", column)
        _set(self, "message", message)
        _set(self, "node", node)
        _set(self, "related", related)


class Belief(Record):
    """A mined MAY-Implied belief: ``if`` (signature or name) implies ``then``."""

    cls: str
    antecedent: tuple[str, ...] | str
    consequent: tuple[str, ...] | str | None
    n: int
    e: int
    z: float

    __slots__ = ("cls", "antecedent", "consequent", "n", "e", "z")

    def __init__(
        self,
        cls: str,
        antecedent: tuple[str, ...] | str,
        consequent: tuple[str, ...] | str | None,
        n: int,
        e: int,
        z: float,
    ) -> None:
        _set(self, "cls", cls)
        _set(self, "antecedent", antecedent)
        _set(self, "consequent", consequent)
        _set(self, "n", n)
        _set(self, "e", e)
        _set(self, "z", z)

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


class TokenEdit(Record):
    """Replace the argument words ``tokens[start:end]`` with ``text`` ("" deletes them
    and the blank before them)."""

    start: int
    end: int
    text: str

    __slots__ = ("start", "end", "text")

    def __init__(self, start: int, end: int, text: str) -> None:
        _set(self, "start", start)
        _set(self, "end", end)
        _set(self, "text", text)


class Edit(Record):
    """A replacement of the bytes ``[start, end)`` of the file ``path``.

    ``expected``: the text those bytes held when the edit was located (a fix is applied
    only where they still do)."""

    path: str
    start: int
    end: int
    content: str
    expected: str | None

    __slots__ = ("path", "start", "end", "content", "expected")

    def __init__(
        self,
        path: str,
        start: int,
        end: int,
        content: str,
        expected: str | None = None,
    ) -> None:
        _set(self, "path", path)
        _set(self, "start", start)
        _set(self, "end", end)
        _set(self, "content", content)
        _set(self, "expected", expected)

    def to_json(self) -> dict:  # type: ignore[type-arg]
        return {"path": self.path, "start": self.start, "end": self.end, "content": self.content}


class Fix(Record):
    """How to fix a diagnostic: edits of the argument words ``tokens`` as written (what a
    rule knows), turned into byte ``edits`` of the file once it has been located there.

    ``safe_from_distro``: an unsafe fix that is safe when the target ROS 2 distribution
    (``--ros-distro``) is this one or newer."""

    applicability: Applicability
    message: str
    tokens: tuple[str, ...]
    token_edits: tuple[TokenEdit, ...]
    edits: tuple[Edit, ...]
    safe_from_distro: str | None

    __slots__ = ("applicability", "message", "tokens", "token_edits", "edits", "safe_from_distro")

    def __init__(
        self,
        applicability: Applicability,
        message: str,
        tokens: tuple[str, ...] = (),
        token_edits: tuple[TokenEdit, ...] = (),
        edits: tuple[Edit, ...] = (),
        safe_from_distro: str | None = None,
    ) -> None:
        _set(self, "applicability", applicability)
        _set(self, "message", message)
        _set(self, "tokens", tokens)
        _set(self, "token_edits", token_edits)
        _set(self, "edits", edits)
        _set(self, "safe_from_distro", safe_from_distro)

    def to_json(self) -> dict:  # type: ignore[type-arg]
        return {
            "applicability": self.applicability.value,
            "message": self.message,
            "edits": [e.to_json() for e in self.edits],
        }


class Diagnostic(Record):
    rule: str
    category: Category
    severity: Severity
    path: str
    line: int
    column: int
    message: str
    node: str | None
    related: tuple[Location, ...]
    belief: Belief | None
    fix: Fix | None

    __slots__ = (
        "rule", "category", "severity", "path", "line", "column", "message", "node", "related",
        "belief", "fix",
    )

    def __init__(
        self,
        rule: str,
        category: Category,
        severity: Severity,
        path: str,
        line: int,
        column: int,
        message: str,
        node: str | None = None,
        related: tuple[Location, ...] = (),
        belief: Belief | None = None,
        fix: Fix | None = None,
    ) -> None:
        _set(self, "rule", rule)
        _set(self, "category", category)
        _set(self, "severity", severity)
        _set(self, "path", path)
        _set(self, "line", line)
        _set(self, "column", column)
        _set(self, "message", message)
        _set(self, "node", node)
        _set(self, "related", related)
        _set(self, "belief", belief)
        _set(self, "fix", fix)

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
