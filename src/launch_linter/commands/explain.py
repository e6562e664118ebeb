"""``launch-linter explain RULE``: the documentation of one rule."""

from __future__ import annotations

import argparse
import sys

from launch_linter.commands.common import EXIT_OK, UsageError
from launch_linter.rules import RULES_BY_ID


def add_parser(subparsers: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    explain = subparsers.add_parser("explain", help="documentation of one rule")
    explain.add_argument("rule")
    explain.set_defaults(handler=run)


def run(ns: argparse.Namespace) -> int:
    rule = RULES_BY_ID.get(ns.rule)
    if rule is None:
        import difflib  # only for the message of a mistake: not at start-up

        close = difflib.get_close_matches(ns.rule, list(RULES_BY_ID), n=1)
        hint = f" (did you mean {close[0]!r}?)" if close else ""
        raise UsageError(f"unknown rule {ns.rule!r}{hint} (see 'launch-linter rules')")
    fix = f", {rule.fix.value} fix" if rule.fix else ""
    sys.stdout.write(
        f"{rule.id} ({rule.category.value}, {rule.severity.value}{fix})\n\n{rule.doc}\n"
    )
    return EXIT_OK
