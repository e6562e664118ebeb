"""Splitting a resolved ``args`` value into the words the program receives."""

from __future__ import annotations

import re
import shlex

from hypothesis import given
from hypothesis import strategies as st

from launch_linter.frontends.tokens import shell_words, split_args
from launch_linter.resolve.value import Hole

WORD_TEXT = st.text(alphabet=st.characters(exclude_categories=["Cs"]), max_size=40)


@given(WORD_TEXT)
def test_words_are_what_shlex_split_gives(text: str) -> None:
    try:
        expected = shlex.split(text)
    except ValueError:
        words, error = shell_words(text)
        assert error is not None
        assert words == [w for w in re.split("[ \t\r\n]", text) if w]
        return
    assert shell_words(text) == (expected, None)


@given(st.text(alphabet=" \t\r\n\"'\\ab", max_size=20))
def test_words_on_dense_quoting(text: str) -> None:
    try:
        expected: object = shlex.split(text)
    except ValueError:
        expected = "error"
    words, error = shell_words(text)
    assert (words if error is None else "error") == expected


@given(st.lists(st.from_regex(r"[A-Za-z0-9_.:=/-]{1,8}", fullmatch=True), max_size=12),
       st.integers(min_value=0, max_value=12))
def test_a_hole_stays_inside_its_word(words: list[str], where: int) -> None:
    where = min(where, len(words))
    hole = Hole("$(arg x)", "not set")
    before = " ".join(words[:where])
    after = " ".join(words[where:])
    value = (before + " " if before else "", hole, "_suffix " + after if after else "_suffix")
    split = split_args(tuple(p for p in value if p != ""))
    assert split.words[where] == "$(arg x)_suffix"
    assert split.unresolved == frozenset({where})
    assert split.words[:where] == tuple(words[:where])
    assert split.words[where + 1:] == tuple(words[where:])


def test_unbalanced_quotes_fall_back_to_blanks_and_say_so() -> None:
    split = split_args(("0 0 0 'a b",))
    assert split.words == ("0", "0", "0", "'a", "b")
    assert split.quoting_error is not None


def test_only_the_four_shell_blanks_separate_words() -> None:
    assert shell_words("a\u00a0b c\x0bd\te\nf\rg")[0] == ["a\u00a0b", "c\x0bd", "e", "f", "g"]
