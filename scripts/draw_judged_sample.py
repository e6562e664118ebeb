#!/usr/bin/env python3
"""Draw a seeded, rule-stratified sample of warning/error findings from the corpus for judging.

Lints the latest version of every developer-corpus file (manifest rows with ``latest: true``)
with the default configuration (bundled beliefs at min z 1, no packages: the corpus stores
files flat), keeps the findings at warning or error located in the file itself, and writes

- ``--counts`` (JSON): how often each rule fires at warning/error, in how many files, and the
  share of files with at least one warning or error; ``precision.py`` weights by these counts;
- ``--findings`` (JSONL): every such finding, with its key (what ``precision.py`` needs to
  know which judged findings are still reported at warning or error);
- ``--out`` (JSONL): the sample, each row with a stable ``key`` (repo, path, rule, line, node)
  so that judgements in ``docs/evaluation/judged.jsonl`` survive message changes.

Stratified: every rule gets ``--per-rule`` findings (all of them when it has fewer), drawn with
``random.Random(--seed)``; the rest of ``--size`` is filled in proportion to frequency. Rows
already judged (same key in ``--judged``) are always kept, so a re-run after a change adds the
new findings to judge without dropping the old.

    PYTHONPATH=src python scripts/draw_judged_sample.py [--corpus ../shared/corpus]
"""

from __future__ import annotations

import argparse
import hashlib
import json
import os
import random
import sys
from collections import Counter, defaultdict

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
EVAL = os.path.join(ROOT, "docs", "evaluation")
# Rules judged in full (when they fire at most --all-cap times): issue 17's whole-robot checks.
WHOLE_ROBOT_RULES = (
    "rep105_order", "optical_frame_rotation", "frame_authority", "conflicting_transform",
    "multiple_parents", "ros2_schema", "ros2_removed_keyword",
)


def stable_key(repo: str, path: str, rule: str, line: int, node: str | None) -> str:
    text = f"{repo}|{path}|{rule}|{line}|{node or ''}"
    return hashlib.sha1(text.encode("utf-8")).hexdigest()[:12]


def findings(corpus: str, profile: str | None) -> tuple[list[dict[str, object]], int]:
    from launch_linter import LintOptions, lint_paths
    from launch_linter.beliefs_files import load_beliefs

    kwargs: dict[str, object] = {}
    if profile is not None:
        kwargs["profile"] = profile
    options = LintOptions(package_paths=(), beliefs=load_beliefs("bundled", 1.0), **kwargs)  # type: ignore[arg-type]
    rows: list[dict[str, object]] = []
    files = 0
    with open(os.path.join(corpus, "manifest.jsonl"), encoding="utf-8") as handle:
        manifest = [json.loads(line) for line in handle]
    for entry in manifest:
        if not entry.get("latest"):
            continue
        files += 1
        path = os.path.join(corpus, entry["file"])
        result = lint_paths([path], options)
        own = result.files[0].path
        for d in result.diagnostics:
            if d.path != own or d.severity.value == "info":
                continue
            rows.append(
                {
                    "key": stable_key(entry["repo"], entry["path"], d.rule, d.line, d.node),
                    "rule": d.rule,
                    "severity": d.severity.value,
                    "repo": entry["repo"],
                    "path": entry["path"],
                    "file": entry["file"],
                    "line": d.line,
                    "node": d.node,
                    "message": d.message,
                }
            )
    return rows, files


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--corpus", default=os.path.join(ROOT, "..", "shared", "corpus"))
    parser.add_argument("--seed", type=int, default=15)
    parser.add_argument("--size", type=int, default=160)
    parser.add_argument("--per-rule", type=int, default=10)
    parser.add_argument("--out", default=os.path.join(EVAL, "sample.jsonl"))
    parser.add_argument("--counts", default=os.path.join(EVAL, "counts.json"))
    parser.add_argument("--judged", default=os.path.join(EVAL, "judged.jsonl"))
    parser.add_argument(
        "--findings", default=os.path.join(EVAL, "findings.jsonl"),
        help="every warning/error finding (key, rule, place): precision.py's membership test",
    )
    parser.add_argument("--profile", default=None, help="lint with this profile (e.g. study)")
    parser.add_argument(
        "--all-of", action="append", default=None, metavar="RULE",
        help="draw every finding of RULE (up to --all-cap) after the seeded draw; default: "
        "issue 17's whole-robot rules, which were added after the first judged sample",
    )
    parser.add_argument("--all-cap", type=int, default=40)
    ns = parser.parse_args()

    rows, files = findings(ns.corpus, ns.profile)
    by_rule: dict[str, list[dict[str, object]]] = defaultdict(list)
    for row in rows:
        by_rule[str(row["rule"])].append(row)
    judged_keys = set()
    if os.path.exists(ns.judged):
        with open(ns.judged, encoding="utf-8") as handle:
            judged_keys = {json.loads(line)["key"] for line in handle if line.strip()}

    rng = random.Random(ns.seed)
    chosen: dict[str, dict[str, object]] = {}
    for rule in sorted(by_rule):
        pool = sorted(by_rule[rule], key=lambda r: str(r["key"]))
        for row in pool:
            if row["key"] in judged_keys:
                chosen[str(row["key"])] = row
        fresh = [r for r in pool if r["key"] not in chosen]
        for row in rng.sample(fresh, min(ns.per_rule, len(fresh))):
            chosen[str(row["key"])] = row
    # After the seeded loop, so the random draw of every other rule stays what it was.
    for rule in sorted(set(ns.all_of if ns.all_of is not None else WHOLE_ROBOT_RULES)):
        pool = sorted(by_rule.get(rule, []), key=lambda r: str(r["key"]))
        for row in pool[: ns.all_cap]:
            chosen.setdefault(str(row["key"]), row)
    rest = sorted((r for r in rows if r["key"] not in chosen), key=lambda r: str(r["key"]))
    room = max(0, ns.size - len(chosen))
    for row in rng.sample(rest, min(room, len(rest))):
        chosen[str(row["key"])] = row

    with open(ns.out, "w", encoding="utf-8") as handle:
        for row in sorted(chosen.values(), key=lambda r: (str(r["rule"]), str(r["key"]))):
            handle.write(json.dumps(row, sort_keys=True) + "\n")
    with open(ns.findings, "w", encoding="utf-8") as handle:
        for row in sorted(rows, key=lambda r: (str(r["rule"]), str(r["key"]))):
            short = {k: row[k] for k in ("key", "rule", "repo", "path", "line")}
            handle.write(json.dumps(short, sort_keys=True) + "\n")
    per_rule = Counter(str(r["rule"]) for r in rows)
    files_per_rule = {
        rule: len({str(r["file"]) for r in group}) for rule, group in by_rule.items()
    }
    flagged = len({str(r["file"]) for r in rows})
    counts = {
        "corpus_latest_files": files,
        "files_with_warning_or_error": flagged,
        "findings": len(rows),
        "profile": ns.profile or "default",
        "rules": {
            rule: {"findings": per_rule[rule], "files": files_per_rule[rule]}
            for rule in sorted(per_rule)
        },
    }
    with open(ns.counts, "w", encoding="utf-8") as handle:
        json.dump(counts, handle, indent=1, sort_keys=True)
        handle.write("\n")
    sys.stdout.write(
        f"{files} files, {len(rows)} warning/error findings in {flagged} files "
        f"({100.0 * flagged / max(files, 1):.1f}%); sample of {len(chosen)} -> {ns.out}\n"
    )
    for rule in sorted(per_rule, key=lambda r: -per_rule[r]):
        sys.stdout.write(f"  {rule:<24} {per_rule[rule]:>5} in {files_per_rule[rule]} files\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
