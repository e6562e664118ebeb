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

import bisect
import codecs
import collections
import os
import re
from collections.abc import Callable, Iterable, Mapping, Sequence
from typing import TYPE_CHECKING, Tuple

from launch_linter.model.diagnostic import Applicability, Diagnostic, Edit, Fix
from launch_linter.model.record import replace
from launch_linter.resolve.xml_safe import (
    declared_encoding,
    read_file_within,
    unsaved_text,
    unsaved_texts,
)
from launch_linter.rules._fixes import distro_at_least

if TYPE_CHECKING:
    import ast

    from launch_linter.frontends.python_trees import Trees

MAX_FIX_BYTES = 8 * 1024 * 1024
MAX_FIX_PASSES = 8
RECENT_SOURCES = 16
"""Files whose sources locating fixes keeps at once."""

_ATTRIBUTE = re.compile(rb"""([A-Za-z_][\w:.-]*)\s*=\s*(?:"([^"]*)"|'([^']*)')""")
_WORD = re.compile(rb"[^ \t\r\n]+")
_TAG_BODY = re.compile(rb"""(?:[^>"']+|"[^"]*"|'[^']*')*""")
_LINE_END = re.compile(rb"\r\n?|\n")
"""What ends a line for expat and for Python's tokenizer alike: LF, CRLF and a lone CR
(``bytes.splitlines`` would also split at form feeds and other separators)."""
_BOM = b"\xef\xbb\xbf"
_ASCII = "".join(map(chr, range(128)))

Span = Tuple[int, int]


def line_starts(data: bytes, first: int = 0) -> list[int]:
    """The offset of each line's first byte; the first line starts at ``first``."""
    return [first] + [match.end() for match in _LINE_END.finditer(data, first)]


def fix_encoding(path: str, data: bytes) -> str | None:
    """The codec a file is read with, when fixes can be located and written in it: UTF-8
    (a Python file, an XML file without a declaration) or a declared ASCII-compatible
    single-byte encoding (where a character is a byte and every markup byte is ASCII); None
    for anything else (UTF-16, multi-byte or unknown encodings), whose fixes are dropped."""
    if path.endswith(".py"):
        return "utf-8"
    if data.startswith((b"\xff\xfe", b"\xfe\xff")):
        return None
    declared = declared_encoding(data)
    if not declared:
        return "utf-8"
    try:
        name = codecs.lookup(declared).name
        if name == "utf-8":
            return name
        if (bytes(range(128)).decode(name) != _ASCII
                or len(bytes(range(256)).decode(name, "replace")) != 256
                or not codecs.lookup(name)._is_text_encoding):
            return None
    except (LookupError, UnicodeError, ValueError, TypeError):
        return None
    return name


class Source:
    """One file's bytes, with what locating words in it needs, worked out once per file
    however many of its diagnostics carry a fix: its encoding, its line starts (the lines
    the parser counted: LF, CRLF and a lone CR), and for Python its syntax tree.

    Positions are worked out from the decoded text: expat's columns count characters and
    Python's count UTF-8 bytes of the line (after a byte order mark, which expat counts as
    a character of the first line and Python skips)."""

    def __init__(self, path: str, data: bytes, module: ast.Module | None = None) -> None:
        """``module``: the syntax tree of ``data``, if the front-end has parsed it."""
        self.path = path
        self.data = data
        self.python = path.endswith(".py")
        self.yaml = path.endswith((".yaml", ".yml"))
        self.encoding = fix_encoding(path, data)
        self._starts: list[int] | None = None
        self._module = module
        self._calls: dict[int, tuple[list[Span], list[str]] | None] = {}

    @property
    def line_starts(self) -> list[int]:
        if self._starts is None:
            skip = len(_BOM) if self.python and self.data.startswith(_BOM) else 0
            self._starts = line_starts(self.data, skip)
        return self._starts

    def text(self, start: int, end: int) -> str | None:
        """The bytes ``[start, end)`` decoded, None when they are not text."""
        if self.encoding is None:
            return None
        try:
            return self.data[start:end].decode(self.encoding)
        except UnicodeDecodeError:
            return None

    def word_spans(self, line: int, column: int) -> list[Span] | None:
        """The spans of the argument words of the element or call at line:column."""
        if self.yaml or self.encoding is None:
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

    def _tag_start(self, line: int, column: int) -> int | None:
        """The byte offset of the ``<`` that starts the tag at line:column (the column in
        characters, as expat counts), None unless there is exactly one there."""
        starts = self.line_starts
        if not 1 <= line <= len(starts) or column < 1:
            return None
        begin = starts[line - 1]
        end = starts[line] if line < len(starts) else len(self.data)
        text = self.text(begin, end)
        if text is None or column > len(text) or text[column - 1] != "<":
            return None
        assert self.encoding is not None
        return begin + len(text[: column - 1].encode(self.encoding))

    def _xml_word_spans(self, line: int, column: int) -> list[Span] | None:
        """Byte spans of the words of the ``args`` attribute of the start tag at line:column."""
        data = self.data
        position = self._tag_start(line, column)
        if position is None:
            return None
        # The end of the start tag: a '>' outside quotes.
        body = _TAG_BODY.match(data, position + 1)  # matches always (maybe nothing)
        end = body.end() if body is not None else position + 1
        if data[end : end + 1] != b">":
            return None
        found: Span | None = None
        for match in _ATTRIBUTE.finditer(data, position, end):
            if match.group(1) == b"args":
                if found is not None:
                    return None
                group = 2 if match.group(2) is not None else 3
                found = (match.start(group), match.end(group))
        if found is None:
            return None
        value = data[found[0] : found[1]]
        if b"$(" in value or b"&" in value or b"<" in value:
            return None
        return [(found[0] + m.start(), found[0] + m.end()) for m in _WORD.finditer(value)]

    def _python_spans(self, line: int) -> tuple[list[Span], list[str]] | None:
        # Imported here: ``ast`` is start-up time for every run that locates no Python fix.
        from launch_linter import fix_python

        if self._module is None:
            self._module = fix_python.parse(self.data)
        return fix_python.call_spans(self._module, line, self.line_starts, self.text)


def _python_literal(text: str, like: bytes) -> str:
    """``text`` as a Python string literal in the quotes of ``like`` where it can be (every
    control character, separator and surrogate escaped, as ``repr`` writes them)."""
    literal = repr(text)
    if like[-1:] == b'"' and literal[0] == "'" and '"' not in text:
        literal = '"' + literal[1:-1] + '"'
    return literal


_XML_UNSAFE = re.compile("[&<>\"'\x00-\x1f\x7f-\x9f\u2028\u2029\ud800-\udfff]")


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
    """The byte edits of ``fix`` in ``source`` at line:column; () when the words found
    there are not exactly the words the rule read, or a new word could not be written."""
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
        words = [source.text(a, b) for a, b in spans]
        if any(word is None for word in words):
            return ()
        written = tuple(word for word in words if word is not None)
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
            if not python and _XML_UNSAFE.search(token_edit.text):
                return ()  # markup or a character an attribute cannot hold as it is
            content = laid_out(token_edit.text, data, spans[first : last + 1], python)
        expected = source.text(start, end)
        if expected is None:
            return ()
        edits.append(Edit(path, start, end, content, expected))
    return tuple(edits)


def read_bytes(path: str) -> bytes | None:
    """The file's bytes (the text ``--diff`` has fixed, while it lints it again), or None
    when it is no regular file, unreadable or too large."""
    data = unsaved_text(path)
    if data is not None:
        return data if len(data) <= MAX_FIX_BYTES else None
    try:
        return read_file_within(path, MAX_FIX_BYTES)
    except OSError:  # NotRegularFile and FileTooLarge included
        return None


def with_located_fixes(
    diagnostics: Sequence[Diagnostic],
    distro: str | None = None,
    sources: Mapping[str, bytes] | None = None,
    trees: Trees | None = None,
) -> tuple[Diagnostic, ...]:
    """Each diagnostic with its fix located in its file (or without a fix when it cannot
    be), a fix that is safe for the target distribution marked safe. A fix already
    located (it has edits) is kept as it is.

    ``sources``: the bytes of some files (else they are read); ``trees``: the Python files
    the front-end parsed, with their bytes (``frontends.python_trees``), not parsed again."""
    given = sources or {}
    # The diagnostics come file by file (a root file's, then its includes'), so the few
    # files seen last are the ones asked for again; keeping every file's source (bytes,
    # line starts, a Python file's syntax tree) would grow with the run.
    cache: collections.OrderedDict[str, Source | None] = collections.OrderedDict()
    out: list[Diagnostic] = []
    for diagnostic in diagnostics:
        fix = diagnostic.fix
        if fix is None or fix.edits:
            out.append(diagnostic)
            continue
        path = diagnostic.path
        if path in cache:
            cache.move_to_end(path)
        else:
            cache[path] = _source(path, given, trees)
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


def _source(path: str, given: Mapping[str, bytes], trees: Trees | None) -> Source | None:
    """``path``'s source: the bytes and tree the front-end parsed, the bytes given, or
    the file read now (None when it cannot be)."""
    parsed = trees.get(os.path.abspath(path)) if trees else None
    if parsed is not None and len(parsed[0]) <= MAX_FIX_BYTES and (
            path not in given or given[path] == parsed[0]):
        return Source(path, parsed[0], parsed[1])
    data = given[path] if path in given else read_bytes(path)
    return None if data is None else Source(path, data)


def wanted(diagnostic: Diagnostic, unsafe: bool) -> bool:
    fix = diagnostic.fix
    return bool(
        fix is not None
        and fix.edits
        and (unsafe or fix.applicability is Applicability.SAFE)
    )


def apply_edits(
    data: bytes, fixes: Iterable[Fix], skipped: list[str] | None = None
) -> tuple[bytes, list[Fix]]:
    """``data`` with every fix whose edits overlap no earlier fix's applied; the fixes
    applied. A fix is all or nothing, and is skipped (its reason added to ``skipped``)
    unless every byte it replaces still reads as the words it was located on and its new
    words can be written in the file's encoding."""
    taken: list[tuple[int, int]] = []  # sorted, disjoint
    applied: list[Fix] = []
    chosen: list[tuple[int, int, bytes]] = []
    for fix in fixes:
        encoded = _encoded_edits(data, fix)
        if isinstance(encoded, str):
            if skipped is not None:
                skipped.append(f"fix skipped ({fix.message}): {encoded}")
            continue
        if any(_overlaps(taken, start, end) for start, end, _ in encoded):
            continue
        for start, end, _ in encoded:
            bisect.insort(taken, (start, end))
        chosen.extend(encoded)
        applied.append(fix)
    if not chosen:
        return data, applied
    pieces: list[bytes] = []
    done = 0
    for start, end, content in sorted(chosen, key=lambda e: (e[0], e[1])):
        pieces += (data[done:start], content)
        done = end
    pieces.append(data[done:])
    return b"".join(pieces), applied


def _encoded_edits(data: bytes, fix: Fix) -> list[tuple[int, int, bytes]] | str:
    """The fix's edits as (start, end, new bytes), or why it cannot be applied."""
    encoded: list[tuple[int, int, bytes]] = []
    for edit in fix.edits:
        encoding = fix_encoding(edit.path, data)
        if encoding is None:
            return "the file's encoding is not one fixes are written in"
        if not 0 <= edit.start <= edit.end <= len(data):
            return "the file is shorter than when the fix was located"
        try:
            if edit.expected is not None and (
                    data[edit.start:edit.end] != edit.expected.encode(encoding)):
                return (f"the file no longer holds {edit.expected!r} at byte {edit.start}"
                        " (changed since it was read)")
            encoded.append((edit.start, edit.end, edit.content.encode(encoding)))
        except UnicodeEncodeError:
            return f"{edit.content!r} cannot be written in the file's encoding ({encoding})"
    return encoded


def _overlaps(taken: list[tuple[int, int]], start: int, end: int) -> bool:
    """Whether [start, end) overlaps a taken span (two insertions at one place do too)."""
    index = max(bisect.bisect_left(taken, (start, start)) - 1, 0)
    while index < len(taken) and taken[index][0] <= end:
        near = taken[index]
        if (near[0] < end and start < near[1]) or near[0] == near[1] == start == end:
            return True
        index += 1
    return False


def fixes_by_file(diagnostics: Iterable[Diagnostic], unsafe: bool) -> dict[str, list[Fix]]:
    grouped: dict[str, dict[Fix, None]] = {}
    for diagnostic in diagnostics:
        fix = diagnostic.fix
        if wanted(diagnostic, unsafe) and fix is not None:
            grouped.setdefault(diagnostic.path, {})[fix] = None
    return {path: list(fixes) for path, fixes in grouped.items()}


def fix_until_stable(
    lint: Callable[[], Sequence[Diagnostic]],
    unsafe: bool,
    write: Callable[[str, bytes, bytes], str | None],
    read: Callable[[str], bytes | None] = read_bytes,
    notes: list[tuple[str, str]] | None = None,
) -> tuple[dict[str, int], Sequence[Diagnostic]]:
    """Apply fixes, lint again, repeat while something changes (bounded). Returns the
    count of fixes applied per rule and the diagnostics of the last lint.

    ``write(path, before, after)`` writes a file or says why not; every fix skipped and
    every file not written is added to ``notes`` as (path, reason), once."""
    counts: dict[str, int] = {}
    noted: dict[tuple[str, str], None] = {}
    refused: set[str] = set()
    diagnostics = lint()
    for _ in range(MAX_FIX_PASSES):
        grouped = fixes_by_file(diagnostics, unsafe)
        rule_of = {id(d.fix): d.rule for d in diagnostics if d.fix is not None}
        changed = False
        for path, fixes in grouped.items():
            if path in refused:
                continue
            data = read(path)
            if data is None:
                continue
            skipped: list[str] = []
            fixed, applied = apply_edits(data, fixes, skipped)
            noted.update(((path, reason), None) for reason in skipped)
            if fixed == data:
                continue
            reason = write(path, data, fixed)
            if reason is not None:
                refused.add(path)
                noted[(path, reason)] = None
                continue
            changed = True
            for fix in applied:
                rule = rule_of.get(id(fix), "?")
                counts[rule] = counts.get(rule, 0) + 1
        if not changed:
            break
        diagnostics = lint()
    if notes is not None:
        notes.extend(noted)
    return counts, diagnostics


__all__ = [
    "Source",
    "apply_edits",
    "fix_until_stable",
    "fixes_by_file",
    "laid_out",
    "locate",
    "locate_in",
    "read_bytes",
    "unsaved_texts",
    "wanted",
    "with_located_fixes",
]
