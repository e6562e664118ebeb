"""How a file's path is shown: relative to the current folder when the file is under it,
absolute otherwise, the same in every format (a path as the user typed it, ``../x`` or
an absolute path into the current folder, would mix both kinds in one report). Every
message that quotes a path shows it this way: the front-ends through their display
function (this one, for every file but the root as discovery named it), the rules and
reports directly."""

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


def shown_in_text(text: str, known: int) -> str:
    """A path a message quotes whose first ``known`` characters are resolved and the rest
    is the substitution written (``/ws/pkg/launch/$(arg model).launch``): the absolute
    folder it starts in shown as :func:`shown_path` shows it, the rest as written."""
    cut = text.rfind("/", 0, known) + 1
    if cut <= 1 or not text.startswith("/"):
        return text
    return shown_path(text[:cut]).rstrip("/") + "/" + text[cut:]


__all__ = ["shown_in_text", "shown_path"]
