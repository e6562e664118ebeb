"""Long runs of the xacro reader's mutation fuzzing (the suite runs 60 cases).

    PYTHONPATH=src python scripts/fuzz_xacro.py --cases 100000

Prints the number of cases, failures and the time taken; a failing case is shrunk by
hypothesis and printed.
"""

from __future__ import annotations

import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests" / "hostile"))

from fuzz_rounds import arguments, run_rounds
from xacro_fuzzing import check_xacro_case, mutated, seeds


def main() -> int:
    ns = arguments(__doc__.splitlines()[0])
    with tempfile.TemporaryDirectory() as scratch:
        folder = Path(scratch)
        return run_rounds(mutated(seeds()), lambda data: check_xacro_case(folder, data),
                          ns.cases, ns.round)


if __name__ == "__main__":
    sys.exit(main())
