"""``may_rename`` (whether a node's arguments may rename it) searches the arguments as one
text: the same answer as asking each word for each renaming word."""

from __future__ import annotations

from hypothesis import given
from hypothesis import strategies as st

from launch_linter.frontends.ros2_actions import RENAMING_WORDS, may_rename

PIECES = st.sampled_from(["__node", "__name", "__ns", "__n", "_", "n", "ode", ":=", "\n", "-r",
                          "a", " "])
WORDS = st.lists(st.lists(PIECES, max_size=4).map("".join), max_size=6)


def word_by_word(words: list[str]) -> bool:
    return any(renaming in word for word in words for renaming in RENAMING_WORDS)


@given(WORDS)
def test_one_text_answers_as_each_word(words: list[str]) -> None:
    assert may_rename(words) == word_by_word(words)


def test_unknown_arguments_may_rename_and_split_words_do_not() -> None:
    assert may_rename(None)
    assert may_rename(["--ros-args", "-r", "__node:=cam"])
    assert not may_rename(["__n", "ode:=cam"])
    assert not may_rename(["_", "_ns:=/a"])
