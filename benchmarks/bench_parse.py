#!/usr/bin/env python3
"""What one launch file costs launch-linter to read and to check, against its parser's floor.

    python benchmarks/bench_parse.py [--corpus DIR] [--runs 5] [--every N]
                                     [--profile N [--format ros1|python] [--measure read|check]]
                                     [--repeat N --format ros1|python --measure floor|read|check]
                                     [--against SRC [--rounds N]] [--collect]

Over the latest version of every corpus file (``manifest.jsonl``, ``latest: true``;
``../shared/corpus`` relative to the repository root by default), grouped by format (the
dispatcher decides which XML files are ROS 1; every ``.py`` file is ROS 2 Python), it
measures per file, in CPU time of this process (``time.process_time``, steadier on a shared
machine) with the wall-clock time beside it:

floor   ROS 1 XML: read the file + parse it with bare expat (``xml.parsers.expat``);
        ROS 2 Python: read the file + ``ast.parse``;
read    launch-linter's front-end: ``load_tree`` of the file (read, parse, resolve; no
        package roots, no launch args, an empty environment, so included packages are not
        followed);
check   launch-linter's ``check`` of the file: ``lint_files`` with the bundled beliefs and
        one job (read, parse, resolve, rules, suppressions, fix locations) over the
        format's files at once, as ``benchmarks/bench_all.py --only per-file`` does;

and the ratios read / floor and check / floor (issue 24's targets: ROS 2 Python check <= 3x
``ast.parse``, ROS 1 XML check <= 10x read + expat). The three measures alternate pass by
pass, so that a change of machine load hits all of them alike; every figure is the median
of ``--runs`` passes with the lowest and highest in brackets, each ratio the median of the
ratios of the same pass. Then, when ``/usr/bin/python3`` can import ``roslaunch``, its own
``XmlLoader`` on the ROS 1 files (``scripts/roslaunch_oracle_driver.py``, timed inside its
process).

``--profile N`` instead runs one pass of ``--measure`` over the ``--format`` files under
``cProfile`` and prints its N costliest functions by own time, then by cumulative time
(the profiler slows Python code more than C code: compare shares, not times).

``--against SRC`` compares with another checkout's ``src`` (main exported with ``git
archive``): ``--rounds`` rounds, each running this script once from this checkout and once
from SRC (``PYTHONPATH``), one after the other (which goes first alternates), so that
both see the same load; it prints
each run's ratios (front-end / floor and check / floor, medians of its passes) and, per
format, the median over the rounds of this checkout's ratio divided by SRC's.

``--collect`` ends every timed pass with ``gc.collect()``: a pass then pays for the reference
cycles it leaves, which the collector would otherwise free during a later pass (charged
to whichever measure runs then; the collector runs every 50,000 allocations, as the
command sets it). What the warm-up left (the imported front-ends and rules, their caches)
is frozen first (``gc.freeze``), as the command freezes what start-up made: a full
collection then walks only what was made since, so each pass, the floor's too, pays for
what it leaves and not for a walk of every object of the process (which made the floor
dearer and the ratios low). The cost of a collection after a pass that leaves nothing is
printed beside the figures.

``--repeat N`` runs only that pass, N times after one warm-up pass, and prints nothing: for
an instruction counter, which the machine's load does not move (docs/performance.md):

    PYTHONHASHSEED=0 valgrind --tool=callgrind --callgrind-out-file=/dev/null \\
        python benchmarks/bench_parse.py --every 8 --repeat 1 --format ros1 --measure read

and again with ``--repeat 3``: half the difference is one pass. The fixed hash seed keeps
the work of two runs the same (set and dict order, hash collisions), and the bytecode must
be compiled before the first of them (``python -m compileall src benchmarks``), or its
compilation is subtracted from the pass.
"""

from __future__ import annotations

import argparse
import cProfile
import gc
import json
import os
import pstats
import statistics
import subprocess
import sys
import time
from typing import Dict, List, Sequence

from bench_common import (  # benchmarks/ is on the path (the script's folder)
    Pass,
    ast_pass,
    expat_pass,
    load_average,
    read,
    roslaunch_per_file,
    spread,
    timed,
)

from launch_linter.beliefs_files import load_beliefs
from launch_linter.cli import tune_collector
from launch_linter.engine import InputFile, LintOptions, lint_files
from launch_linter.frontends.dispatch import front_end, load_tree
from launch_linter.frontends.ros1 import LoadOptions
from launch_linter.workspace import mentions
from launch_linter.workspace.packages import PackageIndex

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
CORPUS = os.path.join(ROOT, "..", "shared", "corpus")
FORMATS = {"ros1": "ROS 1 XML", "python": "ROS 2 Python"}
TARGETS = {"ROS 1 XML": 10.0, "ROS 2 Python": 3.0}
"""Issue 24: check per file at most this many times the floor."""

Timings = Dict[str, List[float]]


def latest_files(corpus: str) -> list[str]:
    paths: dict[str, None] = {}
    with open(os.path.join(corpus, "manifest.jsonl"), encoding="utf-8") as handle:
        for line in handle:
            row = json.loads(line)
            if row.get("latest"):
                paths[os.path.join(corpus, row["file"])] = None
    return list(paths)


def groups_of(paths: Sequence[str]) -> dict[str, list[str]]:
    groups: dict[str, list[str]] = {name: [] for name in FORMATS.values()}
    for path in paths:
        if path.endswith(".py"):
            groups["ROS 2 Python"].append(path)
        elif not path.endswith((".yaml", ".yml")) and front_end(path, read(path)) == "ros1":
            groups["ROS 1 XML"].append(path)
    return groups


FLOORS: dict[str, tuple[str, Pass]] = {
    "ROS 1 XML": ("read + expat", expat_pass),
    "ROS 2 Python": ("read + ast.parse", ast_pass),
}


def make_read_pass() -> Pass:
    # Input files are shown as given, as the engine shows them.
    options = LoadOptions(packages=PackageIndex([]), display_path=str)

    def read_pass(paths: Sequence[str]) -> None:
        for path in paths:
            load_tree(path, options)

    return read_pass


def make_check_pass() -> Pass:
    options = LintOptions(beliefs=load_beliefs("bundled", 1.0))

    def check_pass(paths: Sequence[str]) -> None:
        lint_files([InputFile(os.path.abspath(path), path) for path in paths], options)

    return check_pass


def collecting(function: Pass) -> Pass:
    """``function``, then a collection of the reference cycles it left (``--collect``)."""

    def collected(paths: Sequence[str]) -> None:
        function(paths)
        gc.collect()

    return collected


def idle_collection(times: int = 20) -> float:
    """The median CPU seconds of ``gc.collect()`` when nothing was made since the last."""
    gc.collect()
    costs = []
    for _ in range(times):
        start = time.process_time()
        gc.collect()
        costs.append(time.process_time() - start)
    return statistics.median(costs)


def measure(name: str, paths: list[str], runs: int, passes: dict[str, Pass],
            collect: bool = False) -> dict[str, float]:
    """Print the figures of ``name``'s files; return each pass's median ratio to the floor."""
    floor_label, floor = FLOORS[name]
    measures = {floor_label: floor, **passes}
    if collect:
        measures = {label: collecting(function) for label, function in measures.items()}
    cpu: Timings = {label: [] for label in measures}
    wall: Timings = {label: [] for label in measures}
    for _ in range(runs):
        for label, function in measures.items():
            seconds, elapsed = timed(function, paths)
            cpu[label].append(seconds)
            wall[label].append(elapsed)
    print(f"\n{name}: {len(paths)} files; µs per file, median [lowest..highest] of {runs}")
    print(f"{'measure':18s} {'CPU':>22s} {'wall':>22s} {'/ floor (CPU)':>22s}")
    for label in measures:
        ratio = ("" if label == floor_label else
                 spread([o / f for o, f in zip(cpu[label], cpu[floor_label])], digits=2))
        print(f"{label:18s} {spread(cpu[label], 1e6):>22s} {spread(wall[label], 1e6):>22s} "
              f"{ratio:>22s}")
    ratios = {label: statistics.median(o / f for o, f in zip(cpu[label], cpu[floor_label]))
              for label in passes}
    if "check" in ratios:
        times = ratios["check"]
        verdict = "met" if times <= TARGETS[name] else "not met"
        print(f"target: check <= {TARGETS[name]:g}x {floor_label}: {verdict} ({times:.2f}x)")
    return ratios


RATIOS = "ratios: "
"""How a run started by ``--against`` hands its ratios to the comparing run."""


def compare(ns: argparse.Namespace, against: str) -> int:
    """``--against``: this checkout and ``against`` in alternating runs."""
    argv = [sys.executable, os.path.abspath(__file__), "--corpus", ns.corpus, "--runs",
            str(ns.runs), "--every", str(ns.every), "--no-roslaunch",
            *(["--collect"] if ns.collect else [])]
    sides = {"this": os.path.join(ROOT, "src"), "other": os.path.abspath(against)}
    found: dict[str, list[dict[str, dict[str, float]]]] = {side: [] for side in sides}
    print(f"this: {sides['this']}; other: {sides['other']}; {ns.rounds} rounds; "
          f"{load_average()}")
    for round_number in range(1, ns.rounds + 1):
        order = list(sides.items())
        for side, src in order if round_number % 2 else reversed(order):
            env = dict(os.environ, PYTHONPATH=src)
            done = subprocess.run(argv, env=env, capture_output=True, text=True, check=True)
            line = next(x for x in done.stdout.splitlines() if x.startswith(RATIOS))
            ratios = json.loads(line[len(RATIOS):])
            found[side].append(ratios)
            shown = "; ".join(f"{name}: " + ", ".join(f"{label} {value:.2f}x" for label, value
                                                     in by_label.items())
                              for name, by_label in ratios.items())
            print(f"round {round_number} {side:5s} {shown} ({load_average()})")
    for name in found["this"][0]:
        for label in found["this"][0][name]:
            mine = [r[name][label] for r in found["this"]]
            other = [r[name][label] for r in found["other"]]
            change = [m / o for m, o in zip(mine, other)]
            print(f"{name} {label} / floor: this {spread(mine, digits=2)}, other "
                  f"{spread(other, digits=2)}; this / other {spread(change, digits=3)}")
    return 0


def profile(paths: list[str], function: Pass, count: int) -> None:
    profiler = cProfile.Profile()
    profiler.runcall(function, paths)
    stats = pstats.Stats(profiler)
    stats.sort_stats("tottime").print_stats(count)
    stats.sort_stats("cumtime").print_stats(count)


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--corpus", default=CORPUS)
    parser.add_argument("--runs", type=int, default=5)
    parser.add_argument("--every", type=int, default=1, metavar="N",
                        help="only every Nth corpus file (a quicker sample)")
    parser.add_argument("--profile", type=int, metavar="N", default=0,
                        help="profile one pass and show N functions")
    parser.add_argument("--format", choices=sorted(FORMATS), default="ros1",
                        help="what --profile profiles")
    parser.add_argument("--measure", choices=("floor", "read", "check"), default="check",
                        help="what --profile profiles or --repeat runs")
    parser.add_argument("--repeat", type=int, metavar="N", default=0,
                        help="only run the --format/--measure pass N times, silently")
    parser.add_argument("--no-roslaunch", action="store_true",
                        help="skip roslaunch's loader")
    parser.add_argument("--against", metavar="SRC",
                        help="compare with another checkout's src, in alternating runs")
    parser.add_argument("--rounds", type=int, default=3, help="rounds of --against")
    parser.add_argument("--collect", action="store_true",
                        help="end every timed pass with gc.collect(), so that a pass pays "
                             "for the reference cycles it leaves")
    ns = parser.parse_args()
    if ns.against:
        return compare(ns, ns.against)
    if not os.path.exists(os.path.join(ns.corpus, "manifest.jsonl")):
        print(f"no corpus at {ns.corpus}", file=sys.stderr)
        return 2
    groups = groups_of(latest_files(ns.corpus)[:: ns.every])
    tune_collector()  # the collector as the ``launch-linter`` command sets it
    # A command reads the launch files of a folder once per run, to see whether another
    # one names a file (``workspace/mentions.py``); it reads them again after
    # ``FRESH_SECONDS`` for the language server. Here passes repeat for minutes (under an
    # instruction counter each pass takes longer than that), so without this every pass
    # of a file that asks would read the corpus's 5,518 files again: a run's cost, not a
    # file's (it was 91% of the ROS 1 front-end's instructions on main 36451d7).
    mentions.FRESH_SECONDS = float("inf")
    passes = {"read": make_read_pass(), "check": make_check_pass()}
    if ns.repeat:
        name = FORMATS[ns.format]
        function = FLOORS[name][1] if ns.measure == "floor" else passes[ns.measure]
        for _ in range(ns.repeat + 1):
            function(groups[name])
        return 0
    for paths in groups.values():  # warm-up: imports, regular expressions, page cache
        for function in passes.values():
            function(paths)
    if ns.collect:
        # What exists now lives as long as the process: frozen, so that a collection
        # after a pass walks what the pass made, not everything imported (see above).
        gc.collect()
        gc.freeze()
        print(f"--collect: an idle full collection costs {idle_collection() * 1e6:.0f} µs "
              f"of CPU ({gc.get_freeze_count():,} objects frozen)")
    if ns.profile:
        profile(groups[FORMATS[ns.format]], passes[ns.measure], ns.profile)
        return 0
    print(f"{sum(map(len, groups.values()))} corpus files (latest versions; every "
          f"{ns.every}); Python {sys.version.split()[0]}; {load_average()}")
    ratios = {}
    for name, paths in groups.items():
        if paths:
            ratios[name] = measure(name, paths, ns.runs, passes, ns.collect)
    print(RATIOS + json.dumps(ratios))
    ros1 = groups["ROS 1 XML"]
    measured = None if ns.no_roslaunch or not ros1 else roslaunch_per_file(ros1, ns.runs)
    if measured is not None:
        cpu, wall = measured
        print(f"\nroslaunch XmlLoader on the ROS 1 files: {spread(cpu, 1e6)} µs CPU per "
              f"file, {spread(wall, 1e6)} wall")
    print(f"\n{load_average()} at the end")
    return 0


if __name__ == "__main__":
    sys.exit(main())
