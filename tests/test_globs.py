"""The linear glob matcher (``model.globs``) agrees with ``fnmatch`` and with git's
``.gitignore`` rules as ``pathspec`` reads them, and stays linear on patterns that make
their backtracking regular expressions take minutes."""

from __future__ import annotations

import fnmatch
import time

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from launch_linter.model.globs import fnmatch_glob, path_glob
from launch_linter.workspace.gitignore import parse_rule

PIECES = ["a", "b", "/", "*", "**", "?", "[ab]", "[!a]", ".", "**/", "/**"]
TEXT = st.text(alphabet="ab/.", max_size=12)
PATTERN = st.lists(st.sampled_from(PIECES), max_size=6).map("".join)
# pathspec lets a negated class match "/" (git's wildmatch does not): compared without.
GIT_PATTERN = st.lists(st.sampled_from([p for p in PIECES if p != "[!a]"]),
                       max_size=6).map("".join)


@settings(max_examples=400, deadline=None)
@given(PATTERN, TEXT)
def test_fnmatch_dialect_agrees_with_fnmatch(pattern: str, text: str) -> None:
    assert fnmatch_glob(pattern).match(text) == fnmatch.fnmatchcase(text, pattern)


@settings(max_examples=400, deadline=None)
@given(GIT_PATTERN, TEXT, st.booleans())
def test_gitignore_dialect_agrees_with_pathspec(pattern: str, text: str,
                                                folder: bool) -> None:
    pathspec = pytest.importorskip("pathspec")
    text = text.strip("/")
    if (not text or "//" in text or "//" in pattern or pattern.strip("/") == ""
            or {".", ".."} & set(text.split("/")) or "***" in pattern):
        # Not a path discovery asks about, not a pattern, or "***" (a "**" for git's
        # wildmatch, three single stars for pathspec).
        return
    rule = parse_rule(pattern)
    spec = pathspec.GitIgnoreSpec.from_lines([pattern])
    expected = spec.match_file(text + "/" if folder else text)
    got = rule is not None and rule.verdict(text, folder) is True
    assert got == expected, (pattern, text, folder)


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
