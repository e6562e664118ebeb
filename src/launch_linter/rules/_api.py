"""What a rule is: metadata read from its module, and a pure check over a launch tree."""

from __future__ import annotations

from collections.abc import Callable, Iterable
from dataclasses import dataclass, field
from types import ModuleType

from launch_linter.model.beliefs import BeliefSet
from launch_linter.model.diagnostic import Belief, Category, Diagnostic, Location, Severity
from launch_linter.model.launch import LaunchTree
from launch_linter.model.transform import StaticTransform


@dataclass(frozen=True, slots=True)
class RuleContext:
    """Everything a rule may look at: one launch tree and the selected beliefs."""

    tree: LaunchTree
    beliefs: BeliefSet = field(default_factory=BeliefSet.empty)
    profile: str = "default"
    """``default``, or ``study``: the study's checks and severities (see docs/severity.md)."""
    distro: str | None = None
    """The target ROS distribution (lower case), None when unknown (see docs/severity.md)."""

    @property
    def study(self) -> bool:
        return self.profile == "study"


Check = Callable[[RuleContext], Iterable[Diagnostic]]


@dataclass(frozen=True, slots=True)
class Rule:
    id: str
    category: Category
    severity: Severity
    summary: str
    doc: str
    check: Check


def diagnostic_at(
    module_id: str,
    category: Category,
    severity: Severity,
    transform: StaticTransform,
    message: str,
    related: Iterable[StaticTransform | Location] = (),
    belief: Belief | None = None,
) -> Diagnostic:
    """A diagnostic located at ``transform``'s node, ``related`` pointing at other places."""
    locations = tuple(
        r if isinstance(r, Location) else Location(r.path, r.line, r.column) for r in related
    )
    return Diagnostic(
        rule=module_id,
        category=category,
        severity=severity,
        path=transform.path,
        line=transform.line,
        column=transform.column,
        message=message,
        node=transform.name,
        related=locations,
        belief=belief,
    )


def frontend_diagnostics(context: RuleContext, rule_id: str) -> Iterable[Diagnostic]:
    """The diagnostics of ``rule_id`` that the front-end recorded while reading the tree."""
    return (d for d in context.tree.diagnostics if d.rule == rule_id)


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
