"""Which nodes the knowledge base does not know open the corpus's tf trees most often.

Lints the latest version of every corpus file (manifest rows with ``latest: true``), each
file as its own root, and for each tree asks the tree rules' node view which launched
nodes the knowledge base does not know (each makes the tree *open*: it may publish tf).
Prints the share of trees with nodes that are closed, and the unknown programs ranked by
the number of trees they open (ROS 1 ``pkg/type``, ROS 2 ``package/executable``, a
composable node's plugin, a Gazebo plugin's file name), with how many trees each one
alone keeps open (the tree would close if it were known).

Usage: python scripts/open_tree_nodes.py [--corpus DIR] [--top N] [--every K]
                                        [--repos DIR ...]
``--every K`` lints every K-th latest file (a sample, for a loaded machine). ``--repos``
lints each directory whole instead (a fetched repository, as ``launch-linter check DIR``
does), its packages found in it. Closed trees are also counted per ROS version.
"""

from __future__ import annotations

import argparse
import json
import sys
from collections import Counter
from pathlib import Path

from launch_linter import LintOptions, lint_paths
from launch_linter.knowledge import bundled
from launch_linter.model.robot import NodeRecord
from launch_linter.rules._nodes import program_of, view_of

DEFAULT_CORPUS = Path(__file__).resolve().parent.parent.parent / "shared" / "corpus"


def latest_files(corpus: Path) -> list[Path]:
    files: list[Path] = []
    with open(corpus / "manifest.jsonl", encoding="utf-8") as handle:
        for line in handle:
            row = json.loads(line)
            if row.get("latest"):
                files.append(corpus / row["file"])
    return files


def program(node: NodeRecord) -> str:
    """The program as the knowledge base matches it, with its ROS version and kind."""
    kind = "" if node.kind == "node" else f" [{node.kind}]"
    return f"ROS {node.ros or '?'} {program_of(node)}{kind}"


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--corpus", type=Path, default=DEFAULT_CORPUS)
    parser.add_argument("--top", type=int, default=60)
    parser.add_argument("--every", type=int, default=1)
    parser.add_argument("--repos", type=Path, nargs="+", default=None)
    ns = parser.parse_args(argv)
    if ns.repos:
        runs = [([str(repo)], LintOptions()) for repo in ns.repos]
        where = f"repositories: {len(ns.repos)}, each linted whole"
    else:
        corpus_options = LintOptions(package_paths=())
        runs = [([str(file)], corpus_options)
                for file in latest_files(ns.corpus)[::max(1, ns.every)]]
        where = f"corpus: {ns.corpus}  every {ns.every}th latest file"
    base = bundled()
    opens: Counter[str] = Counter()
    alone: Counter[str] = Counter()
    per_ros: Counter[str] = Counter()
    trees = with_nodes = closed = 0
    for paths, options in runs:
        result = lint_paths(paths, options)
        for tree in result.trees:
            trees += 1
            if not tree.nodes:
                continue
            with_nodes += 1
            ros = f"ROS {tree.nodes[0].ros or '?'}"
            per_ros[ros + " with nodes"] += 1
            view = view_of(tree, base)
            if view.open_because is None:
                closed += 1
                per_ros[ros + " closed"] += 1
                continue
            unknown = {program(n) for n in view.unknown}
            opens.update(unknown)
            if len(unknown) == 1 and not view.unsure:
                alone.update(unknown)
    share = 100.0 * closed / with_nodes if with_nodes else 0.0
    print(where)
    print(f"trees: {trees}; with nodes: {with_nodes}; closed: {closed} ({share:.1f}%)")
    print("; ".join(f"{key}: {count}" for key, count in sorted(per_ros.items())))
    print(f"{'trees opened':>12} {'alone':>6}  program")
    for name, count in opens.most_common(ns.top):
        print(f"{count:>12} {alone[name]:>6}  {name}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
