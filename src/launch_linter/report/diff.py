"""``check --diff``: the fixes as a unified diff that ``git apply`` and ``patch -p1`` accept,
and the hints about fixes that were not applied (worded as ruff words them).

The diff is bytes, not text: its context lines must equal the file's bytes exactly (a
Latin-1 file, a lone CR or a form feed inside a line included), so lines are split at
LF only and never decoded. A last line without LF is followed by ``\\ No newline at end of
file``, as ``diff`` and ``git`` write it, so that the next file's header starts on a line
of its own.
"""

from __future__ import annotations

import difflib
from collections.abc import Sequence

from launch_linter.report.text import hidden_hint

CONTEXT_LINES = 3
NO_NEWLINE = b"\\ No newline at end of file\n"

# What git's quote_c_style escapes by name; every other byte below 0x20, DEL and each
# byte of a non-ASCII character as three octal digits (what git writes by default).
_C_ESCAPES = {0x07: b"\\a", 0x08: b"\\b", 0x09: b"\\t", 0x0A: b"\\n", 0x0B: b"\\v",
              0x0C: b"\\f", 0x0D: b"\\r", 0x22: b'\\"', 0x5C: b"\\\\"}


def _lines(data: bytes) -> list[bytes]:
    """The lines of ``data``, each with its LF (the last one may have none)."""
    lines = data.split(b"\n")
    last = lines.pop()
    out = [line + b"\n" for line in lines]
    if last:
        out.append(last)
    return out


def quoted_name(name: str) -> bytes:
    """A file name for a diff header: as it is when plain, otherwise in double quotes
    with C escapes (git's quoting, which ``git apply`` and GNU ``patch`` read back), so a
    name holding a newline or a tab can neither end the header nor forge a hunk."""
    raw = name.encode("utf-8", "surrogateescape")
    if all(0x20 < byte < 0x7F and byte not in (0x22, 0x5C) for byte in raw):
        return raw
    out = bytearray(b'"')
    for byte in raw:
        if byte in _C_ESCAPES:
            out += _C_ESCAPES[byte]
        elif byte < 0x20 or byte >= 0x7F:
            out += b"\\%03o" % byte
        else:
            out.append(byte)
    return bytes(out) + b'"'


def _range(start: int, count: int) -> bytes:
    """A hunk header's ``start,count``: an empty range starts at the line before it."""
    if count == 0:
        return b"%d,0" % start
    return b"%d" % (start + 1) if count == 1 else b"%d,%d" % (start + 1, count)


def _emit(out: list[bytes], mark: bytes, lines: Sequence[bytes]) -> None:
    for line in lines:
        out.append(mark + line)
        if not line.endswith(b"\n"):
            out.append(b"\n" + NO_NEWLINE)


def unified_diff(path: str, before: bytes, after: bytes) -> bytes:
    """The unified diff from ``before`` to ``after`` of the file ``path`` (headers
    ``a/PATH`` and ``b/PATH``, for ``git apply`` and ``patch -p1``); empty when equal."""
    if before == after:
        return b""
    old, new = _lines(before), _lines(after)
    # An absolute path keeps one slash after the prefix: ``patch -p1`` run from the
    # root applies it where it is.
    name = path.lstrip("/")
    out = [b"--- " + quoted_name("a/" + name) + b"\n",
           b"+++ " + quoted_name("b/" + name) + b"\n"]
    matcher = difflib.SequenceMatcher(None, old, new, autojunk=False)
    for group in matcher.get_grouped_opcodes(CONTEXT_LINES):
        first, last = group[0], group[-1]
        out.append(b"@@ -" + _range(first[1], last[2] - first[1]) + b" +"
                   + _range(first[3], last[4] - first[3]) + b" @@\n")
        for tag, i1, i2, j1, j2 in group:
            if tag == "equal":
                _emit(out, b" ", old[i1:i2])
                continue
            _emit(out, b"-", old[i1:i2])
            _emit(out, b"+", new[j1:j2])
    return b"".join(out)


def diff_summary(fixed: int, hidden: int) -> str:
    """The line after a ``--diff``: what it would fix, and what ``--unsafe-fixes`` would add."""
    tail = f" ({hidden_hint(hidden)})" if hidden else ""
    if fixed == 0:
        return f"No findings would be fixed{tail}."
    return f"Would fix {fixed} finding{'s' if fixed != 1 else ''}{tail}."


def fix_summary(counts: dict[str, int], hidden: int) -> str:
    """The line after a ``--fix``: the fixes applied per rule, and the hidden ones."""
    total = sum(counts.values())
    detail = ", ".join(f"{rule} {n}" for rule, n in sorted(counts.items()))
    line = f"fixed {total} finding(s)" + (f" ({detail})" if detail else "")
    return line + (f"; {hidden_hint(hidden)}." if hidden else "")


__all__ = [
    "diff_summary",
    "fix_summary",
    "quoted_name",
    "unified_diff",
]
