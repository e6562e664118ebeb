"""Linting stored file versions, and what the evaluation keeps of each result."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Tuple

from launch_linter.engine import (
    InputFile,
    LintOptions,
    check_tree,
    finish_diagnostics,
    load_options_for,
    selected_rules,
)
from launch_linter.frontends.dispatch import load_tree
from launch_linter.model.diagnostic import Diagnostic
from launch_linter.model.record import replace
from launch_linter.model.transform import StaticTransform


@dataclass(frozen=True)
class Version:
    """One (repository, path, version) of the database."""

    repo: str
    path: str
    version: str
    latest: bool
    mature: bool
    head_paths: tuple[str, ...] = ()
    """The HEAD files whose history holds this version, when the file was renamed or copied
    since; empty means the version's own path."""

    @property
    def lineage(self) -> tuple[str, ...]:
        """The paths of the latest files this version is an earlier version of."""
        return self.head_paths or (self.path,)


@dataclass(frozen=True)
class Linted:
    """What the linter found in one version: its own transforms and the diagnostics located
    in it (not in files it includes, which are judged when they are linted themselves)."""

    version: Version
    status: str
    transforms: tuple[StaticTransform, ...]
    diagnostics: tuple[Diagnostic, ...]


LintOutcome = Tuple[str, Tuple[StaticTransform, ...], Tuple[Diagnostic, ...]]
"""(file status, own transforms, own diagnostics)."""


def lint_bytes(
    data: bytes, parse_path: str, package_roots: tuple[str, ...], options: LintOptions
) -> LintOutcome:
    """(status, own transforms, own diagnostics) of ``data`` read as the file ``parse_path``.

    The raw bytes go to the front-end as the miner gave them, so that the evaluation sees
    the same transforms as the database; ``package_roots`` are the ``$(find)`` roots the
    miner used for this file.
    """
    item = InputFile(parse_path, parse_path)
    scoped = replace(options, package_paths=package_roots)
    tree = load_tree(item.path, load_options_for(item, scoped, {}), data)
    found = check_tree(tree, selected_rules(scoped), scoped)
    diagnostics = finish_diagnostics((tree,), found, scoped)
    own = tuple(d for d in diagnostics if d.path == item.display)
    transforms = tuple(t for t in tree.transforms if t.path == item.display)
    return tree.status.value, transforms, own
