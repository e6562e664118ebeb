"""The ``launch-linter`` command: a thin layer over the library API."""

from __future__ import annotations

import argparse
import os
import sys
from collections.abc import Callable, Sequence

from launch_linter import __version__
from launch_linter.config import Config, ConfigError, config_for
from launch_linter.engine import LintOptions, LintResult, lint_paths
from launch_linter.model.beliefs import BeliefSet
from launch_linter.model.diagnostic import Severity
from launch_linter.report import json_report, text
from launch_linter.rules import RULES, RULES_BY_ID
from launch_linter.rules._profiles import PROFILES

EXIT_OK, EXIT_FINDINGS, EXIT_USAGE = 0, 1, 2


class UsageError(Exception):
    """A command-line mistake: reported on stderr, exit status 2."""


def _split_ids(values: list[str] | None) -> list[str]:
    ids: list[str] = []
    for value in values or []:
        ids.extend(v.strip() for v in value.split(",") if v.strip())
    return ids


def _check_ids(ids: list[str]) -> None:
    categories = {r.category.value for r in RULES}
    unknown = [i for i in ids if i not in RULES_BY_ID and i not in categories]
    if unknown:
        raise UsageError(f"unknown rule id(s): {', '.join(unknown)} (see 'launch-linter rules')")


def _pairs(values: list[str] | None, separator: str, what: str) -> dict[str, str]:
    out: dict[str, str] = {}
    for value in values or []:
        name, sep, rest = value.partition(separator)
        if not sep or not name:
            raise UsageError(f"{what} must look like NAME{separator}VALUE, not {value!r}")
        out[name] = rest
    return out


def _add_resolution_options(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("paths", nargs="*", metavar="PATH", help="launch files or folders")
    parser.add_argument(
        "--arg",
        action="append",
        metavar="NAME:=VALUE",
        help="set a launch argument, as on the roslaunch command line",
    )
    parser.add_argument(
        "--package-path",
        action="append",
        metavar="DIR",
        help="folder to search for packages for $(find) (repeatable)",
    )
    parser.add_argument(
        "--env",
        action="append",
        metavar="NAME=VALUE",
        help="environment variable for $(env)/$(optenv) (repeatable)",
    )
    parser.add_argument("--config", metavar="FILE", help="configuration file")
    parser.add_argument(
        "--profile",
        choices=PROFILES,
        default=None,
        help="default, or study: the study's checks and severities (docs/severity.md)",
    )
    parser.add_argument(
        "--ros-distro",
        default=None,
        metavar="NAME",
        help="target ROS distribution (default: the ros-distro key, else $ROS_DISTRO, "
        "else what the files show)",
    )
    parser.add_argument(
        "--jobs", type=int, default=None, metavar="N", help="lint files in N processes"
    )


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="launch-linter",
        description="Find mistakes in the static transforms of ROS launch files.",
    )
    parser.add_argument("--version", action="version", version=f"launch-linter {__version__}")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND")

    check = sub.add_parser("check", help="lint launch files")
    _add_resolution_options(check)
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

    transforms = sub.add_parser("transforms", help="print every static transform found")
    _add_resolution_options(transforms)
    transforms.add_argument("--format", choices=("text", "json"), default="text")

    sub.add_parser("rules", help="table of every rule")
    explain = sub.add_parser("explain", help="documentation of one rule")
    explain.add_argument("rule")

    mine = sub.add_parser("mine", help="ingest a corpus into a database and mine beliefs")
    mine.add_argument("corpus")
    mine.add_argument("--db", required=True)
    mine.add_argument("--p0", type=float, default=0.9)
    mine.add_argument("--mature-commits", type=int, default=30)
    mine.add_argument(
        "--mature",
        action="append",
        metavar="REPO",
        help="treat this repository folder as mature (plain folders)",
    )
    mine.add_argument("--jobs", type=int, default=None)

    beliefs = sub.add_parser("beliefs", help="list mined beliefs or write a beliefs file")
    beliefs.add_argument("--db", required=True)
    beliefs.add_argument("--min-z", type=float, default=None)
    beliefs.add_argument("--class", dest="classes", action="append", metavar="CLASS")
    beliefs.add_argument("--format", choices=("table", "json"), default="table")
    beliefs.add_argument("-o", "--output", metavar="FILE")

    generate = sub.add_parser("generate", help="render a standalone linter from beliefs")
    generate.add_argument("--beliefs", default="bundled")
    generate.add_argument("--min-z", type=float, default=1.0)
    generate.add_argument("--class", dest="classes", action="append", metavar="CLASS")
    generate.add_argument("-o", "--output", required=True, metavar="FILE.py")

    evaluate = sub.add_parser("evaluate", help="reproduce the study's Table IV on a database")
    evaluate.add_argument("--db", required=True)
    evaluate.add_argument("--min-z", type=float, default=1.0)
    evaluate.add_argument("--out", default="evaluation", metavar="DIR")
    evaluate.add_argument("--beliefs", default=None)

    graph = sub.add_parser("graph", help="draw the static transform tree of a launch file")
    graph.add_argument("path")
    graph.add_argument("-o", "--output", metavar="FILE.svg|.png|.dot|.mmd")
    graph.add_argument("--arg", action="append", metavar="NAME:=VALUE")
    graph.add_argument("--package-path", action="append", metavar="DIR")
    graph.add_argument("--env", action="append", metavar="NAME=VALUE")
    graph.add_argument("--config", metavar="FILE", help="configuration file")
    graph.add_argument(
        "--beliefs",
        default=None,
        metavar="bundled|study|none|FILE",
        help="mined beliefs for the may_implied rules (default: bundled)",
    )
    return parser


def load_beliefs(spec: str | None, min_z: float) -> BeliefSet:
    from launch_linter.beliefs_files import BeliefsNotFound
    from launch_linter.beliefs_files import load_beliefs as load

    try:
        return load(spec or "bundled", min_z)
    except BeliefsNotFound as exc:
        raise UsageError(str(exc)) from None


def load_config(ns: argparse.Namespace) -> Config:
    """The configuration file for this command's paths (``--config`` or found)."""
    paths = getattr(ns, "paths", None) or [ns.path]
    try:
        return config_for(paths, getattr(ns, "config", None))
    except ConfigError as exc:
        raise UsageError(str(exc)) from None


def lint_options(ns: argparse.Namespace, config: Config | None = None) -> LintOptions:
    """Command-line flags over the configuration file, key by key."""
    config = config if config is not None else load_config(ns)
    select = _split_ids(getattr(ns, "select", None))
    ignore = _split_ids(getattr(ns, "ignore", None))
    _check_ids(select + ignore)
    if not select:
        select = list(config.select or ())
    if not ignore:
        ignore = list(config.ignore or ())
    jobs = getattr(ns, "jobs", None)
    jobs = 1 if jobs is None else jobs
    if jobs < 1:
        raise UsageError("--jobs must be at least 1")
    beliefs = BeliefSet.empty()
    if ns.command in ("check", "graph"):
        min_z = getattr(ns, "min_z", None)
        if min_z is None:
            min_z = config.min_z if config.min_z is not None else 1.0
        beliefs = load_beliefs(getattr(ns, "beliefs", None) or config.beliefs, min_z)
    return LintOptions(
        args={**config.args, **_pairs(ns.arg, ":=", "--arg")},
        env={**config.env, **_pairs(ns.env, "=", "--env")},
        package_paths=tuple(ns.package_path) if ns.package_path else config.package_path,
        select=frozenset(select) if select else None,
        ignore=frozenset(ignore),
        severity=dict(config.severity),
        beliefs=beliefs,
        jobs=jobs,
        per_path_ignores=config.per_path_ignores,
        profile=getattr(ns, "profile", None) or config.profile or "default",
        ros_distro=_ros_distro(getattr(ns, "ros_distro", None), config.ros_distro),
    )


def _ros_distro(given: str | None, configured: str | None) -> str | None:
    """``--ros-distro``, else the configuration key, else ``ROS_DISTRO`` from the real
    environment (a sourced ROS setup names its distribution there); unknown names given
    on the command line are a usage error, an unknown ``ROS_DISTRO`` is passed over."""
    from launch_linter.distro import ROS1_DISTROS, ROS2_DISTROS, is_known, normalise

    name = normalise(given) or normalise(configured)
    if name is not None:
        if not is_known(name):
            known = ", ".join((*ROS1_DISTROS, *ROS2_DISTROS))
            raise UsageError(f"unknown ROS distribution {name!r} (known: {known})")
        return name
    from_env = normalise(os.environ.get("ROS_DISTRO"))
    return from_env if from_env is not None and is_known(from_env) else None


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


def run_check(ns: argparse.Namespace) -> int:
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


def run_transforms(ns: argparse.Namespace) -> int:
    if not ns.paths:
        raise UsageError("transforms needs at least one PATH")
    result = lint_paths(ns.paths, lint_options(ns))
    if ns.format == "json":
        sys.stdout.write(json_report.dumps(json_report.transforms_document(result)) + "\n")
    else:
        for transform in result.transforms:
            sys.stdout.write(text.format_transform(transform) + "\n")
    return EXIT_OK


def run_rules(ns: argparse.Namespace) -> int:
    from launch_linter.measured import precision_text
    from launch_linter.rules._profiles import study_severity

    width = max(len(r.id) for r in RULES)
    for rule in RULES:
        study = study_severity(rule.id, rule.severity)
        level = rule.severity.value if study is rule.severity else (
            f"{rule.severity.value} (study: {study.value})")
        sys.stdout.write(
            f"{rule.id:<{width}}  {rule.category.value:<12}  {level:<24}  "
            f"{precision_text(rule.id):<32}  {rule.summary}\n"
        )
    return EXIT_OK


def run_explain(ns: argparse.Namespace) -> int:
    rule = RULES_BY_ID.get(ns.rule)
    if rule is None:
        raise UsageError(f"unknown rule {ns.rule!r} (see 'launch-linter rules')")
    sys.stdout.write(f"{rule.id} ({rule.category.value}, {rule.severity.value})\n\n{rule.doc}\n")
    return EXIT_OK


def main(argv: Sequence[str] | None = None) -> int:
    parser = build_parser()
    ns = parser.parse_args(argv)
    if ns.command is None:
        parser.print_help()
        return EXIT_USAGE
    handlers: dict[str, Callable[[argparse.Namespace], int]] = {
        "check": run_check,
        "transforms": run_transforms,
        "rules": run_rules,
        "explain": run_explain,
    }
    try:
        handler = handlers.get(ns.command) or _extension_handler(ns.command)
        return handler(ns)
    except UsageError as exc:
        sys.stderr.write(f"launch-linter: error: {exc}\n")
        return EXIT_USAGE
    except BrokenPipeError:
        return EXIT_OK
    except KeyboardInterrupt:
        sys.stderr.write("launch-linter: interrupted\n")
        return EXIT_USAGE
    except Exception as exc:  # the contract: an internal failure is exit 2, never exit 1
        if os.environ.get("LAUNCH_LINTER_DEBUG"):
            raise
        sys.stderr.write(
            f"launch-linter: internal error: {type(exc).__name__}: {exc}\n"
            "(set LAUNCH_LINTER_DEBUG=1 for the traceback, and please report it)\n"
        )
        return EXIT_USAGE


def _extension_handler(command: str) -> Callable[[argparse.Namespace], int]:
    """Commands that need the heavier libraries import them only when used."""
    if command in ("mine", "beliefs"):
        from launch_linter.mining import commands as mining_commands

        return mining_commands.run_mine if command == "mine" else mining_commands.run_beliefs
    if command == "generate":
        from launch_linter.generate import commands as generate_commands

        return generate_commands.run_generate
    if command == "evaluate":
        from launch_linter.evaluation import commands as evaluation_commands

        return evaluation_commands.run_evaluate
    from launch_linter.graph import commands as graph_commands

    return graph_commands.run_graph
