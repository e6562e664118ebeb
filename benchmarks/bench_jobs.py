#!/usr/bin/env python3
"""Time ``lint_paths`` serially and with ``--jobs N`` on the corpus; check equal output.

    python benchmarks/bench_jobs.py [--jobs 1,2,4] [--repeat 3] [PATH]

PATH defaults to ``../shared/corpus/files`` relative to the repository root. Beliefs are
off (``none``) so that only loading and the rules are timed. Prints the best of
``--repeat`` wall-clock times for each job count and whether every result equals the
serial one.
"""

from __future__ import annotations

import argparse
import os
import sys
import time

from launch_linter import LintOptions, lint_paths

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DEFAULT = os.path.join(ROOT, "..", "shared", "corpus", "files")


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[1])
    parser.add_argument("path", nargs="?", default=DEFAULT)
    parser.add_argument("--jobs", default="1,2", help="comma-separated job counts")
    parser.add_argument("--repeat", type=int, default=3)
    ns = parser.parse_args()
    if not os.path.isdir(ns.path):
        print(f"no corpus at {ns.path}", file=sys.stderr)
        return 2
    counts = [int(j) for j in ns.jobs.split(",")]
    serial = lint_paths([ns.path], LintOptions(jobs=1))
    print(f"{len(serial.files)} files, {len(serial.diagnostics)} diagnostics; "
          f"{os.cpu_count()} CPUs")
    same = True
    for jobs in counts:
        best = float("inf")
        for _ in range(ns.repeat):
            start = time.perf_counter()
            result = lint_paths([ns.path], LintOptions(jobs=jobs))
            best = min(best, time.perf_counter() - start)
            same = same and result == serial
        print(f"jobs={jobs}: {best:.2f} s (best of {ns.repeat})")
    print("identical to serial" if same else "DIFFERENT from serial")
    return 0 if same else 1


if __name__ == "__main__":
    sys.exit(main())
