#!/usr/bin/env python3
"""One ROS 1 launch file of N static transforms, in shapes that stress the tf graph rules.

    PYTHONPATH=src python benchmarks/bench_graph.py [--sizes 1000,10000,50000]
        [--shapes pairs,chain,fan,cycle,fanin,dups,ladder] [--timeout 300]

Each (shape, size) runs in a fresh child process, which loads the file, runs every rule
(``engine.check_tree``), locates the fixes and writes the ``check`` JSON document, and
reports the CPU seconds of each phase, the slowest rules and its peak memory (``VmHWM``).
Linear means the µs per node stays flat as N grows.

Shapes: ``pairs`` (independent ``parent_i -> child_i``), ``chain`` (``frame_i ->
frame_i+1``), ``fan`` (``root -> leaf_i``), ``cycle`` (the chain closed by
``frame_N -> frame_0``: one loop of N frames), ``fanin`` (``parent_i -> shared``: one
frame with N parents), ``dups`` (the same ``a -> b`` N times, with different values) and
``ladder`` (``frame_i <-> frame_i+1``: N/2 two-frame loops in one strongly connected
component).
"""

from __future__ import annotations

import argparse
import io
import json
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
SHAPES = ("pairs", "chain", "fan", "cycle", "fanin", "dups", "ladder")


def edges(count: int, shape: str) -> list[tuple[str, str]]:
    if shape == "pairs":
        return [(f"parent_{i}", f"child_{i}") for i in range(count)]
    if shape == "chain":
        return [(f"frame_{i}", f"frame_{i + 1}") for i in range(count)]
    if shape == "fan":
        return [("root", f"leaf_{i}") for i in range(count)]
    if shape == "cycle":
        return [(f"frame_{i}", f"frame_{(i + 1) % count}") for i in range(count)]
    if shape == "fanin":
        return [(f"parent_{i}", "shared") for i in range(count)]
    if shape == "dups":
        return [("a", "b")] * count
    if shape == "ladder":
        half = count // 2
        return [pair for i in range(half)
                for pair in ((f"frame_{i}", f"frame_{i + 1}"), (f"frame_{i + 1}", f"frame_{i}"))]
    raise ValueError(shape)


def launch_file(count: int, shape: str) -> str:
    lines = ["<launch>"]
    for i, (parent, child) in enumerate(edges(count, shape)):
        lines.append(f'  <node pkg="tf2_ros" type="static_transform_publisher" name="tf_{i}" '
                     f'args="0.{i + 1} 0 0 0 0 0 1 {parent} {child}"/>')
    lines.append("</launch>\n")
    return "\n".join(lines)


def child(path: str) -> None:
    """Load, lint, locate fixes and write the JSON document of ``path``; print the figures."""
    from launch_linter import __version__
    from launch_linter.engine import (
        InputFile,
        LintOptions,
        LintResult,
        check_tree,
        finish_diagnostics,
        load_options_for,
        selected_rules,
    )
    from launch_linter.fix import with_located_fixes
    from launch_linter.frontends.dispatch import load_tree
    from launch_linter.model.beliefs import BeliefSet
    from launch_linter.report import json_report
    from launch_linter.rules import RuleContext

    options = LintOptions()
    item = InputFile(os.path.abspath(path), path)
    clock = time.process_time
    started = clock()
    tree = load_tree(item.path, load_options_for(item, options, {}))
    loaded = clock()
    rules = selected_rules(options)
    found = check_tree(tree, rules, options)
    checked = clock()
    diagnostics = with_located_fixes(finish_diagnostics((tree,), found, options))
    result = LintResult((), (tree,), diagnostics)
    out = io.StringIO()
    json_report.write(json_report.check_document(result, BeliefSet.empty(), __version__), out)
    reported = clock()
    # Each rule alone, on a context of its own, to name the slow ones (the shared index is
    # built by whichever rule asks first, so a tree rule's figure includes it).
    per_rule = []
    for rule in rules:
        before = clock()
        for _ in rule.check(RuleContext(tree, options.beliefs, options.profile, None)):
            pass
        per_rule.append((clock() - before, rule.id))
    per_rule.sort(reverse=True)
    with open("/proc/self/status", encoding="ascii") as status:
        peak = next(int(line.split()[1]) for line in status if line.startswith("VmHWM"))
    print(json.dumps({
        "load": loaded - started, "rules": checked - loaded, "output": reported - checked,
        "findings": len(diagnostics), "bytes": len(out.getvalue()), "peak_mib": peak / 1024,
        "slowest": per_rule[:2],
    }))


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--sizes", default="1000,10000,50000")
    parser.add_argument("--shapes", default=",".join(SHAPES))
    parser.add_argument("--timeout", type=float, default=300.0)
    parser.add_argument("--child", help=argparse.SUPPRESS)
    ns = parser.parse_args()
    if ns.child:
        child(ns.child)
        return 0
    env = dict(os.environ, PYTHONPATH=str(ROOT / "src"))
    print(f"{'shape':7s} {'nodes':>6s} {'load s':>7s} {'rules s':>8s} {'output s':>8s} "
          f"{'µs/node':>8s} {'peak MiB':>8s} {'findings':>8s} {'JSON KiB':>8s}  slowest rules")
    with tempfile.TemporaryDirectory(prefix="bench-graph-") as scratch:
        for shape in ns.shapes.split(","):
            for size in (int(s) for s in ns.sizes.split(",")):
                path = os.path.join(scratch, f"{shape}_{size}.launch")
                Path(path).write_text(launch_file(size, shape), encoding="utf-8")
                try:
                    done = subprocess.run(
                        [sys.executable, __file__, "--child", path], env=env, cwd=ROOT,
                        capture_output=True, text=True, timeout=ns.timeout, check=True)
                except subprocess.TimeoutExpired:
                    print(f"{shape:7s} {size:6d} TIMEOUT after {ns.timeout:.0f} s")
                    continue
                except subprocess.CalledProcessError as failed:
                    print(f"{shape:7s} {size:6d} FAILED: {failed.stderr.strip()[-300:]}")
                    continue
                f = json.loads(done.stdout)
                total = f["load"] + f["rules"] + f["output"]
                slowest = ", ".join(f"{rule} {seconds:.2f}" for seconds, rule in f["slowest"])
                print(f"{shape:7s} {size:6d} {f['load']:7.2f} {f['rules']:8.2f} "
                      f"{f['output']:8.2f} {total / size * 1e6:8.1f} {f['peak_mib']:8.0f} "
                      f"{f['findings']:8d} {f['bytes'] / 1024:8.0f}  {slowest}", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
