#!/usr/bin/env python3
"""Rebuild the two beliefs files that the package ships.

    python scripts/build_beliefs.py [--corpus ../shared/corpus] [--db FILE] [--jobs N]

- ``src/launch_linter/data/beliefs-bundled.json``: every belief with n >= 2 mined from the
  corpus (p0 = 0.9, mature = 30 commits or more). It runs exactly

      launch-linter mine ../shared/corpus --db DB
      launch-linter beliefs --db DB -o src/launch_linter/data/beliefs-bundled.json

  in a fresh database (a temporary one unless --db is given), from the repository root.
- ``src/launch_linter/data/beliefs-study.json``: the beliefs that the study's artifact
  published (``../shared/research/study-beliefs.json``), converted by
  ``launch_linter.mining.study`` (n = e = 0, z = the highest threshold that lists them).

Set SOURCE_DATE_EPOCH to fix the ``created`` time and get byte-identical files.
"""

from __future__ import annotations

import argparse
import json
import os
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DATA = os.path.join("src", "launch_linter", "data")


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--corpus", default=os.path.join("..", "shared", "corpus"))
    parser.add_argument(
        "--study", default=os.path.join("..", "shared", "research", "study-beliefs.json")
    )
    parser.add_argument("--db", help="database to mine into (default: a temporary one)")
    parser.add_argument("--jobs", type=int, default=None)
    ns = parser.parse_args()
    os.chdir(ROOT)

    from launch_linter.cli import main as cli
    from launch_linter.mining.beliefs import dumps_document
    from launch_linter.mining.commands import created_now
    from launch_linter.mining.study import study_document

    with tempfile.TemporaryDirectory() as scratch:
        db = ns.db or os.path.join(scratch, "corpus.db")
        jobs = ["--jobs", str(ns.jobs)] if ns.jobs else []
        status = cli(["mine", ns.corpus, "--db", db, *jobs])
        if status != 0:
            return status
        status = cli(["beliefs", "--db", db, "-o", os.path.join(DATA, "beliefs-bundled.json")])
        if status != 0:
            return status

    with open(ns.study, encoding="utf-8") as handle:
        study = json.load(handle)
    label = f"{study.get('source_repository', 'study artifact')} via {ns.study}"
    document = study_document(study, label, created_now())
    target = os.path.join(DATA, "beliefs-study.json")
    with open(target, "w", encoding="utf-8") as handle:
        handle.write(dumps_document(document))
    sys.stderr.write(f"wrote {len(document['beliefs'])} beliefs to {target}\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
