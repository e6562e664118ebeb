"""rules.png: percentage of files per rule, ours beside the study's."""

from __future__ import annotations

import importlib.util

from launch_linter.evaluation.table import FaultTable

PLOT_HINT = "pip install 'launch-linter[plot]'"
"""How to get matplotlib, which only the chart needs (a plain install leaves it out)."""


def chart_available() -> bool:
    """Whether matplotlib is installed (looked up, not imported: importing it is slow)."""
    return importlib.util.find_spec("matplotlib") is not None


def write_chart(table: FaultTable, path: str, title: str) -> None:
    """A horizontal grouped bar chart, one group per line of the fault table."""
    # Imported here: matplotlib is an edge dependency, and Agg draws without a display.
    import matplotlib

    matplotlib.use("Agg")
    from matplotlib import pyplot

    rows = list(table.fault_rows)
    ours = [table.percent(r) for r in rows]
    study = [r.study.percent if r.study is not None else 0.0 for r in rows]
    positions = range(len(rows))
    height = 0.4
    figure, axes = pyplot.subplots(figsize=(9, 0.38 * len(rows) + 1.6))
    try:
        bars = axes.barh(
            [p - height / 2 for p in positions], ours, height, label="this corpus",
            color="#1f77b4",
        )
        study_bars = axes.barh(
            [p + height / 2 for p in positions], study, height, label="study (Table IV)",
            color="#ff7f0e",
        )
        for bar, value in zip(bars, ours):
            axes.annotate(
                f"{value:.2f}", (bar.get_width(), bar.get_y() + bar.get_height() / 2),
                xytext=(3, 0), textcoords="offset points", va="center", fontsize=7,
            )
        for bar, row in zip(study_bars, rows):
            if row.study is not None:
                axes.annotate(
                    f"{row.study.percent:g}",
                    (bar.get_width(), bar.get_y() + bar.get_height() / 2),
                    xytext=(3, 0), textcoords="offset points", va="center", fontsize=7,
                )
        axes.set_yticks(list(positions), [r.rule for r in rows], fontsize=8)
        axes.set_ylim(len(rows) - 0.5, -0.5)  # first row on top, no empty band
        axes.set_xlabel("% of files with the fault")
        axes.set_title(title, fontsize=10)
        axes.set_xlim(0, max([*ours, *study, 1.0]) * 1.15)
        axes.grid(axis="x", linewidth=0.3)
        axes.legend(loc="upper right", fontsize=8)
        figure.tight_layout()
        # No software/date metadata: the committed PNG changes only when the figures do.
        figure.savefig(path, dpi=110, metadata={"Software": None})
    finally:
        pyplot.close(figure)
