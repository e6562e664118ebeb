"""Which tf trees bring up the whole robot, as frame_without_publisher judges it.

Lints launch files or folders (or the corpus's latest files, each its own root) and sorts
every tree whose nodes look up frames by what frame_without_publisher would decide about
a frame none of its publishers gives: the tree is *open* (a node the knowledge base does
not know), or it is closed but not the whole robot (no robot_state_publisher, a
description not read completely, no odometry source), or it is the whole robot for a
robot frame, and also for a global frame when it localizes. A tree's lookups with no
frame missing are counted too: the criterion decides the level, the missing frame the
finding.

Usage: python scripts/whole_robot_trees.py [PATH ...] [--corpus DIR] [--every K]
                                            [--ros-distro NAME] [--show]
``--show`` prints each tree that brings up the whole robot, with its missing frames.
"""

from __future__ import annotations

import argparse
import json
import sys
from collections import Counter
from pathlib import Path

from launch_linter import LintOptions, lint_paths
from launch_linter.knowledge import bundled
from launch_linter.rules import RuleContext
from launch_linter.rules._nodes import NodeView, nodes_of
from launch_linter.rules._tree import edges_of
from launch_linter.rules._whole_robot import whole_robot

DEFAULT_CORPUS = Path(__file__).resolve().parent.parent.parent / "shared" / "corpus"


def latest_files(corpus: Path) -> list[str]:
    files: list[str] = []
    with open(corpus / "manifest.jsonl", encoding="utf-8") as handle:
        for line in handle:
            row = json.loads(line)
            if row.get("latest"):
                files.append(str(corpus / row["file"]))
    return files


def sort(context: RuleContext, view: NodeView) -> str:
    """A closed tree's status, for its first node that looks a frame up."""
    node = view.lookups[0].node
    why, _ = whole_robot(context, node, False)
    if why is not None:
        return why
    localized = whole_robot(context, node, True)[0] is None
    return "whole robot, localized" if localized else "whole robot, not localized"


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("paths", nargs="*")
    parser.add_argument("--corpus", type=Path, default=None)
    parser.add_argument("--every", type=int, default=1)
    parser.add_argument("--ros-distro", default=None)
    parser.add_argument("--show", action="store_true")
    ns = parser.parse_args(argv)
    paths = list(ns.paths)
    if ns.corpus is not None or not paths:
        paths += latest_files(ns.corpus or DEFAULT_CORPUS)[::max(1, ns.every)]
    options = LintOptions(package_paths=None if ns.paths else (), ros_distro=ns.ros_distro,
                          select=frozenset({"frame_without_publisher"}))
    base = bundled()
    status: Counter[str] = Counter()
    missing_by_status: Counter[str] = Counter()
    for path in paths:
        for tree in lint_paths([path], options).trees:
            context = RuleContext(tree, knowledge=base, distro=ns.ros_distro)
            view = nodes_of(context)
            if not view.lookups:
                continue
            frames = {f for e in edges_of(context) for f in (e.parent, e.child)}
            frames.update(f for e in view.edges for f in (e.parent, e.child))
            missing = sorted({lk.frame for lk in view.lookups
                              if lk.frame.lstrip("/") not in frames})
            why = "open" if view.open_because is not None else sort(context, view)
            status[why] += 1
            missing_by_status[why] += bool(missing)
            if ns.show and why.startswith("whole"):
                print(f"{tree.root}: {why}; missing {missing}")
    print(f"trees with lookups: {sum(status.values())}")
    print(f"{'trees':>6} {'missing':>8}  status")
    for why, count in status.most_common():
        print(f"{count:>6} {missing_by_status[why]:>8}  {why}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
