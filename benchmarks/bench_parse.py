#!/usr/bin/env python3
"""How fast launch-linter reads ROS 1 launch files, against the floor and against roslaunch.

    python benchmarks/bench_parse.py [--corpus DIR] [--runs 5] [--profile N]

Over the latest version of every ROS 1 corpus file (``manifest.jsonl``, ``latest: true``;
``../shared/corpus`` relative to the repository root by default; the dispatcher decides
which are ROS 1, so the XML floor fits them all), with every file's bytes already in
memory, it reports files per second (median of ``--runs`` passes) for:

(a) the floor: bare XML parsing with the standard library,
    ``xml.etree.ElementTree.fromstring`` over the bytes;
(b) launch-linter: parse and resolve, ``load_tree`` for each file (no package roots,
    no launch args, an empty environment);
(c) roslaunch's own loader (``XmlLoader`` into a fresh ``ROSLaunchConfig`` per file), when
    ``/usr/bin/python3`` can import it: one process loads every file ``--runs`` times
    (``scripts/roslaunch_oracle_driver.py``), timed inside that process, so the process
    start is not counted;

and the ratios, all from the same run. Each figure is given twice: from wall-clock time,
and from the CPU time of the process (steadier when other work shares the machine).
(a) and (b) alternate pass by pass so that a change of machine load affects both alike.

``--profile N`` instead runs one pass of (b) under ``cProfile`` and prints its N costliest
functions by own time (the profiler slows everything down: compare shares, not times).
"""

from __future__ import annotations

import argparse
import cProfile
import json
import os
import pstats
import statistics
import subprocess
import sys
import time
import xml.etree.ElementTree as ET
from typing import Callable, List, Tuple

from launch_linter.frontends.dispatch import front_end, load_tree
from launch_linter.frontends.ros1 import LoadOptions
from launch_linter.workspace.packages import PackageIndex

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
CORPUS = os.path.join(ROOT, "..", "shared", "corpus")
DRIVER = os.path.join(ROOT, "scripts", "roslaunch_oracle_driver.py")
SYSTEM_PYTHON = "/usr/bin/python3"

Items = List[Tuple[str, bytes]]


def latest_files(corpus: str) -> list[str]:
    paths: dict[str, None] = {}
    with open(os.path.join(corpus, "manifest.jsonl"), encoding="utf-8") as handle:
        for line in handle:
            row = json.loads(line)
            if row.get("latest"):
                paths[os.path.join(corpus, row["file"])] = None
    return list(paths)


def floor_pass(items: Items) -> None:
    for _, data in items:
        # Not contextlib.suppress: its cost per file would slow the floor down.
        try:  # noqa: SIM105
            ET.fromstring(data)
        except ET.ParseError:
            pass


def make_ours_pass(options: LoadOptions) -> Callable[[Items], None]:
    def ours_pass(items: Items) -> None:
        for path, data in items:
            load_tree(path, options, data)

    return ours_pass


def timed(function: Callable[[Items], None], items: Items) -> tuple[float, float]:
    """Wall-clock and CPU seconds of one pass."""
    wall, cpu = time.perf_counter(), time.process_time()
    function(items)
    return time.perf_counter() - wall, time.process_time() - cpu


def rate(count: int, runs: list[float]) -> float:
    return count / statistics.median(runs)


def roslaunch_runs(paths: list[str], runs: int, cwd: str
                   ) -> tuple[list[float], list[float]] | None:
    if not os.path.exists(SYSTEM_PYTHON):
        return None
    probe = subprocess.run([SYSTEM_PYTHON, "-c", "import roslaunch"], capture_output=True,
                           check=False)
    if probe.returncode != 0:
        return None
    request = {"package_path": [], "repeat": runs, "files": [{"path": p} for p in paths]}
    done = subprocess.run([SYSTEM_PYTHON, DRIVER], input=json.dumps(request), text=True,
                          capture_output=True, cwd=cwd, env={}, check=True, timeout=3600)
    result = json.loads(done.stdout.splitlines()[-1])
    return [float(r) for r in result["runs"]], [float(r) for r in result["cpu_runs"]]


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[1])
    parser.add_argument("--corpus", default=CORPUS)
    parser.add_argument("--runs", type=int, default=5)
    parser.add_argument("--profile", type=int, metavar="N", default=0,
                        help="profile one pass of launch-linter and show N functions")
    ns = parser.parse_args()
    if not os.path.exists(os.path.join(ns.corpus, "manifest.jsonl")):
        print(f"no corpus at {ns.corpus}", file=sys.stderr)
        return 2
    items = []
    for path in latest_files(ns.corpus):
        with open(path, "rb") as handle:
            data = handle.read()
        if front_end(path, data) == "ros1":
            items.append((path, data))
    paths = [path for path, _ in items]
    count = len(items)
    size = sum(len(d) for _, d in items)
    print(f"{count} ROS 1 files (latest versions), {size / 1e6:.2f} MB; "
          f"median of {ns.runs} passes")
    # Input files are shown as given, as the engine shows them.
    ours_pass = make_ours_pass(LoadOptions(packages=PackageIndex([]), display_path=str))
    ours_pass(items)  # warm-up: imports, regular expressions
    if ns.profile:
        profiler = cProfile.Profile()
        profiler.runcall(ours_pass, items)
        pstats.Stats(profiler).sort_stats("tottime").print_stats(ns.profile)
        return 0
    floor_times, ours_times = [], []
    for _ in range(ns.runs):
        floor_times.append(timed(floor_pass, items))
        ours_times.append(timed(ours_pass, items))
    floor = [rate(count, [t[i] for t in floor_times]) for i in (0, 1)]
    ours = [rate(count, [t[i] for t in ours_times]) for i in (0, 1)]
    print(f"{'files/s':40s} {'wall-clock':>12s} {'CPU time':>12s}")
    print(f"{'(a) floor: ElementTree.fromstring':40s} {floor[0]:12.0f} {floor[1]:12.0f}")
    print(f"{'(b) launch-linter parse + resolve':40s} {ours[0]:12.0f} {ours[1]:12.0f}")
    print(f"{'(b) time / (a) time (target <= 3)':40s} {floor[0] / ours[0]:12.2f} "
          f"{floor[1] / ours[1]:12.2f}")
    measured = roslaunch_runs(paths, ns.runs, os.path.join(ns.corpus, "files"))
    if measured is None:
        print(f"(c) roslaunch: not measured ({SYSTEM_PYTHON} cannot import roslaunch)")
        return 0
    theirs = [rate(count, measured[i]) for i in (0, 1)]
    print(f"{'(c) roslaunch XmlLoader':40s} {theirs[0]:12.0f} {theirs[1]:12.0f}")
    print(f"{'(c) time / (b) time (target >= 10)':40s} {ours[0] / theirs[0]:12.2f} "
          f"{ours[1] / theirs[1]:12.2f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
