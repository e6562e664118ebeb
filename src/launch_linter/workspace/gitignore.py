"""``.gitignore`` rules for folder discovery.

:func:`gitignore_predicate` gives the ``ignored(path, is_folder)`` predicate that
:func:`launch_linter.workspace.discovery.discover` accepts. Every ``.gitignore`` from the
repository's top (the nearest folder up holding ``.git``; without one, every folder up)
down to the path's folder applies, a deeper file overriding a shallower one, as
git does. A folder that is ignored is not entered.

A ``.gitignore`` comes with the repository, so its patterns are matched in linear time
(``model.globs``, git's wildmatch dialect), never by backtracking regular expressions
(``pathspec`` compiles ``**/*a*a/**/*a*a*b`` to one that takes minutes on a deep path).
"""

from __future__ import annotations

import os

from launch_linter.model.globs import Glob, gitignore_glob
from launch_linter.model.record import Record, _set
from launch_linter.resolve import reads
from launch_linter.resolve.xml_safe import read_regular_file

MAX_GITIGNORE_BYTES = 1024 * 1024
MAX_WALK_UP = 64
MAX_PATTERNS = 10_000
"""Lines of one ``.gitignore`` read (each is matched against every path below it)."""
MAX_PATTERN_CHARS = 4096
"""Longest pattern kept (a match costs pattern length times path length)."""


class Rule(Record):
    """One ``.gitignore`` line: its glob (``**/`` put before an unanchored one),
    whether it re-includes (``!``) and whether it applies to folders only (``/`` last)."""

    glob: Glob
    negated: bool
    folders_only: bool

    __slots__ = ("glob", "negated", "folders_only")

    def __init__(self, glob: Glob, negated: bool, folders_only: bool) -> None:
        _set(self, "glob", glob)
        _set(self, "negated", negated)
        _set(self, "folders_only", folders_only)

    def verdict(self, relative: str, is_folder: bool) -> bool | None:
        """True (ignored) or False (re-included) when the rule matches ``relative`` or a
        folder it lies in; None when it does not."""
        if self.glob.matches_a_folder_of(relative) or (
                (is_folder or not self.folders_only) and self.glob.match(relative)):
            return not self.negated
        return None


def parse_rule(line: str) -> Rule | None:
    """The rule of one ``.gitignore`` line, or None (blank, a comment, too long)."""
    line = line.rstrip("\r")
    stripped = line.rstrip(" ")
    # Trailing spaces are dropped, except one quoted with a backslash ("\ ").
    line = stripped + " " if stripped != line and stripped.endswith("\\") else stripped
    if not line or line.startswith("#") or len(line) > MAX_PATTERN_CHARS:
        return None
    negated = line.startswith("!")
    if negated:
        line = line[1:]
    folders_only = line.endswith("/") and not line.endswith("\\/")
    body = line.rstrip("/") if folders_only else line
    if not body:
        return None
    anchored = "/" in body
    body = body.lstrip("/") if anchored else body
    return Rule(gitignore_glob(body if anchored else "**/" + body), negated, folders_only)


class GitIgnore:
    """The ``.gitignore`` files met so far, read once each."""

    def __init__(self) -> None:
        self._specs: dict[str, tuple[Rule, ...] | None] = {}
        self._tops: dict[str, str] = {}
        self._chains: dict[str, list[tuple[str, tuple[Rule, ...]]]] = {}

    def _spec(self, directory: str) -> tuple[Rule, ...] | None:
        if directory not in self._specs:
            spec = None
            try:
                # A repository's file: a FIFO or device named .gitignore is not read.
                data = read_regular_file(os.path.join(directory, ".gitignore"),
                                         MAX_GITIGNORE_BYTES)
            except (OSError, ValueError):
                data = None  # no .gitignore, or not a regular file: nothing ignored here
            if data is not None:
                lines = data.decode("utf-8", "replace").split("\n")[:MAX_PATTERNS]
                rules = tuple(rule for rule in map(parse_rule, lines) if rule is not None)
                # Last rule first: the last one that matches decides.
                spec = tuple(reversed(rules)) or None
            self._specs[directory] = spec
        return self._specs[directory]

    def _top(self, directory: str) -> str:
        """The repository's top folder above ``directory`` (or ``directory`` itself)."""
        if directory in self._tops:
            return self._tops[directory]
        current = directory
        top = ""  # no repository: every .gitignore up the folders applies
        passed: list[str] = []
        for _ in range(MAX_WALK_UP):
            if current in self._tops:  # a folder further up answered already
                top = self._tops[current]
                break
            passed.append(current)
            if reads.exists(os.path.join(current, ".git")):
                top = current
                break
            parent = os.path.dirname(current)
            if parent == current:
                break
            current = parent
        for folder in passed:  # each folder on the way has the same top
            self._tops[folder] = top
        return top

    def _chain(self, directory: str) -> list[tuple[str, tuple[Rule, ...]]]:
        """The folders from the top down to ``directory`` that hold a ``.gitignore``, with
        its rules; worked out once per folder (a folder's files all share it)."""
        found = self._chains.get(directory)
        if found is None:
            top = self._top(directory)
            chain: list[str] = []
            current = directory
            for _ in range(MAX_WALK_UP):
                chain.append(current)
                if current == top:
                    break
                parent = os.path.dirname(current)
                if parent == current:
                    break
                current = parent
            found = []
            for folder in reversed(chain):  # the top first: deeper files override
                spec = self._spec(folder)
                if spec is not None:
                    found.append((folder, spec))
            self._chains[directory] = found
        return found

    def ignored(self, path: str, is_folder: bool) -> bool:
        path = os.path.abspath(path)
        verdict = False
        for folder, spec in self._chain(os.path.dirname(path)):
            # ``path`` is under ``folder`` and both are normal absolute paths: the path
            # relative to it is what follows it (os.path.relpath costs ten times more).
            relative = path[len(folder):].lstrip(os.sep).replace(os.sep, "/")
            for rule in spec:
                result = rule.verdict(relative, is_folder)
                if result is not None:
                    verdict = result
                    break
        return verdict


def gitignore_predicate() -> GitIgnore:
    """A fresh set of ``.gitignore`` rules; pass its ``ignored`` method to discovery."""
    return GitIgnore()
