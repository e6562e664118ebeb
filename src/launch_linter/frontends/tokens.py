"""Split a resolved argument string into argv words, keeping track of unresolved holes."""

from __future__ import annotations

import re
import shlex

from launch_linter.model.record import MutableRecord
from launch_linter.resolve.value import Hole, Value

_OPEN, _CLOSE = "\ue000", "\ue001"
# shlex in POSIX mode with whitespace_split (what shlex.split does) splits on exactly
# these four characters; without quotes or backslashes it is a plain split on them.
_SHLEX_WORD = re.compile(r"[^ \t\r\n]+")
_SHLEX_SPECIAL = re.compile(r"[\"'\\]")


_NO_HOLES: frozenset[int] = frozenset()


class Words(MutableRecord):
    """The argv words of one ``args`` value (treat as read-only)."""

    words: tuple[str, ...]
    """Each word as text; a hole is shown as the substitution that was written."""
    unresolved: frozenset[int]
    """Indices of words that contain a hole."""
    holes: tuple[Hole, ...]
    quoting_error: str | None
    """Why ``shlex.split`` refuses the text (then it was split on whitespace instead)."""

    __slots__ = ("words", "unresolved", "holes", "quoting_error")

    def __init__(
        self,
        words: tuple[str, ...],
        unresolved: frozenset[int],
        holes: tuple[Hole, ...],
        quoting_error: str | None = None,
    ) -> None:
        self.words = words
        self.unresolved = unresolved
        self.holes = holes
        self.quoting_error = quoting_error


def shell_words(text: str) -> tuple[list[str], str | None]:
    """The words roslaunch hands to the program (``shlex.split``), and shlex's complaint if
    it refuses the text (then the text is split on whitespace, as the best guess)."""
    if _SHLEX_SPECIAL.search(text) is None:
        return _SHLEX_WORD.findall(text), None
    try:
        return shlex.split(text), None
    except ValueError as exc:
        return _SHLEX_WORD.findall(text), str(exc)


def split_args(value: Value) -> Words:
    """Split like roslaunch does (``shlex.split``), with holes counted as part of one word."""
    if len(value) == 1 and isinstance(value[0], str):
        plain, error = shell_words(value[0])
        return Words(tuple(plain), _NO_HOLES, (), error)
    holes: list[Hole] = []
    marked: list[str] = []
    for part in value:
        if isinstance(part, str):
            marked.append(part)
        else:
            marked.append(f"{_OPEN}{len(holes)}{_CLOSE}")
            holes.append(part)
    raw, error = shell_words("".join(marked))
    words: list[str] = []
    unresolved: set[int] = set()
    for index, word in enumerate(raw):
        if _OPEN in word:
            unresolved.add(index)
            for number, hole in enumerate(holes):
                word = word.replace(f"{_OPEN}{number}{_CLOSE}", hole.text)
        words.append(word)
    return Words(tuple(words), frozenset(unresolved), tuple(holes), error)
