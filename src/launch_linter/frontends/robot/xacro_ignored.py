"""The ``name:=value`` mappings of a xacro call that no file of the description names.

xacro keeps every mapping of its command line in ``substitution_args_context['arg']``
without checking it against anything (ros/xacro ros2 9d05b0e: ``cli.py`` ``load_mappings``
lines 69-92, ``__init__.py`` ``process_doc`` lines 1030-1054; noetic-devel 7045754 the
same): a mapping that no ``<xacro:arg>``, ``$(arg ...)`` or ``xacro.arg(...)`` reads is
dropped without a word, and what the launch file meant by it (a ``tf_prefix``, a
``use_sim`` switch) never reaches the robot.

The check is on the text, not on the expansion: a name written anywhere in a file the
description read (a macro never called, a branch not taken; XML comments left out, which
xacro never reads) counts as named, so
only a mapping that no configuration of the description can read is kept. Every file an
``<xacro:include>`` names is read, in a branch taken or not; a description whose
expansion was not followed, or with an include whose file is not known (a name built from
an arg, an unknown package) or not readable, is not judged: that file may name the arg.
"""

from __future__ import annotations

import os
import re
from collections.abc import Callable, Sequence

from launch_linter.model.robot import DescriptionKind, DescriptionSource, IgnoredArg
from launch_linter.resolve.xml_safe import read_regular_file

MAX_FILE_BYTES = 4 * 1024 * 1024
"""Most bytes read of one description file or launch file (larger: not judged)."""
MAX_TOTAL_BYTES = 16 * 1024 * 1024
"""Most bytes read over all the files of one description."""
MAX_FILES = 200
"""Most files of one description read for the names they write."""
MAX_ARGS = 200
"""Most mappings of one xacro call that are looked for (each is one pass per file)."""

MAX_SUGGESTED = 20
"""Ignored mappings per call for which close declared names are looked for."""
MAX_DECLARED = 500
"""Most declared arg names a mapping is compared with (each comparison is a difflib
ratio)."""
MAX_TAG_BYTES = 512
"""Most bytes of one ``<xacro:arg ...>`` tag read for its name."""

_INCLUDE = re.compile(rb"<\s*(?:xacro:)?include\b")
_FILENAME = re.compile(rb"\bfilename\s*=\s*[\"']([^\"'>]*)[\"']")
_FIND = re.compile(r"^\$\(find\s+([A-Za-z0-9_.-]+)\)(/[^$]*)$")
_ARG_TAG = re.compile(rb"<\s*xacro:arg\b")
_TAG_NAME = re.compile(rb"\bname\s*=\s*[\"']([^\"'>]*)[\"']")
_IDENTIFIER = re.compile(rb"[A-Za-z0-9_]+")
_WORD = re.compile(rb"[A-Za-z0-9_./-]+")
_NAME = re.compile(r"^[A-Za-z_][A-Za-z0-9_./-]*$")


def ignored_args(source: DescriptionSource, files: Sequence[str], followed: bool,
                 find: Callable[[str], str | None]) -> tuple[IgnoredArg, ...]:
    """The mappings of ``source``'s xacro call that no file of the description names:
    ``files`` (the files the expansion read, the description first) and every file their
    ``<xacro:include>`` elements name, followed or not (``find`` gives a package's
    folder for ``$(find pkg)``); () when not provable."""
    if (source.kind is not DescriptionKind.XACRO or not source.args or not followed
            or not files or source.wrapper is not None):
        return ()
    texts = _all_included(files, find)
    if texts is None:
        return ()
    words: set[bytes] = set()
    declared: list[str] = []
    for text in texts:
        words.update(_IDENTIFIER.findall(text))
        words.update(_WORD.findall(text))
        for tag in _ARG_TAG.finditer(text):
            named = _TAG_NAME.search(_tag_text(text, tag.end()))
            if named:
                declared.append(named.group(1).decode("utf-8", "replace"))
    written = _mappings_written(_read(source.path))
    out: list[IgnoredArg] = []
    seen: set[str] = set()
    for name, _value in source.args[:MAX_ARGS]:
        if name in seen or not _NAME.match(name):
            continue
        seen.add(name)
        # A name is named when it is a word of some file: split at anything but an
        # identifier's characters, or at anything but those and ``./-``.
        if name.encode("utf-8") in words:
            continue
        line, column = written.get(name, (0, 0))
        close = _close(name, declared) if len(out) < MAX_SUGGESTED else ()
        out.append(IgnoredArg(name, source.path, line, column, close))
    return tuple(out)


def _tag_text(text: bytes, after: int) -> bytes:
    """The rest of a tag that starts before ``after``, up to its ``>`` (bounded)."""
    return text[after:after + MAX_TAG_BYTES].split(b">", 1)[0]


def _all_included(files: Sequence[str],
                  find: Callable[[str], str | None]) -> list[bytes] | None:
    """The texts (XML comments left out) of ``files`` and of every file an include
    element of them names, transitively; None when one is not readable or its name not
    known (a ``${...}``, an unknown package): that file may name any arg."""
    queue = list(dict.fromkeys(os.path.abspath(f) for f in files))
    done = set(queue)
    texts: list[bytes] = []
    total = 0
    while queue:
        if len(done) > MAX_FILES:
            return None
        path = queue.pop(0)
        data = _read(path)
        if data is None:
            return None
        total += len(data)
        if total > MAX_TOTAL_BYTES:
            return None
        text = _without_comments(data)
        texts.append(text)
        for tag in _INCLUDE.finditer(text):
            named = _FILENAME.search(_tag_text(text, tag.end()))
            if named is None:
                return None
            target = _included_path(named.group(1).decode("utf-8", "replace"), path, find)
            if target is None:
                return None
            if target not in done:
                done.add(target)
                queue.append(target)
    return texts


def _included_path(name: str, including: str,
                   find: Callable[[str], str | None]) -> str | None:
    """The file an include's ``filename`` names: relative to the including file, or
    under ``$(find pkg)``; None for anything else (a substitution, an arg, a glob)."""
    found = _FIND.match(name)
    if found:
        folder = find(found.group(1))
        if folder is None:
            return None
        name = folder + found.group(2)
    if "$" in name or "*" in name or "?" in name:
        return None
    return os.path.abspath(os.path.join(os.path.dirname(including), name))


def _without_comments(text: bytes) -> bytes:
    """``text`` without its XML comments (xacro reads no name in them); an unclosed
    comment runs to the end, as the XML parser would refuse the file anyway."""
    parts: list[bytes] = []
    position = 0
    while True:
        start = text.find(b"<!--", position)
        if start < 0:
            parts.append(text[position:])
            return b" ".join(parts)
        parts.append(text[position:start])
        end = text.find(b"-->", start + 4)
        if end < 0:
            return b" ".join(parts)
        position = end + 3


def _read(path: str) -> bytes | None:
    """The file's bytes, read as every input is (noted for the results cache); None
    when it cannot be read or is too large."""
    try:
        data = read_regular_file(path, MAX_FILE_BYTES + 1)
    except (OSError, ValueError):
        return None
    return None if len(data) > MAX_FILE_BYTES else data


_MAPPING = re.compile(rb"([A-Za-z_][A-Za-z0-9_./-]*)\s*:=")


def _mappings_written(launch_text: bytes | None) -> dict[str, tuple[int, int]]:
    """Where the launch file writes each ``name:=`` (line, column), for the names it
    writes once; a name written twice or more is left out (its finding is then shown at
    the description's line)."""
    if launch_text is None:
        return {}
    places: dict[str, tuple[int, int]] = {}
    twice: set[str] = set()
    line, line_start, position = 1, 0, 0
    for match in _MAPPING.finditer(launch_text):
        start = match.start()
        newlines = launch_text.count(b"\n", position, start)
        if newlines:
            line += newlines
            line_start = launch_text.rfind(b"\n", position, start) + 1
        position = start
        name = match.group(1).decode("utf-8", "replace")
        if name in places:
            twice.add(name)
        places[name] = (line, start - line_start + 1)
    return {name: place for name, place in places.items() if name not in twice}


def _close(name: str, declared: list[str]) -> tuple[str, ...]:
    # Imported here: difflib is needed only for a mapping nothing names.
    import difflib

    close = difflib.get_close_matches(name, sorted(set(declared))[:MAX_DECLARED], n=3,
                                      cutoff=0.6)
    return tuple(close)
