"""``launch-linter check``: lint launch files and report diagnostics."""

from __future__ import annotations

import argparse
import os
import sys
from collections.abc import Iterator, Sequence

from launch_linter import __version__
from launch_linter.commands.common import EXIT_FINDINGS, EXIT_OK, UsageError
from launch_linter.commands.fix_write import WriteGuard, refused_message
from launch_linter.commands.options import (
    STDIN_NAME,
    add_resolution_options,
    given_paths,
    lint_command_paths,
    lint_options,
    load_config,
    read_stdin,
    results_cache,
)
from launch_linter.engine import LintOptions, LintResult, lint_bytes
from launch_linter.model.diagnostic import Diagnostic, Severity
from launch_linter.model.paths import shown_path
from launch_linter.report import json_report, text
from launch_linter.report.escape import printable
from launch_linter.results_cache import ResultsCache
from launch_linter.workspace.config import Config


def add_parser(subparsers: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    check = subparsers.add_parser("check", help="lint launch files")
    add_resolution_options(check)
    check.add_argument(
        "--format", choices=("text", "json", "sarif", "github", "junit", "gitlab"), default=None
    )
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
    check.add_argument(
        "--no-cache", action="store_true", help="neither read nor write the results cache"
    )
    check.add_argument(
        "--cache-dir", metavar="DIR",
        help="the results cache's folder (default: .launch-linter-cache beside the "
        "configuration file, else in the current folder)",
    )
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


def _report(
    ns: argparse.Namespace, result: LintResult, options: LintOptions, config: Config | None
) -> str | Iterator[str]:
    """The report in the chosen format (statistics instead of findings if asked); JSON in
    pieces, so that a large run never holds its whole text."""
    fmt = ns.format or "text"
    if ns.statistics and fmt == "text":
        return text.statistics(result.diagnostics)
    if fmt == "json":
        return json_report.check_pieces(result, options.beliefs, __version__)
    if fmt in ("sarif", "github"):
        from launch_linter.report import formats

        return formats.render(fmt, result, options.beliefs, __version__)
    if fmt in ("junit", "gitlab"):
        from launch_linter.report import ci_formats

        if fmt == "gitlab":
            return ci_formats.gitlab(result.diagnostics)
        return ci_formats.junit(result, Severity(_fail_on(ns, config)))
    colour = _use_colour(ns.color) and not ns.output_file
    return text.format_diagnostics(result.diagnostics, colour)


def _write_output(ns: argparse.Namespace, report: str | Iterator[str]) -> None:
    pieces = [report] if isinstance(report, str) else report
    if not ns.output_file:
        for piece in pieces:
            sys.stdout.write(piece)
        return
    try:
        with open(ns.output_file, "w", encoding="utf-8") as handle:
            for piece in pieces:
                handle.write(piece)
    except OSError as exc:
        raise UsageError(f"cannot write {ns.output_file}: {exc.strerror or exc}") from None


def _refuse_output_over_input(ns: argparse.Namespace, result: LintResult) -> None:
    """``-o`` naming a file that was linted would overwrite the user's input."""
    if not ns.output_file or not os.path.exists(ns.output_file):
        return
    output = os.path.realpath(ns.output_file)
    if any(os.path.realpath(record.path) == output for record in result.files):
        raise UsageError(f"the output file {printable(ns.output_file)} is one of the files "
                         "linted; refusing to overwrite it")


def _write_guard(ns: argparse.Namespace) -> WriteGuard:
    """``--fix`` writes under the paths given (the current folder when none)."""
    return WriteGuard(given_paths(ns) or [os.curdir],
                      [ns.output_file] if ns.output_file else [])


def _print_notes(notes: Sequence[tuple[str, str]]) -> None:
    for path, reason in notes:
        sys.stderr.write(refused_message(path, reason) + "\n")


def _write_bytes(ns: argparse.Namespace, data: bytes) -> None:
    """A diff, byte for byte (its lines are the files' bytes, in their own encoding)."""
    if not ns.output_file:
        sys.stdout.flush()
        buffer = getattr(sys.stdout, "buffer", None)
        if buffer is None:  # a text-only stream (tests): the bytes as UTF-8 would show them
            sys.stdout.write(data.decode("utf-8", "surrogateescape"))
        else:
            buffer.write(data)
            buffer.flush()
        return
    try:
        with open(ns.output_file, "wb") as handle:
            handle.write(data)
    except OSError as exc:
        raise UsageError(f"cannot write {ns.output_file}: {exc.strerror or exc}") from None


def _run_fixes(ns: argparse.Namespace, options: LintOptions, config: Config,
               cache: ResultsCache | None) -> LintResult:
    """``--fix``: apply fixes, lint again until nothing changes; the last result. A fixed
    file changed, so the next pass lints it (and the roots that include it) again."""
    from launch_linter import fix as fixing
    from launch_linter.report import diff

    last: list[LintResult] = []

    def lint() -> tuple[object, ...]:
        last.append(lint_command_paths(ns, options, config, keep_trees=False, cache=cache))
        return last[-1].diagnostics

    notes: list[tuple[str, str]] = []
    counts, _ = fixing.fix_until_stable(
        lint, ns.unsafe_fixes, _write_guard(ns).write, notes=notes  # type: ignore[arg-type]
    )
    _print_notes(notes)
    if not ns.quiet:
        hidden = text.hidden_fixes(last[-1].diagnostics, ns.unsafe_fixes)
        sys.stderr.write(diff.fix_summary(counts, hidden) + "\n")
    return last[-1]


def _print_diff(ns: argparse.Namespace, options: LintOptions, config: Config,
                cache: ResultsCache | None) -> int:
    """``--diff``: what ``--fix`` would write, as a unified diff; no file changes. The
    same passes as ``--fix`` (fix, lint again, until nothing changes), each pass linting
    the texts fixed so far in place of the files. Exit 1 when there is any."""
    from launch_linter import fix as fixing
    from launch_linter.report import diff

    guard = _write_guard(ns)
    before: dict[str, bytes] = {}
    after: dict[str, bytes] = {}
    last: list[LintResult] = []

    def lint() -> tuple[Diagnostic, ...]:
        if not after:
            last.append(lint_command_paths(ns, options, config, False, cache))
        else:
            # Fixed texts are not on disk: no cached result holds for them.
            with fixing.unsaved_texts(after):
                last.append(lint_command_paths(ns, options, config, False, None))
        return last[-1].diagnostics

    def read(path: str) -> bytes | None:
        return after[path] if path in after else fixing.read_bytes(path)

    def keep(path: str, old: bytes, new: bytes) -> str | None:
        refused = guard.refusal(path)
        if refused is not None:
            return f"fixes not shown: --fix would not write it ({refused})"
        before.setdefault(path, old)
        after[path] = new
        return None

    notes: list[tuple[str, str]] = []
    counts, _ = fixing.fix_until_stable(lint, ns.unsafe_fixes, keep, read, notes)
    _refuse_output_over_input(ns, last[0])
    _print_notes(notes)
    out = [diff.unified_diff(shown_path(path), before[path], after[path]) for path in before]
    _write_bytes(ns, b"".join(out))
    if not ns.quiet:
        hidden = text.hidden_fixes(last[-1].diagnostics, ns.unsafe_fixes)
        sys.stderr.write(diff.diff_summary(sum(counts.values()), hidden) + "\n")
    return EXIT_FINDINGS if any(out) and not ns.exit_zero else EXIT_OK


def _fix_stdin(ns: argparse.Namespace, options: LintOptions) -> int:
    """``-`` with ``--fix``/``--diff``: the fixed bytes (or their diff) on stdout, in the
    encoding they came in."""
    from launch_linter import fix as fixing
    from launch_linter.report import diff

    if len(given_paths(ns)) > 1:
        raise UsageError("'-' (stdin) cannot be combined with other paths")
    name = getattr(ns, "stdin_filename", None) or STDIN_NAME
    data = read_stdin()
    current = data
    last: list[LintResult] = []

    def lint() -> tuple[Diagnostic, ...]:
        last.append(lint_bytes(current, name, options))
        return last[-1].diagnostics

    def read(path: str) -> bytes | None:
        return current if path == name else None

    def keep(path: str, old: bytes, new: bytes) -> str | None:
        nonlocal current
        current = new
        return None

    notes: list[tuple[str, str]] = []
    counts, _ = fixing.fix_until_stable(lint, ns.unsafe_fixes, keep, read, notes)
    result = last[-1]  # the lint of ``current``, the text as fixed
    _print_notes(notes)
    if ns.diff:
        _write_bytes(ns, diff.unified_diff(name, data, current))
        if not ns.quiet:
            hidden = text.hidden_fixes(result.diagnostics, ns.unsafe_fixes)
            sys.stderr.write(diff.diff_summary(sum(counts.values()), hidden) + "\n")
        return EXIT_FINDINGS if current != data and not ns.exit_zero else EXIT_OK
    if hasattr(sys.stdout, "buffer"):
        sys.stdout.flush()
        sys.stdout.buffer.write(current)
        sys.stdout.buffer.flush()
    else:
        sys.stdout.write(current.decode("utf-8", "replace"))
    if not ns.quiet:
        sys.stderr.write(text.format_diagnostics(result.diagnostics))
    return _status(ns, result, None)


def _fail_on(ns: argparse.Namespace, config: Config | None) -> str:
    return str(ns.fail_on or (config.fail_on if config is not None else None) or "warning")


def _status(ns: argparse.Namespace, result: LintResult, config: Config | None) -> int:
    if ns.exit_zero:
        return EXIT_OK
    return _exit_status(result, _fail_on(ns, config))


def run(ns: argparse.Namespace) -> int:
    config = load_config(ns)
    options = lint_options(ns, config)
    if ns.unsafe_fixes and not (ns.fix or ns.diff):
        raise UsageError("--unsafe-fixes needs --fix or --diff")
    if "-" in ns.paths and (ns.fix or ns.diff):
        return _fix_stdin(ns, options)
    # The cache serves --fix and --diff too: it holds findings before their fixes are
    # located, and locating reads each file as it is now, which the cache has just
    # found unchanged since the findings were made.
    cache = results_cache(ns, options, config)
    if cache is not None and ns.format == "json":
        # The report states the count of beliefs: kept with the run key, whose beliefs
        # part is the digest of their file, so that a cached run need not decode it.
        options.beliefs.know_count(cache.count("beliefs", lambda: options.beliefs.count))
    try:
        if ns.diff:
            return _print_diff(ns, options, config, cache)
        result = (
            _run_fixes(ns, options, config, cache)
            if ns.fix
            else lint_command_paths(ns, options, config, keep_trees=False, cache=cache)
        )
    finally:
        if cache is not None:
            cache.save()
    _refuse_output_over_input(ns, result)
    _write_output(ns, _report(ns, result, options, config))
    if (ns.format or "text") == "text" and not ns.quiet:
        sys.stderr.write(text.summary(result.diagnostics, len(result.files)) + "\n")
        hint = text.fix_hint(result.diagnostics) if not ns.fix else None
        if hint is not None:
            sys.stderr.write(hint + "\n")
    return _status(ns, result, config)
