"""The round loop of the long fuzzing runs (``fuzz_fix.py``, ``fuzz_xacro.py``)."""

from __future__ import annotations

import argparse
import time
import traceback
from typing import Any, Callable

from hypothesis import HealthCheck, given, settings
from hypothesis.strategies import SearchStrategy


def arguments(description: str) -> argparse.Namespace:
    """``--cases`` to run in all, in rounds of ``--round`` hypothesis examples."""
    parser = argparse.ArgumentParser(description=description)
    parser.add_argument("--cases", type=int, default=100_000)
    parser.add_argument("--round", type=int, default=2_000)
    return parser.parse_args()


def run_rounds(strategy: SearchStrategy[Any], check: Callable[[Any], None],
               cases: int, round_size: int) -> int:
    """Runs ``check`` on ``cases`` examples of ``strategy``; prints the number of cases,
    failures and the time taken, and returns the exit status (1 when any case failed)."""
    started = time.monotonic()
    done = failures = 0

    def counted(case: Any) -> None:
        nonlocal done
        done += 1
        check(case)

    while done < cases:
        run = settings(max_examples=min(round_size, cases - done), deadline=None,
                       database=None, suppress_health_check=list(HealthCheck))(
            given(case=strategy)(counted))
        try:
            run()
        except Exception:  # a failing case, shrunk by hypothesis: report it, go on
            failures += 1
            traceback.print_exc()
    print(f"{done} cases, {failures} failures, {time.monotonic() - started:.0f} s")
    return 1 if failures else 0
