"""Values that may contain holes: the parts of a text the linter could not resolve."""

from __future__ import annotations

import re
from typing import Tuple, Union

from launch_linter.model.paths import shown_in_text
from launch_linter.model.record import Record, _set

MAX_REASON = 300
"""Longest reason kept in a hole."""


class Hole(Record):
    """An unresolved piece of text: the substitution as written and why it is unknown."""

    text: str
    reason: str

    __slots__ = ("text", "reason")

    def __init__(self, text: str, reason: str) -> None:
        _set(self, "text", text)
        # A reason quotes the reasons of the values it was made from: values that refer to
        # each other would double it at each level.
        if len(reason) > MAX_REASON:
            reason = reason[: MAX_REASON - 3] + "..."
        _set(self, "reason", reason)


Part = Union[str, Hole]
Value = Tuple[Part, ...]


def literal(text: str) -> Value:
    return (text,) if text else ()


def join(parts: list[Part] | tuple[Part, ...]) -> Value:
    """Concatenate parts, merging adjacent strings and dropping empty ones."""
    out: list[Part] = []
    text = ""
    """The run of strings since the last hole."""
    for part in parts:
        if isinstance(part, str):
            text += part
            continue
        if text:
            out.append(text)
            text = ""
        out.append(part)
    if text:
        out.append(text)
    return tuple(out)


def is_resolved(value: Value) -> bool:
    if len(value) == 1:
        return type(value[0]) is str
    return all(isinstance(p, str) for p in value)


def text_of(value: Value) -> str:
    """The value as text, holes shown as the substitution that was written."""
    if len(value) == 1 and type(value[0]) is str:
        return value[0]
    return "".join(p if isinstance(p, str) else p.text for p in value)


def shown_value(value: Value) -> str:
    """``text_of(value)`` as a message quotes a path: the absolute folder its resolved
    start names shown relative to the current folder when under it (``shown_in_text``)."""
    known = len(value[0]) if value and type(value[0]) is str else 0
    return shown_in_text(text_of(value), known)


def resolved_text(value: Value) -> str | None:
    """The value as text, or None when it has a hole."""
    if len(value) == 1:
        only = value[0]
        return only if type(only) is str else None
    if not value:
        return ""
    return "".join(p for p in value if isinstance(p, str)) if is_resolved(value) else None


def holes(value: Value) -> tuple[Hole, ...]:
    if len(value) == 1 and type(value[0]) is str:  # resolved text, most values
        return ()
    return tuple(p for p in value if isinstance(p, Hole))


_NOT_GIVEN = re.compile(r"environment variable '([^'\s]+)' (?:is )?not given \(use --env\)")


def environment_variable(hole: Hole) -> str | None:
    """The name of the environment variable a hole is, when it is only that (its value
    is what the user's shell gives: ``$(env X)``, ``os.environ['X']``); None otherwise."""
    match = _NOT_GIVEN.fullmatch(hole.reason)
    return None if match is None else match.group(1)


def only_environment(value: Value) -> bool:
    """Whether every unknown of ``value`` is an environment variable (a value whose known
    text is worth keeping around it: a path with one unknown name in it)."""
    return all(environment_variable(h) is not None for h in holes(value))


_OPENERS = {"(": ")", "[": "]", "{": "}"}
_MARK = re.compile(r"""[\\'"()\[\]{}:;,]""")
"""The characters :func:`_expression_end` acts on; it jumps over the rest."""
_QUOTED_MARK = re.compile(r"""[\\'"]""")
"""The same inside quotes."""


def _expression_end(text: str, start: int) -> int:
    """Where the expression written at ``text[start:]`` ends: the first ``": "`` outside
    brackets and quotes, if what comes before it is a call or a substitution (has a
    bracket); -1 otherwise (the text is a reason in words)."""
    closing: list[str] = []
    quote = ""
    bracketed = False
    index = start
    while True:
        found = (_QUOTED_MARK if quote else _MARK).search(text, index)
        if found is None:
            return -1
        index = found.start()
        char = text[index]
        if quote:
            if char == "\\":
                index += 1
            elif char == quote:
                quote = ""
        elif char in "'\"":
            quote = char
        elif char in _OPENERS:
            closing.append(_OPENERS[char])
            bracketed = True
        elif closing and char == closing[-1]:
            closing.pop()
        elif not closing and text.startswith(": ", index):
            return index if bracketed else -1
        elif not closing and char in ";,":
            return -1  # several reasons, or words
        index += 1


def blocker(hole: Hole) -> tuple[str, str]:
    """``(what, why)``: the innermost unknown that the hole's reason names, and why it is
    unknown. A reason made from other values' reasons quotes them as ``TEXT: REASON``
    (``PathJoinSubstitution([...]): os.getenv('BASE'): environment variable 'BASE' not
    given``): the last such ``TEXT`` is what really blocks the value, the rest only
    passes it on. ``(hole.text, hole.reason)`` when the reason quotes none."""
    what, why = hole.text, hole.reason
    position = 0
    while position < len(why):
        end = _expression_end(why, position)
        if end < 0:
            break
        what, position = why[position:end], end + 2
    return what, why[position:]


def why_unresolved(value: Value, quoted: bool = False) -> str:
    """Why ``value`` is unknown, each cause once: ``WHAT: WHY`` (the unknowns with one
    cause named together), with ``(in TEXT)`` when the one blocker sits inside a
    substitution written otherwise, unless the caller ``quoted`` the value's text (which
    holds every such substitution); the written text is left out where it is the whole
    value (the caller shows it already)."""
    whole = text_of(value)
    causes: dict[str, list[str]] = {}
    inside: dict[str, list[str]] = {}
    for hole in holes(value):
        what, why = blocker(hole)
        names = causes.setdefault(why, [])
        if what != whole and what not in names:
            names.append(what)
        if what != hole.text and hole.text != whole:
            inside.setdefault(why, []).append(hole.text)
    said = []
    for why, names in causes.items():
        within = inside.get(why, [])
        tail = f" (in {within[0]})" if len(within) == 1 and not quoted else ""
        said.append(f"{', '.join(names)}: {why}{tail}" if names else why)
    return "; ".join(said) or "unresolved"
