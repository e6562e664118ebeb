#!/usr/bin/env python3
"""The verdicts recorded per rule in docs/evaluation's verdict files, counted as written.

    python scripts/verdict_counts.py          # writes src/launch_linter/data/verdicts.json
    python scripts/verdict_counts.py --check  # exit 1 when the data file is not current

A rule's measured precision (``data/precision.json``, ``scripts/precision.py``) comes from
one judged sample of the corpus on one code state. Many rules were judged elsewhere: on
whole repositories, fault cases or corpus trees, each verdict file on the code state of
its own round. Those verdicts are not one sample and give no precision; ``launch-linter
rules`` shows them for a rule it has no measured precision for, per file, with each
verdict label counted as the file writes it (``TRUE``, ``FALSE``, ``HARMLESS``, ``SILENT``
...), never merged into a rate.

A row's rule is its ``rule`` field (its first word: ``duplicate_publisher (plugin
controllers)``), else the file's name when that is a rule id (``frame_without_publisher.jsonl``,
``ros2_param_file_unmatched_judged.jsonl``); rows without a ``verdict`` are findings, not
verdicts, and are skipped.
"""

from __future__ import annotations

import argparse
import json
import os
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
EVAL = os.path.join(ROOT, "docs", "evaluation")
DATA = os.path.join(ROOT, "src", "launch_linter", "data", "verdicts.json")


def rule_ids() -> set[str]:
    sys.path.insert(0, os.path.join(ROOT, "src"))
    from launch_linter.rules import RULES

    return {rule.id for rule in RULES}


def counts(folder: str, known: set[str]) -> dict[str, list[list[object]]]:
    """Per rule, ``[file, {verdict: count}]`` for each verdict file that judges it."""
    table: dict[str, dict[str, dict[str, int]]] = {}
    for name in sorted(os.listdir(folder)):
        if not name.endswith(".jsonl"):
            continue
        stem = name[: -len(".jsonl")]
        stem = stem[: -len("_judged")] if stem.endswith("_judged") else stem
        with open(os.path.join(folder, name), encoding="utf-8") as handle:
            for line in handle:
                if not line.strip():
                    continue
                row = json.loads(line)
                verdict = row.get("verdict")
                if not isinstance(verdict, str) or not verdict:
                    continue
                written = row.get("rule")
                rule = written.split()[0] if isinstance(written, str) and written else stem
                if rule not in known:
                    continue
                per_file = table.setdefault(rule, {}).setdefault(name, {})
                per_file[verdict] = per_file.get(verdict, 0) + 1
    return {rule: [[name, dict(sorted(labels.items(), key=lambda kv: (-kv[1], kv[0])))]
                   for name, labels in files.items()]
            for rule, files in sorted(table.items())}


def document(folder: str = EVAL) -> str:
    data = {"source": "scripts/verdict_counts.py over docs/evaluation/*.jsonl",
            "rules": counts(folder, rule_ids())}
    return json.dumps(data, indent=1, ensure_ascii=False) + "\n"


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--check", action="store_true", help="exit 1 if not current")
    ns = parser.parse_args()
    text = document()
    if ns.check:
        with open(DATA, encoding="utf-8") as handle:
            current = handle.read() == text
        print("verdicts.json is current" if current else
              "verdicts.json is not current: run python scripts/verdict_counts.py")
        return 0 if current else 1
    with open(DATA, "w", encoding="utf-8") as handle:
        handle.write(text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
