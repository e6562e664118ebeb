"""Runs the README's quick start, as written, on several Pythons, each in a fresh copy.

For each Python (default: every pyenv 3.8, 3.10, 3.12 and 3.13 found) it copies the
repository's files (tracked and new, as in the work tree) to a temporary folder, puts that
Python first on ``PATH`` as ``python3``, and runs the commands of the README's first
````sh`` block after ``git clone`` (the copy stands for the clone). Then, in the same
virtual environment, it lints the examples with a configuration file (``select`` of one rule)
and checks that only that rule's findings are printed: the TOML reader works on that Python.
``--dev`` also runs the README's development command (the whole suite; slow).

    python scripts/quick_start_trial.py [--dev] [PYTHON ...]
"""

from __future__ import annotations

import argparse
import glob
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
CONFIG_RULE = "rot_degrees"


def readme_blocks() -> list[str]:
    return re.findall(r"```sh\n(.*?)```", (ROOT / "README.md").read_text(), re.DOTALL)


def quick_start() -> str:
    lines = readme_blocks()[0].splitlines()
    assert lines[0].startswith("git clone"), lines[0]
    return "\n".join(lines[1:])


def dev_command() -> str:
    return readme_blocks()[1].strip()


def copy_repository(target: Path) -> None:
    listed = subprocess.run(
        ["git", "ls-files", "-z", "--cached", "--others", "--exclude-standard"],
        cwd=ROOT, check=True, capture_output=True, text=True,
    ).stdout.split("\0")
    for name in filter(None, listed):
        source = ROOT / name
        if source.is_file():
            (target / name).parent.mkdir(parents=True, exist_ok=True)
            shutil.copy2(source, target / name)


def run(script: str, cwd: Path, python: str) -> subprocess.CompletedProcess[str]:
    shim = cwd / ".shim"
    shim.mkdir(exist_ok=True)
    for name in ("python3", "python"):
        link = shim / name
        if not link.exists():
            link.symlink_to(python)
    env = {k: v for k, v in os.environ.items() if k not in ("VIRTUAL_ENV", "PYTHONPATH")}
    env["PATH"] = f"{shim}:{env['PATH']}"
    return subprocess.run(["bash", "-c", script], cwd=cwd, env=env,
                          capture_output=True, text=True, check=False)


def trial(python: str, dev: bool) -> list[str]:
    version = subprocess.run([python, "-c", "import platform; print(platform.python_version())"],
                             check=True, capture_output=True, text=True).stdout.strip()
    problems: list[str] = []
    with tempfile.TemporaryDirectory(prefix=f"quick-start-{version}-") as folder:
        clone = Path(folder)
        copy_repository(clone)
        start = time.monotonic()
        done = run(quick_start(), clone, python)
        took = time.monotonic() - start
        if done.returncode != 1 or "[multiple_parents]" not in done.stdout:
            problems.append(f"quick start: status {done.returncode}\n{done.stdout}{done.stderr}")
        (clone / "trial.toml").write_text(f'select = ["{CONFIG_RULE}"]\n')
        configured = run(
            ". .venv/bin/activate && launch-linter check --config trial.toml examples/",
            clone, python)
        found = [line for line in configured.stdout.splitlines() if line.startswith("examples/")]
        if configured.returncode != 1 or not found or not all(
                line.endswith(f"[{CONFIG_RULE}]") for line in found):
            problems.append(f"configuration: status {configured.returncode}\n"
                            f"{configured.stdout}{configured.stderr}")
        print(f"{version}: quick start {took:.0f} s, status {done.returncode}, "
              f"{len(done.stdout.splitlines())} lines; with the configuration file "
              f"{len(found)} {CONFIG_RULE} findings, status {configured.returncode}")
        if dev:
            start = time.monotonic()
            tested = run(f". .venv/bin/activate && {dev_command()}", clone, python)
            summary = (tested.stdout.strip().splitlines() or ["(no output)"])[-1]
            print(f"{version}: development command {time.monotonic() - start:.0f} s, "
                  f"status {tested.returncode}: {summary}")
            if tested.returncode != 0:
                problems.append(f"development command:\n{tested.stdout[-3000:]}{tested.stderr}")
    return [f"{version} {p}" for p in problems]


def default_pythons() -> list[str]:
    root = os.environ.get("PYENV_ROOT", os.path.expanduser("~/.pyenv"))
    found = []
    for minor in ("3.8", "3.10", "3.12", "3.13"):
        candidates = sorted(glob.glob(f"{root}/versions/{minor}.*/bin/python{minor}"))
        if candidates:
            found.append(candidates[-1])
    return found


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--dev", action="store_true", help="also run the development command")
    parser.add_argument("pythons", nargs="*", help="Python interpreters (default: pyenv's)")
    options = parser.parse_args()
    problems = []
    for python in options.pythons or default_pythons():
        problems += trial(python, options.dev)
    for problem in problems:
        print(problem, file=sys.stderr)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
