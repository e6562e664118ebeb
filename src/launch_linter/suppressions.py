"""Inline suppressions written in launch files, and per-path ignores from the configuration.

A directive is a comment whose text (after an optional leading ``#``, for YAML and Python
launch files) starts with ``launch-linter:``::

    <!-- launch-linter: disable=dup_sig,rot_degrees -->       the next element
    <!-- launch-linter: disable-file=leading_slash -->         the whole file

``disable`` applies to the first element that starts on a later line than the comment
ends; ``disable-file`` to every diagnostic located in the comment's file. Ids are rule ids
or categories, separated by commas; free text may follow after a space (a reason).

Each id of a directive that suppresses nothing is reported as ``unused_suppression``, and
so are unknown ids and comments that start with ``launch-linter:`` but are not a directive.
An id naming a rule that did not run (``--select``/``--ignore``) is never reported unused:
whether it would have matched is unknown.
"""

from __future__ import annotations

import bisect
import os
import re
from collections.abc import Collection, Iterable, Mapping, Sequence

from launch_linter.model.diagnostic import Diagnostic, Problem
from launch_linter.model.globs import path_glob
from launch_linter.model.launch import DIRECTIVE_MARKER, LaunchTree
from launch_linter.model.record import Record, _set

UNUSED_ID = "unused_suppression"
PREFIX = DIRECTIVE_MARKER
_DIRECTIVE = (  # compiled on first use (``re`` keeps it): most files have no directive
    r"(?s)launch-linter:\s*(?P<kind>disable-file|disable)\s*=\s*"
    r"(?P<ids>[A-Za-z0-9_.-]+(?:\s*,\s*[A-Za-z0-9_.-]+)*)(?P<rest>.*)"
)


class Directive(Record):
    """One ``launch-linter:`` comment; ``target`` is the element line it covers."""

    path: str
    line: int
    """The line the comment ends on (where problems with it are reported)."""
    whole_file: bool
    ids: tuple[str, ...]
    target: int | None
    """Start line of the next element; None for ``disable-file`` or when none follows."""

    __slots__ = ("path", "line", "whole_file", "ids", "target")

    def __init__(
        self,
        path: str,
        line: int,
        whole_file: bool,
        ids: tuple[str, ...],
        target: int | None,
    ) -> None:
        _set(self, "path", path)
        _set(self, "line", line)
        _set(self, "whole_file", whole_file)
        _set(self, "ids", ids)
        _set(self, "target", target)


class Malformed(Record):
    """A comment that starts with ``launch-linter:`` but is not a directive."""

    path: str
    line: int
    text: str

    __slots__ = ("path", "line", "text")

    def __init__(self, path: str, line: int, text: str) -> None:
        _set(self, "path", path)
        _set(self, "line", line)
        _set(self, "text", text)


class PathIgnore(Record):
    """``per-path-ignores``: rules (or categories) ignored in files matching ``pattern``.

    ``pattern`` is relative to ``base`` (the configuration file's folder) and only matches
    files under it; ``*`` and ``?`` stay within one path segment, ``**`` spans segments,
    and a pattern without ``/`` matches the file name at any depth.
    """

    base: str
    pattern: str
    ids: frozenset[str]

    __slots__ = ("base", "pattern", "ids")

    def __init__(self, base: str, pattern: str, ids: frozenset[str]) -> None:
        _set(self, "base", base)
        _set(self, "pattern", pattern)
        _set(self, "ids", ids)

    def matches(self, path: str) -> bool:
        absolute = os.path.abspath(path)
        relative = os.path.relpath(absolute, os.path.abspath(self.base)).replace(os.sep, "/")
        if relative.startswith("../"):
            return False
        if "/" not in self.pattern:
            return glob_match(self.pattern, os.path.basename(absolute))
        return glob_match(_without_dot_slash(self.pattern), relative)


def _without_dot_slash(pattern: str) -> str:
    return pattern[2:] if pattern.startswith("./") else pattern


def glob_match(pattern: str, text: str) -> bool:
    """Whether ``text`` matches the glob ``pattern`` (see :class:`PathIgnore`).

    The pattern comes from a repository's configuration, so it is matched by simulating
    all its positions at once (``model.globs``: time proportional to pattern length times
    text length), not by a backtracking regular expression, which ``*a*a*a*a*b`` would
    make exponential.
    """
    return path_glob(pattern).match(text)


def _directive_text(comment: str) -> str:
    return comment.strip().lstrip("#").strip()


def parse_directives(trees: Iterable[LaunchTree]) -> tuple[list[Directive], list[Malformed]]:
    """Every directive in the files of ``trees``, once each even if a file is read twice."""
    directives: dict[Directive, None] = {}
    malformed: dict[Malformed, None] = {}
    for tree in trees:
        starts: dict[str, list[int]] = {}
        for path, line in tree.element_lines:
            starts.setdefault(path, []).append(line)
        for lines in starts.values():
            lines.sort()
        for comment in tree.comments:
            text = _directive_text(comment.text)
            if not text.startswith(PREFIX):
                continue
            match = re.fullmatch(_DIRECTIVE, text)
            if match is None or (match["rest"] and not match["rest"][0].isspace()):
                malformed[Malformed(comment.path, comment.line, text)] = None
                continue
            whole_file = match["kind"] == "disable-file"
            ids = tuple(dict.fromkeys(i.strip() for i in match["ids"].split(",")))
            target = None if whole_file else _next_line(starts.get(comment.path, []),
                                                         comment.line)
            directives[Directive(comment.path, comment.line, whole_file, ids, target)] = None
    return list(directives), list(malformed)


def _next_line(sorted_lines: list[int], line: int) -> int | None:
    """The first element line after ``line`` (a binary search: a file of 20,000 directives
    searched every element line once per directive)."""
    index = bisect.bisect_right(sorted_lines, line)
    return sorted_lines[index] if index < len(sorted_lines) else None


def _names(diagnostic: Diagnostic) -> tuple[str, str]:
    return (diagnostic.rule, diagnostic.category.value)


class _CoverIndex:
    """The directives that cover a finding (a whole-file directive of its file, or one
    whose next element is on its line), looked up by file and line: checking every finding
    against every directive was quadratic (20,000 directives in one file: more than 30 s)."""

    def __init__(self, directives: Iterable[Directive]) -> None:
        self._files: dict[str, list[Directive]] = {}
        self._lines: dict[tuple[str, int], list[Directive]] = {}
        for directive in directives:
            if directive.whole_file:
                self._files.setdefault(directive.path, []).append(directive)
            elif directive.target is not None:
                self._lines.setdefault((directive.path, directive.target), []).append(directive)

    def of(self, finding: Diagnostic | Problem) -> list[Directive]:
        """The directives covering ``finding``, in the order they were given (by kind)."""
        return (self._files.get(finding.path, [])
                + self._lines.get((finding.path, finding.line), []))


def _unused(path: str, line: int, message: str) -> Problem:
    return Problem(UNUSED_ID, path, line, 1, message)


def apply_suppressions(
    trees: Sequence[LaunchTree],
    diagnostics: Iterable[Diagnostic],
    known: Mapping[str, str],
    ran: Collection[str],
    report_unused: bool,
) -> tuple[list[Diagnostic], list[Problem]]:
    """Drop what the directives in ``trees`` suppress; return (kept, unused-suppression).

    The unused-suppression problems carry no severity: the engine stamps them from the
    rule registry like every other rule's findings.

    ``known`` maps every rule id to its category; ``ran`` holds the ids of the rules that
    ran. ``report_unused`` is False when ``unused_suppression`` itself is not selected.
    """
    directives, malformed = parse_directives(trees)
    categories = set(known.values())
    used: set[tuple[Directive, str]] = set()
    kept: list[Diagnostic] = []
    covering = _CoverIndex(directives)
    for diagnostic in diagnostics:
        hits = [
            (directive, name)
            for directive in covering.of(diagnostic)
            for name in _names(diagnostic)
            if name in directive.ids
        ]
        if hits:
            used.update(hits)
        else:
            kept.append(diagnostic)
    if not report_unused:
        return kept, []
    ran_categories = {known[r] for r in ran if r in known}
    unused: list[Problem] = [
        _unused(m.path, m.line, f"not a launch-linter directive: {m.text!r} "
                "(expected 'launch-linter: disable=RULE,…' or 'disable-file=RULE,…')")
        for m in malformed
    ]
    for directive in directives:
        kind = "disable-file" if directive.whole_file else "disable"
        for name in directive.ids:
            if name not in known and name not in categories:
                unused.append(_unused(
                    directive.path, directive.line,
                    f"unknown rule {name!r} in '{kind}' directive; it suppresses nothing "
                    "(see 'launch-linter rules')",
                ))
            elif (directive, name) in used or name == UNUSED_ID:
                continue
            elif name in ran or name in ran_categories:
                reason = (
                    f"no {name} diagnostic in this file" if directive.whole_file
                    else f"no {name} diagnostic on the next element (line {directive.target})"
                    if directive.target is not None
                    else "no element follows the comment"
                )
                unused.append(_unused(
                    directive.path, directive.line,
                    f"'{kind}={name}' suppresses nothing: {reason}",
                ))
    # A directive may silence the reports about directives (disable-file=unused_suppression).
    reported = [
        d for d in unused
        if not any(UNUSED_ID in directive.ids for directive in covering.of(d))
    ]
    return kept, reported


def ignored_by_path(diagnostic: Diagnostic, ignores: Iterable[PathIgnore]) -> bool:
    """True when a ``per-path-ignores`` entry covers the diagnostic's file and rule."""
    names = _names(diagnostic)
    return any(
        (names[0] in ignore.ids or names[1] in ignore.ids) and ignore.matches(diagnostic.path)
        for ignore in ignores
    )
