#!/usr/bin/env python3
"""Whether ``check`` and ``transforms`` print byte-identical JSON and text to a saved baseline.

    python scripts/output_identity.py --save   [--baseline DIR] [PATH ...]
    python scripts/output_identity.py [--jobs 1,2] [--baseline DIR] [PATH ...]

Runs this checkout's ``launch-linter check`` and ``launch-linter transforms``, each with
``--format json`` and ``--format text`` (``PYTHONPATH`` set to its ``src``) over each PATH
(default: the corpus files, ``../shared/corpus/files``, and the examples), from the repository
root so that every path in the output is the same in every run. ``--save`` stores the outputs in DIR
(default ``build/output-baseline``, which git ignores): run it on the code *before* a
change. Without ``--save`` it runs the same commands, once per ``--jobs`` count, and
compares each output byte for byte with the baseline; it prints the first differing
line of each mismatch and exits 1 if any output differs.

Speed work must not change what the linter says; this is how that is proved.
"""

from __future__ import annotations

import argparse
import hashlib
import os
import subprocess
import sys
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
DEFAULT_PATHS = ("../shared/corpus/files", "examples")
COMMANDS = ("check", "transforms")
FORMATS = ("json", "text")


def run(command: str, form: str, paths: list[str], jobs: int | None) -> bytes:
    env = dict(os.environ, PYTHONPATH=str(REPO / "src"))
    env.pop("NO_COLOR", None)
    argv = [sys.executable, "-m", "launch_linter", command, "--format", form, *paths]
    if jobs is not None:
        argv += ["--jobs", str(jobs)]
    done = subprocess.run(argv, cwd=REPO, env=env, capture_output=True, check=False)
    if done.returncode not in (0, 1):
        sys.stderr.write(done.stderr.decode("utf-8", "replace"))
        raise SystemExit(f"{command} exited {done.returncode}")
    return done.stdout


def first_difference(old: bytes, new: bytes) -> str:
    for number, (a, b) in enumerate(zip(old.splitlines(), new.splitlines()), 1):
        if a != b:
            return f"line {number}:\n  - {a[:300]!r}\n  + {b[:300]!r}"
    return f"lengths differ: {len(old.splitlines())} lines before, {len(new.splitlines())} now"


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[1])
    parser.add_argument("paths", nargs="*", default=list(DEFAULT_PATHS))
    parser.add_argument("--save", action="store_true", help="store the baseline")
    parser.add_argument("--baseline", default=str(REPO / "build" / "output-baseline"))
    parser.add_argument("--jobs", default="1", help="comma-separated job counts to compare")
    ns = parser.parse_args()
    base = Path(ns.baseline)
    if ns.save:
        base.mkdir(parents=True, exist_ok=True)
        for command in COMMANDS:
            for form in FORMATS:
                out = run(command, form, ns.paths, None)
                (base / f"{command}.{form}").write_bytes(out)
                digest = hashlib.sha256(out).hexdigest()[:16]
                print(f"saved {command} {form}: {len(out)} bytes, sha256 {digest}")
        (base / "paths.txt").write_text("\n".join(ns.paths) + "\n", encoding="utf-8")
        return 0
    saved_paths = (base / "paths.txt").read_text(encoding="utf-8").split()
    if saved_paths != ns.paths:
        print(f"the baseline was saved for {saved_paths}, not {ns.paths}", file=sys.stderr)
        return 2
    same = True
    for command in COMMANDS:
        for form in FORMATS:
            old = (base / f"{command}.{form}").read_bytes()
            for jobs in (int(j) for j in ns.jobs.split(",")):
                new = run(command, form, ns.paths, jobs)
                label = f"{command} --format {form} --jobs {jobs}"
                if new == old:
                    print(f"{label}: identical ({len(new)} bytes)")
                else:
                    same = False
                    print(f"{label}: DIFFERENT, {first_difference(old, new)}")
    return 0 if same else 1


if __name__ == "__main__":
    sys.exit(main())
