"""Glob patterns matched in linear time.

Globs come from strangers (a repository's configuration: ``exclude``, ``per-path-ignores``;
its ``.gitignore`` files). Translated into regular expressions (``fnmatch``, ``pathspec``)
they are matched by backtracking: ``*a*a*a*a*a*b`` on a long name, or
``**/*a*a/**/*a*a*b`` on a deep path, takes minutes. Here a pattern is a list of tokens
and every position of it is followed at once (a set of states per character), so a match
costs at most (pattern length) x (text length) steps, whatever the pattern.

Three dialects, one matcher:

- :func:`path_glob`: ``*`` and ``?`` stay within one path segment, ``**/`` is zero or
  more folders, ``**`` anything (``per-path-ignores``).
- :func:`fnmatch_glob`: Python's ``fnmatch``: ``*`` and ``?`` match ``/`` too, ``[...]``
  and ``[!...]`` classes (``exclude`` globs).
- :func:`gitignore_glob`: git's wildmatch: ``*``, ``?`` and classes (``[!...]`` or
  ``[^...]``) stay within a segment, ``**`` is special only as a whole segment, ``\\``
  escapes the next character.
"""

from __future__ import annotations

from functools import lru_cache

_LITERAL, _ONE, _STAR, _ANY, _FOLDERS, _CLASS = range(6)
_SKIPPABLE = (_STAR, _ANY, _FOLDERS)

TYPE_CHECKING = False  # typing is not imported at run time: start-up (docs/performance.md)
if TYPE_CHECKING:
    from typing import Optional, Tuple

    _Class = Tuple[bool, str, Tuple[Tuple[str, str], ...]]
    """(negated, characters, ranges) of a ``[...]`` class."""
    _Token = Tuple[int, str, Optional[_Class]]


class Glob:
    """A compiled glob; :meth:`match` is linear in the text for a given pattern.

    A state is a token index (before that token; ``len(tokens)``: matched), or ``-i - 1``
    inside a folder name that the ``**/`` at token ``i`` is consuming (it may end only
    at a ``/``: ``**/a`` does not match ``ba``)."""

    __slots__ = ("_slash_wild", "_tokens")

    def __init__(self, tokens: tuple[_Token, ...], slash_wild: bool) -> None:
        self._tokens = tokens
        self._slash_wild = slash_wild

    def match(self, text: str) -> bool:
        """Whether the whole ``text`` matches."""
        return self._run(text, False)

    def matches_a_folder_of(self, text: str) -> bool:
        """Whether a prefix of ``text`` that ends before one of its ``/`` matches (a
        folder the path ``text`` lies in)."""
        return self._run(text, True)

    def _run(self, text: str, folders: bool) -> bool:
        tokens = self._tokens
        end = len(tokens)
        states = self._closure({0})
        for char in text:
            if folders and char == "/" and end in states:
                return True
            following: set[int] = set()
            for state in states:
                if state < 0:  # inside a folder name of ``**/``: on to its "/"
                    following.add(-state - 1 if char == "/" else state)
                    continue
                if state == end:
                    continue
                kind, literal, klass = tokens[state]
                if kind == _LITERAL:
                    if char == literal:
                        following.add(state + 1)
                elif kind == _ANY:
                    following.add(state)
                elif kind == _FOLDERS:
                    # A "/" ends a (here empty) folder name: zero or more folders may follow.
                    following.add(state if char == "/" else -state - 1)
                elif char == "/" and not self._slash_wild:
                    continue
                elif kind == _STAR:
                    following.add(state)
                elif kind == _ONE or (klass is not None and _in_class(char, klass)):
                    following.add(state + 1)
            if not following:
                return False
            states = self._closure(following)
        return not folders and end in states

    def _closure(self, states: set[int]) -> set[int]:
        tokens = self._tokens
        out: set[int] = set()
        stack = list(states)
        while stack:
            state = stack.pop()
            if state in out:
                continue
            out.add(state)
            if 0 <= state < len(tokens) and tokens[state][0] in _SKIPPABLE:
                stack.append(state + 1)
        return out


def _in_class(char: str, klass: _Class) -> bool:
    negated, chars, ranges = klass
    found = char in chars or any(low <= char <= high for low, high in ranges)
    return found != negated


def _parse_class(pattern: str, start: int, caret: bool,
                 escapes: bool) -> tuple[_Class, int] | None:
    """The class opening at ``pattern[start] == '['`` and the index after it; None when
    it never closes (the ``[`` is then a literal)."""
    i = start + 1
    negated = False
    if i < len(pattern) and (pattern[i] == "!" or (caret and pattern[i] == "^")):
        negated = True
        i += 1
    members: list[str] = []
    first = True
    while i < len(pattern):
        char = pattern[i]
        if char == "]" and not first:
            break
        if escapes and char == "\\" and i + 1 < len(pattern):
            i += 1
            char = pattern[i]
        members.append(char)
        first = False
        i += 1
    else:
        return None
    chars: list[str] = []
    ranges: list[tuple[str, str]] = []
    index = 0
    while index < len(members):
        if index + 2 < len(members) and members[index + 1] == "-":
            ranges.append((members[index], members[index + 2]))
            index += 3
        else:
            chars.append(members[index])
            index += 1
    return (negated, "".join(chars), tuple(ranges)), i + 1


def _tokens(pattern: str, *, slash_wild: bool, classes: bool, caret: bool,
            escapes: bool, segment_stars: bool) -> tuple[_Token, ...]:
    """``segment_stars``: ``**`` is special only as a whole segment (git)."""
    out: list[_Token] = []
    i = 0
    size = len(pattern)
    while i < size:
        char = pattern[i]
        if char == "*":
            run = i
            while run < size and pattern[run] == "*":
                run += 1
            double = run - i >= 2 and not slash_wild
            if double and segment_stars:
                double = (i == 0 or pattern[i - 1] == "/") and (run == size
                                                                or pattern[run] == "/")
            if double and run < size and pattern[run] == "/":
                out.append((_FOLDERS, "", None))
                run += 1
            elif double:
                out.append((_ANY, "", None))
            elif not out or out[-1][0] != _STAR:
                out.append((_STAR, "", None))
            i = run
            continue
        if char == "?":
            out.append((_ONE, "", None))
        elif char == "[" and classes:
            parsed = _parse_class(pattern, i, caret, escapes)
            if parsed is not None:
                out.append((_CLASS, "", parsed[0]))
                i = parsed[1]
                continue
            out.append((_LITERAL, char, None))
        elif char == "\\" and escapes and i + 1 < size:
            i += 1
            out.append((_LITERAL, pattern[i], None))
        else:
            out.append((_LITERAL, char, None))
        i += 1
    return tuple(out)


@lru_cache(maxsize=1024)
def path_glob(pattern: str) -> Glob:
    """``*``/``?`` within a segment, ``**/`` folders, ``**`` anything; no classes."""
    return Glob(_tokens(pattern, slash_wild=False, classes=False, caret=False,
                        escapes=False, segment_stars=False), False)


@lru_cache(maxsize=1024)
def fnmatch_glob(pattern: str) -> Glob:
    """``fnmatch.fnmatchcase``'s dialect."""
    return Glob(_tokens(pattern, slash_wild=True, classes=True, caret=False, escapes=False,
                        segment_stars=False), True)


@lru_cache(maxsize=4096)
def gitignore_glob(pattern: str) -> Glob:
    """git's wildmatch dialect (with ``WM_PATHNAME``), for the body of a ``.gitignore``
    line (without ``!``, the trailing ``/`` and the leading ``/``)."""
    return Glob(_tokens(pattern, slash_wild=False, classes=True, caret=True, escapes=True,
                        segment_stars=True), False)
