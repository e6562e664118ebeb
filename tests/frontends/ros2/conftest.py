"""Load tiny ROS 2 launch files written into a temporary folder."""

from __future__ import annotations

import os
from pathlib import Path

import pytest
from ros2_helpers import Load

from launch_linter.frontends.dispatch import load_tree
from launch_linter.frontends.ros1 import LoadOptions
from launch_linter.model.launch import LaunchTree
from launch_linter.workspace.packages import PackageIndex


@pytest.fixture
def load(tmp_path: Path) -> Load:
    """``load({"a.launch.xml": text, ...}, "a.launch.xml", args=..., env=..., packages=...)``:
    write the files under a temporary folder and load the root; paths are shown relative
    to that folder."""

    def run(files: dict[str, str], root: str, *, args: dict[str, str] | None = None,
            env: dict[str, str] | None = None, packages: tuple[str, ...] = ()) -> LaunchTree:
        for name, text in files.items():
            target = tmp_path / name
            target.parent.mkdir(parents=True, exist_ok=True)
            target.write_text(text, encoding="utf-8")
        options = LoadOptions(
            args=args or {},
            env=env or {},
            packages=PackageIndex([str(tmp_path / p) for p in packages]),
            display_path=lambda path: os.path.relpath(path, tmp_path),
        )
        return load_tree(str(tmp_path / root), options)

    return run
