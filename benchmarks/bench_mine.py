#!/usr/bin/env python3
"""Time ingest + mine of a whole corpus into a fresh database; report the median of runs.

    python benchmarks/bench_mine.py [--runs 3] [--jobs N] [CORPUS]

CORPUS defaults to ``../shared/corpus`` relative to the repository root; ``--jobs``
defaults to every CPU. Each run mines into a new temporary database, so every run does
the whole work (reading, hashing, parsing, storing, mining). Prints each run's time, the
median, the peak memory of this process and of its worker processes, and what was stored.
"""

from __future__ import annotations

import argparse
import os
import resource
import statistics
import sys
import tempfile
import time

from launch_linter.mining.commands import mine_corpus

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DEFAULT = os.path.join(ROOT, "..", "shared", "corpus")


def peak_mib() -> tuple[float, float]:
    """Peak resident memory (MiB) of this process and of its largest finished child."""
    own = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
    children = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss / 1024
    return own, children


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("corpus", nargs="?", default=DEFAULT)
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--jobs", type=int, default=os.cpu_count() or 1)
    ns = parser.parse_args()
    if not os.path.isdir(ns.corpus):
        print(f"no corpus at {ns.corpus}", file=sys.stderr)
        return 2
    times: list[float] = []
    for run in range(1, ns.runs + 1):
        with tempfile.TemporaryDirectory() as scratch:
            start = time.perf_counter()
            _, mined, totals = mine_corpus(
                ns.corpus, os.path.join(scratch, "corpus.db"), jobs=ns.jobs
            )
            elapsed = time.perf_counter() - start
        times.append(elapsed)
        print(f"run {run}: {elapsed:.2f} s")
    own, children = peak_mib()
    share = totals["unresolved_transforms"] / max(totals["transforms"], 1)
    print(f"corpus: {ns.corpus}; jobs {ns.jobs} of {os.cpu_count()} CPUs")
    print(f"median of {ns.runs}: {statistics.median(times):.2f} s")
    print(f"peak memory: {own:.0f} MiB (main), {children:.0f} MiB (largest worker)")
    print(
        f"stored: {totals['files']} files, {totals['contents']} distinct contents, "
        f"{totals['parse_failures']} parse failures, {totals['unreadable_files']} unreadable, "
        f"{totals['transforms']} transforms ({share:.1%} unresolved), "
        f"{totals['repos']} repositories ({totals['mature_repos']} mature)"
    )
    print(
        f"mined: {mined.beliefs} beliefs from {mined.files} files ({mined.transforms} "
        f"transforms) of {mined.repos} mature repositories"
    )
    return 0


if __name__ == "__main__":
    sys.exit(main())
