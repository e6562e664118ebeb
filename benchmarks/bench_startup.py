#!/usr/bin/env python3
"""Start-up: what a one-file ``check`` costs above bare Python, in CPU time.

    python benchmarks/bench_startup.py [--runs N] [--against SRC]

Whole processes, interleaved round by round (each round runs every case once, so a change
of load hits them alike): ``python -c pass``; ``launch-linter --version``; ``check`` of
one small ROS 1 XML file answered by the results cache (the usual second run: pre-commit,
an editor) and with ``--no-cache`` (read, parsed, rules run); ``check --no-cache`` of one
ROS 2 Python launch file with a fix to locate. For each: the CPU time of the process (user
+ system from ``os.wait4``) with the wall time beside it, both as median [lowest..highest];
the CPU above bare Python and the ratio to it, taken against the bare run of the same
round. Then the same ``check`` cases in process, ``time.process_time()`` read when the
child's code starts, after the command's modules are imported and at the end: how the CPU
time splits into interpreter start, imports and the run itself.

``--against SRC`` adds each linter case run from another checkout's ``src`` (``git
archive main | tar -x -C /tmp/main`` gives one), interleaved with this one's: before and
after in the same rounds. The files are copied to a scratch folder without a configuration
file, which is also the working folder (the results cache goes there).

``benchmarks/bench_all.py --only startup`` runs this section among the others.
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tempfile
import time
import typing
from collections.abc import Sequence
from pathlib import Path

from bench_common import load_average, spread  # benchmarks/ is on the path (the script's)

ROOT = Path(__file__).resolve().parents[1]
Summary = typing.Dict[str, str]

PYTHON_LAUNCH = """from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package="tf2_ros", executable="static_transform_publisher",
             arguments=["0", "0", "0.1", "0", "0", "0", "/base_link", "imu_link"]),
    ])
"""

PHASES = """\
import time
started = time.process_time()
import contextlib, io, json, os, sys
from launch_linter.cli import main
import launch_linter.commands.check
imported = time.process_time()
with contextlib.redirect_stdout(io.StringIO()):
    main(sys.argv[1:])
done = time.process_time()
with open(os.environ["BENCH_PHASES_FILE"], "w", encoding="ascii") as handle:
    json.dump([started, imported - started, done - imported], handle)
"""
"""A ``check`` in process: CPU at the start of the code, for the imports, for the run."""


def run(argv: Sequence[str], env: dict[str, str], cwd: str) -> tuple[float, float]:
    """CPU seconds (user + system of the child, from ``os.wait4``) and wall seconds."""
    started = time.perf_counter()
    child = subprocess.Popen(argv, stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL,
                             stderr=subprocess.DEVNULL, env=env, cwd=cwd)
    _, status, usage = os.wait4(child.pid, 0)
    wall = time.perf_counter() - started
    if os.waitstatus_to_exitcode(status) not in (0, 1):
        raise SystemExit(f"{' '.join(argv)} failed ({status})")
    return usage.ru_utime + usage.ru_stime, wall


def environment(src: Path) -> dict[str, str]:
    """That checkout's code, with its bytecode cached as an installed package has it."""
    env = dict(os.environ, PYTHONPATH=str(src))
    for name in ("PYTHONDONTWRITEBYTECODE", "LAUNCH_LINTER_NO_CACHE"):
        env.pop(name, None)
    return env


def startup_section(runs: int, summary: Summary, against: Path | None = None) -> None:
    scratch = tempfile.mkdtemp(prefix="bench-startup-")
    (Path(scratch) / "sensors.launch").write_bytes(
        (ROOT / "examples" / "sensors.launch").read_bytes())
    (Path(scratch) / "robot.launch.py").write_text(PYTHON_LAUNCH, encoding="utf-8")
    check = [sys.executable, "-m", "launch_linter", "check", "--format", "json"]
    commands = {
        "--version": [sys.executable, "-m", "launch_linter", "--version"],
        "check one XML file (cached)": [*check, "sensors.launch"],
        "check one XML file --no-cache": [*check, "--no-cache", "sensors.launch"],
        "check one Python file --no-cache": [*check, "--no-cache", "robot.launch.py"],
    }
    trees = {"": ROOT / "src"}
    if against is not None:
        trees = {"this: ": ROOT / "src", "other: ": against}
    cases = [("python -c pass", [sys.executable, "-c", "pass"], dict(os.environ))]
    for prefix, src in trees.items():
        cases += [(prefix + label, argv, environment(src)) for label, argv in commands.items()]
    print(f"\n== Start-up, whole process ({runs} interleaved rounds; {load_average()}); ms: "
          "median [lowest..highest]")
    for _, argv, env in cases:  # bytecode written, results cache filled
        run(argv, env, scratch)
    cpus: dict[str, list[float]] = {label: [] for label, _, _ in cases}
    walls: dict[str, list[float]] = {label: [] for label, _, _ in cases}
    for _ in range(runs):
        for label, argv, env in cases:
            cpu, wall = run(argv, env, scratch)
            cpus[label].append(cpu)
            walls[label].append(wall)
    bare = cpus["python -c pass"]
    for label, _, _ in cases:
        above = [c - b for c, b in zip(cpus[label], bare)]
        ratio = [c / b for c, b in zip(cpus[label], bare)]
        print(f"{label:44s} CPU {spread(cpus[label], 1e3):>15s}  wall "
              f"{spread(walls[label], 1e3):>15s}  above bare {spread(above, 1e3):>14s}  "
              f"x bare {spread(ratio, digits=1)}")
        if label != "python -c pass" and not label.startswith("other: "):
            name = label.replace("this: ", "")
            summary[f"start-up: {name}, above bare (ms)"] = spread(above, 1e3)
    _phases(runs, scratch, trees)
    print(f"({load_average()} at the end)")
    for name in os.listdir(scratch):
        if name == ".launch-linter-cache":
            for entry in os.listdir(os.path.join(scratch, name)):
                os.remove(os.path.join(scratch, name, entry))
            os.rmdir(os.path.join(scratch, name))
        else:
            os.remove(os.path.join(scratch, name))
    os.rmdir(scratch)


def _phases(runs: int, scratch: str, trees: dict[str, Path]) -> None:
    print("\n   in process (time.process_time, ms): interpreter start | imports | run")
    cases = [(prefix + label, [sys.executable, "-c", PHASES, "check", "--format", "json",
                               *extra], environment(src))
             for prefix, src in trees.items()
             for label, extra in (("check one XML file (cached)", ["sensors.launch"]),
                                  ("check one XML file --no-cache",
                                   ["--no-cache", "sensors.launch"]))]
    phases: dict[str, list[list[float]]] = {label: [] for label, _, _ in cases}
    with tempfile.NamedTemporaryFile(prefix="bench-phases-") as record:
        for _ in range(runs):
            for label, argv, env in cases:
                run(argv, dict(env, BENCH_PHASES_FILE=record.name), scratch)
                phases[label].append(json.loads(Path(record.name).read_text("ascii")))
    for label, rows in phases.items():
        start, imports, work = ([row[i] for row in rows] for i in range(3))
        print(f"{label:44s} {spread(start, 1e3):>13s} | {spread(imports, 1e3):>13s} | "
              f"{spread(work, 1e3):>13s}")


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[1])
    parser.add_argument("--runs", type=int, default=20, help="interleaved rounds (20)")
    parser.add_argument("--against", type=Path, help="another checkout's src, compared")
    ns = parser.parse_args()
    summary: Summary = {}
    startup_section(ns.runs, summary, ns.against)
    return 0


if __name__ == "__main__":
    sys.exit(main())
