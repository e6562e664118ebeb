"""What the language server knows, without any LSP types (``lsp.py`` speaks the protocol).

Open documents are held as text. Every lint is of one *root* (an entry point: a launch file
that discovery finds or the editor opened) and its findings are kept per root, so that a
file included by two entry points shows the findings of both and a re-lint of one replaces
only its own. Which roots read a file (through ``<include>``, a ``robot_description`` URDF or
xacro, or a xacro include) is learnt from every lint and, at start, from linting the
workspace folders; editing such a file re-lints those roots with the unsaved texts of every
open document (``unsaved_texts``). Options and the configuration file are read as ``check``
reads them, per file.
"""

from __future__ import annotations

import argparse
import os
from collections.abc import Iterable, Sequence
from dataclasses import dataclass

from launch_linter.commands import check as check_command
from launch_linter.commands.options import lint_command_paths, lint_options, load_config
from launch_linter.engine import LintOptions, LintResult, lint_paths, lint_text
from launch_linter.model.diagnostic import Diagnostic
from launch_linter.model.launch import LaunchTree
from launch_linter.model.record import replace
from launch_linter.model.transform import normalise_frame
from launch_linter.resolve.xml_safe import unsaved_texts
from launch_linter.workspace.discovery import (
    CONTENT_SUFFIXES,
    has_launch_content,
    is_launch_name,
)

DESCRIPTION_SUFFIXES = (".urdf", ".xacro")
CONFIG_NAMES = (".launch-linter.toml", "pyproject.toml")
MAX_CHAIN = 64
"""Longest parent chain a hover walks (a cycle or a very deep tree stops it)."""
FRAME_CHARACTERS = frozenset(
    "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_/-.~"
)


@dataclass(frozen=True)
class Edge:
    """A parent -> child transform of a root's tree and who publishes it."""

    parent: str
    child: str
    publisher: str
    path: str
    line: int


def _check_namespace(path: str) -> argparse.Namespace:
    parser = argparse.ArgumentParser(add_help=False)
    check_command.add_parser(parser.add_subparsers(dest="command"))
    return parser.parse_args(["check", path])


def is_launch_file(path: str) -> bool:
    """Named like a launch file, or one by its content (as saved) as discovery finds it."""
    name = os.path.basename(path)
    return is_launch_name(name) or (
        name.endswith(CONTENT_SUFFIXES) and has_launch_content(path, name))


class Session:
    def __init__(self, folders: Sequence[str]) -> None:
        self.folders = [os.path.realpath(f) for f in folders]
        self.texts: dict[str, str] = {}
        self.roots: set[str] = set()
        self.readers: dict[str, set[str]] = {}
        """File -> the roots whose lint read it."""
        self.findings: dict[str, dict[str, list[Diagnostic]]] = {}
        """Root -> file -> that root's findings in that file."""
        self.trees: dict[str, tuple[LaunchTree, ...]] = {}
        self._options: dict[str, LintOptions] = {}

    # -- configuration ----------------------------------------------------------------

    def options_for(self, path: str) -> LintOptions:
        """The options ``launch-linter check PATH`` would use (its configuration file)."""
        folder = os.path.dirname(path)
        if folder not in self._options:
            ns = _check_namespace(path)
            # one process: the unsaved texts live in this one
            self._options[folder] = replace(lint_options(ns, load_config(ns)), jobs=1)
        return self._options[folder]

    def forget_configuration(self) -> None:
        self._options.clear()

    # -- what reads what ----------------------------------------------------------------

    def index(self) -> None:
        """Lint the workspace folders as ``check`` would, to learn the roots and what each
        one reads (findings are published per document as documents are opened)."""
        for folder in self.folders:
            ns = _check_namespace(folder)
            config = load_config(ns)
            result = lint_command_paths(ns, lint_options(ns, config), config, keep_trees=True)
            for record in result.files:
                self.roots.add(os.path.realpath(record.path))
            self._learn(result.trees)

    def _learn(self, trees: Iterable[LaunchTree]) -> None:
        for tree in trees:
            root = os.path.realpath(tree.root)
            read = {*tree.files, *(d.file for d in tree.descriptions if d.file),
                    *(j.path for j in tree.joints),
                    *(j.defined[0] for j in tree.joints if j.defined)}
            for path in read:
                self.readers.setdefault(os.path.realpath(path), set()).add(root)

    def roots_reading(self, path: str) -> set[str]:
        roots = {r for r in self.readers.get(path, ()) if r in self.roots}
        if path in self.roots or (path not in self.readers and is_launch_file(path)):
            roots.add(path)
        if path.endswith(DESCRIPTION_SUFFIXES):
            roots.discard(path)
        return roots

    # -- documents ------------------------------------------------------------------------

    def update(self, path: str, text: str) -> set[str]:
        """The document ``path`` now holds ``text``: re-lint every root that reads it.
        Returns the files whose findings may have changed."""
        path = os.path.realpath(path)
        self.texts[path] = text
        return self.relint(self.roots_reading(path))

    def close(self, path: str) -> None:
        self.texts.pop(os.path.realpath(path), None)

    def relint(self, roots: Iterable[str]) -> set[str]:
        touched: set[str] = set()
        held = {p: t.encode("utf-8", "replace") for p, t in self.texts.items()}
        with unsaved_texts(held):
            for root in sorted(roots):
                touched |= self._lint_root(root)
        return touched

    def _lint_root(self, root: str) -> set[str]:
        options = self.options_for(root)
        result: LintResult
        if root in self.texts:
            # lint_text locates fixes in this text, not in the file on disk
            result = lint_text(self.texts[root], root, options)
        else:
            result = lint_paths([root], options)
        self.roots.add(root)
        self._learn(result.trees)
        self.trees[root] = result.trees
        by_file: dict[str, list[Diagnostic]] = {}
        for diagnostic in result.diagnostics:
            path = os.path.realpath(diagnostic.path)
            if diagnostic.fix is not None and path != root and path in self.texts:
                # located in the saved file, not in the text the editor holds
                diagnostic = replace(diagnostic, fix=None)
            by_file.setdefault(path, []).append(diagnostic)
        before = self.findings.get(root, {})
        self.findings[root] = by_file
        return set(before) | set(by_file)

    def diagnostics(self, path: str) -> list[Diagnostic]:
        """Every root's findings in ``path``, each once."""
        unique: dict[tuple[str, int, int, str, str], Diagnostic] = {}
        for by_file in self.findings.values():
            for diagnostic in by_file.get(path, ()):
                if unique.setdefault(diagnostic.sort_key, diagnostic).fix is None:
                    unique[diagnostic.sort_key] = diagnostic  # the one with a fix, if any
        return sorted(unique.values(), key=lambda d: d.sort_key)

    # -- hover ----------------------------------------------------------------------------

    def frame_at(self, path: str, line: int, character: int) -> str | None:
        """The frame-like word at (0-based) ``line``, ``character`` of the document."""
        lines = self.texts.get(path, "").splitlines()
        if line >= len(lines):
            return None
        text = lines[line]
        start = end = min(character, len(text))
        while start > 0 and text[start - 1] in FRAME_CHARACTERS:
            start -= 1
        while end < len(text) and text[end] in FRAME_CHARACTERS:
            end += 1
        return normalise_frame(text[start:end]) if end > start else None

    def edges(self, path: str) -> list[Edge]:
        """The transforms of every tree of every root that reads ``path``."""
        found: list[Edge] = []
        for root in sorted(self.roots_reading(path) | ({path} & set(self.trees))):
            for tree in self.trees.get(root, ()):
                for t in tree.transforms:
                    if t.parent and t.child:
                        who = f"static_transform_publisher '{t.name or '(unnamed)'}' ({t.package})"
                        found.append(Edge(t.parent, t.child, who, t.path, t.line))
                for j in tree.joints:
                    if j.parent and j.child:
                        who = f"robot_state_publisher: {j.joint_type} joint '{j.name}'"
                        found.append(Edge(j.parent, j.child, who, j.path, j.line))
        return found

    def hover(self, path: str, line: int, character: int) -> str | None:
        """Markdown about the frame under the cursor: its parent chain and its publishers."""
        path = os.path.realpath(path)
        frame = self.frame_at(path, line, character)
        edges = self.edges(path)
        if not frame or not any(frame in (e.parent, e.child) for e in edges):
            return None
        parents: dict[str, list[Edge]] = {}
        for edge in edges:
            if edge not in parents.setdefault(edge.child, []):
                parents[edge.child].append(edge)
        chain = [frame]
        cycle = False
        while chain[-1] in parents and len(chain) < MAX_CHAIN and not cycle:
            parent = parents[chain[-1]][0].parent
            cycle = parent in chain
            chain.append(parent)
        lines = [f"**tf frame `{frame}`**", "", "parent chain: " + " → ".join(
            f"`{name}`" for name in chain) + (" (a cycle)" if cycle else "")]
        publishers = parents.get(frame, [])
        if len(publishers) > 1:
            lines.append(f"\n{len(publishers)} publishers give it a parent:")
        for edge in publishers:
            lines.append(f"- parent `{edge.parent}` from {edge.publisher}, "
                         f"{_shown(edge.path)}:{edge.line}")
        if not publishers:
            lines.append("\nno transform publishes a parent of it (a root of the tree)")
        return "\n".join(lines)


def _shown(path: str) -> str:
    relative = os.path.relpath(path)
    return path if relative.startswith("..") else relative
