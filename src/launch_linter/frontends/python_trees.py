"""The syntax trees of the ROS 2 Python files read while one root file is linted, kept for
locating its fixes (``fix.Source``), so that each file is parsed once: locating a fix in
a Python file needs the tree of the very bytes the front-end parsed, and parsing again was
about a sixth of the cost of such a file.

The engine opens a scope around the lint of one root file (``keeping``); the Python
reader notes each tree it builds (``note``). Outside a scope nothing is kept, and the
trees go with the scope: the memory of a run stays that of one root file.
"""

from __future__ import annotations

import contextlib
import os
from collections.abc import Iterator
from typing import TYPE_CHECKING, Dict, Tuple

if TYPE_CHECKING:
    import ast

Trees = Dict[str, Tuple[bytes, "ast.Module"]]
"""By absolute path: the bytes parsed and their tree."""

_scopes: list[Trees] = []


@contextlib.contextmanager
def keeping() -> Iterator[Trees]:
    """The trees of the Python files parsed inside the ``with`` block."""
    kept: Trees = {}
    _scopes.append(kept)
    try:
        yield kept
    finally:
        _scopes.pop()


def note(path: str, data: bytes, tree: ast.Module) -> None:
    """The front-end parsed ``data``, the file ``path``, into ``tree``."""
    if _scopes:
        _scopes[-1][os.path.abspath(path)] = (data, tree)


__all__ = ["Trees", "keeping", "note"]
