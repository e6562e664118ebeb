"""``check`` drops each tree once its rules ran: the same report, without the trees."""

from __future__ import annotations

from pathlib import Path

from launch_linter import LintOptions, lint_paths

TF = '<node pkg="tf" type="static_transform_publisher" name="{}" args="{}"/>'


def test_a_run_without_trees_reports_the_same(tmp_path: Path) -> None:
    (tmp_path / "a.launch").write_text(
        "<launch>\n"
        "  <!-- launch-linter: disable=rot_degrees -->\n"
        f"  {TF.format('laser', '0 0 0 180 0 0 base laser 100')}\n"
        f"  {TF.format('cam', '0 0 0 90 0 0 base cam 100')}\n"
        "  <!-- launch-linter: disable=no_such_rule -->\n"
        "</launch>\n"
    )
    (tmp_path / "b.launch").write_text(f"<launch>{TF.format('x', '0 0 0 0 0 0 a a 100')}</launch>")
    for jobs in (1, 2):
        kept = lint_paths([str(tmp_path)], LintOptions(jobs=jobs))
        dropped = lint_paths([str(tmp_path)], LintOptions(jobs=jobs), keep_trees=False)
        assert dropped.trees == () and len(kept.trees) == 2
        assert (dropped.files, dropped.diagnostics) == (kept.files, kept.diagnostics)
        rules = {d.rule for d in kept.diagnostics}
        assert "unused_suppression" in rules and "self_transform" in rules
        assert [d.line for d in kept.diagnostics if d.rule == "rot_degrees"] == [4]
