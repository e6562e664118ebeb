"""How a file's path is shown: relative to the current folder when the file is under it,
absolute otherwise, the same in every format (a path as the user typed it, ``../x`` or
an absolute path into the current folder, would mix both kinds in one report)."""

from __future__ import annotations

import os


def shown_path(path: str, folder: str | None = None) -> str:
    """``path`` relative to ``folder`` (default: the current folder) when it lies under
    it, else absolute. Symbolic links are kept as written: the path a user can open."""
    base = os.path.abspath(folder if folder is not None else os.getcwd())
    absolute = os.path.abspath(path)
    try:
        inside = os.path.commonpath([base, absolute]) == base
    except ValueError:  # different drives (Windows)
        return absolute
    return os.path.relpath(absolute, base) if inside else absolute


__all__ = ["shown_path"]
