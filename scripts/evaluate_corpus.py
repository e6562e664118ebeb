#!/usr/bin/env python3
"""Regenerate docs/evaluation/: the study's Table IV on our corpus, its history, and how the
belief threshold moves the counts.

    python scripts/evaluate_corpus.py [--corpus ../shared/corpus] [--out docs/evaluation]
                                      [--db FILE] [--z 1 2 5]

From the repository root, it runs the equivalent of

    launch-linter mine ../shared/corpus --db DB
    launch-linter evaluate --db DB --min-z 1 --out docs/evaluation   (and --min-z 2, 5)

in a fresh database (a temporary one unless --db is given), writes table.md, table.csv,
rules.png and history.md for the first threshold into the output folder, and
thresholds.md comparing every threshold. It prints the totals it found.
"""

from __future__ import annotations

import argparse
import os
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--corpus", default=os.path.join("..", "shared", "corpus"))
    parser.add_argument("--out", default=os.path.join("docs", "evaluation"))
    parser.add_argument("--db", help="database to mine into (default: a temporary one)")
    parser.add_argument("--z", type=float, nargs="+", default=[1.0, 2.0, 5.0])
    parser.add_argument("--jobs", type=int, default=None)
    ns = parser.parse_args()

    from launch_linter.evaluation.evaluate import evaluate, write_outputs
    from launch_linter.evaluation.thresholds import render_thresholds
    from launch_linter.mining.commands import mine_corpus

    # Paths relative to the repository root, so that the outputs name the corpus as
    # ../shared/corpus wherever the clone is.
    os.chdir(ROOT)
    if not os.path.isdir(ns.corpus):
        sys.stderr.write(f"no corpus at {ns.corpus} (relative to {ROOT})\n")
        return 2
    with tempfile.TemporaryDirectory() as scratch:
        db = ns.db or os.path.join(scratch, "corpus.db")
        if ns.db and os.path.exists(ns.db):
            sys.stderr.write(f"{ns.db} exists: give a new database\n")
            return 2
        mine_corpus(ns.corpus, db, jobs=ns.jobs or os.cpu_count() or 1)
        evaluations = [evaluate(db, z) for z in sorted(ns.z)]
    write_outputs(evaluations[0], ns.out)
    with open(os.path.join(ns.out, "thresholds.md"), "w", encoding="utf-8") as handle:
        handle.write(render_thresholds(evaluations))
    for evaluation in evaluations:
        table = evaluation.table
        study, every = table.study_total, table.all_total
        sys.stdout.write(
            f"z >= {evaluation.scope.min_z:g}: {len(evaluation.scope.beliefs.beliefs)} beliefs; "
            f"{table.files} files; study's rules: {study.faults} faults in {study.files} files "
            f"({table.percent(study):.1f}%); all rules: {every.faults} faults in "
            f"{every.files} files ({table.percent(every):.1f}%)\n"
        )
    sys.stdout.write(f"wrote {ns.out}/table.md, table.csv, rules.png, history.md, thresholds.md\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
