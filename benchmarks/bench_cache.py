#!/usr/bin/env python3
"""The results cache on a real workspace: a second run against the first, and one changed
included file (issue 24).

    python benchmarks/bench_cache.py WORKSPACE [--runs 5]

WORKSPACE is a folder that ``check`` walks (for example a colcon workspace whose ``src``
holds autowarefoundation/autoware.universe, autoware_launch and autoware_core: several
hundred launch files). Whole processes of this checkout's ``launch-linter check --format
json`` are timed in CPU time (user + system, from ``os.wait4``), wall time beside; runs
alternate (cold, warm, ``--no-cache``), and each figure is the median with the lowest and
highest in brackets.

- cold: no cache folder (the run also writes the cache); warm: the cache as the previous
  run left it, nothing changed; ``--no-cache``: what a run cost before the cache.
- changed include: one file that several roots include gets a comment; the run with the
  cache must lint again exactly the roots whose entries read it, which must hold every root
  whose tree includes it (the files of each tree of a run without the cache), and print
  what ``--no-cache`` prints. Roots may read a file without including it: the
  ``ros2_undeclared_arg`` check of a ROS 2 launch file reads the workspace's launch files
  to see whether one names it.

The file is restored at the end, and the cache folder (``.launch-linter-cache`` in
WORKSPACE) removed.
"""

from __future__ import annotations

import argparse
import json
import os
import shutil
import statistics
import subprocess
import sys
import time
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO / "src"))

from launch_linter.cli import build_parser  # noqa: E402
from launch_linter.commands.options import (  # noqa: E402
    lint_command_paths,
    lint_options,
    load_config,
    results_cache,
)
from launch_linter.engine import lint_paths  # noqa: E402


def timed(argv: list[str], cwd: Path) -> tuple[float, float, bytes]:
    """CPU seconds (user + system) and wall seconds of a process, and what it printed."""
    env = dict(os.environ, PYTHONPATH=str(REPO / "src"))
    env.pop("LAUNCH_LINTER_NO_CACHE", None)
    start = time.perf_counter()
    process = subprocess.Popen(argv, cwd=cwd, env=env, stdout=subprocess.PIPE,
                               stderr=subprocess.DEVNULL)
    assert process.stdout is not None
    out = process.stdout.read()
    _, status, usage = os.wait4(process.pid, 0)
    wall = time.perf_counter() - start
    process.returncode = os.waitstatus_to_exitcode(status)
    if process.returncode not in (0, 1):
        raise SystemExit(f"{' '.join(argv)} exited {process.returncode}")
    return usage.ru_utime + usage.ru_stime, wall, out


def check(*extra: str) -> list[str]:
    return [sys.executable, "-m", "launch_linter", "check", "--format", "json", *extra, "."]


def summary(values: list[float]) -> str:
    return f"{statistics.median(values):.3f} [{min(values):.3f}..{max(values):.3f}]"


def included_file(workspace: Path) -> tuple[Path, set[str]]:
    """A file that the most roots read besides themselves, and those roots."""
    result = lint_paths(["."], keep_trees=True)
    readers: dict[str, set[str]] = {}
    for tree in result.trees:
        for file in tree.files:
            real = os.path.realpath(file)
            if real != os.path.realpath(tree.root):
                readers.setdefault(real, set()).add(os.path.realpath(tree.root))
    path = max(readers, key=lambda p: (len(readers[p]), p))
    roots = set(readers[path])
    # The file is a root itself when discovery finds it: it is linted again too.
    if any(os.path.realpath(r.path) == path for r in result.files):
        roots.add(path)
    return Path(path), roots


def readers_in_cache(folder: Path, path: Path) -> set[str]:
    """The roots whose cache entries depend on ``path``: its own stamps or a group's (the
    package crawl, the scan of launch files that ``ros2_undeclared_arg`` makes)."""
    (cache_file,) = folder.glob("results-*.json")
    document = json.loads(cache_file.read_text(encoding="utf-8"))
    target = str(path)
    groups = {name for name, stamps in document["groups"].items()
              if any(stamp[0] == target for stamp in stamps)}
    return {os.path.realpath(root) for root, entry in document["entries"].items()
            if any(stamp[0] == target for stamp in entry["stamps"])
            or groups.intersection(entry["groups"])}


def relinted_in_process() -> list[str]:
    ns = build_parser().parse_args(["check", "."])
    config = load_config(ns)
    options = lint_options(ns, config)
    cache = results_cache(ns, options, config)
    assert cache is not None
    lint_command_paths(ns, options, config, keep_trees=False, cache=cache)
    cache.save()
    return [os.path.realpath(p) for p in cache.missed]


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("workspace", type=Path)
    parser.add_argument("--runs", type=int, default=5)
    ns = parser.parse_args()
    workspace = ns.workspace.resolve()
    os.chdir(workspace)
    os.environ.pop("LAUNCH_LINTER_NO_CACHE", None)
    cache_folder = workspace / ".launch-linter-cache"
    print(f"load average at start: {os.getloadavg()[0]:.1f}")
    cold: list[tuple[float, float]] = []
    warm: list[tuple[float, float]] = []
    plain: list[tuple[float, float]] = []
    reference = timed(check("--no-cache"), workspace)[2]
    for _ in range(ns.runs):
        shutil.rmtree(cache_folder, ignore_errors=True)
        cpu, wall, out = timed(check(), workspace)
        assert out == reference, "the cold run's output differs from --no-cache"
        cold.append((cpu, wall))
        cpu, wall, out = timed(check(), workspace)
        assert out == reference, "the warm run's output differs from --no-cache"
        warm.append((cpu, wall))
        cpu, wall, out = timed(check("--no-cache"), workspace)
        assert out == reference, "--no-cache printed something else from one run to the next"
        plain.append((cpu, wall))
    ratios = [w[0] / c[0] for w, c in zip(warm, cold)]
    ratios_plain = [w[0] / p[0] for w, p in zip(warm, plain)]
    files = reference.count(b'"status"')
    print(f"{files} root files, {ns.runs} runs each, alternating; CPU s (wall s)")
    print(f"cold (writes the cache): {summary([c for c, _ in cold])} "
          f"({summary([w for _, w in cold])})")
    print(f"warm (nothing changed):  {summary([c for c, _ in warm])} "
          f"({summary([w for _, w in warm])})")
    print(f"--no-cache:              {summary([c for c, _ in plain])} "
          f"({summary([w for _, w in plain])})")
    print(f"warm / cold, CPU: {summary(ratios)}; warm / --no-cache: {summary(ratios_plain)}")

    path, includers = included_file(workspace)
    expected = readers_in_cache(cache_folder, path)
    original = path.read_bytes()
    comment = b"\n<!-- bench_cache -->\n" if path.suffix in (".xml", ".launch", ".xacro") \
        else b"\n# bench_cache\n"
    try:
        path.write_bytes(original + comment)
        missed = set(relinted_in_process())
        path.write_bytes(original + comment + comment)
        cpu, wall, out = timed(check(), workspace)
        same = out == timed(check("--no-cache"), workspace)[2]
    finally:
        path.write_bytes(original)
        shutil.rmtree(cache_folder, ignore_errors=True)
    print(f"changed include {os.path.relpath(path, workspace)}: included by "
          f"{len(includers)} root(s) (itself counted when it is one), all of them among the "
          f"{len(expected)} whose cache entries read it: {includers <= expected}; linted "
          f"again {len(missed)}; exactly those {len(expected)}: {missed == expected}; output "
          f"identical to --no-cache: {same}; that run {cpu:.3f} s CPU ({wall:.3f} wall)")
    print(f"load average at end: {os.getloadavg()[0]:.1f}")
    return 0 if missed == expected and includers <= expected and same else 1


if __name__ == "__main__":
    sys.exit(main())
