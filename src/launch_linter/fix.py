"""Fixes: find a rule's word edits in the file's bytes and apply them.

A rule says which argument words to replace (:class:`~launch_linter.model.diagnostic.Fix`
``token_edits``, relative to the words it read). Here they become byte edits of the file:
the element the diagnostic points at is found at its line and column, then its ``args``
attribute (XML) or its ``arguments=[...]`` list of string literals (Python), and new
words are laid out like the old ones (:func:`laid_out`). A fix is dropped, never guessed,
when the attribute holds a substitution, an entity or a comment, or its words are not the
ones the rule read. Every byte outside the edited words is kept. The diff of the fixes is
:mod:`launch_linter.report.diff`.
"""

from __future__ import annotations

import ast
import collections
import re
from collections.abc import Callable, Iterable, Mapping, Sequence
from dataclasses import replace
from typing import Tuple

from launch_linter.model.diagnostic import Applicability, Diagnostic, Edit, Fix
from launch_linter.resolve.xml_safe import read_regular_file
from launch_linter.rules._fixes import distro_at_least

MAX_FIX_BYTES = 8 * 1024 * 1024
MAX_FIX_PASSES = 8
RECENT_SOURCES = 16
"""Files whose sources locating fixes keeps at once."""

_ATTRIBUTE = re.compile(rb"""([A-Za-z_][\w:.-]*)\s*=\s*(?:"([^"]*)"|'([^']*)')""")
_WORD = re.compile(rb"[^ \t\r\n]+")
_TAG_BODY = re.compile(rb"""(?:[^>"']+|"[^"]*"|'[^']*')*""")

Span = Tuple[int, int]


def _line_starts(data: bytes) -> list[int]:
    starts = [0]
    index = data.find(b"\n")
    while index >= 0:
        starts.append(index + 1)
        index = data.find(b"\n", index + 1)
    return starts


class Source:
    """One file's bytes, with what locating words in it needs, worked out once per file
    however many of its diagnostics carry a fix: its line starts, and for Python the
    ``arguments=[...]`` lists of its calls by line (one parse)."""

    def __init__(self, path: str, data: bytes) -> None:
        self.path = path
        self.data = data
        self.python = path.endswith(".py")
        self.yaml = path.endswith((".yaml", ".yml"))
        self._starts: list[int] | None = None
        self._module: ast.Module | None = None
        self._calls: dict[int, tuple[list[Span], list[str]] | None] = {}

    @property
    def line_starts(self) -> list[int]:
        if self._starts is None:
            self._starts = _line_starts(self.data)
        return self._starts

    def word_spans(self, line: int, column: int) -> list[Span] | None:
        """The spans of the argument words of the element or call at line:column."""
        if self.yaml:
            return None
        if self.python:
            words = self.python_words(line)
            return None if words is None else words[0]
        return self._xml_word_spans(line, column)

    def python_words(self, line: int) -> tuple[list[Span], list[str]] | None:
        """The spans and values of the string items of ``arguments=[...]`` of the call on
        ``line`` (see ``_python_spans``), worked out once per line."""
        if line not in self._calls:
            self._calls[line] = self._python_spans(line)
        return self._calls[line]

    def _xml_word_spans(self, line: int, column: int) -> list[Span] | None:
        """Byte spans of the words of the ``args`` attribute of the start tag at line:column."""
        data, starts = self.data, self.line_starts
        if not 1 <= line <= len(starts):
            return None
        begin = starts[line - 1]
        position = begin + max(column - 1, 0)
        if data[position : position + 1] != b"<":
            position = data.find(b"<", begin)
            if position < 0 or (line < len(starts) and position >= starts[line]):
                return None
        # The end of the start tag: a '>' outside quotes (an unclosed quote runs to the
        # end of the file).
        body = _TAG_BODY.match(data, position + 1)  # matches always (maybe nothing)
        end = body.end() if body is not None else position + 1
        if data[end : end + 1] not in (b">", b""):
            end = len(data)
        found: Span | None = None
        for match in _ATTRIBUTE.finditer(data, position, end):
            if match.group(1) == b"args":
                group = 2 if match.group(2) is not None else 3
                found = (match.start(group), match.end(group))
        if found is None:
            return None
        value = data[found[0] : found[1]]
        if b"$(" in value or b"&" in value or b"<" in value:
            return None
        return [(found[0] + m.start(), found[0] + m.end()) for m in _WORD.finditer(value)]

    def _python_spans(self, line: int) -> tuple[list[Span], list[str]] | None:
        """Byte spans (quotes included) and values of the string items of
        ``arguments=[...]`` of the first call on ``line`` that has one (in ``ast.walk``
        order); None unless every item is a plain one-line string literal."""
        if self._module is None:
            try:
                self._module = ast.parse(self.data)
            except (SyntaxError, ValueError, RecursionError, MemoryError):
                self._module = ast.Module(body=[], type_ignores=[])
        # ast.walk's breadth-first order, without the subtrees that lie off the line (a
        # file parsed once, each line's search a thin slice of it).
        queue: collections.deque[ast.AST] = collections.deque([self._module])
        while queue:
            node = queue.popleft()
            if isinstance(node, ast.Call) and node.lineno == line:
                for keyword in node.keywords:
                    value = keyword.value
                    if keyword.arg == "arguments" and isinstance(value, (ast.List, ast.Tuple)):
                        return _string_spans(value.elts, self.line_starts)
            for child in ast.iter_child_nodes(node):
                if _may_hold(child, line):
                    queue.append(child)
        return None


def _may_hold(node: ast.AST, line: int) -> bool:
    """False for a node whose lines do not include ``line`` (nor do its children's)."""
    if isinstance(node, _DECORATED):
        return True  # its decorators lie above its first line
    first = getattr(node, "lineno", None)
    last = getattr(node, "end_lineno", None)
    return first is None or last is None or first <= line <= last


_DECORATED = (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)


def _string_spans(items: list[ast.expr], starts: list[int]
                  ) -> tuple[list[Span], list[str]] | None:
    """The items' spans and values, when each is a plain one-line string literal."""
    spans: list[Span] = []
    values: list[str] = []
    for item in items:
        if not (isinstance(item, ast.Constant) and isinstance(item.value, str)):
            return None
        if item.end_lineno != item.lineno or item.end_col_offset is None:
            return None
        base = starts[item.lineno - 1]
        spans.append((base + item.col_offset, base + item.end_col_offset))
        values.append(item.value)
    return spans, values


def _python_literal(text: str, like: bytes) -> str:
    quote = "'" if like[-1:] == b"'" else '"'
    return quote + text.replace("\\", "\\\\").replace(quote, "\\" + quote) + quote


def _flag_groups(words: list[str]) -> list[list[str]]:
    """``words`` cut before each flag (``--x 1 --frame-id map`` → two groups)."""
    groups: list[list[str]] = []
    for word in words:
        if not groups or (word.startswith("--") and len(word) > 2):
            groups.append([])
        groups[-1].append(word)
    return groups


def _line_break(data: bytes, spans: Sequence[Span]) -> str | None:
    """The line break and indentation between the lines the words ``spans`` are written
    on (what comes before the first word of their second line), or None when they are on
    one line."""
    for (_, end), (start, _) in zip(spans, spans[1:]):
        between = data[end:start]
        newline = max(between.rfind(b"\n"), between.rfind(b"\r"))
        if newline < 0:
            continue
        line_start = end + newline + 1
        indent = data[line_start:start]
        if indent.strip(b" \t"):  # something else before the word: align with spaces
            indent = b" " * len(indent.decode("utf-8", "replace"))
        if between[newline:].startswith(b"\r"):
            ending = "\r"
        elif between[:newline].endswith(b"\r"):
            ending = "\r\n"
        else:
            ending = "\n"
        return ending + indent.decode("utf-8", "replace")
    return None


def laid_out(text: str, data: bytes, spans: Sequence[Span], python: bool) -> str:
    """The replacement ``text`` (words) written as the words at ``spans`` were: Python
    string items like the first one (its quotes), separated by ``, ``; and where the
    old words ran over several lines, one flag with its value per line, indented like
    the old words' second line."""
    words = text.split()
    groups = _flag_groups(words) if len(spans) > 1 else [words]
    line_break = _line_break(data, spans)
    if line_break is None or len(groups) < 2:
        groups = [words]
    if python:
        like = data[spans[0][0] : spans[0][1]]
        written = [", ".join(_python_literal(w, like) for w in group) for group in groups]
        return ("," + (line_break or " ")).join(written)
    return (line_break or " ").join(" ".join(group) for group in groups)


def locate(fix: Fix, path: str, line: int, column: int, data: bytes) -> tuple[Edit, ...]:
    """The byte edits of ``fix`` in ``data`` (the file ``path``); () when not found."""
    return locate_in(fix, Source(path, data), line, column)


def locate_in(fix: Fix, source: Source, line: int, column: int) -> tuple[Edit, ...]:
    """The byte edits of ``fix`` in ``source`` at line:column; () when not found."""
    path, data, python = source.path, source.data, source.python
    if python:
        found = source.python_words(line)
        if found is None:
            return ()
        spans, values = found
        # ``arguments`` items are whole words only when none holds a blank.
        if any(not value or value.split() != [value] for value in values):
            return ()
        written = tuple(values)
    else:
        xml_spans = source.word_spans(line, column)
        if xml_spans is None:
            return ()
        spans = xml_spans
        written = tuple(data[a:b].decode("utf-8", "replace") for a, b in spans)
    if written != fix.tokens:
        return ()
    edits: list[Edit] = []
    for token_edit in fix.token_edits:
        first, last = token_edit.start, token_edit.end - 1
        if not 0 <= first <= last < len(spans):
            return ()
        start, end = spans[first][0], spans[last][1]
        if token_edit.text == "":
            # Delete the words with the separator before them (after them for the first).
            if first > 0:
                start = spans[first - 1][1]
            elif last + 1 < len(spans):
                end = spans[last + 1][0]
            content = ""
        else:
            content = laid_out(token_edit.text, data, spans[first : last + 1], python)
        edits.append(Edit(path, start, end, content))
    return tuple(edits)


def read_bytes(path: str) -> bytes | None:
    """The file's bytes, or None when it is no regular file, unreadable or too large."""
    try:
        data = read_regular_file(path, MAX_FIX_BYTES + 1)
    except OSError:  # NotRegularFile included
        return None
    return data if len(data) <= MAX_FIX_BYTES else None


def with_located_fixes(
    diagnostics: Sequence[Diagnostic],
    distro: str | None = None,
    sources: Mapping[str, bytes] | None = None,
) -> tuple[Diagnostic, ...]:
    """Each diagnostic with its fix located in its file (or without a fix when it cannot
    be), a fix that is safe for the target distribution marked safe."""
    given = sources or {}
    # The diagnostics come file by file (a root file's, then its includes'), so the few
    # files seen last are the ones asked for again; keeping every file's source (bytes,
    # line starts, a Python file's syntax tree) would grow with the run.
    cache: collections.OrderedDict[str, Source | None] = collections.OrderedDict()
    out: list[Diagnostic] = []
    for diagnostic in diagnostics:
        fix = diagnostic.fix
        if fix is None:
            out.append(diagnostic)
            continue
        path = diagnostic.path
        if path in cache:
            cache.move_to_end(path)
        else:
            data = given[path] if path in given else read_bytes(path)
            cache[path] = None if data is None else Source(path, data)
            if len(cache) > RECENT_SOURCES:
                cache.popitem(last=False)
        source = cache[path]
        edits = (
            locate_in(fix, source, diagnostic.line, diagnostic.column)
            if source is not None
            else ()
        )
        if not edits:
            out.append(replace(diagnostic, fix=None))
            continue
        applicability = fix.applicability
        if fix.safe_from_distro is not None and distro_at_least(distro, fix.safe_from_distro):
            applicability = Applicability.SAFE
        out.append(replace(diagnostic, fix=replace(fix, edits=edits, applicability=applicability)))
    return tuple(out)


def wanted(diagnostic: Diagnostic, unsafe: bool) -> bool:
    fix = diagnostic.fix
    return bool(
        fix is not None
        and fix.edits
        and (unsafe or fix.applicability is Applicability.SAFE)
    )


def apply_edits(data: bytes, fixes: Iterable[Fix]) -> tuple[bytes, list[Fix]]:
    """``data`` with every fix whose edits overlap no earlier fix's applied; the fixes
    applied. A fix is all or nothing."""
    taken: list[tuple[int, int]] = []
    applied: list[Fix] = []
    chosen: list[Edit] = []
    for fix in fixes:
        spans = [(e.start, e.end) for e in fix.edits]
        if any((a < d and c < b) or a == b == c == d for a, b in spans for c, d in taken):
            continue
        taken.extend(spans)
        chosen.extend(fix.edits)
        applied.append(fix)
    out = data
    for edit in sorted(chosen, key=lambda e: (e.start, e.end), reverse=True):
        out = out[: edit.start] + edit.content.encode("utf-8") + out[edit.end :]
    return out, applied


def fixes_by_file(diagnostics: Iterable[Diagnostic], unsafe: bool) -> dict[str, list[Fix]]:
    grouped: dict[str, list[Fix]] = {}
    for diagnostic in diagnostics:
        fix = diagnostic.fix
        if wanted(diagnostic, unsafe) and fix is not None:
            listed = grouped.setdefault(diagnostic.path, [])
            if fix not in listed:
                listed.append(fix)
    return grouped


def fix_until_stable(
    lint: Callable[[], Sequence[Diagnostic]],
    unsafe: bool,
    write: Callable[[str, bytes], None],
    read: Callable[[str], bytes | None] = read_bytes,
) -> tuple[dict[str, int], Sequence[Diagnostic]]:
    """Apply fixes, lint again, repeat while something changes (bounded). Returns the
    count of fixes applied per rule and the diagnostics of the last lint."""
    counts: dict[str, int] = {}
    diagnostics = lint()
    for _ in range(MAX_FIX_PASSES):
        grouped = fixes_by_file(diagnostics, unsafe)
        rule_of = {id(d.fix): d.rule for d in diagnostics if d.fix is not None}
        changed = False
        for path, fixes in grouped.items():
            data = read(path)
            if data is None:
                continue
            fixed, applied = apply_edits(data, fixes)
            if fixed != data:
                write(path, fixed)
                changed = True
                for fix in applied:
                    rule = rule_of.get(id(fix), "?")
                    counts[rule] = counts.get(rule, 0) + 1
        if not changed:
            break
        diagnostics = lint()
    return counts, diagnostics


def write_file(path: str, data: bytes) -> None:
    """Replace the file's bytes, keeping its permissions (written in place)."""
    with open(path, "r+b") as handle:
        handle.write(data)
        handle.truncate()


__all__ = [
    "Source",
    "apply_edits",
    "fix_until_stable",
    "fixes_by_file",
    "laid_out",
    "locate",
    "locate_in",
    "read_bytes",
    "wanted",
    "with_located_fixes",
    "write_file",
]
