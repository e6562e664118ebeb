"""How the belief threshold moves the counts: several evaluations of one database side by side."""

from __future__ import annotations

import math
from collections import Counter
from collections.abc import Sequence

from launch_linter.evaluation.evaluate import Evaluation
from launch_linter.evaluation.history import FIXED, PERSISTING
from launch_linter.evaluation.study import STUDY_FILES, STUDY_MIN_Z
from launch_linter.model.beliefs import BELIEF_CLASSES


def _cases_needed(z: float, p0: float) -> int:
    """The least n with z(n, n) ≥ z: z(n, n) = sqrt(n (1 - p0) / p0)."""
    return math.ceil(z * z * p0 / (1.0 - p0) - 1e-9)


def render_thresholds(evaluations: Sequence[Evaluation]) -> str:
    """A markdown comparison of ``evaluations`` (one per ``--min-z``, lowest first)."""
    if not evaluations:
        return "# Thresholds\n\nNo evaluation.\n"
    zs = [f"z ≥ {e.scope.min_z:g}" for e in evaluations]
    first = evaluations[0]
    lines = [
        "# How the z threshold moves the counts",
        "",
        f"The same database and the same {first.table.files} latest files of immature "
        f"repositories, linted with the beliefs at or above each threshold. Only the six "
        "`may_implied` rules depend on the threshold; the other rows are repeated to show the "
        f"totals. The study used z ≥ {STUDY_MIN_Z:g} on {STUDY_FILES} files.",
        "",
        "## Beliefs used",
        "",
        f"With p0 = {first.scope.p0:g}, a belief reaches z ≥ Z only with at least "
        f"Z² · p0 / (1 - p0) cases that all agree ("
        + ", ".join(f"{_cases_needed(e.scope.min_z, first.scope.p0)} for z ≥ {e.scope.min_z:g}"
                    for e in evaluations)
        + "). The strongest belief mined into this database has z = "
        + ("none" if first.scope.strongest is None else f"{first.scope.strongest:.2f}")
        + ".",
        "",
        "| class | " + " | ".join(zs) + " |",
        "|---|" + "---:|" * len(zs),
    ]
    counts = [Counter(b.cls for b in e.scope.beliefs.beliefs) for e in evaluations]
    for cls in BELIEF_CLASSES:
        lines.append(f"| {cls} | " + " | ".join(str(c[cls]) for c in counts) + " |")
    lines.append(
        "| **all** | " + " | ".join(str(len(e.scope.beliefs.beliefs)) for e in evaluations) + " |"
    )
    lines += [
        "",
        "## Faults and files with the fault (% of files)",
        "",
        "| rule | " + " | ".join(zs) + " | study (z ≥ 1) |",
        "|---|" + "---:|" * (len(zs) + 1),
    ]
    for index, row in enumerate(first.table.fault_rows):
        cells = []
        for evaluation in evaluations:
            same = evaluation.table.fault_rows[index]
            cells.append(
                f"{same.faults} / {same.files} ({evaluation.table.percent(same):.2f}%)"
            )
        study = "" if row.study is None else (
            f"{row.study.faults} / {row.study.files} ({row.study.percent:g}%)"
        )
        lines.append(f"| {row.rule} | " + " | ".join(cells) + f" | {study} |")
    lines += [
        "",
        "## History of the `may_implied` faults: fixed / persisting",
        "",
        "| rule | " + " | ".join(zs) + " |",
        "|---|" + "---:|" * len(zs),
    ]
    for cls in BELIEF_CLASSES:
        cells = []
        for evaluation in evaluations:
            history = evaluation.history.rules.get(cls)
            cells.append(
                "n/a" if history is None
                else f"{history.outcomes[FIXED]} / {history.outcomes[PERSISTING]}"
            )
        lines.append(f"| {cls} | " + " | ".join(cells) + " |")
    return "\n".join(lines) + "\n"
