"""The ``launch-linter`` command: a thin layer over the library API."""

from __future__ import annotations

import argparse
import os
import sys
from collections.abc import Callable, Sequence

from launch_linter import __version__
from launch_linter.config import Config, ConfigError, config_for
from launch_linter.discovery import Exclusions, Ignored
from launch_linter.engine import LintOptions, LintResult, lint_paths, lint_text
from launch_linter.model.beliefs import BeliefSet
from launch_linter.model.diagnostic import Severity
from launch_linter.report import json_report, text
from launch_linter.rules import RULES, RULES_BY_ID

EXIT_OK, EXIT_FINDINGS, EXIT_USAGE = 0, 1, 2


class UsageError(Exception):
    """A command-line mistake: reported on stderr, exit status 2."""


def _split_ids(values: list[str] | None) -> list[str]:
    ids: list[str] = []
    for value in values or []:
        ids.extend(v.strip() for v in value.split(",") if v.strip())
    return ids


def _check_ids(ids: list[str], where: str = "--select/--ignore") -> None:
    from launch_linter.config import ConfigError, check_rule_ids

    try:
        check_rule_ids(ids, where)
    except ConfigError as exc:
        raise UsageError(str(exc)) from None


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
        "--jobs", type=int, default=None, metavar="N", help="lint files in N processes"
    )
    _add_discovery_options(parser)


def _add_discovery_options(parser: argparse.ArgumentParser) -> None:
    parser.add_argument(
        "--exclude",
        action="append",
        metavar="PATTERNS",
        help="globs of paths to leave out of folder walks, replacing the defaults "
        "(comma-separated, repeatable)",
    )
    parser.add_argument(
        "--extend-exclude",
        action="append",
        metavar="PATTERNS",
        help="globs of paths to leave out in addition to the defaults",
    )
    parser.add_argument(
        "--no-respect-gitignore",
        dest="respect_gitignore",
        action="store_false",
        default=None,
        help="also lint files that .gitignore ignores",
    )
    parser.add_argument(
        "--ros",
        type=int,
        choices=(1, 2),
        default=None,
        help="read XML launch files as this ROS's (default: the package.xml, then content)",
    )
    parser.add_argument(
        "--ros-distro",
        default=None,
        metavar="NAME",
        help="the target ROS 2 distribution (e.g. humble), for fixes that depend on it",
    )
    parser.add_argument(
        "--stdin-filename",
        metavar="NAME",
        help="the file name of the text read from '-' (for paths, packages, config)",
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
    check.add_argument("-o", "--output-file", metavar="FILE", help="write the report to FILE")
    check.add_argument(
        "--statistics", action="store_true", help="a count per rule instead of each finding"
    )
    check.add_argument(
        "--exit-zero", action="store_true", help="exit 0 even when findings reach --fail-on"
    )
    check.add_argument(
        "-q", "--quiet", action="store_true", help="print findings only, no summary"
    )
    check.add_argument("--fix", action="store_true", help="apply the safe fixes")
    check.add_argument(
        "--unsafe-fixes", action="store_true", help="with --fix or --diff, also the unsafe fixes"
    )
    check.add_argument(
        "--diff", action="store_true", help="print the fixes as a diff and change no file"
    )

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

    graph = sub.add_parser(
        "graph", help="draw the static transform trees of a launch file or a folder"
    )
    graph.add_argument("path")
    _add_discovery_options(graph)
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


def input_paths(ns: argparse.Namespace) -> list[str]:
    """The paths to lint: those given, the stdin file name for ``-``, else ``.``."""
    given = getattr(ns, "paths", None)
    if given is None:
        given = [ns.path]
    if not given:
        return [os.curdir]
    stdin_name = getattr(ns, "stdin_filename", None)
    return [stdin_name or "stdin.launch" if p == "-" else p for p in given]


def load_config(ns: argparse.Namespace) -> Config:
    """The configuration file for this command's paths (``--config`` or found)."""
    paths = input_paths(ns)
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
        ros=ns.ros if getattr(ns, "ros", None) is not None else config.ros,
        ros_distro=(getattr(ns, "ros_distro", None) or config.ros_distro or "").lower() or None,
    )


def discovery_for(ns: argparse.Namespace, config: Config) -> tuple[Exclusions, Ignored | None]:
    """Folder-walk exclusions and the ``.gitignore`` predicate, flags over the file."""
    exclude = _split_ids(getattr(ns, "exclude", None)) or None
    if exclude is None and config.exclude is not None:
        exclude = list(config.exclude)
    extend = [*config.extend_exclude, *_split_ids(getattr(ns, "extend_exclude", None))]
    base = os.path.dirname(os.path.abspath(config.path)) if config.path else os.curdir
    exclusions = Exclusions.of(exclude, extend, base)
    respect = getattr(ns, "respect_gitignore", None)
    if respect is None:
        respect = config.respect_gitignore if config.respect_gitignore is not None else True
    if not respect:
        return exclusions, None
    try:
        from launch_linter.gitignore import gitignore_predicate
    except ImportError:  # the standalone linter carries no pathspec: .gitignore not read
        return exclusions, None
    return exclusions, gitignore_predicate().ignored


def lint_command_paths(
    ns: argparse.Namespace, options: LintOptions, config: Config
) -> LintResult:
    """Lint the command's paths (``-``: the text on stdin)."""
    given = getattr(ns, "paths", None)
    if given is None:
        given = [ns.path]
    if "-" in given:
        if len(given) > 1:
            raise UsageError("'-' (stdin) cannot be combined with other paths")
        name = getattr(ns, "stdin_filename", None) or "stdin.launch"
        return lint_text(sys.stdin.read(), name, options)
    exclusions, ignored = discovery_for(ns, config)
    return lint_paths(given or [os.curdir], options, exclusions, ignored)


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


def _report(ns: argparse.Namespace, result: LintResult, options: LintOptions) -> str:
    """The report in the chosen format (statistics instead of findings if asked)."""
    fmt = ns.format or "text"
    if ns.statistics and fmt == "text":
        return text.statistics(result.diagnostics)
    if fmt == "json":
        document = json_report.check_document(result, options.beliefs, __version__)
        return json_report.dumps(document) + "\n"
    if fmt in ("sarif", "github"):
        from launch_linter.report import formats

        return formats.render(fmt, result, options.beliefs, __version__)
    colour = _use_colour(ns.color) and not ns.output_file
    return text.format_diagnostics(result.diagnostics, colour)


def _write_output(ns: argparse.Namespace, report: str) -> None:
    if not ns.output_file:
        sys.stdout.write(report)
        return
    try:
        with open(ns.output_file, "w", encoding="utf-8") as handle:
            handle.write(report)
    except OSError as exc:
        raise UsageError(f"cannot write {ns.output_file}: {exc.strerror or exc}") from None


def _run_fixes(ns: argparse.Namespace, options: LintOptions, config: Config) -> LintResult:
    """``--fix``: apply fixes, lint again until nothing changes; the last result."""
    from launch_linter import fix as fixing

    last: list[LintResult] = []

    def lint() -> tuple[object, ...]:
        last.append(lint_command_paths(ns, options, config))
        return last[-1].diagnostics

    counts, _ = fixing.fix_until_stable(
        lint, ns.unsafe_fixes, fixing.write_file  # type: ignore[arg-type]
    )
    if not ns.quiet:
        total = sum(counts.values())
        detail = ", ".join(f"{rule} {n}" for rule, n in sorted(counts.items()))
        sys.stderr.write(f"fixed {total} finding(s)" + (f" ({detail})" if detail else "") + "\n")
    return last[-1]


def _print_diff(ns: argparse.Namespace, result: LintResult) -> int:
    """``--diff``: the fixes as a unified diff; no file changes. Exit 1 when there is any."""
    from launch_linter import fix as fixing

    out: list[str] = []
    for path, fixes in fixing.fixes_by_file(result.diagnostics, ns.unsafe_fixes).items():
        before = fixing.read_bytes(path)
        if before is None:
            continue
        after, _ = fixing.apply_edits(before, fixes)
        out.append(fixing.unified_diff(path, before, after))
    _write_output(ns, "".join(out))
    return EXIT_FINDINGS if any(out) and not ns.exit_zero else EXIT_OK


def _fix_stdin(ns: argparse.Namespace, options: LintOptions) -> int:
    """``-`` with ``--fix``/``--diff``: the fixed text (or its diff) on stdout."""
    from launch_linter import fix as fixing

    name = getattr(ns, "stdin_filename", None) or "stdin.launch"
    data = sys.stdin.buffer.read() if hasattr(sys.stdin, "buffer") else sys.stdin.read().encode()
    current = data
    for _ in range(fixing.MAX_FIX_PASSES):
        result = lint_text(current.decode("utf-8", "replace"), name, options)
        fixes = fixing.fixes_by_file(result.diagnostics, ns.unsafe_fixes).get(name, [])
        fixed, _ = fixing.apply_edits(current, fixes)
        if fixed == current:
            break
        current = fixed
    if ns.diff:
        _write_output(ns, fixing.unified_diff(name, data, current))
        return EXIT_FINDINGS if current != data and not ns.exit_zero else EXIT_OK
    sys.stdout.write(current.decode("utf-8", "replace"))
    result = lint_text(current.decode("utf-8", "replace"), name, options)
    if not ns.quiet:
        sys.stderr.write(text.format_diagnostics(result.diagnostics))
    return _status(ns, result, None)


def _status(ns: argparse.Namespace, result: LintResult, config: Config | None) -> int:
    if ns.exit_zero:
        return EXIT_OK
    fail_on = ns.fail_on or (config.fail_on if config is not None else None) or "warning"
    return _exit_status(result, fail_on)


def run_check(ns: argparse.Namespace) -> int:
    config = load_config(ns)
    options = lint_options(ns, config)
    if ns.unsafe_fixes and not (ns.fix or ns.diff):
        raise UsageError("--unsafe-fixes needs --fix or --diff")
    if "-" in ns.paths and (ns.fix or ns.diff):
        return _fix_stdin(ns, options)
    if ns.diff:
        return _print_diff(ns, lint_command_paths(ns, options, config))
    fixing = ns.fix
    result = _run_fixes(ns, options, config) if fixing else lint_command_paths(ns, options, config)
    _write_output(ns, _report(ns, result, options))
    if (ns.format or "text") == "text" and not ns.quiet:
        sys.stderr.write(text.summary(result.diagnostics, len(result.files)) + "\n")
    return _status(ns, result, config)


def run_transforms(ns: argparse.Namespace) -> int:
    config = load_config(ns)
    result = lint_command_paths(ns, lint_options(ns, config), config)
    if ns.format == "json":
        sys.stdout.write(json_report.dumps(json_report.transforms_document(result)) + "\n")
    else:
        for transform in result.transforms:
            sys.stdout.write(text.format_transform(transform) + "\n")
    return EXIT_OK


def run_rules(ns: argparse.Namespace) -> int:
    width = max(len(r.id) for r in RULES)
    for rule in RULES:
        fix = rule.fix.value if rule.fix else "-"
        sys.stdout.write(
            f"{rule.id:<{width}}  {rule.category.value:<12}  "
            f"{rule.severity.value:<7}  {fix:<6}  {rule.summary}\n"
        )
    return EXIT_OK


def run_explain(ns: argparse.Namespace) -> int:
    rule = RULES_BY_ID.get(ns.rule)
    if rule is None:
        import difflib

        close = difflib.get_close_matches(ns.rule, list(RULES_BY_ID), n=1)
        hint = f" (did you mean {close[0]!r}?)" if close else ""
        raise UsageError(f"unknown rule {ns.rule!r}{hint} (see 'launch-linter rules')")
    fix = f", {rule.fix.value} fix" if rule.fix else ""
    sys.stdout.write(
        f"{rule.id} ({rule.category.value}, {rule.severity.value}{fix})\n\n{rule.doc}\n"
    )
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
