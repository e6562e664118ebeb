"""``launch-linter rules``: the table of every rule."""

from __future__ import annotations

import argparse
import sys

from launch_linter.commands.common import EXIT_OK
from launch_linter.rules import RULES


def add_parser(subparsers: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    subparsers.add_parser("rules", help="table of every rule").set_defaults(handler=run)


def run(ns: argparse.Namespace) -> int:
    width = max(len(r.id) for r in RULES)
    for rule in RULES:
        fix = rule.fix.value if rule.fix else "-"
        sys.stdout.write(
            f"{rule.id:<{width}}  {rule.category.value:<12}  "
            f"{rule.severity.value:<7}  {fix:<6}  {rule.summary}\n"
        )
    return EXIT_OK
