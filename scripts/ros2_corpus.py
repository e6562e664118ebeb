"""How the ROS 2 front-ends see the corpus: which files are ROS 2, and what is in them.

Usage: python scripts/ros2_corpus.py [CORPUS]   (default: ../shared/corpus)

Every file of ``CORPUS/files`` goes through the front-end dispatcher. For the files it
reads as ROS 2 launch files (ROS 2 launch XML also uses the ``.launch`` suffix), the
script prints how many there are, their transforms, which of the ROS 2 argument
mistakes they hold, and the front-end's own diagnostics. It also times the dispatch and
the ROS 2 loading. No package roots are given, so ``$(find-pkg-share)`` stays unresolved.
"""

from __future__ import annotations

import sys
import time
from collections import Counter
from pathlib import Path

from launch_linter.frontends.dispatch import front_end, load_tree
from launch_linter.frontends.ros1 import LoadOptions
from launch_linter.workspace.packages import PackageIndex

ROOT = Path(__file__).resolve().parent.parent


def main(argv: list[str]) -> int:
    corpus = Path(argv[1]) if len(argv) > 1 else ROOT.parent / "shared" / "corpus"
    files = sorted((corpus / "files").glob("*"))
    if not files:
        print(f"no files under {corpus / 'files'}", file=sys.stderr)
        return 2
    options = LoadOptions(packages=PackageIndex([]))
    counts: Counter[str] = Counter()
    issues: Counter[str] = Counter()
    diagnostics: Counter[str] = Counter()
    start = time.perf_counter()
    for path in files:
        data = path.read_bytes()
        if front_end(str(path), data) != "ros2":
            counts["ros1 files"] += 1
            continue
        tree = load_tree(str(path), options, data)
        counts["ros2 files"] += 1
        counts[f"ros2 files {tree.status.value}"] += 1
        for transform in tree.transforms:
            counts["ros2 transforms"] += 1
            counts["ros2 transforms unresolved"] += bool(transform.unresolved)
            issues.update(issue.kind for issue in transform.arg_issues)
            issues["arity_issue"] += transform.arity_issue is not None
            issues["number_issues"] += bool(transform.number_issues)
        diagnostics.update(d.rule for d in tree.problems)
    elapsed = time.perf_counter() - start
    print(f"corpus: {corpus} ({len(files)} files)")
    for key in sorted(counts):
        print(f"  {key}: {counts[key]}")
    print("  argument mistakes in ROS 2 transforms: "
          + (", ".join(f"{k} {v}" for k, v in sorted(issues.items()) if v) or "none"))
    print("  front-end diagnostics in ROS 2 files: "
          + (", ".join(f"{k} {v}" for k, v in sorted(diagnostics.items())) or "none"))
    print(f"  dispatch of every file + ROS 2 loading: {elapsed:.2f} s")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
