"""Limits and bounded operations of the linter's two interpreters of launch-file Python.

roslaunch's ``$(eval)`` (``resolve/safe_eval.py``) and ROS 2 ``*.launch.py`` files
(``frontends/ros2_python``) are both Python the linter reads but never runs. Each has its
own interpreter, because their languages and their ways of failing differ (``$(eval)``
refuses with an error; a launch file yields an *unknown* value), but the limits on what
they build and the operations on text that could build something large are here, in one
place, so that there is one set of limits to audit.

Every operation checks the size of its result *before* building it and reports a refusal
by raising :class:`Refused` with a short reason; the caller turns that into its own kind of
failure.
"""

from __future__ import annotations

import re
import string
from collections.abc import Iterator, Sequence
from typing import Final

# -- roslaunch's $(eval): one expression ------------------------------------------------
EVAL_MAX_SOURCE_CHARS: Final = 10_000
"""Longest expression text accepted."""
EVAL_MAX_NODES: Final = 2_000
"""Most syntax-tree nodes (operator and context markers not counted)."""
EVAL_MAX_DEPTH: Final = 100
"""Deepest nesting of syntax-tree nodes."""
EVAL_MAX_POW_EXPONENT: Final = 10_000
"""Largest integer exponent of ``int ** int`` (unless the base is -1, 0 or 1)."""
EVAL_MAX_INT_BITS: Final = 100_000
"""Largest integer produced anywhere during evaluation, in bits."""
EVAL_MAX_ITEMS: Final = 1_000_000
"""Largest string (characters) or container (items, counted recursively) produced."""
EVAL_MAX_WORK: Final = 500_000
"""Budget of abstract work units for one evaluation; see ``_Interpreter.charge``."""
EVAL_MAX_INT_TEXT: Final = 10_000
"""Longest digit string ``int()`` converts (longer ones would make it quadratic if Python's
own digit limit is lifted)."""
EVAL_MAX_FORMAT_FIELD: Final = 10_000
"""Widest field width or precision of ``'...' % x``."""

# -- ROS 2 Python launch files: one file ------------------------------------------------
PYTHON_MAX_STEPS: Final = 200_000
"""Statements and expressions interpreted for one file (and for each ``OpaqueFunction``)."""
PYTHON_MAX_CALL_DEPTH: Final = 16
"""Deepest nesting of calls of the file's own functions."""
PYTHON_MAX_ITEMS: Final = 10_000
"""Largest list, tuple or range built."""
PYTHON_MAX_TEXT: Final = 100_000
"""Longest text built."""
PYTHON_MAX_FORMAT_FIELD: Final = 999
"""Widest field width or precision of ``'...' % x``."""


class Refused(Exception):
    """A bounded operation refuses its arguments; ``reason`` says why, in a few words."""

    def __init__(self, reason: str) -> None:
        super().__init__(reason)
        self.reason = reason


# -- str methods --------------------------------------------------------------------------

STRING_METHODS: Final = frozenset({
    "join", "split", "rsplit", "replace", "strip", "lstrip", "rstrip", "lower", "upper",
    "startswith", "endswith", "find", "rfind", "count", "capitalize", "title",
})
"""The ``str`` methods seen in launch files (joining and splitting names, case): none of
them can grow its input by more than ``replace()`` or ``join()`` can, and those two are
sized first."""


def check_join(separator: str, items: Sequence[str], max_text: int) -> None:
    """Refuse ``separator.join(items)`` when its result would be longer than ``max_text``."""
    size = sum(len(item) for item in items)
    if size + len(separator) * max(0, len(items) - 1) > max_text:
        raise Refused(f"str.join() result too long: more than {max_text} characters")


def string_method(receiver: str, name: str, args: Sequence[object], max_text: int) -> object:
    """``receiver.name(*args)`` for a method of :data:`STRING_METHODS`, its result sized
    first; the caller has checked that ``args`` are plain values."""
    if name not in STRING_METHODS:
        raise Refused(f"str.{name}() is not supported")
    if name == "replace" and len(args) >= 2 and isinstance(args[0], str):
        grown = len(str(args[1])) - len(args[0])
        if grown > 0 and len(receiver) + receiver.count(args[0]) * grown > max_text:
            raise Refused(f"str.replace() result too long: more than {max_text} characters")
    if name == "join" and len(args) == 1 and isinstance(args[0], (list, tuple)) and all(
        isinstance(item, str) for item in args[0]
    ):
        check_join(receiver, args[0], max_text)
    try:
        result: object = getattr(str, name)(receiver, *args)
    except OverflowError as exc:
        # Python reports an overflow with (errno, text); keep only the text.
        detail = exc.args[-1] if exc.args else ""
        raise Refused(f"str.{name}(): numeric overflow: {detail}") from None
    except (ArithmeticError, LookupError, TypeError, ValueError) as exc:
        raise Refused(f"str.{name}(): {exc}") from None
    return result


# -- formatting ---------------------------------------------------------------------------

# printf-style conversion specifiers; "%%" first so it is consumed as a unit.
_PERCENT_FIELD: Final = re.compile(r"%%|%(?:\([^)]*\))?[#0\- +]*(\*|[0-9]+)?(?:\.(\*|[0-9]*))?")


def percent_refusal(template: str, max_field: int) -> str | None:
    """Why ``template % values`` could allocate without bound (a ``*`` width, a width or
    precision above ``max_field``), or None when every field is bounded."""
    for match in _PERCENT_FIELD.finditer(template):
        for width in match.groups():
            if width == "*":
                return "'*' field widths in % formatting are not supported"
            if width and (len(width) > 6 or int(width) > max_field):
                return f"% format field width or precision above {max_field:,}"
    return None


def format_fields(template: str) -> Iterator[tuple[str, int | None]]:
    """The parts of a ``str.format`` template: each literal text, then the index of the
    argument that follows it (None after the last text). Only plain ``{}`` and ``{0}``
    fields are taken: a format spec or conversion is unbounded in size, and an attribute
    or item lookup would reach into a value."""
    try:
        fields = list(string.Formatter().parse(template))
    except ValueError:
        raise Refused("malformed format string") from None
    automatic = 0
    for text, field_name, spec, conversion in fields:
        if field_name is None:
            yield text, None
            continue
        if spec or conversion or not (field_name == "" or field_name.isdigit()):
            raise Refused("str.format() with this field is not interpreted")
        yield text, automatic if field_name == "" else int(field_name)
        automatic += 1
