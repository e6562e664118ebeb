"""The fixture workspace of the whole-tree rules (catkin and ament packages, a xacro
description with includes, macros, args and conditionals, launch files that include each
other): lint one of its launch files with one rule."""

from __future__ import annotations

from pathlib import Path

from launch_linter import LintOptions, lint_paths
from launch_linter.model import Diagnostic

WS = Path(__file__).resolve().parent.parent / "fixtures" / "robot_ws"


def ws_lint(launch: str, rule: str, args: dict[str, str] | None = None
            ) -> tuple[Diagnostic, ...]:
    options = LintOptions(args=args or {}, package_paths=(str(WS),),
                          select=frozenset({rule}))
    return lint_paths([str(WS / "src" / launch)], options).diagnostics
