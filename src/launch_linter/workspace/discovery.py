"""Which files a folder holds to lint: launch files by name and content, each once.

A folder is walked for every launch file ROS 1 and ROS 2 name that way (``*.launch``,
``*.launch.xml``, ``*_launch.xml``, ``*.launch.py``, ``*_launch.py``, ``*.launch.yaml``,
``*.launch.yml``, ``*_launch.yaml``, ``*_launch.yml``), for ``*.xml`` and rostest ``*.test``
files whose root element is ``<launch>``, and for robot descriptions (``*.urdf``,
``*.xacro``), which are checked as ``check_urdf`` reads them. It skips version-control
folders and the other default exclusions (replaced by ``exclude``, extended by
``extend_exclude``, ruff's convention), the ``build/``, ``install/``, ``log/`` and
``devel/`` folders of catkin and colcon workspaces (only where they are workspace folders:
beside a ``src/`` folder, or marked with ``COLCON_IGNORE``/``CATKIN_IGNORE``/
``AMENT_IGNORE``), and whatever the injected ``ignored`` predicate rejects (the command
line passes the ``.gitignore`` rules there;
this module stays standard-library only). A file named explicitly is always linted. Each
file is taken once, by its real path, under the first name it was found by.
"""

from __future__ import annotations

import os
import re
from collections.abc import Iterator, Sequence

from launch_linter.model.globs import Glob, fnmatch_glob
from launch_linter.model.paths import shown_path
from launch_linter.model.record import Record, _set
from launch_linter.resolve import reads
from launch_linter.resolve.xml_safe import NotRegularFile, read_regular_file

LAUNCH_SUFFIXES = (
    ".launch",
    ".launch.xml",
    "_launch.xml",
    ".launch.yaml",
    ".launch.yml",
    "_launch.yaml",
    "_launch.yml",
    ".launch.py",
    "_launch.py",
)
VCS_FOLDERS = (".git", ".hg", ".svn", ".bzr", "_darcs", "CVS", ".jj", ".pijul")
DEFAULT_EXCLUDE: tuple[str, ...] = (
    *VCS_FOLDERS,
    ".*",  # hidden folders (editor and tool caches); the walk always skipped them
    "__pycache__",
    "node_modules",
    "venv",
)
WORKSPACE_FOLDERS = ("build", "install", "log", "devel", "devel_isolated", "build_isolated",
                     "install_isolated")
WORKSPACE_MARKERS = ("COLCON_IGNORE", "CATKIN_IGNORE", "AMENT_IGNORE")
MAX_DISCOVERED_FILES = 200_000

TYPE_CHECKING = False  # typing is not imported at run time: start-up (docs/performance.md)
if TYPE_CHECKING:
    from typing import Callable

    Ignored = Callable[[str, bool], bool]
    """``ignored(absolute_path, is_folder)``: True to leave the path out."""

# The patterns that sniff a file's content are text, compiled on first use (``re`` keeps
# them): a run whose folder walk the results cache answers reads no file's content.
# The first element of an XML document: after the declaration, comments, doctype and
# processing instructions.
_SPACE = rb"\s*"
_PROLOGUE_PARTS = ((b"<?", b"?>"), (b"<!--", b"-->"), (b"<!DOCTYPE", b">"))
MAX_SNIFF_BYTES = 1024 * 1024
"""How far into a ``.xml`` file discovery looks for its root element (licence headers and
long comments come first in some files)."""
_LAUNCH_ROOT = rb"<launch[\s>/]"
_PY_LAUNCH = rb"(?m)^def generate_launch_description\s*\("
_YAML_LAUNCH = rb"(?:\xef\xbb\xbf)?(?:\s*#[^\n]*\n|\s*\n|---[^\n]*\n)*launch\s*:"
CONTENT_SUFFIXES = (".xml", ".test", ".py", ".yaml", ".yml")
"""Suffixes whose content decides: ``.test`` is a rostest file, a launch file with
``<test>`` elements when its root is ``<launch>``."""
MAX_CONTENT_BYTES = 256 * 1024


class InputFile(Record):
    path: str
    """Absolute path."""
    display: str
    """As the user gave it (relative stays relative)."""

    __slots__ = ("path", "display")

    def __init__(self, path: str, display: str) -> None:
        _set(self, "path", path)
        _set(self, "display", display)


def is_launch_name(name: str) -> bool:
    """Whether a file name alone makes it a launch file."""
    return name.endswith(LAUNCH_SUFFIXES)


def _root_offset(head: bytes) -> int | None:
    """Where the first element starts, after the XML declaration, comments, doctype and
    processing instructions; None when that prologue runs past ``head``. Each step moves
    forward with ``find``, so a hostile prologue (thousands of unclosed comments) costs
    linear time, where a lazy regular expression would rescan the rest for each one."""
    position = 0
    while True:
        position = re.compile(_SPACE).match(head, position).end()  # type: ignore[union-attr]
        for opener, closer in _PROLOGUE_PARTS:
            if head.startswith(opener, position):
                end = head.find(closer, position + len(opener))
                if end < 0:
                    return None
                position = end + len(closer)
                break
        else:
            return position if position < len(head) else None


def has_launch_root(path: str) -> bool:
    """Whether the XML file at ``path`` has ``<launch>`` as its root element. Up to
    :data:`MAX_SNIFF_BYTES` are read, so a long licence header does not hide the root;
    only regular files are opened (a FIFO would block discovery)."""
    try:
        head = read_regular_file(path, MAX_SNIFF_BYTES)
    except (OSError, NotRegularFile):
        return False
    if head.startswith(b"\xef\xbb\xbf"):
        head = head[3:]
    start = _root_offset(head)
    return start is not None and re.compile(_LAUNCH_ROOT).match(head, start) is not None


def has_launch_content(path: str, name: str) -> bool:
    """Whether a file that is not named like a launch file is one by its content: XML
    with a ``<launch>`` root, a Python file defining ``generate_launch_description`` (what
    ``ros2 launch`` calls), or YAML whose top-level key is ``launch:``."""
    if name.endswith((".xml", ".test")):
        return has_launch_root(path)
    try:
        data = read_regular_file(path, MAX_CONTENT_BYTES)
    except (OSError, NotRegularFile):
        return False
    if name.endswith(".py"):
        return re.search(_PY_LAUNCH, data) is not None
    return re.match(_YAML_LAUNCH, data) is not None


def is_workspace_folder(directory: str, name: str) -> bool:
    """A colcon/catkin output folder: named like one and beside ``src/`` or marked."""
    if name not in WORKSPACE_FOLDERS:
        return False
    full = os.path.join(directory, name)
    if reads.is_dir(os.path.join(directory, "src")):
        return True
    return any(reads.exists(os.path.join(full, marker)) for marker in WORKSPACE_MARKERS)


class Exclusions(Record):
    """Glob patterns (ruff's ``exclude``/``extend-exclude``) matched against a path's
    base name, its path relative to ``base`` and its absolute path."""

    patterns: tuple[str, ...]
    base: str

    __slots__ = ("patterns", "base")

    def __init__(self, patterns: tuple[str, ...] = DEFAULT_EXCLUDE, base: str = ".") -> None:
        _set(self, "patterns", patterns)
        _set(self, "base", base)

    @classmethod
    def of(
        cls,
        exclude: Sequence[str] | None = None,
        extend_exclude: Sequence[str] = (),
        base: str = ".",
    ) -> Exclusions:
        chosen = tuple(exclude) if exclude is not None else DEFAULT_EXCLUDE
        return cls(chosen + tuple(extend_exclude), os.path.abspath(base))

    def excludes(self, absolute: str) -> bool:
        names, anchored = _compiled(self.patterns)
        name = os.path.basename(absolute)
        if any(glob.match(name) for glob in names):
            return True
        if not anchored:
            return False
        relative = os.path.relpath(absolute, self.base).replace(os.sep, "/")
        absolute = absolute.replace(os.sep, "/")
        return any(glob.match(relative) or glob.match(absolute) for glob in anchored)


_COMPILED: dict[tuple[str, ...], tuple[tuple[Glob, ...], tuple[Glob, ...]]] = {}


def _compiled(patterns: tuple[str, ...]) -> tuple[tuple[Glob, ...], tuple[Glob, ...]]:
    """The globs for base names, and those with a ``/`` (matched against the relative and
    the absolute path), made once: discovery asks for every path of a walk. A
    configuration's globs are matched in linear time (``model.globs``), never by
    ``fnmatch``'s backtracking regular expressions (``*a*a*a*a*a*b``: minutes on Python
    3.8)."""
    found = _COMPILED.get(patterns)
    if found is None:
        cleaned = [pattern.rstrip("/") for pattern in patterns]
        # A name has no "/": a glob with one cannot match it.
        names = tuple(fnmatch_glob(p) for p in cleaned if "/" not in p)
        anchored = tuple(fnmatch_glob(p[2:] if p.startswith("./") else p)
                         for p in cleaned if "/" in p)
        found = _COMPILED[patterns] = (names, anchored)
    return found


def walk(top: str, followlinks: bool = False) -> Iterator[tuple[str, list[str], list[str]]]:
    """``os.walk`` (top-down, the caller may prune ``subdirs`` in place), without recursion:
    before Python 3.12 ``os.walk`` recursed once per level, and 1,500 nested folders in a
    repository raised RecursionError and lost the whole run."""
    stack = [top]
    while stack:
        directory = stack.pop()
        subdirs: list[str] = []
        files: list[str] = []
        links: set[str] = set()
        try:
            with os.scandir(directory) as entries:
                for entry in entries:
                    try:
                        is_folder = entry.is_dir()
                    except OSError:
                        is_folder = False
                    if is_folder:
                        subdirs.append(entry.name)
                        if not followlinks and entry.is_symlink():
                            links.add(entry.name)
                    else:
                        files.append(entry.name)
        except OSError:
            continue
        yield directory, subdirs, files
        stack.extend(os.path.join(directory, name) for name in reversed(subdirs)
                     if name not in links)


DESCRIPTION_SUFFIXES = (".urdf", ".xacro")
"""Robot descriptions, linted on their own (``.urdf.xacro`` ends with ``.xacro``)."""
NOT_DESCRIPTION_SUFFIXES = (".srdf.xacro",)
"""MoveIt's semantic descriptions: their root is ``<robot>`` too, but they hold no links."""


def is_description_name(name: str) -> bool:
    lower = name.lower()
    return lower.endswith(DESCRIPTION_SUFFIXES) and not lower.endswith(NOT_DESCRIPTION_SUFFIXES)


def discover(
    paths: Sequence[str],
    exclusions: Exclusions | None = None,
    ignored: Ignored | None = None,
) -> list[InputFile]:
    """Input files: each file named, and launch files found under each folder named."""
    rules = exclusions if exclusions is not None else Exclusions()
    found: list[InputFile] = []
    seen: set[str] = set()

    def add(path: str) -> None:
        real = os.path.realpath(path)
        if real not in seen and len(found) < MAX_DISCOVERED_FILES:
            seen.add(real)
            found.append(InputFile(os.path.abspath(path), shown_path(path)))

    def skip(absolute: str, is_folder: bool) -> bool:
        return rules.excludes(absolute) or (ignored is not None and ignored(absolute, is_folder))

    for given in paths:
        if not reads.is_dir(given):
            add(given)
            continue
        visited: set[tuple[int, int]] = set()
        for directory, subdirs, files in walk(given):
            # The folder's identity, not its real path (which costs a look-up per level:
            # quadratic in a deep tree).
            try:
                info = os.stat(directory)
            except OSError:
                continue
            if (info.st_dev, info.st_ino) in visited:
                subdirs[:] = []
                continue
            visited.add((info.st_dev, info.st_ino))
            # A file or folder added or removed here changes what is found.
            reads.note_folder(directory, info, subdirs, files, reads.EVERY_FILE)
            # Entries are plain names: joined to the absolute folder, made once, they are
            # the absolute paths os.path.abspath would make of each (a getcwd apiece).
            absolute_dir = os.path.abspath(directory)
            subdirs[:] = sorted(
                d
                for d in subdirs
                if not is_workspace_folder(directory, d)
                and not skip(os.path.join(absolute_dir, d), True)
            )
            for name in sorted(files):
                full = os.path.join(directory, name)
                described = is_description_name(name)
                if not (is_launch_name(name) or name.endswith(CONTENT_SUFFIXES) or described):
                    continue
                if skip(os.path.join(absolute_dir, name), False):
                    continue
                if is_launch_name(name) or described or has_launch_content(full, name):
                    add(full)
    return found
