"""What a rule is: metadata read from its module, and a pure check over a launch tree."""

from __future__ import annotations

import itertools
import typing
from collections.abc import Iterable
from types import ModuleType
from typing import Any, Callable, TypeVar

from launch_linter.knowledge import KnowledgeBase, bundled
from launch_linter.model.beliefs import BeliefSet
from launch_linter.model.diagnostic import (
    Applicability,
    Belief,
    Category,
    Diagnostic,
    Fix,
    Location,
    Problem,
    Severity,
)
from launch_linter.model.launch import LaunchTree
from launch_linter.model.record import Record, _set
from launch_linter.model.transform import StaticTransform

T = TypeVar("T")


class RuleContext(Record):
    """Everything a rule may look at: one launch tree and the selected beliefs."""

    tree: LaunchTree
    beliefs: BeliefSet
    profile: str
    """``default``, or ``study``: the study's checks and severities (see docs/severity.md)."""
    distro: str | None
    """The target ROS distribution (lower case), None when unknown (see docs/severity.md)."""
    knowledge: KnowledgeBase
    """The tf publishers and frame consumers known (bundled, extended by the config)."""
    _shared: dict[Callable[[Any], Any], Any]
    """What ``shared`` worked out for this tree, by the function that works it out."""

    __slots__ = ("tree", "beliefs", "profile", "distro", "knowledge", "_shared")
    _private = ("_shared",)

    def __init__(
        self,
        tree: LaunchTree,
        beliefs: BeliefSet | None = None,
        profile: str = "default",
        distro: str | None = None,
        knowledge: KnowledgeBase | None = None,
    ) -> None:
        _set(self, "tree", tree)
        _set(self, "beliefs", BeliefSet.empty() if beliefs is None else beliefs)
        _set(self, "profile", profile)
        _set(self, "distro", distro)
        _set(self, "knowledge", bundled() if knowledge is None else knowledge)
        _set(self, "_shared", {})

    @property
    def study(self) -> bool:
        return self.profile == "study"

    def shared(self, index: Callable[[LaunchTree], T]) -> T:
        """``index(tree)``, worked out once for all the rules run on this tree: the edges
        of the tf tree, the transforms by file (several rules read each; none re-scans)."""
        try:
            return typing.cast(T, self._shared[index])
        except KeyError:
            value = self._shared[index] = index(self.tree)
            return value

    def derived(self, index: Callable[[RuleContext], T]) -> T:
        """``index(context)``, worked out once per tree, for what needs more than the tree
        (the knowledge base): the node-published edges."""
        try:
            return typing.cast(T, self._shared[index])
        except KeyError:
            value = self._shared[index] = index(self)
            return value


class Finding(Record):
    """What a rule reports: where, what, and on what evidence; never which rule or category.

    The engine stamps the rule's id, category and severity from the registry. ``severity``
    is set only by a rule with two documented levels (e.g. ``bad_quaternion``'s info-level
    notice about a quaternion slightly off unit length); None means the rule's ``SEVERITY``.
    """

    path: str
    line: int
    column: int
    message: str
    node: str | None
    related: tuple[Location, ...]
    belief: Belief | None
    severity: Severity | None
    fix: Fix | None
    """Word edits that fix it (see ``rules._fixes``); the engine locates them in the file."""

    __slots__ = (
        "path", "line", "column", "message", "node", "related", "belief", "severity", "fix",
    )

    def __init__(
        self,
        path: str,
        line: int,
        column: int,
        message: str,
        node: str | None = None,
        related: tuple[Location, ...] = (),
        belief: Belief | None = None,
        severity: Severity | None = None,
        fix: Fix | None = None,
    ) -> None:
        _set(self, "path", path)
        _set(self, "line", line)
        _set(self, "column", column)
        _set(self, "message", message)
        _set(self, "node", node)
        _set(self, "related", related)
        _set(self, "belief", belief)
        _set(self, "severity", severity)
        _set(self, "fix", fix)


Check = Callable[[RuleContext], typing.Iterable[Finding]]


class Rule(Record):
    id: str
    category: Category
    severity: Severity
    summary: str
    doc: str
    check: Check
    fix: Applicability | None
    """The kind of fix the rule offers (its module's ``FIX``), None for none."""

    __slots__ = ("id", "category", "severity", "summary", "doc", "check", "fix")

    def __init__(
        self,
        id: str,
        category: Category,
        severity: Severity,
        summary: str,
        doc: str,
        check: Check,
        fix: Applicability | None = None,
    ) -> None:
        _set(self, "id", id)
        _set(self, "category", category)
        _set(self, "severity", severity)
        _set(self, "summary", summary)
        _set(self, "doc", doc)
        _set(self, "check", check)
        _set(self, "fix", fix)

    def diagnostic(self, finding: Finding, override: Severity | None = None) -> Diagnostic:
        """``finding`` stamped with this rule's metadata; ``override`` (configuration or
        command line) wins over the finding's own level, which wins over the default."""
        return Diagnostic(
            rule=self.id,
            category=self.category,
            severity=override or finding.severity or self.severity,
            path=finding.path,
            line=finding.line,
            column=finding.column,
            message=finding.message,
            node=finding.node,
            related=finding.related,
            belief=finding.belief,
            fix=finding.fix,
        )


def finding_at(
    transform: StaticTransform,
    message: str,
    related: Iterable[StaticTransform | Location] = (),
    belief: Belief | None = None,
    severity: Severity | None = None,
    fix: Fix | None = None,
) -> Finding:
    """A finding located at ``transform``'s node, ``related`` pointing at other places."""
    locations = tuple(
        r if isinstance(r, Location) else Location(r.path, r.line, r.column) for r in related
    )
    return Finding(
        path=transform.path,
        line=transform.line,
        column=transform.column,
        message=message,
        node=transform.name,
        related=locations,
        belief=belief,
        severity=severity,
        fix=fix,
    )


def finding_of(problem: Problem) -> Finding:
    """A problem recorded by a front-end or the suppression pass, as a finding."""
    return Finding(
        problem.path, problem.line, problem.column, problem.message, problem.node, problem.related
    )


def frontend_findings(context: RuleContext, rule_id: str) -> Iterable[Finding]:
    """The problems of ``rule_id`` that the front-end recorded while reading the tree."""
    return (finding_of(p) for p in context.tree.problems if p.rule == rule_id)


def rule_from_module(module: ModuleType) -> Rule:
    """Build a :class:`Rule` from a module's ``ID``, ``CATEGORY``, ``SEVERITY``, docstring
    (first line = summary) and ``check``."""
    doc = (module.__doc__ or "").strip()
    return Rule(
        id=module.ID,
        category=module.CATEGORY,
        severity=module.SEVERITY,
        summary=doc.splitlines()[0] if doc else module.ID,
        doc=doc,
        check=module.check,
        fix=getattr(module, "FIX", None),
    )


WORLD_FIXED_FRAMES = frozenset({"map", "world", "odom", "earth"})
"""Frames fixed in the world (REP 105): a sensor or robot hangs under them, never a mount."""


_WORLD_ORDER = {"earth": 0, "world": 1, "map": 2, "odom": 3}
"""REP 105's order of the world-fixed frames: each is the parent of the next."""


def _world_base(frame: str) -> str:
    return frame.rsplit("/", 1)[-1].lower().rstrip("0123456789_")


def is_world_fixed(frame: str) -> bool:
    """``map``, ``world``, ``odom``, ``earth``, and ``<robot>/map`` style or ``map2`` variants."""
    return _world_base(frame) in WORLD_FIXED_FRAMES


def goes_down_from_world(parent: str, child: str) -> bool:
    """True when ``parent`` → ``child`` hangs a frame under a world-fixed one the usual way:
    a robot or sensor frame under any of them, or world-fixed frames in REP 105's order
    (earth → world → map → odom)."""
    if not is_world_fixed(parent):
        return False
    if not is_world_fixed(child):
        return True
    return _WORLD_ORDER[_world_base(parent)] < _WORLD_ORDER[_world_base(child)]


def by_file(transforms: Iterable[StaticTransform]) -> dict[str, list[StaticTransform]]:
    """Transforms grouped by the file that declares them, each group in tree order."""
    groups: dict[str, list[StaticTransform]] = {}
    for transform in transforms:
        groups.setdefault(transform.path, []).append(transform)
    return groups


def transforms_by_file(tree: LaunchTree) -> dict[str, list[StaticTransform]]:
    """The tree's transforms by file: an index for ``RuleContext.shared`` (read, never
    changed, by the rules that share it)."""
    return by_file(tree.transforms)


def can_coexist(a: StaticTransform, b: StaticTransform) -> bool:
    """False when the two presence conditions exclude each other (``if`` vs ``unless``)."""
    return not a.condition.excludes(b.condition)


def same_element(a: StaticTransform, b: StaticTransform) -> bool:
    """True for one ``<node>`` element reached twice (its file included twice)."""
    return (a.path, a.line, a.column) == (b.path, b.line, b.column)


def place(transform: StaticTransform, seen_from: StaticTransform) -> str:
    """Where ``transform`` is, as a reader of ``seen_from``'s diagnostic wants it."""
    if transform.path == seen_from.path:
        return f"line {transform.line}"
    return f"{transform.path}:{transform.line}"


MAX_LISTED = 5
"""Most items a message lists before "and N more"."""
MAX_RELATED = 10
"""Most related locations one diagnostic carries (output per finding stays bounded)."""


def summarised(items: list[str], limit: int = MAX_LISTED) -> list[str]:
    """``items``, the ones past ``limit`` folded into a final "and N more"."""
    return summarised_lazily(items, len(items), limit)


def summarised_lazily(items: Iterable[str], count: int, limit: int = MAX_LISTED) -> list[str]:
    """``summarised`` of the ``count`` items of ``items``, only the ones shown worked out
    (the output per finding stays bounded, and so does the work for it)."""
    if count <= limit:
        return list(items)
    return [*itertools.islice(items, limit), f"and {count - limit} more"]
