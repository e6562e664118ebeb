"""ROS 2 substitutions: the launch grammar, resolution, conditions, argv splitting."""

from __future__ import annotations

import contextlib
import os

import pytest
from hypothesis import given
from hypothesis import strategies as st

from launch_linter.resolve.ros2_substitution import (
    Call,
    Opaque,
    Ros2Scope,
    SubstitutionError,
    SubstitutionSyntaxError,
    Text,
    parse,
    resolve,
    split_command_line,
    to_bool,
    written,
)
from launch_linter.resolve.value import Hole, Value, is_resolved, resolved_text, text_of


def scope(configs: dict[str, str] | None = None, env: dict[str, str] | None = None,
          packages: dict[str, str] | None = None) -> Ros2Scope:
    names: dict[str, str] = {}

    def anon(name: str) -> str:
        return names.setdefault(name, f"{name}_anon{len(names) + 1}")

    return Ros2Scope(
        configs={k: (v,) if v else () for k, v in (configs or {}).items()},
        env=env or {},
        find=(packages or {}).get,
        anon=anon,
        filename="/ws/src/pkg/launch/robot.launch.xml",
    )


def text(source: str, context: Ros2Scope | None = None) -> str | None:
    return resolved_text(resolve(parse(source), context or scope()))


def value(source: str, context: Ros2Scope | None = None) -> Value:
    return resolve(parse(source), context or scope())


# -- grammar ---------------------------------------------------------------------------


def test_plain_text_is_one_text() -> None:
    assert parse("base_link") == (Text("base_link"),)
    assert parse("") == ()


def test_call_with_arguments_and_its_written_form() -> None:
    (call,) = parse("$(var frame)")
    assert isinstance(call, Call)
    assert (call.name, call.args, call.written) == ("var", ((Text("frame"),),), "$(var frame)")


def test_adjacent_text_and_calls() -> None:
    parts = parse("$(var robot)_base_link")
    assert isinstance(parts[0], Call) and parts[1] == Text("_base_link")


def test_nested_and_quoted_arguments() -> None:
    (call,) = parse("$(env HOME '/a default/$(var x)')")
    assert isinstance(call, Call) and call.name == "env"
    default = call.args[1]
    assert default[0] == Text("/a default/")
    assert isinstance(default[1], Call) and default[1].written == "$(var x)"


def test_backslash_escapes_a_dollar() -> None:
    assert parse(r"cost \$(not a call)") == (Text("cost $(not a call)"),)


@pytest.mark.parametrize(("source", "expected"), [
    # A backslash stays before a newline and at the end (launch's r'\\(.)').
    ("a\\\nb", (Text("a\\\nb"),)),
    ("a\\", (Text("a\\"),)),
    ("x$(env \"A B\" c)y$", (Text("x"), Call("env", ((Text("A B"),), (Text("c"),)),
                                            '$(env "A B" c)'), Text("y$"))),
    ("$(var 'a\\'b')", (Call("var", ((Text("a'b"),),), "$(var 'a\\'b')"),)),
    ("$(var a\\ b)", (Call("var", ((Text("a b"),),), "$(var a\\ b)"),)),
    ("$(find-pkg-share \u00e9_1)", (Call("find-pkg-share", ((Text("\u00e9_1"),),),
                                          "$(find-pkg-share \u00e9_1)"),)),
])
def test_text_runs_escapes_and_quotes(source: str, expected: tuple[object, ...]) -> None:
    # Plain text is taken in runs up to the next '$(' or backslash (or, in an argument,
    # the next character that matters): the result is the character-by-character one.
    assert parse(source) == expected


@pytest.mark.parametrize(("source", "position"), [
    ("$(var a'b)", 7), ("$(var $x)", 6), ("$(var 'open", 11),
])
def test_syntax_errors_say_where(source: str, position: int) -> None:
    with pytest.raises(SubstitutionSyntaxError) as raised:
        parse(source)
    assert raised.value.position == position


@pytest.mark.parametrize("source", ["$(var x", "$(var 'x)", "$()", "$(var x(y)"])
def test_malformed_substitutions_are_syntax_errors(source: str) -> None:
    with pytest.raises(SubstitutionSyntaxError):
        parse(source)


def test_deep_nesting_is_refused() -> None:
    source = "$(var " * 40 + "x" + ")" * 40
    with pytest.raises(SubstitutionSyntaxError):
        parse(source)


@given(st.text(alphabet=st.characters(blacklist_characters="$\\"), max_size=60))
def test_text_without_dollar_or_backslash_is_kept(source: str) -> None:
    assert written(parse(source)) == source


@given(st.text(max_size=60))
def test_parse_never_fails_otherwise(source: str) -> None:
    with contextlib.suppress(SubstitutionSyntaxError):
        parse(source)


# -- resolution ------------------------------------------------------------------------


def test_var_reads_configurations_and_falls_back_to_its_default() -> None:
    assert text("$(var frame)", scope({"frame": "laser"})) == "laser"
    assert text("$(var frame base_link)") == "base_link"
    (hole,) = value("$(var frame)")
    assert isinstance(hole, Hole) and hole.text == "$(var frame)"
    assert "--arg frame:=VALUE" in hole.reason


def test_nested_var_names() -> None:
    context = scope({"side": "left", "wheel_left": "wl_link"})
    assert text("$(var wheel_$(var side))", context) == "wl_link"


def test_env_reads_only_the_given_environment() -> None:
    assert text("$(env ROBOT)", scope(env={"ROBOT": "r2"})) == "r2"
    assert text("$(env ROBOT r1)") == "r1"
    assert not is_resolved(value("$(env ROBOT)"))


def test_find_pkg_share_uses_the_package_index() -> None:
    context = scope(packages={"robot": "/ws/src/robot"})
    assert text("$(find-pkg-share robot)/launch/a.launch.py", context) == (
        "/ws/src/robot/launch/a.launch.py"
    )
    assert not is_resolved(value("$(find-pkg-share other)/x", context))


@pytest.mark.parametrize("source", [
    "$(find-pkg-prefix robot)", "$(command 'ls /')", "$(find-exec ls)",
    "$(param use_sim_time)", "$(param robot_frame base_link)", "$(launch_log_dir)",
    "$(log_dir)",
])
def test_runtime_only_substitutions_are_unresolved(source: str) -> None:
    result = value(source)
    assert not is_resolved(result) and text_of(result) == source


def test_dirname_filename_and_anon() -> None:
    assert text("$(dirname)") == "/ws/src/pkg/launch"
    assert text("$(filename)") == "/ws/src/pkg/launch/robot.launch.xml"
    context = scope()
    assert text("$(anon tf) $(anon tf) $(anon other)", context) == "tf_anon1 tf_anon1 other_anon2"


def test_eval_goes_through_the_safe_interpreter() -> None:
    assert text("$(eval '$(var a) * 2')", scope({"a": "3"})) == "6"
    assert text("$(eval 'pi / 2')") == str(3.141592653589793 / 2)
    refused = value("$(eval '__import__(\"os\").system(\"true\")')")
    assert not is_resolved(refused)
    assert not is_resolved(value("$(eval '$(var unknown) + 1')"))


@pytest.mark.parametrize(("source", "expected"), [
    ("$(not true)", "false"),
    ("$(and true false)", "false"),
    ("$(or false 1)", "true"),
    ("$(equals $(var a) 2.0)", "true"),
    ("$(not-equals $(var a) 2)", "false"),
    ("$(if $(var on) yes no)", "yes"),
    ("$(and false $(var unset))", "false"),
])
def test_boolean_substitutions(source: str, expected: str) -> None:
    assert text(source, scope({"a": "2", "on": "true"})) == expected


def test_boolean_of_an_unknown_value_is_unknown() -> None:
    assert not is_resolved(value("$(or false $(var unset))"))


@pytest.mark.parametrize("source", [
    "$(optenv X)", "$(arg x)", "$(var)", "$(not a b)", "$(param)", "$(log_dir x)",
    "$(launch-log-dir)",
])
def test_what_launch_refuses_raises(source: str) -> None:
    with pytest.raises(SubstitutionError):
        value(source)


def test_opaque_parts_become_holes() -> None:
    assert resolve((Opaque("f(x)", "unknown"),), scope()) == (Hole("f(x)", "unknown"),)


@pytest.mark.parametrize(("word", "truth"), [
    ("true", True), (" True ", True), ("1", True), ("false", False), ("FALSE", False),
    ("0", False),
])
def test_condition_truth(word: str, truth: bool) -> None:
    assert to_bool((word,)) is truth


def test_condition_truth_refuses_other_words_and_waits_for_holes() -> None:
    with pytest.raises(ValueError):
        to_bool(("yes",))
    assert to_bool((Hole("$(var x)", "unset"),)) is None


# -- argv ------------------------------------------------------------------------------


def items(source: str, context: Ros2Scope | None = None) -> list[str]:
    return [text_of(resolve(item, context or scope())) for item in
            split_command_line(parse(source))]


def test_literal_text_is_split_like_a_shell() -> None:
    assert items("--x 1  --frame-id 'base link'") == ["--x", "1", "--frame-id", "base link"]


def test_a_substitution_is_one_argument_whatever_its_value() -> None:
    context = scope({"all": "0 0 0 0 0 0 a b"})
    assert items("$(var all)", context) == ["0 0 0 0 0 0 a b"]


def test_substitutions_join_the_text_they_touch() -> None:
    context = scope({"robot": "r1"})
    assert items("--frame-id $(var robot)_base --child-frame-id $(var robot)/laser x", context) == [
        "--frame-id", "r1_base", "--child-frame-id", "r1/laser", "x",
    ]
    assert items("$(var robot) $(var robot)", context) == ["r1", "r1"]


def test_dirname_path_example() -> None:
    assert items("$(dirname)/a.yaml b") == [os.path.join("/ws/src/pkg/launch", "a.yaml"), "b"]
