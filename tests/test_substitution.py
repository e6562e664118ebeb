"""roslaunch substitution args (``$(...)``), resolved statically."""

from __future__ import annotations

import os
from collections.abc import Mapping

import pytest
from hypothesis import given
from hypothesis import strategies as st

from launch_linter.resolve.substitution import (
    SubstitutionError,
    SubstitutionScope,
    collect_commands,
    resolve,
    to_bool,
)
from launch_linter.resolve.value import Hole, Value, holes, is_resolved, resolved_text, text_of

PACKAGES = {"robot": "/ws/src/robot", "tools": "/ws/src/tools_dir"}


def scope(
    args: Mapping[str, Value] | None = None,
    env: Mapping[str, str] | None = None,
    missing_arg: object = None,
    anon: dict[str, str] | None = None,
) -> SubstitutionScope:
    table = {} if anon is None else anon

    def make_anon(anon_id: str) -> str:
        return table.setdefault(anon_id, f"{anon_id}_anon{len(table) + 1}")

    return SubstitutionScope(
        args=args or {},
        env=env or {},
        find=PACKAGES.get,
        anon=make_anon,
        filename="/ws/src/robot/launch/a.launch",
        missing_arg=missing_arg,  # type: ignore[arg-type]
    )


def text(value: Value) -> str:
    resolved = resolved_text(value)
    assert resolved is not None, value
    return resolved


# --- the lexer ------------------------------------------------------------------------


def reference_lexer(source: str) -> list[str]:
    """roslaunch's character-by-character state machine, written out plainly."""
    out, buffer, state = [], "", "out"
    for char in source:
        if char == "$":
            if state in ("lparen", "in"):
                raise SubstitutionError("dollar")
            state = "dollar"
        elif char == "(":
            if state == "dollar":
                state = "lparen"
            elif state != "out":
                raise SubstitutionError("paren")
        elif char == ")":
            if state == "in":
                out.append(buffer)
                buffer = ""
            state = "out"
        elif state == "dollar":
            state = "out"
        elif state == "lparen":
            state = "in"
        if state == "in":
            buffer += char
    return out


def outcome(lexer: object, source: str) -> object:
    try:
        return lexer(source)  # type: ignore[operator]
    except SubstitutionError as exc:
        return "dollar" if "Dollar" in str(exc) or str(exc) == "dollar" else "paren"


@given(st.text(alphabet="$() ab", max_size=30))
def test_lexer_matches_roslaunch_state_machine_on_dense_input(source: str) -> None:
    assert outcome(collect_commands, source) == outcome(reference_lexer, source)


@given(st.text(max_size=60))
def test_lexer_matches_roslaunch_state_machine_on_any_text(source: str) -> None:
    assert outcome(collect_commands, source) == outcome(reference_lexer, source)


@pytest.mark.parametrize(
    ("source", "commands"),
    [
        ("no substitution", []),
        ("$(arg a)$(arg b)", ["arg a", "arg b"]),
        ("$$(arg a)", ["arg a"]),
        ("$()", []),
        ("$(arg a", []),
        ("a)b$ (c)", []),
        ("$(find p)/x $(env  E )", ["find p", "env  E "]),
    ],
)
def test_lexer_examples(source: str, commands: list[str]) -> None:
    assert collect_commands(source) == commands


@pytest.mark.parametrize(
    ("source", "message"),
    [
        ("$(arg $(arg x))", "Dollar signs"),
        ("$($(arg x))", "Dollar signs"),
        ("$(arg (x))", "Invalid left parenthesis"),
        ("$((x))", "Invalid left parenthesis"),
    ],
)
def test_lexer_errors(source: str, message: str) -> None:
    with pytest.raises(SubstitutionError, match=message):
        collect_commands(source)


# --- each command --------------------------------------------------------------------


@given(st.text().filter(lambda s: "$" not in s))
def test_text_without_dollar_is_unchanged(source: str) -> None:
    assert text(resolve(source, scope())) == source


@given(
    st.from_regex(r"[A-Za-z_][A-Za-z0-9_]{0,10}", fullmatch=True),
    st.text().filter(lambda s: "$" not in s),
)
def test_arg_is_replaced_by_its_value(name: str, value: str) -> None:
    assert text(resolve(f"x/$(arg {name})/y", scope({name: (value,)}))) == f"x/{value}/y"


def test_arg_replaces_every_identical_occurrence_and_adjacent_ones() -> None:
    args = {"a": ("front",), "b": ("_laser",)}
    assert text(resolve("$(arg a)$(arg b) $(arg a)", scope(args))) == "front_laser front"
    assert text(resolve("$(arg   a)_x", scope(args))) == "front_x"
    assert text(resolve("$$(arg a)", scope(args))) == "$front"


def test_missing_arg_is_a_hole_naming_the_arg() -> None:
    value = resolve("pre_$(arg nope)_post", scope())
    assert not is_resolved(value)
    assert text_of(value) == "pre_$(arg nope)_post"
    (hole,) = holes(value)
    assert hole.text == "$(arg nope)" and "nope" in hole.reason


def test_missing_arg_callback_decides_between_hole_and_error() -> None:
    def closed(name: str) -> str:
        raise SubstitutionError(f"included file requires the '{name}' arg to be set")

    with pytest.raises(SubstitutionError, match="requires the 'x' arg"):
        resolve("$(arg x)", scope(missing_arg=closed))
    (hole,) = holes(resolve("$(arg x)", scope(missing_arg=lambda n: f"give {n}")))
    assert hole.reason == "give x"


def test_arg_value_with_a_hole_flows_through() -> None:
    inner = (Hole("$(env R)", "not given"),)
    value = resolve("$(arg a)_link", scope({"a": inner}))
    assert value == (inner[0], "_link")


@pytest.mark.parametrize(
    ("source", "message"),
    [
        ("$(arg)", "must specify a variable name"),
        ("$(arg a b)", "may only specify one arg"),
        ("$(env)", "only accepts one argument"),
        ("$(env A B)", "only accepts one argument"),
        ("$(optenv)", "must specify an environment variable"),
        ("$(anon)", "must specify a name"),
        ("$(anon a b)", "may only specify one name"),
        ("$(find)", "only accepts one argument"),
        ("$(find a b)", "only accepts one argument"),
        ("$(foo bar)", "Unknown substitution command"),
        ("$( )", "Unknown substitution command"),
        (" $(eval 1)", "Unknown substitution command"),
    ],
)
def test_what_roslaunch_refuses(source: str, message: str) -> None:
    with pytest.raises(SubstitutionError, match=message):
        resolve(source, scope({"a": ("1",)}))


def test_env_reads_only_the_given_mapping() -> None:
    assert text(resolve("$(env ROBOT)", scope(env={"ROBOT": "r2"}))) == "r2"
    (hole,) = holes(resolve("$(env HOME)", scope()))
    assert "HOME" in hole.reason and "--env" in hole.reason


def test_optenv_default_is_the_remaining_words_joined_by_one_space() -> None:
    assert text(resolve("$(optenv X child   with  spaces)", scope())) == "child with spaces"
    assert text(resolve("$(optenv X dflt)", scope(env={"X": "set"}))) == "set"
    assert text(resolve("a$(optenv X)b", scope())) == "ab"


def test_dirname_is_the_folder_of_the_file_being_read() -> None:
    assert text(resolve("$(dirname)/x.launch", scope())) == "/ws/src/robot/launch/x.launch"


def test_anon_uses_the_scope_table() -> None:
    table: dict[str, str] = {}
    assert text(resolve("$(anon n) $(anon n) $(anon m)", scope(anon=table))) == (
        "n_anon1 n_anon1 m_anon2"
    )
    assert table == {"n": "n_anon1", "m": "m_anon2"}


@pytest.mark.parametrize(
    ("source", "expected"),
    [
        ("$(find robot)", "/ws/src/robot"),
        ("$(find robot)/launch/a.launch", "/ws/src/robot/launch/a.launch"),
        ("$(find robot)_suffix", "/ws/src/robot/_suffix"),
        ("$(find robot)//abs/path", "/abs/path"),
        ("$(find robot)/", "/ws/src/robot"),
        ("$(find robot)\\cfg\\x.yaml", "/ws/src/robot/cfg/x.yaml"),
        ("$(find robot)/a\tb c", "/ws/src/robot/a\tb c"),
        ("x $(find tools)/y $(find robot)", "x /ws/src/tools_dir/y /ws/src/robot"),
    ],
)
def test_find_joins_the_following_path_like_roslaunch(source: str, expected: str) -> None:
    assert text(resolve(source, scope())) == expected


def test_find_of_a_missing_package_is_a_hole_keeping_the_path() -> None:
    value = resolve("$(find absent)/launch/x.launch more", scope())
    assert text_of(value) == "$(find absent)/launch/x.launch more"
    (hole,) = holes(value)
    assert "absent" in hole.reason


def test_find_in_an_arg_value_is_resolved_by_the_second_pass() -> None:
    args = {"where": ("$(find robot)/cfg",), "bad": ("$(foo)",), "lit": ("$(env X)",)}
    assert text(resolve("$(arg where)", scope(args))) == "/ws/src/robot/cfg"
    # other commands in arg values stay literal, unknown ones are errors
    assert text(resolve("$(arg lit)", scope(args, env={"X": "1"}))) == "$(env X)"
    with pytest.raises(SubstitutionError, match="Unknown substitution command"):
        resolve("$(arg bad)", scope(args))


def test_find_path_running_into_a_hole_keeps_the_separator() -> None:
    args: dict[str, Value] = {"sub": (Hole("$(arg sub)", "not set"),)}
    value = resolve("$(find robot)/$(arg sub)/x.launch", scope(args))
    assert value[0] == "/ws/src/robot/"
    assert text_of(value) == "/ws/src/robot/$(arg sub)/x.launch"


# --- $(eval) -----------------------------------------------------------------------------


def test_eval_is_only_for_a_whole_value() -> None:
    args = {"n": ("3",), "name": ("base",)}
    assert text(resolve("$(eval n * 2 + 1)", scope(args))) == "7"
    assert text(resolve("$(eval name + '_link')", scope(args))) == "base_link"
    assert text(resolve("$(eval arg('n') > 2)", scope(args))) == "True"
    assert text(resolve("$(eval radians(180) == pi)", scope(args))) == "True"


def test_eval_refuses_double_underscores_like_roslaunch() -> None:
    with pytest.raises(SubstitutionError, match="double underscore"):
        resolve("$(eval __import__('os').system('true'))", scope())


def test_eval_outside_the_safe_language_is_a_hole() -> None:
    (hole,) = holes(resolve("$(eval 9**9**9)", scope()))
    assert "not evaluated" in hole.reason
    (hole,) = holes(resolve("$(eval open('/etc/passwd'))", scope()))
    assert hole.text == "$(eval open('/etc/passwd'))"


def test_eval_of_an_unknown_arg_is_a_hole_naming_it() -> None:
    args: dict[str, Value] = {"x": (Hole("$(env X)", "not given"),)}
    (hole,) = holes(resolve("$(eval x + 1)", scope(args)))
    assert "x" in hole.reason


# --- truthiness --------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("source", "truth"),
    [("true", True), ("1", True), (" TRUE ", True), ("True", True),
     ("false", False), ("0", False), ("\tFalse\n", False)],
)
def test_if_unless_truth(source: str, truth: bool) -> None:
    assert to_bool((source,)) is truth


@pytest.mark.parametrize("source", ["yes", "on", "2", "", "tru e"])
def test_if_unless_refuses_other_words(source: str) -> None:
    with pytest.raises(ValueError, match="is not a 'bool' type"):
        to_bool((source,) if source else ())


def test_unresolved_condition_is_unknown() -> None:
    assert to_bool((Hole("$(arg x)", "not set"),)) is None


def test_dirname_uses_the_absolute_folder() -> None:
    relative = SubstitutionScope({}, {}, PACKAGES.get, str, "rel/a.launch")
    assert text(resolve("$(dirname)", relative)) == os.path.abspath("rel")
