"""Start-up: a command imports what its run needs, when it needs it (issue 16).

Each case runs in a fresh interpreter and lists the modules that importing the command
line and running it added to ``sys.modules``; the modules named here must not be among
them. No timing: a module that is imported is a cost whatever the machine.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

import launch_linter
from launch_linter.commands.options import NO_CACHE_VARIABLE

SRC = str(Path(launch_linter.__file__).resolve().parents[1])

# Imports a run over ROS 1 XML files without fixes, robots or ignore files never needs.
HEAVY = (
    "launch_linter.fix",  # only when a finding carries a fix, or --fix/--diff
    "launch_linter.frontends.ros2_launch",
    "launch_linter.frontends.ros2_python",
    "launch_linter.frontends.ros2_xml",
    "launch_linter.frontends.ros2_yaml",
    "launch_linter.decode_ros2",
    "launch_linter.frontends.robot.xacro",  # only when a robot description is expanded
    "launch_linter.frontends.robot.urdf",
    "launch_linter.report.formats",  # SARIF and GitHub output only
    "launch_linter.mining",
    "launch_linter.generate",
    "launch_linter.evaluation",
    "launch_linter.graph",
    "multiprocessing",  # the process pool: only for several jobs
    "concurrent.futures",
    "logging",
    "xml.etree",
    "yaml",
    "difflib",  # only for "did you mean" messages and diffs
    "sqlite3",
    "tempfile",  # only when a file (the results cache, a fixed file) is written
    "dataclasses",  # the types of the ROS 1 path are records (model/record.py)
    "launch_linter.fix_python",  # only when a fix is located in a Python file
    "launch_linter.commands.transforms",  # a command imports its own module alone
    "launch_linter.commands.rules",
    "launch_linter.commands.explain",
)

LAUNCH = """\
<launch>
  <arg name="rate" default="100"/>
  <node pkg="tf2_ros" type="static_transform_publisher" name="base_to_laser"
        args="0.1 0 0.2 0 0 0 base_link laser"/>
  <node pkg="tf" type="static_transform_publisher" name="base_to_imu"
        args="0 0 0.1 0 0 0 1 base_link imu_link $(arg rate)"/>
</launch>
"""

PROBE = """\
import contextlib, io, json, sys
before = set(sys.modules)
from launch_linter.cli import main
with contextlib.redirect_stdout(io.StringIO()), contextlib.redirect_stderr(io.StringIO()):
    try:
        status = main(json.loads(sys.argv[1]))
    except SystemExit as exc:  # --version
        status = exc.code
print(json.dumps({"status": status, "new": sorted(set(sys.modules) - before)}))
"""


def _imported(argv: list[str], cwd: Path, cache: bool = False) -> tuple[int, set[str]]:
    env = dict(os.environ, PYTHONPATH=SRC)
    env.pop("LAUNCH_LINTER_DEBUG", None)
    if cache:
        env.pop(NO_CACHE_VARIABLE, None)
    done = subprocess.run([sys.executable, "-c", PROBE, json.dumps(argv)], cwd=cwd, env=env,
                          capture_output=True, text=True, check=True, timeout=120)
    result = json.loads(done.stdout.splitlines()[-1])
    return int(result["status"]), set(result["new"])


def _heavy(modules: set[str]) -> list[str]:
    return sorted(m for m in modules if any(m == h or m.startswith(h + ".") for h in HEAVY))


def test_check_of_one_ros1_file_imports_nothing_heavy(tmp_path: Path) -> None:
    (tmp_path / "base.launch").write_text(LAUNCH, encoding="utf-8")
    status, modules = _imported(["check", "--format", "json", "base.launch"], tmp_path)
    assert status == 0
    assert "launch_linter.frontends.ros1" in modules  # the probe saw the run's imports
    assert _heavy(modules) == []
    # Answered from the results cache the first run wrote: no front-end, no tempfile.
    _imported(["check", "--format", "json", "base.launch"], tmp_path, cache=True)
    status, modules = _imported(["check", "--format", "json", "base.launch"], tmp_path,
                                cache=True)
    assert status == 0
    assert "launch_linter.frontends.ros1" not in modules
    assert "launch_linter.rules.self_transform" not in modules  # no rule runs: none loaded
    assert _heavy(modules) == []


# Imports a run answered by the results cache never needs (issue 24): no rule runs, no
# package is looked up, no help is printed, the bundled beliefs are not decoded.
NOT_WHEN_CACHED = (
    "launch_linter.rules._api",  # the rules' API: rules/__init__ gives it lazily
    "launch_linter.rules._tree",
    "launch_linter.knowledge",
    "launch_linter.workspace.packages",
    "launch_linter.report.published",  # the transforms command's
    "launch_linter.workspace.toml_fallback",  # only without a TOML parser (3.8, 3.10)
    "typing",  # annotations and aliases only, under TYPE_CHECKING
    "shutil",  # argparse measures the terminal only to format help
)


def _brought_by_argparse() -> set[str]:
    """What importing argparse alone imports (3.8's argparse imports shutil itself)."""
    probe = "import sys; b = set(sys.modules); import argparse; print(sorted(set(sys.modules) - b))"
    done = subprocess.run([sys.executable, "-I", "-c", probe], capture_output=True, text=True,
                          check=True, timeout=60)
    return set(json.loads(done.stdout.replace("'", '"')))


def test_a_run_answered_by_the_cache_imports_only_what_it_uses(tmp_path: Path) -> None:
    (tmp_path / "base.launch").write_text(LAUNCH, encoding="utf-8")
    for _ in range(2):  # the first run writes the cache
        status, modules = _imported(["check", "--format", "json", "base.launch"], tmp_path,
                                    cache=True)
        assert status == 0
    assert "launch_linter.results_cache" in modules  # the probe saw the run's imports
    unwanted = set(NOT_WHEN_CACHED) - _brought_by_argparse()
    assert sorted(unwanted & modules) == []
    # The text report too (it states no count of beliefs).
    status, modules = _imported(["check", "base.launch"], tmp_path, cache=True)
    status, modules = _imported(["check", "base.launch"], tmp_path, cache=True)
    assert sorted(unwanted & modules) == []


def test_check_of_a_folder_without_ignore_files_imports_nothing_heavy(tmp_path: Path) -> None:
    if any((folder / ".gitignore").exists() for folder in tmp_path.parents):
        pytest.skip("a folder above the temporary one has a .gitignore, which is read")
    for name in ("a.launch", "b.launch"):
        (tmp_path / "launch" / name).parent.mkdir(exist_ok=True)
        (tmp_path / "launch" / name).write_text(LAUNCH, encoding="utf-8")
    status, modules = _imported(["check", "--format", "json", "launch"], tmp_path)
    assert status == 0
    assert _heavy(modules) == []


def test_version_imports_no_command(tmp_path: Path) -> None:
    status, modules = _imported(["--version"], tmp_path)
    assert status == 0
    assert not any(m.startswith(("launch_linter.engine", "launch_linter.commands.check",
                                 "launch_linter.model", "launch_linter.rules")) for m in modules)
