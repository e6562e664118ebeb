"""``args`` split into argv items exactly as launch's ``ExecuteProcess._parse_cmdline``.

launch splits each literal text with ``shlex.split`` and never splits a substitution.
Property: when every substitution stands for an opaque word, that is the same as
``shlex.split`` of the whole line, except for launch's one artefact (a whitespace-only
text closes the current item even when it is empty: whitespace before a leading
substitution, or an empty attribute, gives an empty argument); a text that ``shlex``
refuses is an error.
"""

from __future__ import annotations

import shlex

import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st
from ros2_helpers import Load, rules

from launch_linter.model.launch import FileStatus
from launch_linter.resolve.ros2_substitution import (
    Call,
    CommandLineError,
    Sub,
    Subs,
    Text,
    parse,
    split_command_line,
)


def _marker(index: int) -> str:
    return f"\ue000{index}\ue001"


def _render(item: Subs, calls: list[Call]) -> str:
    return "".join(p.text if isinstance(p, Text) else _marker(calls.index(p)) for p in item)


TEXT = st.text(alphabet="ab '\"\\\t", min_size=1, max_size=8)


@st.composite
def command_lines(draw: st.DrawFn) -> tuple[Sub, ...]:
    kinds = draw(st.lists(st.booleans(), max_size=7))
    parts: list[Sub] = []
    for index, is_text in enumerate(kinds):
        if is_text and parts and isinstance(parts[-1], Text):
            continue  # the parser never yields two texts in a row
        if is_text:
            parts.append(Text(draw(TEXT)))
        else:
            parts.append(Call("var", ((Text(f"v{index}"),),), f"$(var v{index})"))
    return tuple(parts)


@settings(max_examples=400, deadline=None)
@given(command_lines())
def test_same_as_shlex_of_the_whole_line_but_launchs_artefact(subs: tuple[Sub, ...]) -> None:
    calls = [p for p in subs if isinstance(p, Call)]
    texts = [p.text for p in subs if isinstance(p, Text)]
    refused = False
    for text in texts:
        try:
            shlex.split(text)
        except ValueError:
            refused = True
    if refused:
        with pytest.raises(CommandLineError):
            split_command_line(subs)
        return
    # launch tests the raw text's last character: an escaped trailing space ('a\\ ')
    # still closes the item (see test_examples); the whole-line model does not.
    assume(not any(text.endswith(("\\ ", "\\\t")) for text in texts))
    items = split_command_line(subs)
    rendered = [_render(item, calls) for item in items]
    whole = "".join(p.text if isinstance(p, Text) else _marker(calls.index(p)) for p in subs)
    expected = shlex.split(whole)
    if not subs:
        expected = [""]
    leading_blank = bool(subs) and isinstance(subs[0], Text) and not subs[0].text.strip()
    if leading_blank:
        # launch closes the (empty) current item on a whitespace-only text.
        expected = ["", *expected] if len(subs) > 1 else [""]
    assert rendered == expected
    # A substitution is never split and keeps its place.
    assert [p for item in items for p in item if isinstance(p, Call)] == calls


@pytest.mark.parametrize(("source", "expected"), [
    ("", [""]),
    ("   ", [""]),
    ("0 0 0 0 0 0 a b", ["0", "0", "0", "0", "0", "0", "a", "b"]),
    (" $(var x) 0 b", ["", "$(var x)", "0", "b"]),
    ("$(var x)  $(var y)", ["$(var x)", "$(var y)"]),
    ("--frame-id $(var p)_link --child-frame-id 'a b'", [
        "--frame-id", "$(var p)_link", "--child-frame-id", "a b"]),
    ("a\\ b", ["a", "b"]),  # launch unescapes '\\ ' before shlex sees it
    ("x\\\\ $(var y)", ["x ", "$(var y)"]),  # an escaped space ends the text: item closed
])
def test_examples(source: str, expected: list[str]) -> None:
    items = split_command_line(parse(source))
    assert ["".join(p.text if isinstance(p, Text) else p.written for p in item)
            for item in items] == expected


@pytest.mark.parametrize("source", ["--frame-id 'base", 'a "b', "a b\\\\"])
def test_what_shlex_refuses_is_an_error(source: str) -> None:
    with pytest.raises(CommandLineError):
        split_command_line(parse(source))


def test_space_before_a_leading_substitution_shifts_the_arguments(load: Load) -> None:
    tree = load({"a.launch.xml": (
        '<launch>\n<arg name="x" default="0.1"/>\n'
        '<node pkg="tf2_ros" exec="static_transform_publisher" name="t"'
        ' args=" $(var x) 0 0 0 0 0 base laser"/>\n</launch>\n'
    )}, "a.launch.xml")
    (transform,) = tree.transforms
    assert transform.tokens[:2] == ("", "0.1")
    assert transform.form == "quaternion"  # nine items: the program reads x from ''


def test_an_unclosed_quote_refuses_the_file(load: Load) -> None:
    tree = load({"a.launch.xml": (
        '<launch>\n<node pkg="tf2_ros" exec="static_transform_publisher" name="t"'
        " args=\"--frame-id 'base --child-frame-id cam\"/>\n</launch>\n"
    )}, "a.launch.xml")
    assert rules(tree) == [("parse_error", 2)]
    assert tree.status is FileStatus.PARSE_ERROR and tree.transforms == ()
