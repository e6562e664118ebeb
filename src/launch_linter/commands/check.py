"""``launch-linter check``: lint launch files and report diagnostics."""

from __future__ import annotations

import argparse
import os
import sys

from launch_linter import __version__
from launch_linter.commands.common import EXIT_FINDINGS, EXIT_OK, UsageError
from launch_linter.commands.options import add_resolution_options, lint_options, load_config
from launch_linter.engine import LintResult, lint_paths
from launch_linter.model.diagnostic import Severity
from launch_linter.report import json_report, text


def add_parser(subparsers: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    check = subparsers.add_parser("check", help="lint launch files")
    add_resolution_options(check)
    check.add_argument("--format", choices=("text", "json", "sarif", "github"), default=None)
    check.add_argument(
        "--select",
        action="append",
        metavar="IDS",
        help="only these rules or categories (comma-separated)",
    )
    check.add_argument(
        "--ignore",
        action="append",
        metavar="IDS",
        help="skip these rules or categories (comma-separated)",
    )
    check.add_argument(
        "--beliefs",
        default=None,
        metavar="bundled|study|none|FILE",
        help="mined beliefs for the may_implied rules (default: bundled)",
    )
    check.add_argument(
        "--min-z",
        type=float,
        default=None,
        metavar="Z",
        help="minimum z-score of a belief (default 1.0)",
    )
    check.add_argument(
        "--fail-on",
        choices=("error", "warning", "info"),
        default=None,
        help="lowest severity that makes the exit status 1 (default warning)",
    )
    check.add_argument("--color", choices=("auto", "always", "never"), default="auto")
    check.set_defaults(handler=run)


def _exit_status(result: LintResult, fail_on: str) -> int:
    threshold = Severity(fail_on).rank
    return (
        EXIT_FINDINGS if any(d.severity.rank >= threshold for d in result.diagnostics) else EXIT_OK
    )


def _use_colour(choice: str) -> bool:
    if choice == "always":
        return True
    if choice == "never" or os.environ.get("NO_COLOR"):
        return False
    return sys.stdout.isatty()


def run(ns: argparse.Namespace) -> int:
    if not ns.paths:
        raise UsageError("check needs at least one PATH")
    config = load_config(ns)
    options = lint_options(ns, config)
    result = lint_paths(ns.paths, options)
    fmt = ns.format or "text"
    if fmt == "json":
        sys.stdout.write(
            json_report.dumps(json_report.check_document(result, options.beliefs, __version__))
            + "\n"
        )
    elif fmt in ("sarif", "github"):
        from launch_linter.report import formats

        sys.stdout.write(formats.render(fmt, result, options.beliefs, __version__))
    else:
        colour = _use_colour(ns.color)
        sys.stdout.write(text.format_diagnostics(result.diagnostics, colour))
        sys.stderr.write(text.summary(result.diagnostics, len(result.files)) + "\n")
    return _exit_status(result, ns.fail_on or config.fail_on or "warning")
