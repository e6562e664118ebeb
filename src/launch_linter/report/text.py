"""Human-readable output: ``path:line:col: severity: message [rule]``."""

from __future__ import annotations

from collections.abc import Iterable, Sequence

from launch_linter.model.diagnostic import Applicability, Diagnostic, Severity
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
    and how many of them ``--fix`` fixes (``fixable``) and how many only with
    ``--unsafe-fixes`` (``hidden``), counted as :func:`fix_hint` counts them."""
    counts: dict[tuple[str, str], list[int]] = {}
    for d in diagnostics:
        entry = counts.setdefault((d.rule, d.severity.value), [0, 0, 0])
        entry[0] += 1
        if d.fix is not None and d.fix.edits:
            entry[1 if d.fix.applicability is Applicability.SAFE else 2] += 1
    rows = sorted(counts.items(), key=lambda item: (-item[1][0], item[0]))
    lines = []
    for (rule, severity), (count, fixable, hidden) in rows:
        parts = ([f"{fixable} fixable"] if fixable else []) + (
            [f"{hidden} hidden"] if hidden else [])
        note = f"  [{', '.join(parts)}]" if parts else ""
        lines.append(f"{count:>6}  {rule:<26} {severity}{note}")
    return "\n".join(lines) + ("\n" if lines else "")


def hidden_fixes(diagnostics: Iterable[Diagnostic], unsafe: bool) -> int:
    """How many located fixes ``--unsafe-fixes`` would add (0 when it is given)."""
    if unsafe:
        return 0
    return sum(1 for d in diagnostics if d.fix is not None and d.fix.edits
               and d.fix.applicability is not Applicability.SAFE)


def hidden_hint(hidden: int) -> str:
    """ruff's sentence about the fixes that only ``--unsafe-fixes`` enables."""
    noun = "hidden fix" if hidden == 1 else "hidden fixes"
    return f"{hidden} {noun} can be enabled with the `--unsafe-fixes` option"


def fix_hint(diagnostics: Sequence[Diagnostic]) -> str | None:
    """The line after a report (ruff's ``[*] N fixable with the `--fix` option``): how
    many findings ``--fix`` would fix, and how many more ``--unsafe-fixes`` would; None
    when no finding has a fix."""
    safe = sum(1 for d in diagnostics if d.fix is not None and d.fix.edits
               and d.fix.applicability is Applicability.SAFE)
    hidden = hidden_fixes(diagnostics, False)
    if safe == 0 and hidden == 0:
        return None
    if safe == 0:
        return f"No fixes available ({hidden_hint(hidden)})."
    tail = f" ({hidden_hint(hidden)})" if hidden else ""
    return f"[*] {safe} fixable with the `--fix` option{tail}."


MAX_PUBLISHERS = 4
"""Entry points named after an edge in the ``transforms`` listing (then "and N more")."""


def _publishers(entry_points: Sequence[str]) -> list[str]:
    if not entry_points:
        return []
    shown = ", ".join(entry_points[:MAX_PUBLISHERS])
    more = len(entry_points) - MAX_PUBLISHERS
    return [f"in {shown}" + (f" and {more} more" if more > 0 else "")]


def format_joint(j: RobotJoint, entry_points: Sequence[str] = ()) -> str:
    """A URDF edge in the ``transforms`` text listing: ``urdf`` and the joint type where a
    launch transform shows its node and package; ``entry_points``: those that publish it."""
    translation = f"({', '.join(f'{v:g}' for v in j.translation)})" if j.translation else "?"
    rotation = f"rpy({', '.join(f'{v:g}' for v in j.rpy)})" if j.rpy else "?"
    extra = [f"via {j.source.path}:{j.source.line}"]
    if not j.condition.always:
        extra.append(f"when {j.condition.describe()}")
    if j.unresolved:
        extra.append(f"unresolved: {', '.join(j.unresolved)}")
    extra.extend(_publishers(entry_points))
    # Joint and link names come from a robot description: escaped like every input string.
    return printable(
        f"{j.path}:{j.line}:{j.column}: urdf {j.joint_type} joint {j.name} "
        f"{j.parent or '?'} -> {j.child or '?'} t={translation} r={rotation}"
        f"  [{'; '.join(extra)}]"
    )


def format_transform(t: StaticTransform, entry_points: Sequence[str] = ()) -> str:
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
    extra.extend(_publishers(entry_points))
    tail = f"  [{'; '.join(extra)}]" if extra else ""
    return printable(
        f"{t.path}:{t.line}:{t.column}: {t.namespace}{t.name or '?'} ({t.package}) "
        f"{t.parent or '?'} -> {t.child or '?'} t={translation} r={rotation}{tail}"
    )
