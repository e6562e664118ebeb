"""Per-rule counts over the developer corpus, like the study's Table IV.

Lints the latest version of every corpus file (manifest rows with ``latest: true``), each
file as its own root (the corpus stores files flat, so includes and ``$(find)`` rarely
resolve), and prints, separately for immature and mature repositories, how many
diagnostics each rule gave and in how many files.

Usage: python scripts/corpus_rule_counts.py [--corpus DIR] [--beliefs bundled|none|FILE]
                                             [--show RULE ...]
``--show`` prints every diagnostic of those rules with its repository and path.
"""

from __future__ import annotations

import argparse
import json
import sys
from collections import Counter
from dataclasses import dataclass
from pathlib import Path

from launch_linter import LintOptions, lint_paths
from launch_linter.beliefs_files import load_beliefs
from launch_linter.model import Diagnostic
from launch_linter.rules import RULES

DEFAULT_CORPUS = Path(__file__).resolve().parent.parent.parent / "shared" / "corpus"
GROUPS = ("immature", "mature")


@dataclass(frozen=True)
class Entry:
    repo: str
    path: str
    file: Path
    mature: bool


def latest_entries(corpus: Path) -> list[Entry]:
    entries: list[Entry] = []
    with open(corpus / "manifest.jsonl", encoding="utf-8") as handle:
        for line in handle:
            row = json.loads(line)
            if row.get("latest"):
                entries.append(
                    Entry(row["repo"], row["path"], corpus / row["file"], bool(row["mature"]))
                )
    return entries


def lint_entry(entry: Entry, options: LintOptions) -> tuple[tuple[Diagnostic, ...], int]:
    """Diagnostics located in the entry's own file, and its number of transforms."""
    result = lint_paths([str(entry.file)], options)
    record = result.files[0]
    return tuple(d for d in result.diagnostics if d.path == record.path), record.transforms


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--corpus", type=Path, default=DEFAULT_CORPUS)
    parser.add_argument("--beliefs", default="bundled")
    parser.add_argument("--show", nargs="*", default=[], metavar="RULE")
    ns = parser.parse_args(argv)
    options = LintOptions(package_paths=(), beliefs=load_beliefs(ns.beliefs, 1.0))

    entries = latest_entries(ns.corpus)
    files = Counter("mature" if e.mature else "immature" for e in entries)
    diagnostics: dict[str, Counter[str]] = {g: Counter() for g in GROUPS}
    with_rule: dict[str, Counter[str]] = {g: Counter() for g in GROUPS}
    off_default: dict[str, Counter[tuple[str, str]]] = {g: Counter() for g in GROUPS}
    defaults = {rule.id: rule.severity for rule in RULES}
    with_any: Counter[str] = Counter()
    transforms: Counter[str] = Counter()
    for entry in entries:
        group = "mature" if entry.mature else "immature"
        found, count = lint_entry(entry, options)
        transforms[group] += count
        rules = Counter(d.rule for d in found)
        diagnostics[group].update(rules)
        with_rule[group].update(rules.keys())
        off_default[group].update(
            (d.rule, d.severity.value) for d in found if d.severity is not defaults[d.rule]
        )
        if any(d.category.value != "launch" for d in found):
            with_any[group] += 1
        for d in found:
            if d.rule in ns.show:
                print(f"SHOW {group} {entry.repo} {entry.path}:{d.line}: {d.message} [{d.rule}]")

    print(f"corpus: {ns.corpus}  beliefs: {ns.beliefs}")
    for group in GROUPS:
        print(f"{group}: {files[group]} latest files, {transforms[group]} transforms")
    header = f"{'rule':<20} {'imm diag':>9} {'imm files':>9} {'imm %':>6}"
    header += f" {'mat diag':>9} {'mat files':>9} {'mat %':>6}"
    print(header)
    for rule in RULES:
        cells = []
        for group in GROUPS:
            count, nfiles = diagnostics[group][rule.id], with_rule[group][rule.id]
            share = 100.0 * nfiles / files[group] if files[group] else 0.0
            cells.append(f"{count:>9} {nfiles:>9} {share:>6.2f}")
        print(f"{rule.id:<20} {' '.join(cells)}")
    for group in GROUPS:
        for (rule_id, severity), count in sorted(off_default[group].items()):
            print(f"{group}: {count} of the {rule_id} diagnostics are {severity}")
    for group in GROUPS:
        share = 100.0 * with_any[group] / files[group] if files[group] else 0.0
        print(
            f"{group}: files with a finding outside the 'launch' category: "
            f"{with_any[group]} of {files[group]} ({share:.1f}%)"
        )
    return 0


if __name__ == "__main__":
    sys.exit(main())
