"""Long runs of the xacro reader's mutation fuzzing (the suite runs 60 cases).

    PYTHONPATH=src python scripts/fuzz_xacro.py --cases 100000

Prints the number of cases, failures and the time taken; a failing case is shrunk by
hypothesis and printed.
"""

from __future__ import annotations

import argparse
import sys
import tempfile
import time
import traceback
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests" / "hostile"))

from hypothesis import HealthCheck, given, settings
from xacro_fuzzing import check_xacro_case, mutated, seeds


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cases", type=int, default=100_000)
    parser.add_argument("--round", type=int, default=2_000)
    ns = parser.parse_args()
    pool = seeds()
    started = time.monotonic()
    cases = failures = 0
    with tempfile.TemporaryDirectory() as scratch:
        folder = Path(scratch)

        def counted(data: bytes) -> None:
            nonlocal cases
            cases += 1
            check_xacro_case(folder, data)

        while cases < ns.cases:
            run = settings(max_examples=min(ns.round, ns.cases - cases), deadline=None,
                           database=None, suppress_health_check=list(HealthCheck))(
                given(data=mutated(pool))(counted))
            try:
                run()
            except Exception:  # a failing case, shrunk by hypothesis: report it, go on
                failures += 1
                traceback.print_exc()
    print(f"{cases} cases, {failures} failures, {time.monotonic() - started:.0f} s")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
