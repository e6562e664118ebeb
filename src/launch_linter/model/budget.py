"""One work budget per root file: steps taken, bytes produced and CPU time.

Depth limits alone do not bound work: arguments that reference each other double a value
at each level, one file can be included hundreds of times, a Python launch value can grow
on itself. Every front-end, evaluator and tf rule that can loop on input therefore charges
the budget of the root file it works for, and checks a size *before* it builds the text.
When the budget runs out, :class:`BudgetExceeded` is raised; the front-end that catches it
reports a diagnostic at the place where it ran out and keeps what it had read, and the run
goes on with the next file.

The limits are far above what real launch files need (the costliest of the corpus's 4,084
files takes 642 steps, produces 10.5 KB and took 0.16 s on a busy machine) and far below what
hurts a laptop (seconds of work and some hundred megabytes at most per file).
"""

from __future__ import annotations

import time
from collections.abc import Callable

MAX_STEPS = 2_000_000
"""Elements, substitutions, syntax nodes and evaluator work units, all files of a tree."""
MAX_BYTES = 64 * 1024 * 1024
"""Characters of text produced (resolved values, included files, evaluated strings)."""
MAX_SECONDS = 5.0
"""CPU time for one root file. CPU time, not wall time: work is what is bounded, and on a
busy machine (a CI runner, ``--jobs`` beside other programs) the wall clock would cut a
large but honest file short. Nothing in a run waits on anything else (only regular files
are read), so every hang on input is work and counts."""
_CLOCK_EVERY = 1024
"""Steps between two looks at the clock (a look costs more than a step)."""


class BudgetExceeded(Exception):
    """The work budget of a root file ran out; ``reason`` says which limit."""

    def __init__(self, reason: str) -> None:
        super().__init__(reason)
        self.reason = reason

    @property
    def message(self) -> str:
        """What a front-end reports where the budget ran out."""
        return f"work budget of this launch tree exhausted ({self.reason}); the rest is not read"


class Budget:
    """Counters for one root file; not shared between files or threads."""

    __slots__ = ("_clock", "_next_clock", "deadline", "max_bytes", "max_steps", "produced",
                 "seconds", "steps")

    def __init__(
        self,
        max_steps: int = MAX_STEPS,
        max_bytes: int = MAX_BYTES,
        seconds: float = MAX_SECONDS,
        clock: Callable[[], float] | None = None,
    ) -> None:
        self._clock = clock or time.process_time
        self.max_steps = max_steps
        self.max_bytes = max_bytes
        self.seconds = seconds
        self.deadline = self._clock() + seconds
        self.steps = 0
        self.produced = 0
        self._next_clock = _CLOCK_EVERY

    def step(self, count: int = 1) -> None:
        """Charge ``count`` steps; raise :class:`BudgetExceeded` past a limit."""
        self.steps += count
        if self.steps >= self._next_clock:
            self._next_clock = self.steps + _CLOCK_EVERY
            if self.steps > self.max_steps:
                raise BudgetExceeded(f"more than {self.max_steps:,} steps of work")
            if self._clock() > self.deadline:
                raise BudgetExceeded(f"more than {self.seconds:g} s of work")

    def produce(self, size: int) -> None:
        """Charge ``size`` characters about to be built; raise before building them."""
        if size > self.max_bytes - self.produced:
            raise BudgetExceeded(
                f"more than {self.max_bytes // (1024 * 1024)} MB of text would be produced")
        self.produced += size
        self.step(1 + size // 4096)

    def left(self) -> int:
        """Characters that may still be produced."""
        return max(0, self.max_bytes - self.produced)
