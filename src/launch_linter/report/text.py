"""Human-readable output: ``path:line:col: severity: message [rule]``."""

from __future__ import annotations

from collections.abc import Iterable

from launch_linter.model.diagnostic import Diagnostic, Severity
from launch_linter.model.robot import RobotJoint
from launch_linter.model.transform import StaticTransform
from launch_linter.report.escape import printable

_COLOURS = {Severity.ERROR: "\033[31m", Severity.WARNING: "\033[33m", Severity.INFO: "\033[36m"}
_BOLD, _RESET = "\033[1m", "\033[0m"


def format_diagnostic(d: Diagnostic, colour: bool = False) -> str:
    level = d.severity.value
    location = f"{printable(d.path)}:{d.line}:{d.column}:"
    if colour:
        level = f"{_COLOURS[d.severity]}{level}{_RESET}"
        location = f"{_BOLD}{location}{_RESET}"
    return f"{location} {level}: {printable(d.message)} [{d.rule}]"


def format_diagnostics(diagnostics: Iterable[Diagnostic], colour: bool = False) -> str:
    lines = [format_diagnostic(d, colour) for d in diagnostics]
    return "\n".join(lines) + ("\n" if lines else "")


def summary(diagnostics: Iterable[Diagnostic], files: int) -> str:
    counts = {s: 0 for s in Severity}
    for d in diagnostics:
        counts[d.severity] += 1
    return (
        f"{files} file(s): {counts[Severity.ERROR]} error(s), "
        f"{counts[Severity.WARNING]} warning(s), {counts[Severity.INFO]} info"
    )


def statistics(diagnostics: Iterable[Diagnostic]) -> str:
    """ruff's ``--statistics``: a count per rule with its severity, most frequent first,
    and how many of them a fix is offered for."""
    counts: dict[tuple[str, str], list[int]] = {}
    for d in diagnostics:
        entry = counts.setdefault((d.rule, d.severity.value), [0, 0])
        entry[0] += 1
        if d.fix is not None and d.fix.edits:
            entry[1] += 1
    rows = sorted(counts.items(), key=lambda item: (-item[1][0], item[0]))
    lines = []
    for (rule, severity), (count, fixable) in rows:
        note = f"  [{fixable} fixable]" if fixable else ""
        lines.append(f"{count:>6}  {rule:<26} {severity}{note}")
    return "\n".join(lines) + ("\n" if lines else "")


def format_joint(j: RobotJoint) -> str:
    """A URDF edge in the ``transforms`` text listing: ``urdf`` and the joint type where a
    launch transform shows its node and package."""
    translation = f"({', '.join(f'{v:g}' for v in j.translation)})" if j.translation else "?"
    rotation = f"rpy({', '.join(f'{v:g}' for v in j.rpy)})" if j.rpy else "?"
    extra = [f"via {j.source.path}:{j.source.line}"]
    if not j.condition.always:
        extra.append(f"when {j.condition.describe()}")
    if j.unresolved:
        extra.append(f"unresolved: {', '.join(j.unresolved)}")
    # Joint and link names come from a robot description: escaped like every input string.
    return printable(
        f"{j.path}:{j.line}:{j.column}: urdf {j.joint_type} joint {j.name} "
        f"{j.parent or '?'} -> {j.child or '?'} t={translation} r={rotation}"
        f"  [{'; '.join(extra)}]"
    )


def format_transform(t: StaticTransform) -> str:
    rotation = (
        f"{t.rotation.kind.value}({', '.join(f'{v:g}' for v in t.rotation.values)})"
        if t.rotation
        else "?"
    )
    translation = f"({', '.join(f'{v:g}' for v in t.translation)})" if t.translation else "?"
    extra = []
    if not t.condition.always:
        extra.append(f"when {t.condition.describe()}")
    if t.unresolved:
        extra.append(f"unresolved: {', '.join(t.unresolved_names)}")
    tail = f"  [{'; '.join(extra)}]" if extra else ""
    return printable(
        f"{t.path}:{t.line}:{t.column}: {t.namespace}{t.name or '?'} ({t.package}) "
        f"{t.parent or '?'} -> {t.child or '?'} t={translation} r={rotation}{tail}"
    )
