#!/usr/bin/env python3
"""Issue 27's trial: `check` on whole repositories, with counts a person then judges.

    python scripts/workspace_trial.py OUT_DIR REPO [REPO ...]

For each repository folder it runs ``launch-linter check --format json`` (as a user would,
in a subprocess, with this process's environment, so a sourced ``AMENT_PREFIX_PATH`` is
seen) and writes ``OUT_DIR/<repo>.json``; then it prints one line per repository: errors,
warnings and infos, whether a tree of the repository starts ``robot_state_publisher``
with a description, and whether any such tree had its description read (URDF joints
found, or, for a URDF without joints, no problem reported about the description), and
how many distinct URDF joints those trees hold. The
errors and warnings are listed in ``OUT_DIR/<repo>.findings.txt`` for judging by reading
the files. Run it with ``PYTHONPATH`` pointing at another checkout's ``src`` to measure
that version.
"""

from __future__ import annotations

import argparse
import collections
import json
import os
import subprocess
import sys

from launch_linter.engine import LintOptions, lint_paths

RSP = "robot_state_publisher"


def counts(repo: str, out_dir: str) -> collections.Counter[str]:
    name = os.path.basename(os.path.normpath(repo))
    report = os.path.join(out_dir, name + ".json")
    subprocess.run(
        [sys.executable, "-m", "launch_linter", "check", repo, "--format", "json",
         "-o", report, "--exit-zero"],
        check=True,
    )
    with open(report, encoding="utf-8") as handle:
        diagnostics = json.load(handle)["diagnostics"]
    with open(os.path.join(out_dir, name + ".findings.txt"), "w", encoding="utf-8") as out:
        for d in diagnostics:
            if d["severity"] in ("error", "warning"):
                out.write(f"{d['severity']} {d['rule']} {d['path']}:{d['line']}: "
                          f"{d['message']}\n")
    return collections.Counter(d["severity"] for d in diagnostics)


def descriptions(repo: str) -> tuple[bool, bool, int]:
    """(a tree starts robot_state_publisher with a description, one such tree had it
    read, the distinct URDF joints of those trees)."""
    try:
        from launch_linter.workspace.environment import environment_places

        options = LintOptions(environment=environment_places(os.environ))
    except ImportError:  # a checkout from before issue 27 (measured with PYTHONPATH)
        options = LintOptions()
    result = lint_paths([repo], options)
    starting = [t for t in result.trees
                if t.descriptions and any(n.package == RSP for n in t.nodes)]
    joints = {(j.path, j.line, j.name, j.parent, j.child) for t in starting for j in t.joints}
    return bool(starting), any(
        t.joints or not any(p.message.startswith("robot description") for p in t.problems)
        for t in starting), len(joints)


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("out_dir")
    parser.add_argument("repos", nargs="+")
    ns = parser.parse_args()
    os.makedirs(ns.out_dir, exist_ok=True)
    print("repo\terrors\twarnings\tinfos\tstarts_rsp\tdescription_read\tjoints")
    for repo in ns.repos:
        found = counts(repo, ns.out_dir)
        starts, read, joints = descriptions(repo)
        print(f"{os.path.basename(os.path.normpath(repo))}\t{found['error']}\t"
              f"{found['warning']}\t{found['info']}\t{starts}\t{read}\t{joints}", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
