"""History: which faults of earlier versions of a file are gone from its latest version.

A fault is a rule's diagnostic at one transform of an earlier version. Its transform is
looked up in the latest version of the same file of the same repository by node name, then
by signature (parent, child), so that a fixed name survives a frame swap and fixed frames
survive a rename. Then:

- **fixed**: the transform is still there and the rule no longer says the same thing about
  it (for mined beliefs: about the same belief): evidence that a developer repaired it;
- **persisting**: the same rule still fires on it;
- **gone**: no transform of that name or signature is left, so the history says nothing
  about whether the fault was understood.

Diagnostics that no transform carries (``parse_error``, most of ``roslaunch_error``) are
about the file: such a fault persists when the latest version has the same message.

The same fault seen in several earlier versions of a file counts once (one fault per file,
rule, transform name and signature, and belief). A version whose file was renamed or copied
since is compared with each latest file whose history holds it.
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from dataclasses import dataclass, field

from launch_linter.evaluation.lint import Linted, Version
from launch_linter.model.diagnostic import Diagnostic
from launch_linter.model.transform import Field, StaticTransform

FIXED, PERSISTING, GONE = "fixed", "persisting", "gone"
OUTCOMES = (FIXED, PERSISTING, GONE)


@dataclass(frozen=True)
class Fault:
    """One fault of an earlier version, and what became of it in the latest version."""

    rule: str
    earlier: Version
    latest: Version
    before: Diagnostic
    transform_before: StaticTransform | None
    transform_after: StaticTransform | None
    after: Diagnostic | None
    outcome: str


@dataclass
class RuleHistory:
    diagnostics: int = 0
    """Diagnostics on earlier versions, before counting a repeated fault once."""
    outcomes: dict[str, int] = field(default_factory=lambda: dict.fromkeys(OUTCOMES, 0))
    immature: dict[str, int] = field(default_factory=lambda: dict.fromkeys(OUTCOMES, 0))
    """The same, for repositories below the maturity threshold only."""
    fixed_repos: set[str] = field(default_factory=set)
    """Repositories with at least one fixed fault: a repository of many near-identical
    files can fix the same fault many times."""

    @property
    def faults(self) -> int:
        return sum(self.outcomes.values())


@dataclass(frozen=True)
class History:
    rules: dict[str, RuleHistory]
    faults: tuple[Fault, ...]
    earlier_versions: int
    """Earlier versions compared with at least one latest version."""
    comparisons: int
    """(earlier version, latest file) pairs: a version copied into several files counts
    once per file."""
    files_with_history: int
    """Latest files that have at least one earlier version."""
    orphans: int
    """Earlier versions whose latest file is not in the database."""


def _name(transform: StaticTransform) -> str | None:
    return transform.name if transform.name and transform.knows(Field.NAME) else None


def _at(transforms: Sequence[StaticTransform], diagnostic: Diagnostic) -> StaticTransform | None:
    for transform in transforms:
        if (transform.line, transform.column) == (diagnostic.line, diagnostic.column):
            return transform
    return None


def _belief_key(diagnostic: Diagnostic) -> object:
    belief = diagnostic.belief
    return None if belief is None else (belief.cls, belief.antecedent, belief.consequent)


def match_transform(
    transform: StaticTransform, candidates: Sequence[StaticTransform]
) -> StaticTransform | None:
    """The transform of ``candidates`` that is ``transform`` in another version: the same
    node name, else the same signature."""
    name = _name(transform)
    if name is not None:
        for candidate in candidates:
            if _name(candidate) == name:
                return candidate
    signature = transform.signature
    if signature is not None:
        for candidate in candidates:
            if candidate.signature == signature:
                return candidate
    return None


def _classify(
    diagnostic: Diagnostic, earlier: Linted, latest: Linted
) -> tuple[object, StaticTransform | None, StaticTransform | None, Diagnostic | None, str]:
    """(identity of the fault, transform before, transform after, diagnostic after, outcome)."""
    before = _at(earlier.transforms, diagnostic)
    if before is None:
        same = [
            d for d in latest.diagnostics
            if (d.rule, d.message) == (diagnostic.rule, diagnostic.message)
            and _at(latest.transforms, d) is None
        ]
        outcome = PERSISTING if same else FIXED
        return ("file", diagnostic.message), None, None, same[0] if same else None, outcome
    key = (_name(before), before.signature, _belief_key(diagnostic))
    after = match_transform(before, latest.transforms)
    if after is None:
        return key, before, None, None, GONE
    same = [
        d for d in latest.diagnostics
        if d.rule == diagnostic.rule
        and (d.line, d.column) == (after.line, after.column)
        and _belief_key(d) == _belief_key(diagnostic)
    ]
    return key, before, after, same[0] if same else None, PERSISTING if same else FIXED


def follow_history(linted: Iterable[Linted], rules: Sequence[str]) -> History:
    """Compare every earlier version in ``linted`` with its latest version, for ``rules``."""
    items = list(linted)
    latest = {(i.version.repo, i.version.path): i for i in items if i.version.latest}
    wanted = set(rules)
    per_rule = {rule: RuleHistory() for rule in rules}
    seen: set[tuple[object, ...]] = set()
    faults: list[Fault] = []
    compared = orphans = earlier = 0
    with_history: set[tuple[str, str]] = set()
    for item in items:
        if item.version.latest:
            continue
        found = (latest.get((item.version.repo, head)) for head in item.version.lineage)
        targets = [t for t in found if t is not None]
        if not targets:
            orphans += 1
            continue
        earlier += 1
        for target in targets:
            head = target.version.path
            compared += 1
            with_history.add((item.version.repo, head))
            for diagnostic in item.diagnostics:
                if diagnostic.rule not in wanted:
                    continue
                history = per_rule[diagnostic.rule]
                history.diagnostics += 1
                key, before, after, again, outcome = _classify(diagnostic, item, target)
                identity = (item.version.repo, head, diagnostic.rule, key)
                if identity in seen:
                    continue
                seen.add(identity)
                history.outcomes[outcome] += 1
                if outcome == FIXED:
                    history.fixed_repos.add(item.version.repo)
                if not item.version.mature:
                    history.immature[outcome] += 1
                faults.append(
                    Fault(diagnostic.rule, item.version, target.version, diagnostic,
                          before, after, again, outcome)
                )
    return History(per_rule, tuple(faults), earlier, compared, len(with_history), orphans)


def _share(part: int, whole: int) -> str:
    return f"{100.0 * part / whole:.0f}%" if whole else "n/a"


def _node(transform: StaticTransform | None) -> str:
    if transform is None:
        return "(none)"
    name = transform.name or "(unnamed)"
    return f"`{name}` args `{transform.args}`"


def _examples(
    faults: Sequence[Fault], rules: Iterable[str], fixed: int, persisting: int
) -> list[str]:
    """A few faults per rule, fixed ones first, each from a different repository."""
    lines: list[str] = []
    order = sorted(faults, key=lambda f: (f.earlier.repo, f.latest.path, f.before.line))
    for rule in rules:
        picked: list[Fault] = []
        for outcome, limit in ((FIXED, fixed), (PERSISTING, persisting)):
            repos: set[str] = set()
            for fault in order:
                if len(repos) >= limit:
                    break
                wanted = fault.rule == rule and fault.outcome == outcome
                if wanted and fault.earlier.repo not in repos:
                    repos.add(fault.earlier.repo)
                    picked.append(fault)
        if not picked:
            continue
        lines += [f"### `{rule}`", ""]
        for fault in picked:
            where = f"{fault.earlier.repo}: `{fault.latest.path}`"
            if fault.earlier.path != fault.latest.path:
                where += f" (earlier at `{fault.earlier.path}`)"
            lines.append(
                f"- **{fault.outcome}** — {where}, version {fault.earlier.version[:10]} → latest"
            )
            lines.append(f"  - before, line {fault.before.line}: {fault.before.message}")
            if fault.outcome == FIXED and fault.transform_before is None:
                lines.append("  - after: the latest version no longer has this diagnostic")
            elif fault.outcome == FIXED:
                lines.append(
                    f"  - after: no `{rule}` diagnostic; node {_node(fault.transform_before)} "
                    f"is now {_node(fault.transform_after)}"
                )
            elif fault.after is not None:
                lines.append(f"  - after, line {fault.after.line}: {fault.after.message}")
        lines.append("")
    return lines


def render_history(history: History, preamble: Sequence[str]) -> str:
    lines = [
        "# History: faults of earlier versions, fixed or persisting in the latest version",
        "",
        *preamble,
        "",
        f"{history.earlier_versions} earlier versions of {history.files_with_history} files "
        "were compared with the file's latest version in the same repository "
        f"({history.comparisons} comparisons: a version that was copied into several files "
        "is compared with each)"
        + (f" ({history.orphans} earlier versions have no latest file in the database)."
           if history.orphans else "."),
        "",
        "A fault is counted once per file even when several earlier versions have it. "
        "*fixed*: the transform (same node name, else same parent and child) is still in the "
        "latest version and the rule no longer fires on it; *persisting*: it still does; "
        "*gone*: the transform was removed, so the history says nothing about the fault. "
        "*fixed share* is fixed / (fixed + persisting).",
        "",
        "| rule | diagnostics | faults | fixed | persisting | gone | fixed share "
        "| repos with a fix | fixed (immature repos) | persisting (immature repos) |",
        "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|",
    ]
    for rule, counts in history.rules.items():
        fixed, persisting = counts.outcomes[FIXED], counts.outcomes[PERSISTING]
        lines.append(
            f"| {rule} | {counts.diagnostics} | {counts.faults} | {fixed} | {persisting} "
            f"| {counts.outcomes[GONE]} | {_share(fixed, fixed + persisting)} "
            f"| {len(counts.fixed_repos)} "
            f"| {counts.immature[FIXED]} | {counts.immature[PERSISTING]} |"
        )
    total = {o: sum(c.outcomes[o] for c in history.rules.values()) for o in OUTCOMES}
    lines.append(
        f"| **all** | {sum(c.diagnostics for c in history.rules.values())} "
        f"| {sum(total.values())} | {total[FIXED]} | {total[PERSISTING]} | {total[GONE]} "
        f"| {_share(total[FIXED], total[FIXED] + total[PERSISTING])} "
        f"| {len(set().union(*(c.fixed_repos for c in history.rules.values())))} "
        f"| {sum(c.immature[FIXED] for c in history.rules.values())} "
        f"| {sum(c.immature[PERSISTING] for c in history.rules.values())} |"
    )
    lines += ["", "## Examples", ""]
    lines += _examples(history.faults, history.rules, fixed=2, persisting=1)
    return "\n".join(lines).rstrip("\n") + "\n"
