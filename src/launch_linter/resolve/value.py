"""Values that may contain holes: the parts of a text the linter could not resolve."""

from __future__ import annotations

from dataclasses import dataclass

MAX_REASON = 300
"""Longest reason kept in a hole."""


@dataclass(frozen=True, slots=True)
class Hole:
    """An unresolved piece of text: the substitution as written and why it is unknown."""

    text: str
    reason: str

    def __post_init__(self) -> None:
        # A reason quotes the reasons of the values it was made from: values that refer to
        # each other would double it at each level.
        if len(self.reason) > MAX_REASON:
            object.__setattr__(self, "reason", self.reason[: MAX_REASON - 3] + "...")


Part = str | Hole
Value = tuple[Part, ...]


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


def resolved_text(value: Value) -> str | None:
    """The value as text, or None when it has a hole."""
    if len(value) == 1:
        only = value[0]
        return only if type(only) is str else None
    if not value:
        return ""
    return "".join(p for p in value if isinstance(p, str)) if is_resolved(value) else None


def holes(value: Value) -> tuple[Hole, ...]:
    return tuple(p for p in value if isinstance(p, Hole))
