"""Deep mutation fuzzing of every front-end (the suite runs a few seconds of the same).

    PYTHONPATH=src python scripts/fuzz_frontends.py --minutes 60 [--corpus ../shared/corpus/files]

Seeds are the repository's own launch-file fixtures, plus up to ``--corpus-limit`` real
files from ``--corpus``. Cases run in rounds of ``--round`` hypothesis examples per
front-end until the time is up; a failing case is shrunk by hypothesis, written to
``--out`` and reported. Prints the number of cases run and the time taken.
"""

from __future__ import annotations

import argparse
import sys
import tempfile
import time
import traceback
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests" / "hostile"))

from fuzzing import check_case, corpus_seeds, mutated, seeds
from hypothesis import HealthCheck, given, settings


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--minutes", type=float, default=10.0)
    parser.add_argument("--round", type=int, default=500, help="examples per front-end round")
    parser.add_argument("--corpus", default=None, help="folder of real launch files (seeds)")
    parser.add_argument("--corpus-limit", type=int, default=400)
    parser.add_argument("--out", default="fuzz-failures", help="folder for failing cases")
    ns = parser.parse_args()
    pool = seeds() + (corpus_seeds(ns.corpus, ns.corpus_limit) if ns.corpus else [])
    kinds = sorted({kind for kind, _ in pool})
    deadline = time.monotonic() + ns.minutes * 60
    started = time.monotonic()
    cases = 0
    failures = 0
    rounds = 0
    with tempfile.TemporaryDirectory() as scratch:
        folder = Path(scratch)
        while time.monotonic() < deadline:
            kind = kinds[rounds % len(kinds)]
            rounds += 1
            subset = [seed for seed in pool if seed[0] == kind]

            @settings(max_examples=ns.round, deadline=None, database=None,
                      suppress_health_check=list(HealthCheck))
            @given(case=mutated(subset))
            def run(case: tuple[str, bytes]) -> None:
                nonlocal cases
                cases += 1
                check_case(folder, *case)

            try:
                run()
            except Exception:  # a property failed: keep the shrunk case and go on
                failures += 1
                out = Path(ns.out)
                out.mkdir(exist_ok=True)
                (out / f"failure-{failures}.txt").write_text(traceback.format_exc())
                print(f"failure {failures} ({kind}): see {out}", flush=True)
            hours = (time.monotonic() - started) / 3600
            print(f"{cases} cases, {failures} failures, {hours:.2f} h", flush=True)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
