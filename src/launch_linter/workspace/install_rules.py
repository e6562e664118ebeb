"""Install rules of a package: which source file lands at which path of its share folder.

The readers (:mod:`.cmake_install`, :mod:`.python_install`) fill a :class:`Layout`;
:meth:`Layout.explain` maps a path relative to ``share/<package>`` back to the source
files that may be installed there, and says whether the rules were read completely and
exactly enough for a missing source to prove the installed file absent.
"""

from __future__ import annotations

import fnmatch
import posixpath
from dataclasses import dataclass, field
from typing import NamedTuple

MAX_RULES = 2_000
MAX_REASONS = 20


@dataclass(frozen=True)
class InstallRule:
    """One source installed into the share folder.

    ``kind`` is ``directory`` (``source`` is a folder whose files land under ``target``)
    or ``file`` (``source`` lands at ``target``). Paths are package-relative, ``/``
    separated; ``target`` is relative to ``share/<package>`` ("" is that folder)."""

    kind: str
    source: str
    target: str
    includes: tuple[str, ...] = ()
    """``FILES_MATCHING PATTERN``s: a file is installed only if its name matches one."""
    excludes: tuple[str, ...] = ()
    """``PATTERN ... EXCLUDE``: a file or folder whose name matches is left out."""
    exact: bool = True
    """Whether the filters are modelled exactly (a ``REGEX`` is not)."""
    origin: str = ""


class Explanation(NamedTuple):
    sources: list[str]
    """Package-relative files that install to the path, in rule order."""
    complete: bool
    """Every rule was read and every rule that names the path filters exactly: a path no
    listed source provides is then not installed."""
    reasons: list[str]


@dataclass
class Layout:
    rules: list[InstallRule] = field(default_factory=list)
    reasons: list[str] = field(default_factory=list)
    """Why the rules are incomplete (empty when every rule was read)."""

    def add(self, rule: InstallRule) -> None:
        if len(self.rules) < MAX_RULES:
            self.rules.append(rule)
        else:
            self.unread(f"more than {MAX_RULES} install rules")

    def unread(self, reason: str) -> None:
        if len(self.reasons) < MAX_REASONS:
            self.reasons.append(reason)

    def extend(self, other: Layout) -> None:
        for rule in other.rules:
            self.add(rule)
        for reason in other.reasons:
            self.unread(reason)

    def explain(self, share_path: str) -> Explanation:
        """The sources of ``share_path`` (relative to ``share/<package>``, normalised)."""
        sources: list[str] = []
        exact = True
        for rule in self.rules:
            if rule.kind == "file":
                if rule.target == share_path:
                    sources.append(rule.source)
                continue
            rest = _below(share_path, rule.target)
            if rest is None:
                continue
            if _filtered_out(rest, rule):
                continue
            exact = exact and rule.exact
            sources.append(rule.source if rest == "." else posixpath.join(rule.source, rest))
        return Explanation(sources, exact and not self.reasons, list(self.reasons))

    def installed_as(self, source: str) -> list[str]:
        """Where the package-relative file ``source`` lands, relative to
        ``share/<package>``, in rule order (empty when no rule installs it)."""
        targets: list[str] = []
        for rule in self.rules:
            if rule.kind == "file":
                if rule.source == source:
                    targets.append(rule.target)
                continue
            rest = _below(source, rule.source)
            if rest is not None and rest != "." and not _filtered_out(rest, rule):
                targets.append(posixpath.join(rule.target, rest) if rule.target else rest)
        return targets


def _below(path: str, folder: str) -> str | None:
    if not folder or folder == ".":
        return path
    if path == folder:
        return "."
    if path.startswith(folder + "/"):
        return path[len(folder) + 1:]
    return None


def _filtered_out(rest: str, rule: InstallRule) -> bool:
    parts = rest.split("/")
    if any(fnmatch.fnmatchcase(part, pattern) for part in parts for pattern in rule.excludes):
        return True
    return bool(rule.includes) and rest != "." and not any(
        fnmatch.fnmatchcase(parts[-1], pattern) for pattern in rule.includes)


def share_relative(destination: str, package: str) -> str | None:
    """``destination`` relative to ``share/<package>``: "" for that folder itself, None
    for a destination elsewhere (``lib/``, ``include/``, another package's share)."""
    cleaned = posixpath.normpath(destination.replace("\\", "/").strip())
    prefix = "share/" + package
    if cleaned == prefix:
        return ""
    if cleaned.startswith(prefix + "/"):
        return cleaned[len(prefix) + 1:]
    return None
