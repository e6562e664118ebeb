"""Long runs of the fix property (the suite runs 150 cases of the same).

    PYTHONPATH=src python scripts/fuzz_fix.py --cases 100000

Runs rounds of ``--round`` hypothesis examples until ``--cases`` have run; prints the
number of cases, failures and the time taken. A failing case is shrunk by hypothesis and
printed.
"""

from __future__ import annotations

import argparse
import sys
import time
import traceback
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests" / "hostile"))

from fix_property import check_fix_property, launch_files
from hypothesis import HealthCheck, given, settings


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cases", type=int, default=100_000)
    parser.add_argument("--round", type=int, default=2_000)
    ns = parser.parse_args()
    started = time.monotonic()
    cases = failures = 0

    def counted(case: tuple[str, bytes, bytes]) -> None:
        nonlocal cases
        cases += 1
        check_fix_property(*case)

    while cases < ns.cases:
        run = settings(max_examples=min(ns.round, ns.cases - cases), deadline=None,
                       database=None, suppress_health_check=list(HealthCheck))(
            given(case=launch_files())(counted))
        try:
            run()
        except Exception:  # a failing case, shrunk by hypothesis: report it, go on
            failures += 1
            traceback.print_exc()
    print(f"{cases} cases, {failures} failures, {time.monotonic() - started:.0f} s")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
