"""``bracket_fault``: what it calls no Python expression, no Python compiles."""

from __future__ import annotations

import pytest
from hypothesis import given
from hypothesis import strategies as st

from launch_linter.frontends.robot.xacro_values import bracket_fault

PIECES = st.sampled_from(["(", ")", "[", "]", "{", "}", "'", '"', "\\", "#", "\n", "a", "1",
                          " + ", ",", ":", "'''", "r'", "'('", '")"'])


@given(st.lists(PIECES, max_size=14).map("".join))
def test_what_it_refuses_does_not_compile(text: str) -> None:
    if bracket_fault(text) is not None:
        with pytest.raises(SyntaxError):
            compile(text, "<expression>", "eval")


@pytest.mark.parametrize("text, fault", [
    ("mass * (3 * r * r + l * l) / 12)", "')' closes no bracket"),
    ("[1, (2]", "']' does not close its bracket"),
    ("'a' + (1", "'(' is not closed"),
    ("'abc", "a string is not closed"),
    ("'(' + \")\" + '''x)'''", None),
    ("f(a)[1] # )", None),
    ("r'\\\\' + '\\')'", None),
])
def test_examples(text: str, fault: str | None) -> None:
    assert bracket_fault(text) == fault
