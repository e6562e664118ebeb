"""What linting a file read from disk, so that its result can be reused while that holds.

The results cache (``launch_linter.results_cache``) keeps a root file's findings with the
*stamp* of every path its lint depended on, and reuses them only while every stamp still
holds. The stamps are recorded here, in one place that every read goes through:

- ``resolve.xml_safe.read_regular_file`` notes each file it reads (:func:`note_read`) or
  fails to read (:func:`note_path`): launch files, includes, xacro, URDF, parameter
  files, package manifests, install rules. A new kind of input read with it is recorded
  without more work.
- :func:`is_file`, :func:`exists` and :func:`is_dir` are ``os.path``'s, noting the kind
  of the path they looked at: a missing include that appears later changes the result.
- :func:`note_folder` notes a folder whose *listing* decided something (the package crawl).
- A cache shared by the files of one run (the package index, the robot descriptions,
  each ``package.xml``'s ROS version) works a value out once; the files after the first
  depend on what that work read too. :func:`remembered` (or :func:`recording` and
  :func:`depend_on` for a lazy value) records the work in a log of its own and adds that
  log to every file that uses the value.

Nothing is recorded unless a :func:`recording` is active, so a run without the cache pays
one list test per read. Recording is per process and per thread of linting (one lint at a
time in a process, as the engine and its worker processes do).
"""

from __future__ import annotations

import os
import stat
import time
from collections.abc import Callable, Iterable, Iterator
from contextlib import contextmanager

FILE = "f"
FOLDER = "d"
OTHER = "o"
ABSENT = "-"

TYPE_CHECKING = False  # typing is not imported at run time: start-up (docs/performance.md)
if TYPE_CHECKING:
    from typing import Hashable, Optional, Tuple, TypeVar

    _T = TypeVar("_T")
    _K = TypeVar("_K", bound=Hashable)
    Stamp = Tuple[str, int, int, Optional[str]]
    """``(kind, size, mtime_ns, digest)`` of a path. ``size`` is -1 when only the kind was
    looked at (a probe, or a folder); ``mtime_ns`` is -1 when it was not looked at and 0 when
    it cannot vouch for the content (the file changed less than ``SETTLE_NS`` before it was
    read: a later write within the same clock tick would leave it unchanged), so the content
    is compared; ``digest`` is the BLAKE2b of the content read (of a folder: of its listing),
    None when not all of it was (or only the kind was looked at)."""

SETTLE_NS = 2_000_000_000
"""A modification time this close to the read is not trusted to reveal a later change
(file systems stamp times in ticks of up to 2 s on FAT, a few ms on ext4)."""


class ReadLog:
    """The stamps one piece of work depended on, and the logs of shared work it used."""

    __slots__ = ("groups", "stamps", "unstable")

    def __init__(self) -> None:
        self.stamps: dict[str, Stamp] = {}
        self.groups: list[ReadLog] = []
        self.unstable = False
        """A path was seen in two states during the work: its result must not be kept."""

    def add(self, path: str, stamp: Stamp) -> None:
        old = self.stamps.get(path)
        if old is None or old == stamp:
            self.stamps[path] = stamp  # the first, or the same again: one store either way
        elif old[0] == stamp[0] and _looked_at_less(old, stamp):
            self.stamps[path] = stamp
        elif not (old[0] == stamp[0] and _looked_at_less(stamp, old)):
            self.unstable = True

    def closure(self) -> list[ReadLog]:
        """This log's groups and theirs, each once, in a fixed order."""
        seen: dict[int, ReadLog] = {}
        pending = list(reversed(self.groups))
        while pending:
            log = pending.pop()
            if id(log) not in seen:
                seen[id(log)] = log
                pending.extend(reversed(log.groups))
        return list(seen.values())

    def is_unstable(self) -> bool:
        return self.unstable or any(log.unstable for log in self.closure())


def _looked_at_less(weaker: Stamp, stronger: Stamp) -> bool:
    """Whether ``weaker`` is ``stronger`` with less looked at (a probe of a file read)."""
    return (weaker[1] == -1 or weaker[1] == stronger[1]) \
        and (weaker[2] == -1 or weaker[2] == stronger[2]) and weaker[3] is None


_active: list[ReadLog] = []
"""The logs being recorded, innermost last; a read is noted in the innermost."""


@contextmanager
def recording() -> Iterator[ReadLog]:
    """Record what the work inside reads in a new log."""
    log = ReadLog()
    _active.append(log)
    try:
        yield log
    finally:
        _active.pop()


def depend_on(log: ReadLog) -> None:
    """The work being recorded used a value that the work recorded in ``log`` made."""
    if _active and log is not _active[-1]:
        groups = _active[-1].groups
        if not any(group is log for group in groups):
            groups.append(log)


def remembered(store: dict[_K, tuple[_T, ReadLog]], key: _K,
               compute: Callable[[], _T]) -> _T:
    """``compute()`` once per ``key`` in ``store`` (a run-level cache); every caller,
    the first and the later ones, depends on what computing it read."""
    found = store.get(key)
    if found is None:
        with recording() as log:
            value = compute()
        found = store[key] = (value, log)
    depend_on(found[1])
    return found[0]


def kind_of(mode: int) -> str:
    if stat.S_ISREG(mode):
        return FILE
    return FOLDER if stat.S_ISDIR(mode) else OTHER


def note_read(path: str, status: os.stat_result, data: bytes) -> None:
    """``data`` was read from the regular file ``path`` whose descriptor had ``status``."""
    if not _active:
        return
    complete = len(data) == status.st_size
    _active[-1].add(path, (FILE, status.st_size, _vouching_mtime(status.st_mtime_ns),
                           digest(data) if complete else None))


def _vouching_mtime(mtime_ns: int) -> int:
    return mtime_ns if time.time_ns() - mtime_ns >= SETTLE_NS else 0


def too_recent(status: os.stat_result) -> bool:
    """Whether a file's modification time is too recent to vouch for its content."""
    return _vouching_mtime(status.st_mtime_ns) == 0


def note_status(path: str, status: os.stat_result) -> None:
    """A value made from the file ``path`` was reused because its ``os.stat`` (``status``)
    is unchanged: it depends on the file as a read would, without a digest."""
    if _active:
        _active[-1].add(path, (kind_of(status.st_mode), status.st_size,
                               _vouching_mtime(status.st_mtime_ns), None))


def list_folder(path: str) -> list[str]:
    """``os.listdir``, noted as a listing of every entry (:func:`note_folder`)."""
    if not _active:
        return os.listdir(path)
    folders, files = _entries(path)
    note_folder(path, os.stat(path), folders, files, EVERY_FILE)
    return [*folders, *files]


def note_unsaved() -> None:
    """Text that is not on disk (an editor's unsaved buffer) stood in for a file."""
    if _active:
        _active[-1].unstable = True


def note_path(path: str) -> None:
    """The kind of ``path`` (or its absence) decided something."""
    if _active:
        _noted_kind(path)


PACKAGE_LISTING = "=" + ",".join(sorted((
    "package.xml", "manifest.xml", "CATKIN_IGNORE", "COLCON_IGNORE", "AMENT_IGNORE",
    "rospack_nosubdirs")))
"""A listing that counts the files whose presence a crawl of packages acts on; any other
file can come and go without changing the stamp."""
EVERY_FILE = "*"
"""A listing that counts every file (discovery)."""


def suffix_listing(suffixes: Iterable[str]) -> str:
    """A listing that counts the files whose names end (in lower case) with a suffix."""
    return "~" + ",".join(suffixes)


CACHE_FOLDER = ".launch-linter-cache"
UNLISTED = frozenset((CACHE_FOLDER,))
"""Left out of every listing: the results cache's own folder, which the first run creates
after it walked the folders (a hidden folder: discovery and the crawl never enter it)."""


def note_folder(path: str, status: os.stat_result, folders: Iterable[str],
                files: Iterable[str], listing: str = PACKAGE_LISTING) -> None:
    """The listing of the folder ``path`` (whose ``os.stat`` is ``status``; ``folders``
    and ``files`` its entries, as ``os.walk`` gives them) decided something: its
    subfolders and the files that ``listing`` counts (``PACKAGE_LISTING``, the files a
    package crawl acts on; ``EVERY_FILE``; ``suffix_listing(...)``). An entry added or
    removed changes the folder's modification time; only those counted change the
    listing's digest."""
    if _active:
        _active[-1].add(path, (FOLDER, -1, _vouching_mtime(status.st_mtime_ns),
                               listing_digest(folders, files, listing)))


def _counted(listing: str) -> Callable[[str], bool]:
    """Which file names ``listing`` counts. It is written in the cache, which is
    untrusted: anything but the three forms counts nothing (and the stamp then fails)."""
    kind, items = listing[:1], tuple(listing[1:].split(","))
    if kind == "*" and not listing[1:]:
        return lambda name: True
    if kind == "=":
        return frozenset(items).__contains__
    if kind == "~":
        return lambda name: name.lower().endswith(items)
    raise ValueError(f"unknown listing {listing[:40]!r}")


def listing_digest(folders: Iterable[str], files: Iterable[str], listing: str) -> str:
    """``listing``, ``|`` and the digest of the subfolders and counted files."""
    counted = _counted(listing)
    entries = sorted([*(f"d{name}" for name in folders if name not in UNLISTED),
                      *(f"f{name}" for name in files if counted(name))])
    found = digest("\0".join(entries).encode("utf-8", "surrogateescape"))
    return f"{listing}|{found}"


def _entries(path: str) -> tuple[list[str], list[str]]:
    """The names of the folder ``path``'s subfolders and of its other entries, as
    ``os.walk`` splits them."""
    folders: list[str] = []
    files: list[str] = []
    with os.scandir(path) as entries:
        for entry in entries:
            try:
                is_folder = entry.is_dir()
            except OSError:
                is_folder = False
            (folders if is_folder else files).append(entry.name)
    return folders, files


def _listing_now(path: str, listing: str) -> str:
    """:func:`listing_digest` of the folder ``path`` as ``os.walk`` would list it now."""
    return listing_digest(*_entries(path), listing)


def _kind_now(path: str) -> str:
    try:
        return kind_of(os.stat(path).st_mode)
    except (OSError, ValueError):
        return ABSENT


def _noted_kind(path: str) -> str:
    """The kind of ``path`` now, noted by the innermost recording."""
    kind = _kind_now(path)
    _active[-1].add(path, (kind, -1, -1, None))
    return kind


def is_file(path: str) -> bool:
    """``os.path.isfile``, noted."""
    return _noted_kind(path) == FILE if _active else os.path.isfile(path)


def is_dir(path: str) -> bool:
    """``os.path.isdir``, noted."""
    return _noted_kind(path) == FOLDER if _active else os.path.isdir(path)


def exists(path: str) -> bool:
    """``os.path.exists``, noted."""
    return _noted_kind(path) != ABSENT if _active else os.path.exists(path)


def digest(data: bytes) -> str:
    """The BLAKE2b digest of ``data``, as 32 hexadecimal digits."""
    try:
        # hashlib's own BLAKE2, without hashlib: importing that loads OpenSSL, 2-3 ms of
        # start-up for a digest the standard library computes itself.
        from _blake2 import blake2b
    except ImportError:  # another Python implementation
        from hashlib import blake2b

    return blake2b(data, digest_size=16).hexdigest()


class Freshness:
    """Whether stamps still hold, each path looked at once per run (many files share
    their package manifests and includes). ``read`` reads a file whole for its digest."""

    def __init__(self, read: Callable[[str, int], bytes]) -> None:
        self._read = read
        self._known: dict[tuple[str, Stamp], bool] = {}

    def holds(self, path: str, stamp: Stamp) -> bool:
        key = (path, stamp)
        known = self._known.get(key)
        if known is None:
            known = self._known[key] = self._holds(path, stamp)
        return known

    def _holds(self, path: str, stamp: Stamp) -> bool:
        kind, size, mtime_ns, content = stamp
        try:
            status = os.stat(path)
        except (OSError, ValueError):
            return kind == ABSENT
        if kind_of(status.st_mode) != kind:
            return False
        if size < 0:
            if content is None:
                return True  # a probe: the kind was all that was looked at
            # a folder's listing
            if mtime_ns > 0 and status.st_mtime_ns == mtime_ns:
                return True
            try:
                return _listing_now(path, content.rpartition("|")[0]) == content
            except (OSError, ValueError):
                return False
        if status.st_size != size:
            return False
        if mtime_ns > 0 and status.st_mtime_ns == mtime_ns:
            return True
        if content is None:
            return False
        try:
            return digest(self._read(path, size + 1)) == content
        except OSError:
            return False
