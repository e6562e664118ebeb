#!/usr/bin/env python3
"""Whether every ``check --diff`` over the corpus is a patch that ``git apply --check`` and
``patch -p1 --dry-run`` accept, and applies to what ``--fix`` writes.

    nice python scripts/diff_applies.py [--limit N] [--distro humble] [CORPUS_FILES]

Copies the corpus files (default ``../shared/corpus/files``; the first N with
``--limit``) into a temporary folder, each twice: as it is, and without its final
newline (where a patch must say ``\\ No newline at end of file``). Runs this checkout's
``launch-linter check --diff --unsafe-fixes`` there (every fix, safe or not; the target
distribution decides which fixes exist), then checks the patch with both programs,
applies it once with ``git apply`` to one copy (``--diff`` shows the result of all of
``--fix``'s passes, so a ``--diff`` of the result must be empty) and runs ``--fix
--unsafe-fixes`` on another, and compares them: both must give the same bytes. Prints
the counts; exits 1 when any check fails.
"""

from __future__ import annotations

import argparse
import os
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
DEFAULT_FILES = REPO.parent / "shared" / "corpus" / "files"


def _linter(folder: Path, *argv: str) -> subprocess.CompletedProcess[bytes]:
    env = dict(os.environ, PYTHONPATH=str(REPO / "src"))
    return subprocess.run([sys.executable, "-m", "launch_linter", "check", ".", *argv],
                          cwd=folder, env=env, capture_output=True, check=False)


def _copy(files: list[Path], folder: Path) -> None:
    for index, source in enumerate(files):
        data = source.read_bytes()
        (folder / f"{index:05d}").mkdir()
        (folder / f"{index:05d}" / source.name).write_bytes(data)
        (folder / f"{index:05d}" / ("nonl-" + source.name)).write_bytes(data.rstrip(b"\r\n"))


def _run(tool: list[str], folder: Path, patch: bytes) -> str | None:
    done = subprocess.run(tool, cwd=folder, input=patch, capture_output=True, check=False)
    return None if done.returncode == 0 else (done.stdout + done.stderr).decode()[:2000]


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("files", nargs="?", type=Path, default=DEFAULT_FILES)
    parser.add_argument("--limit", type=int, default=None)
    parser.add_argument("--distro", default="humble", help="--ros-distro for the run")
    ns = parser.parse_args()
    files = sorted(p for p in ns.files.iterdir() if p.is_file())[: ns.limit]
    failures = 0
    with tempfile.TemporaryDirectory() as temporary:
        patched, fixed = Path(temporary) / "patched", Path(temporary) / "fixed"
        patched.mkdir()
        _copy(files, patched)
        shutil.copytree(patched, fixed)
        options = ("--unsafe-fixes", "--ros-distro", ns.distro, "--exit-zero", "--no-cache")
        done = _linter(patched, "--diff", *options)
        patch = done.stdout
        headers = patch.count(b"\n+++ ") + patch.startswith(b"+++ ")
        print(f"{len(files)} corpus files, {2 * len(files)} copies; the diff: {len(patch)} "
              f"bytes, {headers} file(s), {patch.count(NO_NEWLINE)} no-newline marker(s); "
              f"{done.stderr.decode().strip().splitlines()[-1:]}")
        for name, tool in (("git apply --check", ["git", "apply", "--check", "-"]),
                           ("patch -p1 --dry-run",
                            ["patch", "-p1", "--dry-run", "--batch", "--silent"])):
            error = _run(tool, patched, patch)
            print(f"{name}: {'ok' if error is None else 'FAILED'}")
            if error is not None:
                failures += 1
                print(error)
        # --diff runs --fix's passes: one application gives --fix's bytes, and leaves
        # nothing for another --diff.
        error = _run(["git", "apply", "-"], patched, patch)
        if error is not None:
            failures += 1
            print(f"git apply: FAILED\n{error}")
        again = _linter(patched, "--diff", *options).stdout
        left = again.count(b"\n+++ ") + again.startswith(b"+++ ")
        print(f"files with a fix left after applying the diff once: {left}")
        failures += bool(left)
        _linter(fixed, "--fix", *options)
        differing = [str(p.relative_to(fixed)) for p in sorted(fixed.rglob("*")) if p.is_file()
                     and p.read_bytes() != (patched / p.relative_to(fixed)).read_bytes()]
        print(f"files where --fix and the applied --diff differ: {len(differing)}")
        for name in differing[:20]:
            print(f"  {name}")
        failures += bool(differing)
    return 1 if failures else 0


NO_NEWLINE = b"\n\\ No newline at end of file\n"

if __name__ == "__main__":
    sys.exit(main())
