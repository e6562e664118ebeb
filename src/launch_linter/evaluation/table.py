"""Table IV: faults per rule in the latest version of each file, beside the study's figures."""

from __future__ import annotations

import csv
import io
from collections.abc import Sequence
from dataclasses import dataclass

from launch_linter.evaluation.lint import Linted
from launch_linter.evaluation.study import STUDY_FILES, STUDY_TABLE_IV, STUDY_TOTAL, StudyRow
from launch_linter.model.diagnostic import Severity
from launch_linter.rules import Rule

TOTAL_STUDY_RULES = "total (study's 14 rules)"
TOTAL_ALL_RULES = "total (all fault rules)"

CSV_COLUMNS = (
    "rule", "category", "faults", "files", "percent_files", "repos",
    "study_faults", "study_files", "study_percent_files",
)


@dataclass(frozen=True)
class RuleRow:
    """One line of the table: a rule, or a total over several rules."""

    rule: str
    category: str
    faults: int
    files: int
    """Files with at least one diagnostic of the rule(s): for a total, not a sum."""
    repos: int
    study: StudyRow | None


@dataclass(frozen=True)
class FaultTable:
    files: int
    """Files linted: the denominator of every percentage."""
    repos: int
    study_rows: tuple[RuleRow, ...]
    study_total: RuleRow
    extra_rows: tuple[RuleRow, ...]
    """Rules the study did not have (tf and launch categories)."""
    all_total: RuleRow
    info_rows: tuple[RuleRow, ...]
    """Info diagnostics (``unresolved``, …): not faults, counted apart."""

    @property
    def fault_rows(self) -> tuple[RuleRow, ...]:
        """Every line of the fault table, in print order."""
        return (*self.study_rows, self.study_total, *self.extra_rows, self.all_total)

    def percent(self, row: RuleRow) -> float:
        return 100.0 * row.files / self.files if self.files else 0.0


def is_fault_rule(rule: Rule) -> bool:
    """Info diagnostics say what the linter could not see; they are not faults."""
    return rule.severity is not Severity.INFO


def _row(
    rule: str,
    category: str,
    linted: Sequence[Linted],
    ids: set[str],
    study: StudyRow | None,
    include_info: bool = False,
) -> RuleRow:
    # A fault rule may also speak at info level (bad_quaternion's rounding notice): only
    # its warnings and errors are faults.
    faults = 0
    files = 0
    repos: set[str] = set()
    for item in linted:
        here = sum(
            1
            for d in item.diagnostics
            if d.rule in ids and (include_info or d.severity is not Severity.INFO)
        )
        if here:
            faults += here
            files += 1
            repos.add(item.version.repo)
    return RuleRow(rule, category, faults, files, len(repos), study)


def fault_table(linted: Sequence[Linted], rules: Sequence[Rule]) -> FaultTable:
    """Count the diagnostics of ``linted`` (the latest versions evaluated) per rule."""
    by_id = {r.id: r for r in rules}
    study_ids = [i for i in STUDY_TABLE_IV if i in by_id]
    extra = [r for r in rules if r.id not in STUDY_TABLE_IV and is_fault_rule(r)]
    fault_ids = {r.id for r in rules if is_fault_rule(r)}
    return FaultTable(
        files=len(linted),
        repos=len({item.version.repo for item in linted}),
        study_rows=tuple(
            _row(i, by_id[i].category.value, linted, {i}, STUDY_TABLE_IV[i]) for i in study_ids
        ),
        study_total=_row(TOTAL_STUDY_RULES, "", linted, set(study_ids), STUDY_TOTAL),
        extra_rows=tuple(_row(r.id, r.category.value, linted, {r.id}, None) for r in extra),
        all_total=_row(TOTAL_ALL_RULES, "", linted, fault_ids, None),
        info_rows=tuple(
            _row(r.id, r.category.value, linted, {r.id}, None, include_info=True)
            for r in rules
            if not is_fault_rule(r)
        ),
    )


def _percent(value: float) -> str:
    return f"{value:.2f}"


def render_csv(table: FaultTable) -> str:
    out = io.StringIO()
    writer = csv.writer(out, lineterminator="\n")
    writer.writerow(CSV_COLUMNS)
    for row in table.fault_rows:
        study = row.study
        writer.writerow([
            row.rule, row.category, row.faults, row.files, _percent(table.percent(row)),
            row.repos,
            "" if study is None else study.faults,
            "" if study is None else study.files,
            "" if study is None else f"{study.percent:g}",
        ])
    return out.getvalue()


def _md_line(cells: Sequence[str]) -> str:
    return "| " + " | ".join(cells) + " |"


def render_markdown(table: FaultTable, preamble: Sequence[str]) -> str:
    """The table with ``preamble`` (lines saying what was linted, with which beliefs)."""
    lines = ["# Table IV on this corpus, beside the study's", "", *preamble, ""]
    lines.append(_md_line([
        "rule", "category", "faults", "files", "% files", "repos",
        "study faults", "study files", "study % files",
    ]))
    lines.append(_md_line(["---", "---", *["---:"] * 7]))
    for row in table.fault_rows:
        study = row.study
        name = f"**{row.rule}**" if row.rule in (TOTAL_STUDY_RULES, TOTAL_ALL_RULES) else row.rule
        lines.append(_md_line([
            name, row.category, str(row.faults), str(row.files),
            _percent(table.percent(row)), str(row.repos),
            "" if study is None else str(study.faults),
            "" if study is None else str(study.files),
            "" if study is None else f"{study.percent:g}",
        ]))
    lines += [
        "",
        f"Percentages are of the {table.files} files linted here and of the study's "
        f"{STUDY_FILES} files. A total counts the files with at least one fault of those "
        "rules, so it is not the sum of the rows above it. The study's total of faults "
        f"({STUDY_TOTAL.faults}) is printed as published; its rows add up to "
        f"{sum(r.faults for r in STUDY_TABLE_IV.values())}.",
        "",
        "Not faults (information about what the linter could not see), counted apart:",
        "",
    ]
    for row in table.info_rows:
        lines.append(
            f"- `{row.rule}`: {row.faults} diagnostics in {row.files} files "
            f"({_percent(table.percent(row))}%) of {row.repos} repositories"
        )
    return "\n".join(lines) + "\n"

