"""What a rule is: metadata read from its module, and a pure check over a launch tree."""

from __future__ import annotations

import typing
from collections.abc import Iterable
from dataclasses import dataclass, field
from types import ModuleType
from typing import Callable

from launch_linter.model.beliefs import BeliefSet
from launch_linter.model.diagnostic import Belief, Category, Diagnostic, Location, Severity
from launch_linter.model.launch import LaunchTree
from launch_linter.model.transform import StaticTransform


@dataclass(frozen=True)
class RuleContext:
    """Everything a rule may look at: one launch tree and the selected beliefs."""

    tree: LaunchTree
    beliefs: BeliefSet = field(default_factory=BeliefSet.empty)


Check = Callable[[RuleContext], typing.Iterable[Diagnostic]]


@dataclass(frozen=True)
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
