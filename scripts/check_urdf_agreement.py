"""How often the linter's URDF structure verdict agrees with urdfdom's ``check_urdf`` on
real robot descriptions, and what xacro refuses on both sides.

Usage: ``python scripts/check_urdf_agreement.py DIR [DIR ...]`` where each DIR is a
checked-out repository. Every ``*.urdf``/``*.xacro`` file whose root is ``<robot>`` and
that defines a link is read both ways, with default args and the packages found in all
DIRs: the real xacro (a development-only oracle, ``scripts/xacro_oracle_driver.py``)
expands it and ``check_urdf`` (Debian ``liburdfdom-tools``) judges the result; the linter
lints the file on its own with the structure rules and ``xacro_error``. A file the real
xacro refuses is compared on that (the linter should report ``xacro_error`` or leave the
file unproven); the others on accept/refuse and the root link. Prints one line per
disagreement and a summary.
"""

from __future__ import annotations

import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
from collections import Counter
from pathlib import Path

from launch_linter import LintOptions, lint_paths
from launch_linter.frontends.robot.describe import RobotCache
from launch_linter.frontends.robot.standalone import load_description
from launch_linter.workspace.packages import PackageIndex

DRIVER = Path(__file__).resolve().parent / "xacro_oracle_driver.py"
STRUCTURE = frozenset({"urdf_root", "urdf_duplicate_name", "urdf_missing_link"})
_ROOT_LINK = re.compile(r"root Link: (\S+)")
_NAME = re.compile(r"<name>([^<]+)</name>")


def urdfdom(text: str, check_urdf: str) -> tuple[bool, str | None, str]:
    with tempfile.NamedTemporaryFile("w", suffix=".urdf", delete=False) as out:
        out.write(text)
    try:
        done = subprocess.run([check_urdf, out.name], capture_output=True, timeout=20)
        raw = done.stdout + done.stderr
    except subprocess.TimeoutExpired as stopped:
        raw = (stopped.stdout or b"") + (stopped.stderr or b"")
    finally:
        os.unlink(out.name)
    said = raw[:4096].decode("utf-8", "replace")
    accepted = "Successfully Parsed XML" in said
    root = _ROOT_LINK.search(said)
    error = next((line for line in said.splitlines() if line.startswith("Error")), "")
    return accepted, root.group(1) if root else None, error


def _package_folders(dirs: list[str]) -> dict[str, str]:
    """Package name -> folder, from every ``package.xml`` under ``dirs`` (for the oracle)."""
    out: dict[str, str] = {}
    for directory in dirs:
        for manifest in sorted(Path(directory).rglob("package.xml")):
            name = _NAME.search(manifest.read_text(encoding="utf-8", errors="replace"))
            if name:
                out.setdefault(name.group(1).strip(), str(manifest.parent.resolve()))
    return out


def main() -> int:
    check_urdf = shutil.which("check_urdf")
    if check_urdf is None:
        print("check_urdf not found (Debian: apt-get install liburdfdom-tools)")
        return 2
    dirs = sys.argv[1:]
    packages = PackageIndex(dirs)
    package_json = json.dumps(_package_folders(dirs))
    counts: Counter[str] = Counter()
    for directory in dirs:
        for path in sorted(Path(directory).rglob("*")):
            if not path.name.lower().endswith((".urdf", ".xacro")) or not path.is_file():
                continue
            tree = load_description(str(path), {}, packages, RobotCache(), str, {})
            if not tree.robots or not tree.robots[0].links:
                counts["not a whole robot (a part, macros only, or not read)"] += 1
                continue
            robot = tree.robots[0]
            refusal = ""
            if path.name.lower().endswith(".urdf"):
                text = path.read_text(encoding="utf-8", errors="replace")
            else:
                done = subprocess.run([sys.executable, str(DRIVER), str(path), package_json,
                                       "--urdf"], capture_output=True, text=True, timeout=120)
                text, refusal = done.stdout, done.stderr
            options = LintOptions(package_paths=tuple(dirs),
                                  select=STRUCTURE | {"xacro_error"})
            diagnostics = lint_paths([str(path)], options).diagnostics
            ours_xacro = any(d.rule == "xacro_error" for d in diagnostics)
            if not text.strip() and "No such file or directory" in refusal:
                # The oracle reads packages as source folders; the linter, like colcon,
                # also maps what CMakeLists installs elsewhere (issue 27).
                counts["xacro refuses in the source tree (a file installed elsewhere): "
                       "not compared"] += 1
                continue
            if not text.strip():
                key = ("xacro refuses: linter reports xacro_error" if ours_xacro else
                       "xacro refuses: linter leaves it unproven" if not robot.complete else
                       "xacro refuses: linter does not see it")
                counts[key] += 1
                if key.endswith("not see it"):
                    print(f"{path}: the real xacro refuses it; the linter reads it whole")
                continue
            accepted, root, error = urdfdom(text, check_urdf)
            refused = any(d.rule in STRUCTURE for d in diagnostics)
            children = {joint.child for joint in robot.joints}
            roots = [link.name for link in robot.links if link.name not in children]
            ours_root = roots[0] if roots and not refused else None
            if not robot.complete:
                counts["expansion not followed whole (unknown values): not compared"] += 1
            elif accepted == (not refused) and (not accepted or root == ours_root):
                counts["agree"] += 1
            else:
                counts["disagree"] += 1
                print(f"{path}: check_urdf {'accepts' if accepted else 'refuses'} "
                      f"(root {root}) {error}; linter {'refuses' if refused else 'accepts'}"
                      f" (root {ours_root})")
    for key, count in sorted(counts.items()):
        print(f"{count:5d}  {key}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
