from __future__ import annotations

import csv
import io

from evaluation_helpers import launch, linted, node

from launch_linter.evaluation.study import STUDY_TABLE_IV, STUDY_TOTAL
from launch_linter.evaluation.table import (
    CSV_COLUMNS,
    TOTAL_ALL_RULES,
    TOTAL_STUDY_RULES,
    fault_table,
    render_csv,
    render_markdown,
)
from launch_linter.rules import RULES

SELF = node("self_tf", "0 0 0 0 0 0 base_link base_link 100")
DEGREES = node("laser_tf", "0.1 0 0.2 90 0 0 base_link laser 100")
CLEAN = node("imu_tf", "0 0 0.1 0 0 0 base_link imu_link 100")
UNRESOLVED = node("cam_tf", "0 0 0 0 0 0 $(arg base) camera_link 100")


def _rows(table):  # type: ignore[no-untyped-def]
    return {row.rule: row for row in table.fault_rows}


def test_total_counts_files_with_any_fault_not_the_sum() -> None:
    table = fault_table(
        [
            linted(launch(SELF, DEGREES), repo="r/a"),
            linted(launch(SELF, CLEAN), repo="r/b", path="launch/b.launch"),
            linted(launch(CLEAN), repo="r/b", path="launch/c.launch"),
        ],
        RULES,
    )
    rows = _rows(table)
    assert table.files == 3 and table.repos == 2
    assert (rows["self_transform"].faults, rows["self_transform"].files) == (2, 2)
    assert (rows["rot_degrees"].faults, rows["rot_degrees"].files) == (1, 1)
    total = rows[TOTAL_STUDY_RULES]
    assert total.faults == 3
    assert total.files == 2  # the sum of the rows' files would be 3
    assert total.repos == 2
    assert table.percent(total) == 200 / 3


def test_study_rows_first_then_extra_rules_and_info_apart() -> None:
    table = fault_table([linted(launch(UNRESOLVED, "  <nope/>"))], RULES)
    order = [row.rule for row in table.fault_rows]
    assert order[:14] == list(STUDY_TABLE_IV)
    assert order[14] == TOTAL_STUDY_RULES
    assert order[-1] == TOTAL_ALL_RULES
    assert "bad_arity" in order[15:] and "parse_error" in order[15:]
    assert "unresolved" not in order
    info = {row.rule: row for row in table.info_rows}
    assert info["unresolved"].files == 1 and info["unresolved"].faults >= 1
    assert _rows(table)[TOTAL_ALL_RULES].files == 0  # an unresolved value is not a fault


def test_csv_columns_and_study_figures() -> None:
    table = fault_table([linted(launch(SELF))], RULES)
    rows = list(csv.DictReader(io.StringIO(render_csv(table))))
    assert tuple(rows[0]) == CSV_COLUMNS
    by_rule = {row["rule"]: row for row in rows}
    assert by_rule["self_transform"]["faults"] == "1"
    assert by_rule["self_transform"]["percent_files"] == "100.00"
    assert by_rule["dup_name"]["study_files"] == "43"
    assert by_rule[TOTAL_STUDY_RULES]["study_files"] == str(STUDY_TOTAL.files)
    assert by_rule["bad_arity"]["study_faults"] == ""
    assert len(rows) == len(table.fault_rows)


def test_markdown_shows_ours_beside_the_study() -> None:
    table = fault_table([linted(launch(SELF)), linted(launch(CLEAN), path="b.launch")], RULES)
    text = render_markdown(table, ["- a preamble line"])
    assert "- a preamble line" in text
    line = next(x for x in text.splitlines() if x.startswith("| self_transform "))
    assert line.rstrip(" |").split(" | ")[2:9] == ["1", "1", "50.00", "1", "4", "4", "0.05"]
    assert "`unresolved`: 0 diagnostics" in text
