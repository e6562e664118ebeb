"""Where and how ``--fix`` writes: only regular files under the paths given on the command
line, never through a symbolic link that leaves them, never the report's output file, and
atomically (a temporary file beside the file, renamed over it, its mode kept), refused when
the file changed since it was read.

A launch file may include files anywhere (``../outside/inc.launch``, an absolute path) and
a folder may hold symbolic links out of it: findings in those files are reported, but the
user asked to fix only what they named.
"""

from __future__ import annotations

import contextlib
import os
import stat
from collections.abc import Iterable

from launch_linter.report.escape import printable

_READ_LIMIT = 64 * 1024 * 1024


class WriteGuard:
    """The files ``--fix`` may write: regular files whose real path lies under one of
    ``roots`` (the command line's paths, files or folders), except ``excluded``."""

    def __init__(self, roots: Iterable[str], excluded: Iterable[str] = ()) -> None:
        self.roots = tuple(os.path.realpath(root) for root in roots)
        self.excluded = frozenset(os.path.realpath(path) for path in excluded)

    def _under_roots(self, real: str) -> bool:
        return any(real == root or real.startswith(root.rstrip(os.sep) + os.sep)
                   for root in self.roots)

    def refusal(self, path: str) -> str | None:
        """Why ``path`` may not be written, None when it may."""
        real = os.path.realpath(path)
        if real in self.excluded:
            return "it is the report's output file"
        if not self._under_roots(real):
            if self._under_roots(os.path.abspath(path)):
                return "a symbolic link leads it out of the paths given on the command line"
            return "it is not under the paths given on the command line"
        try:
            mode = os.lstat(real).st_mode
        except OSError as exc:
            return f"it cannot be read ({exc.strerror or exc})"
        if not stat.S_ISREG(mode):
            return "it is not a regular file"
        return None

    def write(self, path: str, before: bytes, after: bytes) -> str | None:
        """Replace ``path``'s bytes ``before`` by ``after``; why not, None when written."""
        refused = self.refusal(path)
        if refused is None:
            refused = write_atomically(os.path.realpath(path), before, after)
        return None if refused is None else f"fixes not written: {refused}"


def write_atomically(real: str, before: bytes, after: bytes) -> str | None:
    """Write ``after`` to the regular file ``real`` (a real path) through a temporary file
    renamed over it, keeping its mode; refused (the reason returned) when the file no
    longer holds ``before``."""
    try:
        descriptor = os.open(real, os.O_RDONLY | os.O_NONBLOCK | getattr(os, "O_NOFOLLOW", 0))
    except OSError as exc:
        return f"it cannot be opened ({exc.strerror or exc})"
    try:
        status = os.fstat(descriptor)
        if not stat.S_ISREG(status.st_mode):
            return "it is not a regular file"
        if status.st_size != len(before) or _read_all(descriptor) != before:
            return "it changed since it was read"
    finally:
        os.close(descriptor)
    folder, name = os.path.split(real)
    import tempfile  # only when a file is written: with ``random`` it is start-up time

    try:
        handle, temporary = tempfile.mkstemp(prefix=f".{name}.", suffix=".fix", dir=folder)
    except OSError as exc:
        return f"no temporary file could be made beside it ({exc.strerror or exc})"
    try:
        with os.fdopen(handle, "wb") as out:
            out.write(after)
            out.flush()
            os.fchmod(out.fileno(), stat.S_IMODE(status.st_mode))
            os.fsync(out.fileno())
        os.replace(temporary, real)
    except OSError as exc:
        with contextlib.suppress(OSError):
            os.unlink(temporary)
        return f"it could not be written ({exc.strerror or exc})"
    return None


def _read_all(descriptor: int) -> bytes:
    pieces: list[bytes] = []
    total = 0
    while total <= _READ_LIMIT:
        piece = os.read(descriptor, 1 << 20)
        if not piece:
            break
        pieces.append(piece)
        total += len(piece)
    return b"".join(pieces)


def refused_message(path: str, reason: str) -> str:
    """The line ``--fix`` prints for a fix skipped or a file not written."""
    return f"launch-linter: {printable(path)}: {printable(reason)}"
