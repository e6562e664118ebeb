"""Split a resolved argument string into argv words, keeping track of unresolved holes."""

from __future__ import annotations

import shlex
from dataclasses import dataclass

from launch_linter.resolve.value import Hole, Value

_OPEN, _CLOSE = "\ue000", "\ue001"


@dataclass(frozen=True, slots=True)
class Words:
    words: tuple[str, ...]
    """Each word as text; a hole is shown as the substitution that was written."""
    unresolved: frozenset[int]
    """Indices of words that contain a hole."""
    holes: tuple[Hole, ...]


def split_args(value: Value) -> Words:
    """Split like roslaunch does (``shlex.split``), with holes counted as part of one word."""
    holes: list[Hole] = []
    marked: list[str] = []
    for part in value:
        if isinstance(part, str):
            marked.append(part)
        else:
            marked.append(f"{_OPEN}{len(holes)}{_CLOSE}")
            holes.append(part)
    text = "".join(marked)
    try:
        raw = shlex.split(text)
    except ValueError:
        raw = text.split()
    words: list[str] = []
    unresolved: set[int] = set()
    for index, word in enumerate(raw):
        if _OPEN in word:
            unresolved.add(index)
            for number, hole in enumerate(holes):
                word = word.replace(f"{_OPEN}{number}{_CLOSE}", hole.text)
        words.append(word)
    return Words(tuple(words), frozenset(unresolved), tuple(holes))
