"""Run one rule over tiny inline launch files."""

from __future__ import annotations

from pathlib import Path
from typing import Callable, List, Tuple

import pytest

from launch_linter import LintOptions, lint_paths, lint_text
from launch_linter.model import Diagnostic

Lint = Callable[..., List[Tuple[str, int]]]
LintDiagnostics = Callable[..., Tuple[Diagnostic, ...]]


def run_rule(
    xml: str, rule: str, args: dict[str, str] | None = None, path: str = "test.launch"
) -> tuple[Diagnostic, ...]:
    """The diagnostics of ``rule`` alone for launch text ``xml``."""
    options = LintOptions(args=args or {}, package_paths=(), select=frozenset({rule}))
    return lint_text(xml, path, options).diagnostics


@pytest.fixture
def lint() -> Lint:
    """``lint(xml, rule, args=None)`` -> ``[(rule, line), ...]``."""

    def run(xml: str, rule: str, args: dict[str, str] | None = None) -> list[tuple[str, int]]:
        return [(d.rule, d.line) for d in run_rule(xml, rule, args)]

    return run


@pytest.fixture
def lint_diagnostics() -> LintDiagnostics:
    """``lint_diagnostics(xml, rule, args=None)`` -> the full diagnostics."""
    return run_rule


@pytest.fixture
def lint_tree(tmp_path: Path) -> Callable[..., tuple[Diagnostic, ...]]:
    """``lint_tree({"a.launch": xml, ...}, root, rule)``: write the files, lint ``root``."""

    def run(files: dict[str, str], root: str, rule: str) -> tuple[Diagnostic, ...]:
        for name, text in files.items():
            (tmp_path / name).write_text(text, encoding="utf-8")
        options = LintOptions(package_paths=(), select=frozenset({rule}))
        return lint_paths([str(tmp_path / root)], options).diagnostics

    return run
