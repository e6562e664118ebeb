"""What every kind of knowledge entry shares: its sources, its text fields, and the error
that names a fault of a knowledge file. Standard library only: the core reads it."""

from __future__ import annotations

import re
from typing import Any

from launch_linter.model.record import Record, _set

_COMMIT = re.compile(r"^[0-9a-f]{40}$")
MAX_KNOWLEDGE_BYTES = 4 * 1024 * 1024
"""The most a knowledge file may hold, bundled or a user's."""


class KnowledgeError(ValueError):
    """A knowledge file that does not follow the format; the message names the entry."""


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


def _texts(value: Any, where: str) -> tuple[str, ...]:
    if value is None:
        return ()
    if not isinstance(value, list):
        raise KnowledgeError(f"{where} must be a list of strings")
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
