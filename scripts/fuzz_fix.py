"""Long runs of the fix property (the suite runs 150 cases of the same).

    PYTHONPATH=src python scripts/fuzz_fix.py --cases 100000

Runs rounds of ``--round`` hypothesis examples until ``--cases`` have run; prints the
number of cases, failures and the time taken. A failing case is shrunk by hypothesis and
printed.
"""

from __future__ import annotations

import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests" / "hostile"))

from fix_property import check_fix_property, launch_files
from fuzz_rounds import arguments, run_rounds


def main() -> int:
    ns = arguments(__doc__.splitlines()[0])
    return run_rounds(launch_files(), lambda case: check_fix_property(*case),
                      ns.cases, ns.round)


if __name__ == "__main__":
    sys.exit(main())
