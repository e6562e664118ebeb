"""How often our xacro expansion agrees with the real xacro on real robot descriptions.

Usage: ``python scripts/xacro_agreement.py DIR [DIR ...] [name:=value ...]`` where each DIR
is a checked-out repository or a bare git directory (its HEAD's text files are copied to a temporary
folder first). Every ``*.xacro``/``*.urdf`` file whose root is ``<robot>`` is expanded by
both, with default args and the packages found in all DIRs; the joints (name, type,
parent, child, origin within 1e-6) are compared; ``name:=value`` words are given to both
as xacro args (``ur_type:=ur5e``). Prints one line per file and a summary.
The real xacro is a development-only oracle (``scripts/xacro_oracle_driver.py``).
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
import tempfile
from pathlib import Path
from typing import Optional, Tuple

from launch_linter.frontends.robot.urdf import joints_of
from launch_linter.frontends.robot.xacro import expand
from launch_linter.model.robot import DescriptionKind, DescriptionSource
from launch_linter.model.transform import Condition
from launch_linter.workspace.packages import PackageIndex

DRIVER = Path(__file__).resolve().parent / "xacro_oracle_driver.py"
TEXT_SUFFIXES = (".xacro", ".urdf", "package.xml", ".yaml", ".launch")
Joint = Tuple[str, str, Optional[str], Optional[str], Tuple[float, ...], Tuple[float, ...]]


def export_git(git_dir: str, out: str) -> None:
    """Copy the text files the descriptions need from a bare repository's HEAD."""
    names = subprocess.run(["git", "--git-dir", git_dir, "ls-tree", "-r", "--name-only",
                            "HEAD"], capture_output=True, text=True, check=True).stdout
    for name in names.splitlines():
        if not name.endswith(TEXT_SUFFIXES):
            continue
        blob = subprocess.run(["git", "--git-dir", git_dir, "show", f"HEAD:{name}"],
                              capture_output=True, check=False)
        if blob.returncode != 0:
            continue
        target = Path(out) / name
        target.parent.mkdir(parents=True, exist_ok=True)
        target.write_bytes(blob.stdout)


def _numbers(text: str) -> tuple[float, ...]:
    try:
        return tuple(float(w) for w in text.split())
    except ValueError:
        return ()


def oracle(path: str, packages: dict[str, str], args: list[str]) -> list[Joint] | None:
    done = subprocess.run([sys.executable, str(DRIVER), path, json.dumps(packages), *args],
                          capture_output=True, text=True, check=False, timeout=120)
    try:
        answer = json.loads(done.stdout)
    except json.JSONDecodeError:
        return None
    if "error" in answer:
        return None
    return [(j["name"], j["type"], j["parent"], j["child"], _numbers(j["xyz"]),
             _numbers(j["rpy"])) for j in answer["joints"]]


def ours(path: str, index: PackageIndex, args: list[str]) -> tuple[list[Joint], int]:
    expansion = expand(path, dict(a.split(":=", 1) for a in args), index.find)
    if expansion.root is None:
        return [], len(expansion.problems)
    source = DescriptionSource(path, 1, 1, DescriptionKind.XACRO, path)
    joints = joints_of(expansion.root, source, lambda p: p, Condition())
    return ([(j.name, j.joint_type, j.parent, j.child, j.translation or (), j.rpy or ())
             for j in joints], len(expansion.problems))


def same(expected: list[Joint], got: list[Joint]) -> int | None:
    """None when the joints differ; else how many of ours have an unknown value (an
    unknown value agrees with anything: the linter says it does not know)."""
    if len(expected) != len(got):
        return None
    unknown = 0
    for x, y in zip(expected, got):
        frames_differ = any(b is not None and a != b
                            for a, b in zip(x[2:4], y[2:4]))
        if x[:2] != y[:2] or frames_differ:
            return None
        if None in y[2:4] or not y[4] or not y[5]:
            unknown += 1
        for ours, theirs in ((y[4], x[4]), (y[5], x[5])):
            if ours and (len(ours) != len(theirs)
                         or any(abs(p - q) > 1e-6 for p, q in zip(ours, theirs))):
                return None
    return unknown


def is_robot(path: Path) -> bool:
    try:
        head = path.read_bytes()[:4096]
    except OSError:
        return False
    return b"<robot" in head


def main(argv: list[str]) -> int:
    args = [a for a in argv if ":=" in a]
    argv = [a for a in argv if ":=" not in a]
    with tempfile.TemporaryDirectory() as scratch:
        roots = []
        for i, given in enumerate(argv):
            if os.path.isdir(os.path.join(given, "objects")):
                folder = os.path.join(scratch, str(i))
                export_git(given, folder)
                roots.append(folder)
            else:
                roots.append(given)
        index = PackageIndex(roots)
        index.find("")
        packages = dict(index._packages or {})
        counts = {"agree": 0, "agree_where_known": 0, "differ": 0, "oracle_refuses": 0}
        for root in roots:
            for path in sorted(Path(root).rglob("*")):
                if path.suffix not in (".xacro", ".urdf") or not is_robot(path):
                    continue
                expected = oracle(str(path), packages, args)
                got, problems = ours(str(path), index, args)
                shown = os.path.relpath(path, scratch) if str(path).startswith(scratch) else path
                if expected is None:
                    counts["oracle_refuses"] += 1
                    print(f"oracle refuses  {shown} (ours: {len(got)} joints, "
                          f"{problems} problems)")
                elif same(expected, got) == 0:
                    counts["agree"] += 1
                    print(f"agree           {shown} ({len(got)} joints)")
                elif same(expected, got) is not None:
                    counts["agree_where_known"] += 1
                    print(f"agree if known  {shown} ({len(got)} joints, "
                          f"{same(expected, got)} with unknown values)")
                else:
                    counts["differ"] += 1
                    print(f"DIFFER          {shown} (xacro {len(expected)} joints, "
                          f"ours {len(got)}, {problems} problems)")
        print(json.dumps(counts))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
