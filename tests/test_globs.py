"""The linear glob matcher (``model.globs``) agrees with ``fnmatch`` and with git's
``.gitignore`` rules as ``git status`` applies them, and stays linear on patterns that make
their backtracking regular expressions take minutes."""

from __future__ import annotations

import fnmatch
import random
import shutil
import subprocess
import time
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from launch_linter.model.globs import fnmatch_glob, path_glob
from launch_linter.workspace.gitignore import GitIgnore, parse_rule

PIECES = ["a", "b", "/", "*", "**", "?", "[ab]", "[!a]", ".", "**/", "/**"]
TEXT = st.text(alphabet="ab/.", max_size=12)
PATTERN = st.lists(st.sampled_from(PIECES), max_size=6).map("".join)
GIT_PIECES = [*PIECES, "[^a]", "\\*"]


@settings(max_examples=400, deadline=None)
@given(PATTERN, TEXT)
def test_fnmatch_dialect_agrees_with_fnmatch(pattern: str, text: str) -> None:
    assert fnmatch_glob(pattern).match(text) == fnmatch.fnmatchcase(text, pattern)


def _random_cases(count: int) -> list[tuple[str, str]]:
    """(pattern, file path) pairs from the pieces above, with a fixed seed."""
    chooser = random.Random(20261126)
    cases: list[tuple[str, str]] = []
    while len(cases) < count:
        pattern = "".join(chooser.choice(GIT_PIECES) for _ in range(chooser.randint(1, 6)))
        text = "".join(chooser.choice("ab/.") for _ in range(chooser.randint(1, 12)))
        text = text.strip("/")
        if (not text or "//" in text or "//" in pattern or pattern.strip("/") == ""
                or {".", ".."} & set(text.split("/")) or "***" in pattern
                or pattern.startswith("#") or text.split("/")[0] == ".git"):
            continue  # not a path discovery meets, or not a pattern
        cases.append((pattern, text))
    return cases


def test_gitignore_dialect_agrees_with_git(tmp_path: Path) -> None:
    """What ``git status`` ignores, discovery ignores: each case is a folder with one
    ``.gitignore`` line and one file; a file counts as ignored when it or a folder it
    lies in is (discovery does not enter an ignored folder). pathspec is no oracle
    here: it ignores ``a/a`` by ``a/**/`` and git does not."""
    git = shutil.which("git")
    if git is None:
        pytest.skip("git is not installed")
    cases = _random_cases(1500)
    for index, (pattern, text) in enumerate(cases):
        case = tmp_path / f"c{index}"
        (case / text).parent.mkdir(parents=True, exist_ok=True)
        (case / text).write_bytes(b"")
        (case / ".gitignore").write_text(pattern + "\n", encoding="utf-8")
    subprocess.run([git, "init", "-q", str(tmp_path)], check=True)
    status = subprocess.run(
        [git, "-c", "core.quotePath=false", "status", "--porcelain", "--ignored", "-uall"],
        cwd=tmp_path, check=True, capture_output=True, text=True).stdout
    ignored_by_git = [line[3:] for line in status.splitlines() if line.startswith("!! ")]
    ignore = GitIgnore()
    for index, (pattern, text) in enumerate(cases):
        path = f"c{index}/{text}"
        by_git = any(path == entry or (entry.endswith("/") and path.startswith(entry))
                     for entry in ignored_by_git)
        parts = text.split("/")
        folders = [str(tmp_path / f"c{index}" / "/".join(parts[:depth]))
                   for depth in range(1, len(parts))]
        ours = (any(ignore.ignored(folder, True) for folder in folders)
                or ignore.ignored(str(tmp_path / path), False))
        assert ours == by_git, (pattern, text)


def test_a_negated_class_stays_within_a_segment() -> None:
    rule = parse_rule("a[!a]b")
    assert rule is not None and rule.verdict("acb", False) and not rule.verdict("a/b", False)


def test_path_dialect() -> None:
    assert path_glob("launch/*.launch").match("launch/a.launch")
    assert not path_glob("*.launch").match("launch/a.launch")
    assert path_glob("**/a.launch").match("a.launch")
    assert path_glob("src/**/x").match("src/a/b/x")


@pytest.mark.parametrize("pattern,text", [
    ("*a" * 12 + "*b", "a" * 4000),
    ("**/*a*a/**/*a*a*b", ("a" * 250 + "/") * 16 + "c"),
    ("**/a/" * 10 + "b", "a/" * 2000 + "c"),
])
def test_backtracking_patterns_are_linear(pattern: str, text: str) -> None:
    started = time.process_time()
    assert not fnmatch_glob(pattern).match(text)
    rule = parse_rule(pattern)
    assert rule is not None and rule.verdict(text, False) is None
    assert time.process_time() - started < 2
