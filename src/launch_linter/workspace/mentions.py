"""Which launch files another file of the same package names: those are (also) included.

ROS 2 includes a launch file by a path its includer builds (``os.path.join(share,
'launch', 'rsp.launch.py')``, ``$(find-pkg-share pkg)/launch/rsp.launch.xml``), so the
file's name is written in the includer even when the path around it cannot be resolved.
A launch file that another file of its package names is (also) an included file: the
launch configurations it reads may be passed by that includer, so reading one that the
file does not declare is not proof that ``ros2 launch`` of it stops.

The files looked at are the launch files (by name, or any file in a ``launch`` folder)
of the workspace (the ``src`` folder of a colcon/catkin workspace), else of the
repository (the nearest folder up with a ``.git``), else of the package (the folder of
the nearest ``package.xml``), else of the file's own folder. Each such folder is read
once per run (its names are kept :data:`FRESH_SECONDS`, so that a long-lived process, the
language server, sees an include written since), bounded in files and bytes.
"""

from __future__ import annotations

import contextlib
import os
import re
import time

from launch_linter.resolve import reads
from launch_linter.resolve.xml_safe import NotRegularFile, read_regular_file
from launch_linter.workspace.discovery import (
    VCS_FOLDERS,
    WORKSPACE_FOLDERS,
    is_launch_name,
    walk,
)
from launch_linter.workspace.packages import MAX_WALK_UP, default_package_roots, nearest_package_xml

MAX_FILES = 5_000
"""Files read per folder; past them, the names found so far are all there is."""
MAX_FILE_BYTES = 256 * 1024
MAX_TOTAL_BYTES = 32 * 1024 * 1024
"""Bytes read per folder, all files together."""
MAX_FOLDERS = 20_000
MAX_CACHED_FOLDERS = 256
FRESH_SECONDS = 10.0
"""How long the names read in a folder are used before the folder is read again."""
READ_SUFFIXES = (".py", ".xml", ".launch", ".yaml", ".yml")
"""Files that may include a launch file: launch files of every format and Python helpers."""
_SUFFIX = re.compile(rb"\.(?:py|xml|launch|ya?ml)\b")
"""Where a file name written in a path or string ends. The name is then read backwards
from there (bounded), never with a pattern that starts at every letter of a long word."""
_NAME_BYTES = frozenset(b"abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_.-")
MAX_NAME = 255
MAX_WRITERS = 16
"""Files kept per name written: past them, who writes the name is unknown."""

_names_by_folder: dict[
    str, tuple[float, dict[str, tuple[str, ...]], bool, reads.ReadLog]] = {}
"""For each folder read: when, each file name written in it → the first
:data:`MAX_WRITERS` + 1 files writing it (a file may write its own name, in a usage
comment), whether every file was read (no bound cut the scan, no file failed), and what
reading them read: every file that asks depends on it (the results cache,
``resolve.reads``)."""
_LISTING = reads.suffix_listing(READ_SUFFIXES)
"""The files of a folder that count for the results cache: those that may be read (a
launch file's name ends with one of these suffixes too)."""


def _names_in(folder: str) -> tuple[dict[str, tuple[str, ...]], bool]:
    """Every file name written in the files under ``folder``, with the files writing it
    (at most :data:`MAX_WRITERS` + 1), and whether every file was read."""
    names: dict[str, tuple[str, ...]] = {}
    complete = True
    files = 0
    folders = 0
    total = 0
    for directory, subdirs, entries in walk(folder):
        folders += 1
        if folders > MAX_FOLDERS:
            return names, False
        with contextlib.suppress(OSError):  # a folder gone since it was listed
            reads.note_folder(directory, os.stat(directory), subdirs, entries, _LISTING)
        subdirs[:] = sorted(
            d for d in subdirs
            if not d.startswith(".") and d not in VCS_FOLDERS and d not in WORKSPACE_FOLDERS
            and d != "__pycache__"
        )
        in_launch_folder = os.path.basename(directory) == "launch"
        for entry in sorted(entries):
            if not (is_launch_name(entry) or (in_launch_folder and entry.endswith(READ_SUFFIXES))):
                continue
            files += 1
            if files > MAX_FILES or total > MAX_TOTAL_BYTES:
                return names, False
            path = os.path.join(directory, entry)
            try:
                data = read_regular_file(path, MAX_FILE_BYTES)
            except (OSError, NotRegularFile):
                complete = False
                continue
            total += len(data)
            complete = complete and len(data) < MAX_FILE_BYTES
            for text in _file_names(data):
                writers = names.get(text, ())
                if len(writers) <= MAX_WRITERS:
                    names[text] = (*writers, path)
    return names, complete


def _file_names(data: bytes) -> set[str]:
    """The file names (``rsp.launch.py``) written in ``data``, in linear time."""
    found: set[str] = set()
    for match in _SUFFIX.finditer(data):
        start = match.start()
        lowest = max(0, start - MAX_NAME)
        while start > lowest and data[start - 1] in _NAME_BYTES:
            start -= 1
        if start < match.start():
            found.add(data[start:match.end()].decode("ascii"))
    return found


def scope(absolute: str) -> str:
    """The folder whose launch files may include ``absolute`` (see the module's doc)."""
    manifest = nearest_package_xml(absolute)
    if manifest is None:
        return os.path.dirname(absolute)
    roots = default_package_roots(absolute)
    if roots and os.path.basename(roots[0]) == "src":
        return roots[0]
    directory = os.path.dirname(manifest)
    for _ in range(MAX_WALK_UP):
        if reads.exists(os.path.join(directory, ".git")):
            return directory
        parent = os.path.dirname(directory)
        if parent == directory:
            break
        directory = parent
    return os.path.dirname(manifest)


def _writers(absolute: str) -> tuple[tuple[str, ...], bool]:
    """The files near ``absolute`` that write its file name (at most :data:`MAX_WRITERS`
    + 1, perhaps itself), and whether the scan read every file."""
    folder = scope(absolute)
    now = time.monotonic()
    read = _names_by_folder.get(folder)
    if read is None or now - read[0] > FRESH_SECONDS:
        if len(_names_by_folder) >= MAX_CACHED_FOLDERS:
            _names_by_folder.clear()
        with reads.recording() as log:
            names, complete = _names_in(folder)
        read = _names_by_folder[folder] = (now, names, complete, log)
    reads.depend_on(read[3])
    return read[1].get(os.path.basename(absolute), ()), read[2]


def named_by_another_file(path: str) -> str | None:
    """A launch file near ``path`` (see the module's doc), other than ``path``, that writes
    its file name."""
    absolute = os.path.abspath(path)
    others = [w for w in _writers(absolute)[0] if w != absolute]
    return others[0] if others else None


def every_writer(path: str) -> tuple[str, ...] | None:
    """Every launch file near ``path`` (see the module's doc), other than ``path``, that
    writes its file name; None when that is unknown (a bound cut the scan, a file could
    not be read, or more than :data:`MAX_WRITERS` write it)."""
    absolute = os.path.abspath(path)
    writers, complete = _writers(absolute)
    if not complete or len(writers) > MAX_WRITERS:
        return None
    return tuple(w for w in writers if w != absolute)
