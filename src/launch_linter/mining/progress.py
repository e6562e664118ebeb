"""A progress bar on stderr, drawn only when stderr is a terminal."""

from __future__ import annotations

import sys
import time
from typing import TextIO

WIDTH = 30
INTERVAL_S = 0.1


class Progress:
    """``label [#####     ] done/total``, redrawn at most every ``INTERVAL_S`` seconds."""

    def __init__(self, label: str, total: int, stream: TextIO | None = None) -> None:
        self.stream = stream if stream is not None else sys.stderr
        self.enabled = self.stream.isatty()
        self.label = label
        self.total = total
        self.done = 0
        self._drawn_at = 0.0

    def advance(self, count: int = 1) -> None:
        self.done += count
        now = time.monotonic()
        if self.enabled and (now - self._drawn_at >= INTERVAL_S or self.done >= self.total):
            self._drawn_at = now
            self._draw()

    def _draw(self) -> None:
        filled = WIDTH if self.total <= 0 else min(WIDTH, WIDTH * self.done // self.total)
        bar = "#" * filled + " " * (WIDTH - filled)
        self.stream.write(f"\r{self.label} [{bar}] {self.done}/{self.total}")
        self.stream.flush()

    def finish(self) -> None:
        if self.enabled and self.total:
            self._draw()
            self.stream.write("\n")
            self.stream.flush()
