#!/usr/bin/env python3
"""Summarise a beliefs file: strongest beliefs, counts per threshold, overlap with the study.

    python scripts/belief_report.py [--beliefs bundled|study|FILE] [--top 15]
                                    [--thresholds 1,2,5,10] [--compare study|FILE] [--p0 P]

For each class: the ``--top`` strongest beliefs; how many pass each z threshold; how many
of the beliefs at z >= 1 are also among the compared beliefs at z >= 1 (by default the
study's artifact); and how many of the compared beliefs are stored at all (any z).
``--p0`` rescores every belief from its n and e with another p0 (the artifact used 0.85).
"""

from __future__ import annotations

import argparse
import sys

from launch_linter.beliefs_files import load_beliefs
from launch_linter.mining.stats import z_score
from launch_linter.model.beliefs import BELIEF_CLASSES
from launch_linter.model.diagnostic import Belief
from launch_linter.model.record import replace


def key(belief: Belief) -> tuple[object, object]:
    return (belief.antecedent, belief.consequent)


def show(belief: Belief) -> str:
    def text(k: object) -> str:
        return f"({' -> '.join(k)})" if isinstance(k, tuple) else repr(k)

    then = f" => {text(belief.consequent)}" if belief.consequent is not None else ""
    return f"z={belief.z:6.2f} n={belief.n:3d} e={belief.e:3d}  {text(belief.antecedent)}{then}"


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--beliefs", default="bundled")
    parser.add_argument("--compare", default="study")
    parser.add_argument("--top", type=int, default=15)
    parser.add_argument("--thresholds", default="1,2,5,10")
    parser.add_argument("--p0", type=float, help="rescore from n and e with this p0")
    ns = parser.parse_args()
    every = load_beliefs(ns.beliefs, float("-inf"))
    p0 = every.p0
    if ns.p0 is not None:
        p0 = ns.p0
        every = replace(every, beliefs=tuple(
            replace(b, z=z_score(b.n, b.e, p0)) for b in every.beliefs if b.n
        ))
    other = load_beliefs(ns.compare, 1.0)
    thresholds = [float(t) for t in ns.thresholds.split(",")]
    print(f"beliefs: {ns.beliefs} (p0 = {p0}); compared with {ns.compare} at z >= 1")
    header = "class".ljust(18) + "".join(f"z>={t:g}".rjust(8) for t in thresholds)
    print(header + "    all  ours>=1 in theirs  theirs stored in ours")
    for cls in BELIEF_CLASSES:
        ours = every.of_class(cls)
        passing = [sum(1 for b in ours if b.z >= t) for t in thresholds]
        mine = {key(b) for b in ours if b.z >= 1.0}
        stored = {key(b) for b in ours}
        theirs = {key(b) for b in other.of_class(cls)}
        print(cls.ljust(18) + "".join(f"{c:8d}" for c in passing)
              + f"{len(ours):7d}  {len(mine & theirs):4d} of {len(mine):<4d}"
              + f"       {len(theirs & stored):4d} of {len(theirs)}")
    for cls in BELIEF_CLASSES if ns.top > 0 else ():
        print(f"\n{cls}: top {ns.top}")
        for belief in sorted(every.of_class(cls), key=lambda b: (-b.z, -b.n))[: ns.top]:
            print("  " + show(belief))
    return 0


if __name__ == "__main__":
    sys.exit(main())
