"""``ament_launch_linter [PATH ...] [--xunit-file FILE]``: Launch-Linter for ament.

It runs the ``launch-linter`` command (``LAUNCH_LINTER`` names another, with arguments, e.g.
``python3 -m launch_linter``), so the linter may live in any Python environment (pip, pipx, a
virtual environment) while colcon and CMake use the system's Python. It lints the given
folders (default: the current one, the package's source folder under ``colcon test``):
every launch file, and the URDF and xacro files they load. The findings are printed; with
``--xunit-file`` they are also written as JUnit XML (one test case per file, a failure per
finding at or above ``--fail-on``). The exit status is the linter's: 0 clean, 1 findings.
"""

from __future__ import annotations

import argparse
import os
import shlex
import shutil
import subprocess
import sys


def linter_command() -> list[str] | None:
    named = os.environ.get("LAUNCH_LINTER")
    if named:
        return shlex.split(named)
    found = shutil.which("launch-linter")
    return [found] if found else None


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(
        description="Check the static transforms of launch files, URDF and xacro.")
    parser.add_argument("paths", nargs="*", default=[os.curdir],
                        help="files or folders to check (default: the current folder)")
    parser.add_argument("--xunit-file", help="also write the results as JUnit XML")
    parser.add_argument("--fail-on", choices=("error", "warning", "info"), default="warning",
                        help="lowest severity that fails the test (default: warning)")
    parser.add_argument("--config", help="a Launch-Linter configuration file")
    args = parser.parse_args(sys.argv[1:] if argv is None else argv)

    command = linter_command()
    if command is None:
        print("ament_launch_linter: the 'launch-linter' command is not on PATH: install it "
              "(python3 -m pip install launch-linter, or from its repository) or name it "
              "with LAUNCH_LINTER", file=sys.stderr)
        return 1
    check = [*command, "check", *args.paths, "--fail-on", args.fail_on]
    if args.config:
        check += ["--config", args.config]
    if args.xunit_file:
        folder = os.path.dirname(os.path.abspath(args.xunit_file))
        os.makedirs(folder, exist_ok=True)
        written = subprocess.run([*check, "--format", "junit", "-o", args.xunit_file],
                                 check=False)
        if written.returncode not in (0, 1):
            return written.returncode
    return subprocess.run(check, check=False).returncode


if __name__ == "__main__":
    sys.exit(main())
