"""What every kind of knowledge entry shares: its sources, its text fields, and the error
that names a fault of a knowledge file. Standard library only: the core reads it."""

from __future__ import annotations

import re
from typing import Any

from launch_linter.model import distro
from launch_linter.model.record import Record, _set

_COMMIT = re.compile(r"^[0-9a-f]{40}$")
MAX_KNOWLEDGE_BYTES = 4 * 1024 * 1024
"""The most a knowledge file may hold, bundled or a user's."""


class KnowledgeError(ValueError):
    """A knowledge file that does not follow the format; the message names the entry."""


class EntryError(KnowledgeError):
    """A fault of one item of a knowledge file: ``section``'s item ``index``."""

    def __init__(self, message: str, section: str, index: int) -> None:
        super().__init__(message)
        self.section = section
        self.index = index


class Source(Record):
    """Where an entry's facts were read: the repository, package, file, branch or tag,
    commit and lines."""

    repository: str
    package: str
    file: str
    ref: str
    commit: str
    lines: str

    __slots__ = ("repository", "package", "file", "ref", "commit", "lines")

    def __init__(
        self,
        repository: str,
        package: str,
        file: str,
        ref: str,
        commit: str,
        lines: str,
    ) -> None:
        _set(self, "repository", repository)
        _set(self, "package", package)
        _set(self, "file", file)
        _set(self, "ref", ref)
        _set(self, "commit", commit)
        _set(self, "lines", lines)


def _text(value: Any, where: str) -> str:
    if not isinstance(value, str) or not value:
        raise KnowledgeError(f"{where} must be a non-empty string")
    return value


def _texts(value: Any, where: str, required: bool = False, non_empty: bool = False
           ) -> tuple[str, ...]:
    """A list of non-empty strings. Absent (None) reads as empty unless ``required``: a
    field whose absence would change what the entry means (a value fact's ``accepts``:
    without it a closed fact would refuse every value) must be written. ``non_empty``: an
    empty list is a fault too (a launch fact's ``launch`` paths)."""
    if value is None and not required:
        return ()
    if not isinstance(value, list):
        raise KnowledgeError(f"{where} must be a list of strings")
    if non_empty and not value:
        raise KnowledgeError(f"{where} must be a non-empty list of strings")
    return tuple(_text(item, f"{where}[{i}]") for i, item in enumerate(value))


def _source(data: Any, where: str) -> Source:
    if not isinstance(data, dict):
        raise KnowledgeError(f"{where} must be an object")
    fields = {key: _text(data.get(key), f"{where}.{key}")
              for key in ("repository", "package", "file", "ref", "commit", "lines")}
    if not _COMMIT.match(fields["commit"]):
        raise KnowledgeError(f"{where}.commit must be a 40-digit commit hash")
    return Source(**fields)


def _sources(value: Any, where: str) -> tuple[Source, ...]:
    """An entry's ``sources``: a non-empty list of where its facts were read."""
    if not isinstance(value, list) or not value:
        raise KnowledgeError(f"{where} must list where the entry was read")
    return tuple(_source(item, f"{where}[{i}]") for i, item in enumerate(value))


def _distributions(data: dict[str, Any], ros: tuple[int, ...], where: str
                   ) -> tuple[str, ...]:
    """The distributions an entry holds for: ``distros`` as listed (a program that went
    and came back), or the run of the release order (``model.distro``) from ``since`` to
    ``until``, either one open: a distribution added to the order joins every open run
    without an edit of the entries. Names outside the entry's ROS versions are faults."""
    orders = {1: distro.ROS1_DISTROS, 2: distro.ROS2_DISTROS}
    known = tuple(name for version in ros for name in orders.get(version, ()))
    since, until = data.get("since"), data.get("until")
    if "distros" in data:
        if since is not None or until is not None:
            raise KnowledgeError(f"{where} gives distros or since/until, not both")
        listed = _texts(data.get("distros"), f"{where}.distros")
        versions = "/".join(map(str, ros))
        if not listed:
            raise KnowledgeError(f"{where}.distros must list distributions of ROS "
                                 f"{versions} ({', '.join(known)})")
        for name in listed:
            if name not in known:
                raise KnowledgeError(f"{where}.distros names {name!r}, not a distribution "
                                     f"of ROS {versions} ({', '.join(known)})")
        return listed
    if since is None and until is None:
        raise KnowledgeError(f"{where} needs distros, or since and/or until")
    if len(ros) != 1:
        raise KnowledgeError(f"{where}: since/until need one ROS version in ros")
    order = orders[ros[0]]
    bounds = []
    for key, value, default in (("since", since, 0), ("until", until, len(order) - 1)):
        if value is None:
            bounds.append(default)
        elif value in order:
            bounds.append(order.index(value))
        else:
            raise KnowledgeError(f"{where}.{key} must be a distribution of ROS {ros[0]} "
                                 f"({', '.join(order)})")
    if bounds[0] > bounds[1]:
        raise KnowledgeError(f"{where}.since comes after its until")
    return order[bounds[0]:bounds[1] + 1]


_TOKEN = re.compile(r'"(?:[^"\\]|\\.)*"|[\[\]{},]')
_SPACE = re.compile(r"\s*")


def item_line(text: str, section: str, index: int) -> int | None:
    """The line where item ``index`` of the top-level list ``section`` of the JSON
    document ``text`` begins (None: not found). One pass over the text's tokens."""
    depth = 0
    key = ""
    count = -1  # -1: not inside the section's list
    for token in _TOKEN.finditer(text):
        mark = token.group()
        if mark in "{[":
            depth += 1
            if mark == "[" and depth == 2 and key == section:
                count = 0
            else:
                continue
        elif mark in "}]":
            depth -= 1
            if count >= 0 and depth < 2:
                return None
            continue
        elif mark == ",":
            if count < 0 or depth != 2:
                continue
            count += 1
        else:
            if depth == 1:
                key = mark[1:-1]
            continue
        if count == index:
            start = _SPACE.match(text, token.end())
            return text.count("\n", 0, start.end() if start else token.end()) + 1
    return None
