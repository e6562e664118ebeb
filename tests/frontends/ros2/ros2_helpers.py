"""Small helpers shared by the ROS 2 front-end tests."""

from __future__ import annotations

from pathlib import Path
from typing import Callable

from launch_linter.model.launch import LaunchTree
from launch_linter.model.transform import StaticTransform

FIXTURES = Path(__file__).resolve().parent / "fixtures"

Load = Callable[..., LaunchTree]
"""The ``load`` fixture: ``load({"a.launch.xml": text, ...}, "a.launch.xml", ...)``."""


def by_name(tree: LaunchTree) -> dict[str | None, StaticTransform]:
    return {t.name: t for t in tree.transforms}


def rules(tree: LaunchTree) -> list[tuple[str, int]]:
    return [(d.rule, d.line) for d in tree.problems]
