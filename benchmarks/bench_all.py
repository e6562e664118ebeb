#!/usr/bin/env python3
"""Every speed figure of launch-linter in one run: per format, whole process, start-up, scaling.

    python benchmarks/bench_all.py [--quick] [--runs N] [--corpus DIR] [--only SECTIONS]

Sections (``--only per-file,process,startup,files,nodes,jobs`` picks some):

per-file  One process, every corpus file (``files/``; ``--quick``: every 4th) grouped by
          format (the dispatcher decides ROS 1 or ROS 2 XML). For each format, launch-linter's
          cost per file (``lint_files`` with the bundled beliefs and one job: read, parse,
          resolve, rules, suppressions) against that format's floor: read + bare expat and
          read + ElementTree for XML, read + ``ast.parse`` for Python, read + the YAML
          composer for YAML. Then roslaunch's own ``XmlLoader`` on the ROS 1 files (Debian's
          ``/usr/bin/python3`` with ``python3-roslaunch``; timed inside its process, so its
          start-up is not counted). Passes alternate, so a change of load hits all alike.
process   Whole processes on the ROS 1 files: ``launch-linter check --format json`` against
          the roslaunch loader driver (``scripts/roslaunch_oracle_driver.py``) loading the
          same files once; start-up included on both sides.
startup   ``python -c pass``, ``launch-linter --version`` and ``check`` of one small file, cached
          and not, whole process and in process (``benchmarks/bench_startup.py``).
files     ``check`` of synthetic corpora of 1K to 50K files (the corpus files, then copies
          with renamed frames): time and peak memory of the process.
nodes     One ROS 1 file of 1K to 50K ``static_transform_publisher`` nodes in three shapes:
          independent pairs, a chain of frames, a fan from one frame; roslaunch on the pairs.
jobs      ``check`` of 10 and 100 synthetic files and of the corpus with ``--jobs 1``,
          ``--jobs 2`` and the default (and what the default chose at that load).

The run ends with a table of the issue's targets (per-format ratio to the floor, roslaunch
speed-up, start-up, memory at 50,000 files, the jobs default) against what it measured.

Every figure is the median of ``--runs`` runs with the spread (lowest to highest) in
brackets. CPU time (``process_time`` in-process, user + system of a child) is steadier than
wall-clock time on a shared machine; both are shown. ``uptime`` is printed first and last.
"""

from __future__ import annotations

import argparse
import json
import os
import resource
import statistics
import subprocess
import sys
import tempfile
import time
import typing
import xml.etree.ElementTree as ET
from collections.abc import Sequence
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "benchmarks"))
from bench_common import (  # noqa: E402 - benchmarks/ is on the path (above)
    DRIVER,
    SYSTEM_PYTHON,
    Pass,
    ast_pass,
    expat_pass,
    load_average,
    read,
    roslaunch_per_file,
    spread,
    timed,
)

CORPUS = ROOT / ".." / "shared" / "corpus"
SECTIONS = ("per-file", "process", "startup", "files", "nodes", "jobs")

# typing's spellings: the alias is evaluated at run time (Python 3.8).
Summary = typing.Dict[str, str]
"""What each section measured against the issue's targets, for the closing table."""


# ---------------------------------------------------------------- per-file, in one process


def etree_pass(paths: Sequence[str]) -> None:
    for path in paths:
        try:  # noqa: SIM105
            ET.fromstring(read(path))
        except ET.ParseError:
            pass


def yaml_pass(paths: Sequence[str]) -> None:
    import yaml  # type: ignore[import-untyped]

    # The loader the YAML front-end composes with: libyaml's where PyYAML was built with it.
    loader = getattr(yaml, "CSafeLoader", yaml.SafeLoader)
    for path in paths:
        try:  # noqa: SIM105
            yaml.compose(read(path).decode("utf-8", "replace"), Loader=loader)
        except yaml.YAMLError:
            pass


def make_ours_pass() -> Pass:
    from launch_linter.beliefs_files import load_beliefs
    from launch_linter.engine import InputFile, LintOptions, lint_files

    options = LintOptions(beliefs=load_beliefs("bundled", 1.0))

    def ours_pass(paths: Sequence[str]) -> None:
        lint_files([InputFile(os.path.abspath(p), p) for p in paths], options)

    return ours_pass


def formats_of(paths: Sequence[str]) -> dict[str, list[str]]:
    from launch_linter.frontends.dispatch import front_end

    groups: dict[str, list[str]] = {"ROS 1 XML": [], "ROS 2 XML": [], "ROS 2 Python": [],
                                    "ROS 2 YAML": []}
    for path in paths:
        if path.endswith(".py"):
            groups["ROS 2 Python"].append(path)
        elif path.endswith((".yaml", ".yml")):
            groups["ROS 2 YAML"].append(path)
        elif front_end(path, read(path)) == "ros2":
            groups["ROS 2 XML"].append(path)
        else:
            groups["ROS 1 XML"].append(path)
    return {name: group for name, group in groups.items() if group}


FLOORS: dict[str, list[tuple[str, Pass]]] = {
    "ROS 1 XML": [("read + expat", expat_pass), ("read + ElementTree", etree_pass)],
    "ROS 2 XML": [("read + expat", expat_pass), ("read + ElementTree", etree_pass)],
    "ROS 2 Python": [("read + ast.parse", ast_pass)],
    "ROS 2 YAML": [("read + yaml.compose", yaml_pass)],
}


def per_file_section(files: list[str], runs: int, summary: Summary) -> None:
    from launch_linter.cli import tune_collector

    groups = formats_of(files)
    ours_pass = make_ours_pass()
    tune_collector()  # the collector as the ``launch-linter`` command sets it
    for group in groups.values():  # warm-up: imports, regular expressions, page cache
        ours_pass(group)
    times: dict[tuple[str, str], list[tuple[float, float]]] = {}
    for _ in range(runs):
        for name, group in groups.items():
            for label, function in [*FLOORS[name], ("launch-linter", ours_pass)]:
                times.setdefault((name, label), []).append(timed(function, group))
    print("\n== Per file, one process (µs per file: median [lowest..highest])")
    print(f"{'format':13s} {'files':>6s} {'measure':20s} {'CPU':>22s} {'wall':>22s} "
          f"{'ours / this (CPU)':>20s}")
    ours_cpu: dict[str, list[float]] = {}
    for name, group in groups.items():
        ours = [cpu for cpu, _ in times[(name, "launch-linter")]]
        ours_cpu[name] = ours
        for label, _ in [*FLOORS[name], ("launch-linter", ours_pass)]:
            measured = times[(name, label)]
            cpu = [c for c, _ in measured]
            wall = [w for _, w in measured]
            ratio = ("" if label == "launch-linter" else
                     spread([o / c for o, c in zip(ours, cpu)], digits=2))
            if label == FLOORS[name][0][0]:
                summary[f"{name}: ours / {label}"] = f"{ratio}x"
            print(f"{name:13s} {len(group):6d} {label:20s} {spread(cpu, 1e6):>22s} "
                  f"{spread(wall, 1e6):>22s} {ratio:>20s}")
    ros1 = groups.get("ROS 1 XML", [])
    measured = roslaunch_per_file(ros1, runs) if ros1 else None
    if measured is None:
        print(f"roslaunch: not measured ({SYSTEM_PYTHON} cannot import roslaunch)")
        return
    cpu, wall = measured
    speed_up = [t / o for t, o in zip(sorted(cpu), sorted(ours_cpu["ROS 1 XML"]))]
    print(f"{'ROS 1 XML':13s} {len(ros1):6d} {'roslaunch XmlLoader':20s} "
          f"{spread(cpu, 1e6):>22s} {spread(wall, 1e6):>22s}")
    print(f"roslaunch / launch-linter on ROS 1 XML (CPU, runs paired by rank): "
          f"{spread(speed_up, digits=2)}x")
    summary["roslaunch / ours, ROS 1 XML per file"] = f"{spread(speed_up, digits=2)}x"


# ---------------------------------------------------------------- child processes


# A child's ``ru_maxrss`` counts the memory of the process it was forked from (Linux keeps
# the high-water mark across ``exec``), so a child reports its own peak (``VmHWM``) at exit.
PEAK = """\
import atexit, os, runpy, sys
def _peak():
    with open("/proc/self/status", encoding="ascii") as status:
        kib = next(line.split()[1] for line in status if line.startswith("VmHWM"))
    with open(os.environ["BENCH_PEAK_FILE"], "w", encoding="ascii") as out:
        out.write(kib)
atexit.register(_peak)
target = sys.argv.pop(1)
if target.endswith(".py"):
    sys.argv[0] = target
    runpy.run_path(target, run_name="__main__")
else:
    runpy.run_module(target, run_name="__main__", alter_sys=True)
"""


def with_peak(argv: Sequence[str]) -> list[str]:
    """``argv`` (``python -m MODULE ...`` or ``python FILE ...``) reporting its peak memory."""
    rest = list(argv[2:]) if argv[1] == "-m" else list(argv[1:])
    return [argv[0], "-c", PEAK, *rest]


def run_child(argv: Sequence[str], stdin: bytes | None = None, env: dict[str, str] | None = None,
              timeout: float = 3600.0) -> tuple[float, float, float, int]:
    """Wall seconds, CPU seconds (user + system), peak memory (MiB) and status of one child.

    The peak is measured only for an ``argv`` made by ``with_peak`` (else it is NaN).
    """
    with tempfile.NamedTemporaryFile(prefix="bench-peak-") as peak_file:
        env = dict(os.environ if env is None else env, BENCH_PEAK_FILE=peak_file.name)
        wall, cpu, status = _run_child(argv, stdin, env, timeout)
        text = Path(peak_file.name).read_text(encoding="ascii").strip()
    return wall, cpu, int(text) / 1024 if text else float("nan"), status


def _run_child(argv: Sequence[str], stdin: bytes | None, env: dict[str, str],
               timeout: float) -> tuple[float, float, int]:
    started = time.perf_counter()
    with tempfile.TemporaryFile() as feed:
        if stdin is not None:
            feed.write(stdin)
            feed.seek(0)
        child = subprocess.Popen(argv, stdin=feed, stdout=subprocess.DEVNULL,
                                 stderr=subprocess.DEVNULL, env=env, cwd=ROOT)
        deadline = started + timeout
        while True:
            pid, status, usage = os.wait4(child.pid, os.WNOHANG)
            if pid:
                break
            if time.perf_counter() > deadline:
                child.kill()
                os.wait4(child.pid, 0)
                child.returncode = -9
                return timeout, float("nan"), -9
            time.sleep(0.002)
    child.returncode = os.waitstatus_to_exitcode(status)
    wall = time.perf_counter() - started
    return wall, usage.ru_utime + usage.ru_stime, child.returncode


def linter(*args: str) -> list[str]:
    return [sys.executable, "-m", "launch_linter", *args]


def linter_env() -> dict[str, str]:
    """This checkout's code, with its bytecode cached as an installed package has it."""
    env = dict(os.environ, PYTHONPATH=str(ROOT / "src"))
    env.pop("PYTHONDONTWRITEBYTECODE", None)
    return env


def repeated(argv: Sequence[str], runs: int, stdin: bytes | None = None,
             env: dict[str, str] | None = None, timeout: float = 3600.0
             ) -> tuple[list[float], list[float], list[float], int]:
    walls, cpus, mems, status = [], [], [], 0
    for _ in range(runs):
        wall, cpu, mem, status = run_child(argv, stdin, env, timeout)
        walls.append(wall)
        cpus.append(cpu)
        mems.append(mem)
        if status not in (0, 1):
            break
    return walls, cpus, mems, status


def process_section(ros1: list[str], runs: int) -> None:
    print(f"\n== Whole process on the {len(ros1)} ROS 1 XML files (seconds: median [spread])")
    ours = repeated(with_peak(linter("check", "--format", "json", "--jobs", "1", *ros1)), runs,
                    env=linter_env())
    print(f"{'launch-linter check --jobs 1':34s} CPU {spread(ours[1], digits=2)}  "
          f"wall {spread(ours[0], digits=2)}  peak {spread(ours[2])} MiB")
    if not os.path.exists(SYSTEM_PYTHON):
        return
    request = json.dumps({"package_path": [],
                          "files": [{"path": os.path.abspath(p)} for p in ros1]}).encode()
    theirs = repeated(with_peak([SYSTEM_PYTHON, DRIVER]), runs, stdin=request, env={})
    if theirs[3] != 0:
        print("roslaunch driver: not measured (it failed)")
        return
    print(f"{'roslaunch XmlLoader (driver)':34s} CPU {spread(theirs[1], digits=2)}  "
          f"wall {spread(theirs[0], digits=2)}  peak {spread(theirs[2])} MiB")
    print(f"roslaunch / launch-linter, whole process CPU: "
          f"{statistics.median(theirs[1]) / statistics.median(ours[1]):.2f}x")


# ---------------------------------------------------------------- scaling


def build_files(corpus: Path, out: str, count: int) -> None:
    """``count`` distinct files in folders of 1,000: the corpus files, then renamed copies.

    Copy k >= 1 of a file has ``_k`` appended to its frames (``synthetic_corpus``); every
    file ends with a comment naming its copy, in its own syntax.
    """
    from synthetic_corpus import copy_comment, full_suffix, rename_frames

    names = sorted(os.listdir(corpus / "files"))
    contents = {name: read(str(corpus / "files" / name)) for name in names[:count]}
    for number in range(count):
        copy, index = divmod(number, len(names))
        name = names[index]
        data = contents[name]
        if copy:
            data = rename_frames(data, f"_{copy}".encode())
        folder = os.path.join(out, f"{number // 1000:03d}")
        os.makedirs(folder, exist_ok=True)
        suffix = full_suffix(name)
        with open(os.path.join(folder, f"{number:06d}{suffix}"), "wb") as handle:
            handle.write(data + copy_comment(suffix, copy))


def files_section(corpus: Path, sizes: Sequence[int], runs: int, summary: Summary) -> None:
    print("\n== check of N synthetic files (one process, --jobs 1)")
    print(f"{'files':>7s} {'CPU s':>20s} {'µs per file (CPU)':>18s} {'wall s':>20s} "
          f"{'peak MiB':>10s} {'KiB per file':>13s}")
    per_file: dict[int, float] = {}
    for size in sizes:
        with tempfile.TemporaryDirectory(prefix="bench-files-") as scratch:
            build_files(corpus, scratch, size)
            count = size
            walls, cpus, mems, status = repeated(
                with_peak(linter("check", "--format", "json", "--jobs", "1", "--beliefs",
                                 "bundled", scratch)), runs, env=linter_env())
        if status not in (0, 1):
            print(f"{count:7d} failed with status {status}")
            continue
        print(f"{count:7d} {spread(cpus, digits=2):>20s} "
              f"{statistics.median(cpus) / count * 1e6:18.0f} {spread(walls, digits=2):>20s} "
              f"{statistics.median(mems):10.0f} {statistics.median(mems) * 1024 / count:13.1f}")
        per_file[count] = statistics.median(cpus) / count
        summary[f"peak memory at {count:,} files (MiB)"] = spread(mems)
    if len(per_file) > 1:
        low, high = min(per_file), max(per_file)
        summary[f"CPU per file, {high:,} / {low:,} files"] = (
            f"{per_file[high] / per_file[low]:.2f}x")


def nodes_file(count: int, shape: str) -> str:
    lines = ["<launch>"]
    for i in range(count):
        if shape == "pairs":
            parent, child = f"parent_{i}", f"child_{i}"
        elif shape == "chain":
            parent, child = f"frame_{i}", f"frame_{i + 1}"
        else:
            parent, child = "root", f"leaf_{i}"
        lines.append(f'  <node pkg="tf2_ros" type="static_transform_publisher" name="tf_{i}" '
                     f'args="0.1 0 0 0 0 0 1 {parent} {child}"/>')
    lines.append("</launch>\n")
    return "\n".join(lines)


def nodes_section(sizes: Sequence[int], roslaunch_sizes: Sequence[int], runs: int,
                  timeout: float) -> None:
    print("\n== One ROS 1 file of N static_transform_publisher nodes "
          f"(check --format json; timeout {timeout:.0f} s)")
    print(f"{'shape':6s} {'nodes':>7s} {'CPU s':>22s} {'µs per node':>12s} {'peak MiB':>9s}"
          "  status")
    with tempfile.TemporaryDirectory(prefix="bench-nodes-") as scratch:
        for shape in ("pairs", "chain", "fan"):
            for size in sizes:
                path = os.path.join(scratch, f"{shape}_{size}.launch")
                Path(path).write_text(nodes_file(size, shape), encoding="utf-8")
                _, cpus, mems, status = repeated(
                    with_peak(linter("check", "--format", "json", "--beliefs", "none", path)),
                    runs,
                    env=linter_env(), timeout=timeout)
                note = {0: "ok", 1: "ok (findings)", -9: "TIMEOUT"}.get(status, f"exit {status}")
                cpu = spread(cpus, digits=2) if status in (0, 1) else "-"
                per = statistics.median(cpus) / size * 1e6 if status in (0, 1) else float("nan")
                print(f"{shape:6s} {size:7d} {cpu:>22s} {per:12.1f} "
                      f"{statistics.median(mems):9.0f}  {note}")
        if not os.path.exists(SYSTEM_PYTHON):
            return
        for size in roslaunch_sizes:
            path = os.path.join(scratch, f"pairs_{size}.launch")
            if not os.path.exists(path):
                Path(path).write_text(nodes_file(size, "pairs"), encoding="utf-8")
            measured = roslaunch_per_file([path], 1)
            if measured is None:
                return
            print(f"{'pairs':6s} {size:7d} roslaunch XmlLoader CPU {measured[0][0]:.2f} s "
                  f"({measured[0][0] / size * 1e6:.1f} µs per node)")


def jobs_section(corpus: Path, runs: int, summary: Summary) -> None:
    """``--jobs 1``, ``--jobs 2`` and the default on 10 and 100 files and the corpus."""
    from launch_linter.engine import auto_jobs

    files_dir = corpus / "files"
    corpus_count = len(os.listdir(files_dir))
    print(f"\n== check by job count ({os.cpu_count()} CPUs; {load_average()}; wall s: median "
          "[spread]; ratio to --jobs 1 run by run)")
    print(f"{'input':>14s} {'jobs':18s} {'wall s':>20s} {'CPU s':>20s} "
          f"{'/ --jobs 1 (wall)':>20s}")
    cases = [("--jobs 1", ["--jobs", "1"]), ("--jobs 2", ["--jobs", "2"]), ("default", [])]
    with tempfile.TemporaryDirectory(prefix="bench-jobs-") as scratch:
        inputs = []
        for size in (10, 100):
            folder = os.path.join(scratch, str(size))
            build_files(corpus, folder, size)
            inputs.append((f"{size} files", folder, size))
        inputs.append((f"corpus {corpus_count}", str(files_dir), corpus_count))
        verdicts = []
        for name, path, count in inputs:
            walls: dict[str, list[float]] = {label: [] for label, _ in cases}
            cpus: dict[str, list[float]] = {label: [] for label, _ in cases}
            chosen = auto_jobs(count)  # what the default picks at this load, for the record
            for _ in range(runs):  # interleaved, so that load changes hit every case alike
                for label, extra in cases:
                    wall, cpu, _, _ = run_child(linter("check", "--format", "json", *extra,
                                                       path), env=linter_env())
                    walls[label].append(wall)
                    cpus[label].append(cpu)
            serial = walls["--jobs 1"]
            for label, _ in cases:
                ratio = [w / s for w, s in zip(walls[label], serial)]
                note = f" (chose {chosen})" if label == "default" else ""
                print(f"{name:>14s} {label + note:18s} {spread(walls[label], digits=2):>20s} "
                      f"{spread(cpus[label], digits=2):>20s} {spread(ratio, digits=2):>20s}")
                if label == "default":
                    # Wall time is what a user waits for; CPU shows whether a wall-time
                    # difference is the work or the load (the same job count is the same
                    # work).
                    cpu_ratio = statistics.median(cpus[label]) / statistics.median(
                        cpus["--jobs 1"])
                    verdicts.append(f"{name} (chose {chosen}) wall {spread(ratio, digits=2)} "
                                    f"CPU {cpu_ratio:.2f}")
    summary["jobs default / --jobs 1 (wall)"] = "; ".join(verdicts)


TARGETS = (  # issue 24's
    ("ROS 1 XML: ours / read + expat", "<= 10x"),
    ("ROS 2 Python: ours / read + ast.parse", "<= 3x"),
    ("roslaunch / ours, ROS 1 XML per file", "-"),
    ("start-up: check one XML file (cached), above bare (ms)", "<= 40"),
    ("start-up: check one XML file --no-cache, above bare (ms)", "<= 40"),
    ("peak memory at 50,000 files (MiB)", "<= 300 MB"),
    ("jobs default / --jobs 1 (wall)", "<= 1 + noise"),
)


def print_summary(summary: Summary) -> None:
    """The issue's targets against what this run measured (median [spread]), then the
    other figures, so that a closing note can quote one table."""
    if not summary:
        return
    print("\n== Targets of issue 24 against this run")
    width = max(len(key) for key in summary) + 2
    print(f"{'measure':{width}s} {'target':>14s}  measured")
    targets = dict(TARGETS)
    for key, _ in TARGETS:
        if key in summary:
            print(f"{key:{width}s} {targets[key]:>14s}  {summary[key]}")
    for key, value in summary.items():
        if key not in targets:
            print(f"{key:{width}s} {'-':>14s}  {value}")


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[1])
    parser.add_argument("--quick", action="store_true", help="fewer files, runs and sizes")
    parser.add_argument("--runs", type=int, default=None, help="runs per figure (5; quick 3)")
    parser.add_argument("--corpus", type=Path, default=CORPUS)
    parser.add_argument("--only", default=",".join(SECTIONS),
                        help=f"comma-separated sections of {','.join(SECTIONS)}")
    parser.add_argument("--sizes", help="file counts for 'files' and node counts for "
                        "'nodes', comma-separated (default 1000,5000,10000,50000 and "
                        "1000,10000,50000; quick 1000,5000)")
    ns = parser.parse_args()
    runs = ns.runs or (3 if ns.quick else 5)
    only = set(ns.only.split(","))
    files_dir = ns.corpus / "files"
    if not files_dir.is_dir():
        print(f"no corpus at {ns.corpus}", file=sys.stderr)
        return 2
    files = sorted(str(files_dir / name) for name in os.listdir(files_dir))
    if ns.quick:
        files = files[::4]
    print(f"{len(files)} corpus files; {runs} runs per figure; {os.cpu_count()} CPUs; "
          f"Python {sys.version.split()[0]}; {load_average()}")
    started = time.perf_counter()
    summary: Summary = {}
    if "per-file" in only:
        per_file_section(files, runs, summary)
    if "process" in only:
        process_section(formats_of(files).get("ROS 1 XML", []), runs)
    if "startup" in only:
        from bench_startup import startup_section  # benchmarks/ is on the path (above)

        startup_section(runs * 4, summary)
    chosen = tuple(int(s) for s in ns.sizes.split(",")) if ns.sizes else None
    if "files" in only:
        sizes = chosen or ((1_000, 5_000) if ns.quick else (1_000, 5_000, 10_000, 50_000))
        files_section(ns.corpus, sizes, 1 if ns.quick else min(runs, 3), summary)
    if "nodes" in only:
        sizes = chosen or ((1_000, 5_000) if ns.quick else (1_000, 10_000, 50_000))
        nodes_section(sizes, (1_000,) if ns.quick else (1_000, 10_000), 1,
                      60.0 if ns.quick else 600.0)
    if "jobs" in only:
        jobs_section(ns.corpus, runs, summary)
    print_summary(summary)
    print(f"\ndone in {time.perf_counter() - started:.0f} s; {load_average()}; "
          f"this process peak {resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024:.0f} MiB")
    return 0


if __name__ == "__main__":
    sys.exit(main())
