"""What can be known of a TOML document without a TOML parser.

The package reads TOML with ``tomllib`` (Python 3.11) or ``tomli`` (its dependency on older
Pythons). A standalone linter carries only the standard library, so on Python 3.8 to 3.10
without ``tomli`` it has no parser; it must still pass over a ``pyproject.toml`` that holds
no launch-linter settings, as the package does, and refuse anything else, never guess.
"""

from __future__ import annotations

import re

_HEADER = re.compile(r"\s*\[\[?\s*(?P<first>\"[^\"]*\"|'[^']*'|[A-Za-z0-9_-]+)")
_PYPROJECT_TABLES = ("build-system", "project", "tool", "dependency-groups")
REFUSED = (
    "this Python has no TOML parser (tomllib is new in Python 3.11): install tomli,"
    " run with a newer Python, or give the settings as options"
)


class NoTomlParser(ValueError):
    """A document that may hold launch-linter settings, and no parser to read it."""


def loads_without_parser(text: str) -> dict[str, object]:
    """``{}`` for a document that cannot hold launch-linter settings, else ``NoTomlParser``.

    Such a document has no top-level keys, only the usual ``pyproject.toml`` tables, and
    ``launch-linter`` in no table header and no key of the ``[tool]`` table (short of
    spelling it with escape sequences).
    """
    table: str | None = None
    for line in text.splitlines():
        stripped = line.strip()
        if not stripped or stripped.startswith("#"):
            continue
        header = _HEADER.match(stripped) if stripped.startswith("[") else None
        if header is not None:
            first = header.group("first").strip("\"'")
            if first not in _PYPROJECT_TABLES or "launch-linter" in stripped:
                raise NoTomlParser(REFUSED)
            table = re.sub(r"[\s\"']", "", stripped.strip("[").partition("]")[0])
        elif table is None or (table == "tool" and "launch-linter" in stripped.partition("=")[0]):
            raise NoTomlParser(REFUSED)
    return {}
