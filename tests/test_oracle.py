"""Differential test: our ROS 1 loader against the real roslaunch ``XmlLoader``.

``scripts/roslaunch_oracle_driver.py`` loads every ``tests/fixtures/ros1/*.launch`` with
Debian's roslaunch (``/usr/bin/python3``, package ``python3-roslaunch``), with the launch
args, environment and package roots of ``tests/fixtures/ros1/oracle.json``. For each file
roslaunch accepts, the static transform nodes we find must be exactly roslaunch's
(resolved name, namespace, package, type, args, and the ``<node>``'s line and column), all
resolved and unconditional. For each file it refuses, we must report why.
"""

from __future__ import annotations

import json
import os
import subprocess
from pathlib import Path
from typing import Any

import pytest

from launch_linter.frontends.dispatch import load_tree
from launch_linter.frontends.ros1 import TF_PACKAGES, LoadOptions, ns_join
from launch_linter.model.launch import LaunchTree
from launch_linter.workspace.packages import PackageIndex

ROOT = Path(__file__).resolve().parent.parent
FIXTURES = ROOT / "tests" / "fixtures" / "ros1"
DRIVER = ROOT / "scripts" / "roslaunch_oracle_driver.py"
SYSTEM_PYTHON = "/usr/bin/python3"
CONFIG = json.loads((FIXTURES / "oracle.json").read_text(encoding="utf-8"))
FILES = sorted(p.name for p in FIXTURES.glob("*.launch"))


def _roslaunch_missing() -> str | None:
    if not os.path.exists(SYSTEM_PYTHON):
        return f"{SYSTEM_PYTHON} does not exist"
    probe = subprocess.run([SYSTEM_PYTHON, "-c", "import roslaunch"], capture_output=True,
                           text=True, check=False)
    if probe.returncode != 0:
        return f"{SYSTEM_PYTHON} cannot import roslaunch (apt-get install python3-roslaunch)"
    return None


def _settings(name: str) -> dict[str, dict[str, str]]:
    entry = CONFIG["files"].get(name, {})
    return {"args": entry.get("args", {}), "env": entry.get("env", {})}


def _roots() -> list[str]:
    return [str(FIXTURES / p) for p in CONFIG["package_path"]]


@pytest.fixture(scope="module")
def oracle() -> dict[str, dict[str, Any]]:
    missing = _roslaunch_missing()
    if missing:
        pytest.skip(missing)
    request = {
        "package_path": _roots(),
        "files": [{"path": name, **_settings(name)} for name in FILES],
    }
    # roslaunch opens relative include paths from its working directory.
    done = subprocess.run(
        [SYSTEM_PYTHON, str(DRIVER)], input=json.dumps(request), capture_output=True,
        text=True, cwd=FIXTURES, check=True, timeout=300,
    )
    rows = [json.loads(line) for line in done.stdout.splitlines()]
    return {row["path"]: row for row in rows}


def _ours(name: str) -> LaunchTree:
    settings = _settings(name)
    options = LoadOptions(args=settings["args"], env=settings["env"],
                          packages=PackageIndex(_roots()))
    return load_tree(str(FIXTURES / name), options)


def test_fixture_set_is_broad() -> None:
    assert len(FILES) >= 30
    text = "".join((FIXTURES / name).read_text(encoding="utf-8") for name in FILES)
    for feature in ("$(arg", "$(eval", "$(find", "$(env", "$(optenv", "$(dirname", "$(anon",
                    "pass_all_args", "<include", "<group", "unless=", "if=", "ns="):
        assert feature in text, feature


@pytest.mark.parametrize("name", FILES)
def test_same_static_transforms_as_roslaunch(name: str, oracle: dict[str, dict[str, Any]]) -> None:
    row = oracle[name]
    tree = _ours(name)
    if not row["ok"]:
        blocking = [d for d in tree.problems
                    if d.rule in ("parse_error", "roslaunch_error", "unresolved")]
        assert blocking, f"roslaunch refuses {name} ({row['error']}) but we report nothing"
        return
    theirs = sorted(
        (n["resolved_name"], n["namespace"], n["package"], n["type"], n["args"],
         n["line"], n["column"])
        for n in row["nodes"]
        if n["type"] == "static_transform_publisher" and n["package"] in TF_PACKAGES
    )
    ours = sorted(
        (ns_join(t.namespace, t.name) if t.name else None, t.namespace, t.package,
         t.executable, t.args, t.line, t.column)
        for t in tree.transforms
    )
    assert ours == theirs
    for transform in tree.transforms:
        assert transform.unresolved_names == (), transform
        assert transform.condition.always, transform
    errors = [d for d in tree.problems if d.rule in ("parse_error", "roslaunch_error")]
    assert errors == []
