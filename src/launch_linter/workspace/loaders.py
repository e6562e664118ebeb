"""Which file of the workspace may load a robot description: one that writes its name.

Nothing finds a URDF or xacro file by itself: a launch file (``<param command="xacro
$(find p)/urdf/r.urdf.xacro">``, ``Command(['xacro ', path])``, ``open(path).read()``), a
xacro include, a Gazebo ``model.config``, a node or a script names it, by a path whose
last part is the file's name, or by a name built from a written tail
(``$(arg model).urdf.xacro``, ``f'{robot}.urdf'``, ``robot + '_description.urdf'``, a glob
``*.xacro``): such a tail may complete to any name that ends with it. A description whose
name, and every tail it ends with, no file of the workspace writes is loaded by nothing
there.

Files under a ``test``/``tests`` folder do not count: ``colcon test``/``catkin
run_tests`` run them, the robot never does (realsense2_description's
``tests/test_xacro.py`` runs xacro on each ``*.xacro`` of its folder for its exit status).

The workspace read is the one :mod:`.mentions` reads (its ``src``, else the repository,
else the package), every file but meshes, images, archives and recordings; bounded in
files and bytes: a scan cut by a bound names every description (unknown, never "not
named"). Each folder is read once per run (:data:`mentions.FRESH_SECONDS`).
"""

from __future__ import annotations

import contextlib
import os
import re
import time

from launch_linter.resolve import reads
from launch_linter.resolve.xml_safe import NotRegularFile, read_regular_file
from launch_linter.workspace.discovery import VCS_FOLDERS, WORKSPACE_FOLDERS, walk
from launch_linter.workspace.mentions import FRESH_SECONDS, MAX_CACHED_FOLDERS, scope

MAX_FILES = 50_000
MAX_TOTAL_BYTES = 256 * 1024 * 1024
"""Bytes read per workspace, all files together; a file is read whole or the scan is cut."""
MAX_FOLDERS = 20_000
MAX_NAME = 255
TEST_FOLDERS = frozenset(("test", "tests"))
SKIPPED_SUFFIXES = (
    ".stl", ".dae", ".obj", ".ply", ".pcd", ".3ds", ".fbx", ".glb", ".gltf", ".mtl",
    ".png", ".jpg", ".jpeg", ".gif", ".bmp", ".pgm", ".ppm", ".tif", ".tiff", ".ico",
    ".svg", ".bag", ".db3", ".mcap", ".zip", ".gz", ".tgz", ".bz2", ".xz", ".tar",
    ".pdf", ".mp4", ".avi", ".mov", ".so", ".a", ".o", ".pyc", ".bin", ".npy", ".pt",
    ".onnx", ".pth", ".h5", ".csv", ".vtk", ".xcf", ".qch", ".wav", ".mp3", ".ttf",
)
"""Files that name no description (meshes, images, archives, data): never read."""
MANIFESTS = frozenset(("package.xml", "manifest.xml"))
"""A package's manifest loads nothing: not read (an edit to one relints no description)."""
DESCRIPTIONS = re.compile(rb"\.(?:urdf|xacro)(?:\.xacro)?(?![A-Za-z0-9_])")
"""Where a description's name written in a path or string ends; the name is then read
backwards from there (bounded), never with a pattern that starts at every letter."""
_NAME_BYTES = frozenset(b"abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_.-")
_BUILT_BEFORE = frozenset(b")}*%")
"""A byte before a written name that makes it the tail of a built one: ``$(arg x)``,
``${x}``/``{x}``, a glob's ``*``, a ``%s`` format."""
_PATH_SEPARATORS = frozenset(b"/\\")
"""Before a name that starts with a separator (``urdf/_d435.urdf.xacro``): a whole name;
elsewhere (``robot + '_arm.urdf'``) the tail of a joined one."""


class _Written:
    """The description names and tails written in one workspace, each with up to two
    files writing it; ``complete`` False when a bound cut the scan. A tail is kept with
    the folder written before the substitution it follows (``urdf`` in
    ``$(find p)/urdf/$(arg model).urdf.xacro``; empty when none is written): a built
    name reaches only a file in that folder."""

    def __init__(self) -> None:
        self.names: dict[bytes, tuple[str, ...]] = {}
        self.tails: dict[bytes, dict[bytes, tuple[str, ...]]] = {}
        self.complete = True

    def add(self, data: bytes, path: str, suffix: re.Pattern[bytes] = DESCRIPTIONS) -> None:
        # Each backward read stops at the previous name's end: linear in the file.
        previous_end = 0
        for match in suffix.finditer(data):
            start = _run_start(data, match.start(), previous_end)
            previous_end = match.end()
            written = data[start:match.end()]
            before = data[start - 1] if start > 0 else None
            if before == ord("%"):
                written = written[1:]  # '%s.urdf': the format's letter is not the name's
            if before in _BUILT_BEFORE:
                folder = _folder_before(data, start - 1, match.start() - MAX_NAME)
            elif written[:1] in (b".", b"_", b"-") and before not in _PATH_SEPARATORS:
                folder = b""
            else:
                _note(self.names, written, path)
                continue
            _note(self.tails.setdefault(written, {}), folder, path)

    def writer_of(self, path: str) -> str | None:
        name = os.path.basename(path).encode("utf-8", "surrogateescape")
        parent = os.path.basename(os.path.dirname(path)).encode("utf-8", "surrogateescape")
        candidates = [self.names.get(name, ())]
        for start in range(len(name)):
            folders = self.tails.get(name[start:], {})
            candidates += [folders.get(b"", ()), folders.get(parent, ())]
        for writers in candidates:
            others = [w for w in writers if w != path]
            if others:
                return others[0]
        return None


def _note(found: dict[bytes, tuple[str, ...]], key: bytes, path: str) -> None:
    writers = found.get(key, ())
    if len(writers) < 2 and path not in writers:
        found[key] = (*writers, path)


def _run_start(data: bytes, end: int, lowest: int) -> int:
    """Where the name bytes that end at ``end`` start (not before ``lowest``, nor more
    than :data:`MAX_NAME` bytes back)."""
    start = end
    lowest = max(lowest, end - MAX_NAME)
    while start > lowest and data[start - 1] in _NAME_BYTES:
        start -= 1
    return start


def _folder_before(data: bytes, marker: int, lowest: int) -> bytes:
    """The folder written before the substitution (or glob) that ends at ``marker``:
    ``urdf`` in ``urdf/$(arg model)`` and ``urdf/real_$(arg m)``; empty when none is."""
    opener = marker
    if data[marker] in b")}":
        opener = data.rfind(b"{" if data[marker] == ord("}") else b"(", max(lowest, 0), marker)
        if opener < 0:
            return b""
        if opener > 0 and data[opener - 1] == ord("$"):
            opener -= 1
    stem = _run_start(data, opener, lowest)
    if stem == 0 or data[stem - 1] not in _PATH_SEPARATORS:
        return b""
    return data[_run_start(data, stem - 1, lowest):stem - 1]


_written_by_folder: dict[tuple[str, bytes], tuple[float, _Written, reads.ReadLog]] = {}


def loader_of(path: str, suffix: re.Pattern[bytes] = DESCRIPTIONS) -> str | None:
    """A file of the workspace around ``path`` (outside test folders, other than
    ``path``) that writes its name or a tail it ends with: it may load it; the workspace
    folder when a bound cut the scan (unknown); None when nothing names it. ``suffix``:
    where names of that kind of file end (:data:`DESCRIPTIONS`)."""
    absolute = os.path.abspath(path)
    folder = scope(absolute)
    now = time.monotonic()
    read = _written_by_folder.get((folder, suffix.pattern))
    if read is None or now - read[0] > FRESH_SECONDS:
        if len(_written_by_folder) >= MAX_CACHED_FOLDERS:
            _written_by_folder.clear()
        with reads.recording() as log:
            written = _written_in(folder, suffix)
        read = _written_by_folder[folder, suffix.pattern] = (now, written, log)
    reads.depend_on(read[2])
    if not read[1].complete:
        return folder
    return read[1].writer_of(absolute)


def _written_in(folder: str, suffix: re.Pattern[bytes]) -> _Written:
    written = _Written()
    files = folders = total = 0
    for directory, subdirs, entries in walk(folder):
        folders += 1
        if folders > MAX_FOLDERS:
            written.complete = False
            return written
        with contextlib.suppress(OSError):  # a folder gone since it was listed
            reads.note_folder(directory, os.stat(directory), subdirs, entries, reads.EVERY_FILE)
        subdirs[:] = sorted(
            d for d in subdirs
            if not d.startswith(".") and d not in VCS_FOLDERS and d not in WORKSPACE_FOLDERS
            and d != "__pycache__" and d.lower() not in TEST_FOLDERS
        )
        for entry in sorted(entries):
            if entry.lower().endswith(SKIPPED_SUFFIXES) or entry in MANIFESTS:
                continue
            files += 1
            if files > MAX_FILES:
                written.complete = False
                return written
            path = os.path.join(directory, entry)
            try:
                data = read_regular_file(path, MAX_TOTAL_BYTES - total + 1)
            except (OSError, NotRegularFile):
                continue
            total += len(data)
            if total > MAX_TOTAL_BYTES:
                written.complete = False
                return written
            written.add(data, path, suffix)
    return written
