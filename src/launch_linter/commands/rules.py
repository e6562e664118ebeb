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
    for rule in RULES:
        study = study_severity(rule.id, rule.severity)
        fix = rule.fix.value if rule.fix else "-"
        sys.stdout.write(
            f"{rule.id:<{width}}  {rule.category.value:<12}  {rule.severity.value:<7}  "
            f"{fix:<6}  study={study.value:<7}  {precision_text(rule.id):<32}  "
            f"{rule.summary}\n"
        )
    return EXIT_OK
