"""Macros that read their own parameters as ``$(arg)`` (``xacro_param_as_arg``) in every
version of every ``.xacro``/``.urdf`` file of git repositories' histories.

Usage: ``python scripts/param_as_arg_history.py GIT_DIR [GIT_DIR ...]`` where each GIT_DIR
is a (bare) git directory. Every distinct file version reachable from any ref is scanned
once (``git rev-list --objects --all --missing=allow-any``, read through
``git cat-file --batch``); one line per use: repository folder, path, blob, line, macro,
parameter. Grouped by (repository,
macro, parameter), the lines give the defects to follow through ``git log`` to the commit
that introduced and the one that removed each (docs/evaluation/xacro_param_as_arg.md).
"""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

from launch_linter.frontends.robot.xacro_macros import params_read_as_args

SUFFIXES = (".xacro", ".urdf")


def description_blobs(git_dir: str) -> dict[str, str]:
    """Blob id -> the first path it was seen at, for every description file version."""
    # A snapshot may lack its largest blobs (meshes): listed all the same, read if present.
    listed = subprocess.run(["git", "--git-dir", git_dir, "rev-list", "--objects", "--all",
                             "--missing=allow-any"], capture_output=True, text=True)
    if listed.returncode != 0:
        print(f"{git_dir}: {listed.stderr.strip()[:200]}", file=sys.stderr)
    listing = listed.stdout
    blobs: dict[str, str] = {}
    for line in listing.splitlines():
        blob, _, path = line.partition(" ")
        if path.endswith(SUFFIXES):
            blobs.setdefault(blob, path)
    return blobs


def contents(git_dir: str, blobs: list[str]) -> dict[str, bytes]:
    """The bytes of each blob, read in one ``git cat-file --batch``."""
    if not blobs:
        return {}
    out = subprocess.run(["git", "--git-dir", git_dir, "cat-file", "--batch"],
                         input="".join(b + "\n" for b in blobs).encode(),
                         capture_output=True).stdout
    found: dict[str, bytes] = {}
    position = 0
    while position < len(out):
        end = out.index(b"\n", position)
        header = out[position:end].split()
        if len(header) != 3:  # "<id> missing": a blob the snapshot does not hold
            position = end + 1
            continue
        size = int(header[2])
        found[header[0].decode()] = out[end + 1:end + 1 + size]
        position = end + 1 + size + 1
    return found


def main(git_dirs: list[str]) -> int:
    for git_dir in git_dirs:
        blobs = description_blobs(git_dir)
        name = Path(git_dir).resolve().parent.name
        for blob, data in contents(git_dir, list(blobs)).items():
            for uses in params_read_as_args(data, False).values():
                for use in uses:
                    print(name, blobs[blob], blob[:10], use.line, use.macro, use.name)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
