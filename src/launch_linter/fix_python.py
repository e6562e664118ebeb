"""Locating a fix's words in a Python launch file: the string items of ``arguments=[...]``
of the call on a line, found in the file's syntax tree (the front-end's, when it parsed
these bytes: ``frontends.python_trees``; parsed here otherwise, as the front-end does).

A module of its own so that ``ast`` is imported only by runs that locate a Python fix.
"""

from __future__ import annotations

import ast
import collections
from collections.abc import Callable, Sequence
from typing import Tuple

Span = Tuple[int, int]


def parse(data: bytes) -> ast.Module:
    """``data``'s tree as the front-end reads it (UTF-8, a byte order mark allowed); an
    empty module when it is not Python."""
    try:
        return ast.parse(data.decode("utf-8-sig"))
    except (SyntaxError, ValueError, RecursionError, MemoryError):
        return ast.Module(body=[], type_ignores=[])


def call_spans(
    module: ast.Module, line: int, line_starts: Sequence[int],
    text: Callable[[int, int], str | None],
) -> tuple[list[Span], list[str]] | None:
    """Byte spans (quotes included) and values of the string items of ``arguments=[...]``
    of the first call on ``line`` that has one (in ``ast.walk`` order); None unless every
    item is a plain one-line string literal whose bytes (``text`` of a span) read as it."""
    # ast.walk's breadth-first order, without the subtrees that lie off the line (a
    # file parsed once, each line's search a thin slice of it).
    queue: collections.deque[ast.AST] = collections.deque([module])
    while queue:
        node = queue.popleft()
        if isinstance(node, ast.Call) and node.lineno == line:
            for keyword in node.keywords:
                value = keyword.value
                if keyword.arg == "arguments" and isinstance(value, (ast.List, ast.Tuple)):
                    return _string_spans(value.elts, line_starts, text)
        for child in ast.iter_child_nodes(node):
            if _may_hold(child, line):
                queue.append(child)
    return None


def _string_spans(
    items: list[ast.expr], starts: Sequence[int], text: Callable[[int, int], str | None],
) -> tuple[list[Span], list[str]] | None:
    """The items' spans and values, when each is a plain one-line string literal
    whose bytes in the file read as that string."""
    spans: list[Span] = []
    values: list[str] = []
    for item in items:
        if not (isinstance(item, ast.Constant) and isinstance(item.value, str)):
            return None
        if item.end_lineno != item.lineno or item.end_col_offset is None:
            return None
        if not 1 <= item.lineno <= len(starts):
            return None
        base = starts[item.lineno - 1]
        span = (base + item.col_offset, base + item.end_col_offset)
        if not _reads_as(text(*span), item.value):
            return None
        spans.append(span)
        values.append(item.value)
    return spans, values


def _reads_as(literal: str | None, value: str) -> bool:
    """Whether ``literal`` is one Python string literal whose value is ``value``."""
    if literal is None or literal[-1:] not in ("'", '"'):
        return False
    try:
        # What ``ast.literal_eval`` reads a string literal (a constant's own span) as,
        # without its nested helper functions: they refer to each other, a cycle of a dozen
        # objects per call left to the garbage collector (nine calls per corpus Python file).
        body = ast.parse(literal, mode="eval").body
    except (SyntaxError, ValueError, RecursionError, MemoryError):
        return False
    return isinstance(body, ast.Constant) and body.value == value


def _may_hold(node: ast.AST, line: int) -> bool:
    """False for a node whose lines do not include ``line`` (nor do its children's)."""
    if isinstance(node, _DECORATED):
        return True  # its decorators lie above its first line
    first = getattr(node, "lineno", None)
    last = getattr(node, "end_lineno", None)
    return first is None or last is None or first <= line <= last


_DECORATED = (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)

__all__ = ["call_spans", "parse"]
