"""``launch-linter evaluate``: the study's Table IV on a mined database."""

from __future__ import annotations

import argparse
import sqlite3
import sys

from launch_linter.commands.common import EXIT_OK, EXIT_USAGE


def add_parser(subparsers: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    evaluate = subparsers.add_parser(
        "evaluate", help="reproduce the study's Table IV on a database"
    )
    evaluate.add_argument("--db", required=True)
    evaluate.add_argument("--min-z", type=float, default=1.0)
    evaluate.add_argument("--out", default="evaluation", metavar="DIR")
    evaluate.add_argument("--beliefs", default=None)
    evaluate.set_defaults(handler=run)


def run(ns: argparse.Namespace) -> int:
    # Imported here: every command line builds this parser, few evaluate.
    from launch_linter.evaluation.chart import PLOT_HINT, chart_available
    from launch_linter.evaluation.evaluate import CHART, EvaluationError, evaluate, write_outputs

    try:
        evaluation = evaluate(ns.db, ns.min_z, ns.beliefs)
        paths = write_outputs(evaluation, ns.out)
    except (EvaluationError, sqlite3.Error, OSError) as exc:
        sys.stderr.write(f"launch-linter: error: {exc}\n")
        return EXIT_USAGE
    table = evaluation.table
    total = table.all_total
    history = evaluation.history.rules.values()
    fixed = sum(h.outcomes["fixed"] for h in history)
    persisting = sum(h.outcomes["persisting"] for h in history)
    sys.stdout.write(
        f"linted {table.files} latest files of {table.repos} immature repositories with "
        f"{len(evaluation.scope.beliefs.beliefs)} beliefs (z >= {ns.min_z:g}): "
        f"{total.files} files ({table.percent(total):.1f}%) with a fault, "
        f"{total.faults} faults\n"
        f"history: {fixed} faults of earlier versions fixed, {persisting} persisting\n"
        f"wrote {', '.join(paths)}\n"
    )
    if not chart_available():
        sys.stderr.write(f"launch-linter: {CHART} not drawn: it needs matplotlib ({PLOT_HINT})\n")
    for where, reason in evaluation.scope.not_linted:
        sys.stderr.write(f"launch-linter: warning: {where}: {reason}\n")
    return EXIT_OK
