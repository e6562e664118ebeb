"""``launch-linter rules``: the table of every rule, its level and measured precision."""

from __future__ import annotations

import argparse
import sys

from launch_linter.commands.common import EXIT_OK
from launch_linter.rules import RULES


def add_parser(subparsers: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    subparsers.add_parser("rules", help="table of every rule").set_defaults(handler=run)


def run(ns: argparse.Namespace) -> int:
    """Each rule's level (and the study's, where it differs) and its measured precision."""
    from launch_linter.measured import precision_text
    from launch_linter.rules._profiles import study_severity

    width = max(len(r.id) for r in RULES)
    sys.stdout.write(f"{'ID':<{width}}  {'CATEGORY':<12}  {'SEVERITY':<8}  SUMMARY  "
                     "[FIX; STUDY'S LEVEL; MEASURED PRECISION]\n")
    for rule in RULES:
        # The contract's columns first (id, category, severity, summary); what this version
        # adds follows the summary, so a reader of the four columns is not misled.
        notes = [f"precision {precision_text(rule.id)}"]
        study = study_severity(rule.id, rule.severity)
        if study is not rule.severity:
            notes.insert(0, f"study: {study.value}")
        if rule.fix:
            notes.insert(0, f"fix: {rule.fix.value}")
        sys.stdout.write(
            f"{rule.id:<{width}}  {rule.category.value:<12}  {rule.severity.value:<8}  "
            f"{rule.summary}  [{'; '.join(notes)}]\n"
        )
    return EXIT_OK
