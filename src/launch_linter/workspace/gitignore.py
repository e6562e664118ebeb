"""``.gitignore`` rules for folder discovery (an edge module: it uses ``pathspec``).

:func:`gitignore_predicate` gives the ``ignored(path, is_folder)`` predicate that
:func:`launch_linter.workspace.discovery.discover` accepts. Every ``.gitignore`` from the
repository's top (the nearest folder up holding ``.git``; without one, every folder up)
down to the path's folder applies, a deeper file overriding a shallower one, as
git does. A folder that is ignored is not entered.

``pathspec`` is imported when the first ``.gitignore`` is read: a run over files, or over
folders without one, does not pay for it at start-up. Without ``pathspec`` (the standalone
linter carries none) no ``.gitignore`` is read and nothing is ignored.
"""

from __future__ import annotations

import os
import re
import typing

from launch_linter.resolve import reads
from launch_linter.resolve.xml_safe import read_regular_file

if typing.TYPE_CHECKING:
    import pathspec

MAX_GITIGNORE_BYTES = 1024 * 1024
MAX_WALK_UP = 64
MAX_STARS_PER_SEGMENT = 2
"""``pathspec`` matches with Python's backtracking regular expressions: a segment with k
single ``*`` costs up to n^k steps on a name of n characters (``*a*a*a*a*b`` on a 255-character
name: seconds per path). Real patterns hold one or two (``*.tar.*``); a pattern with more
is dropped (it then ignores nothing)."""
MAX_PATTERNS = 10_000
"""Lines of one ``.gitignore`` read (each is matched against every path below it)."""
_STARS = re.compile(r"(?<!\*)\*(?!\*)")


class GitIgnore:
    """The ``.gitignore`` files met so far, read once each."""

    def __init__(self) -> None:
        self._specs: dict[str, pathspec.GitIgnoreSpec | None] = {}
        self._tops: dict[str, str] = {}
        self._chains: dict[str, list[tuple[str, pathspec.GitIgnoreSpec]]] = {}

    def _spec(self, directory: str) -> pathspec.GitIgnoreSpec | None:
        if directory not in self._specs:
            spec = None
            try:
                # A repository's file: a FIFO or device named .gitignore is not read.
                data = read_regular_file(os.path.join(directory, ".gitignore"),
                                         MAX_GITIGNORE_BYTES)
                lines = [line for line in data.decode("utf-8", "replace").splitlines()
                         [:MAX_PATTERNS] if _cheap(line)]
                import pathspec

                spec = pathspec.GitIgnoreSpec.from_lines(lines)
            except (OSError, ValueError, ImportError):
                # no .gitignore, one pathspec cannot read, or no pathspec: nothing ignored
                spec = None
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

    def _chain(self, directory: str) -> list[tuple[str, pathspec.GitIgnoreSpec]]:
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
            if is_folder:
                relative += "/"
            result = _check(spec, relative)
            if result is not None:
                verdict = result
        return verdict


def _cheap(line: str) -> bool:
    """Whether ``pathspec`` matches the pattern in low polynomial time."""
    return all(len(_STARS.findall(segment)) <= MAX_STARS_PER_SEGMENT
               for segment in line.split("/"))


def _check(spec: pathspec.GitIgnoreSpec, relative: str) -> bool | None:
    """True (ignored), False (re-included by a ``!`` pattern) or None (no pattern)."""
    check_file = getattr(spec, "check_file", None)
    if check_file is not None:
        result = check_file(relative)
        include = getattr(result, "include", None)
        return None if include is None else bool(include)
    return True if spec.match_file(relative) else None


def gitignore_predicate() -> GitIgnore:
    """A fresh set of ``.gitignore`` rules; pass its ``ignored`` method to discovery."""
    return GitIgnore()
