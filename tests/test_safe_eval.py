"""Tests for launch_linter.resolve.safe_eval, the interpreter behind ``$(eval ...)``.

Python's own ``eval`` appears here only as a test oracle, on text these tests generate.
"""

from __future__ import annotations

import math
import warnings
from collections.abc import Mapping

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from launch_linter.resolve.safe_eval import (
    MAX_INT_BITS,
    EvalError,
    EvalScope,
    EvalUnresolved,
    evaluate,
)


def make_scope(
    args: Mapping[str, str | None] | None = None,
    env: Mapping[str, str] | None = None,
    packages: Mapping[str, str] | None = None,
    dirname: str | None = "/ws/src/demo/launch",
) -> EvalScope:
    known = dict(packages or {})
    return EvalScope(
        args=dict(args or {}),
        env=dict(env or {}),
        find=known.get,
        anon=lambda id_: f"{id_}_host_1234_5678",
        dirname=dirname,
    )


def run(source: str, **args: str | None) -> str:
    return evaluate(source, make_scope(args=args))


def refused(source: str, scope: EvalScope | None = None) -> EvalError:
    """The refusal of ``source``, which must be a plain EvalError (not "unresolved")."""
    with pytest.raises(EvalError) as info:
        evaluate(source, scope or make_scope())
    assert not isinstance(info.value, EvalUnresolved), info.value.reason
    assert info.value.reason
    return info.value


def python_oracle(source: str) -> str | None:
    """str() of Python's own result, or None where Python raises."""
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", SyntaxWarning)
            value = eval(source, {"__builtins__": {}}, {})  # test oracle on generated text only
    except (ArithmeticError, TypeError, ValueError, LookupError):
        return None
    if isinstance(value, complex):
        return None
    return str(value)


# --- agreement with Python on generated expressions ------------------------------------

_NUMBERS = st.one_of(
    st.integers(min_value=0, max_value=60).map(str),
    st.sampled_from(["0.0", "0.5", "0.1", "1.25", "2.0", "3.75", "10.0", "1e-3", "2.5e2"]),
)


def _arithmetic(children: st.SearchStrategy[str]) -> st.SearchStrategy[str]:
    binary = st.tuples(children, st.sampled_from(["+", "-", "*", "/", "//", "%"]), children)
    # Powers only of literals, so no intermediate value leaves the bounds.
    power = st.tuples(_NUMBERS, st.sampled_from(["0", "1", "2", "3", "-1", "-2", "0.5", "1.5"]))
    return st.one_of(
        binary.map(lambda t: f"({t[0]} {t[1]} {t[2]})"),
        power.map(lambda t: f"({t[0]} ** {t[1]})"),
        children.map(lambda c: f"(-{c})"),
        children.map(lambda c: f"(+{c})"),
    )


ARITHMETIC = st.recursive(_NUMBERS, _arithmetic, max_leaves=12)


@settings(max_examples=400, deadline=None)
@given(ARITHMETIC)
def test_arithmetic_matches_python(source: str) -> None:
    expected = python_oracle(source)
    if expected is None:
        refused(source)
    else:
        assert run(source) == expected


_MIXED_LEAVES = st.sampled_from(
    ["0", "1", "2", "3", "-1", "0.5", "True", "False", "None", "''", "'a'", "'ab'", "'b'"]
)


def _mixed(children: st.SearchStrategy[str]) -> st.SearchStrategy[str]:
    compare_ops = st.sampled_from(["==", "!=", "<", "<=", ">", ">=", "in", "not in"])
    return st.one_of(
        st.tuples(children, st.sampled_from(["and", "or", "+", "-", "*"]), children).map(
            lambda t: f"({t[0]} {t[1]} {t[2]})"
        ),
        st.lists(st.tuples(compare_ops, children), min_size=1, max_size=3).flatmap(
            lambda rest: children.map(
                lambda first: "(" + first + "".join(f" {op} {c}" for op, c in rest) + ")"
            )
        ),
        st.tuples(children, children, children).map(lambda t: f"({t[0]} if {t[1]} else {t[2]})"),
        children.map(lambda c: f"(not {c})"),
        st.lists(children, max_size=3).map(lambda items: "[" + ", ".join(items) + "]"),
        st.lists(children, max_size=3).map(
            lambda items: "(" + "".join(f"{i}," for i in items) + ")"
        ),
        st.tuples(children, st.sampled_from(["0", "1", "-1", "5"])).map(
            lambda t: f"{t[0]}[{t[1]}]"
        ),
        st.tuples(
            children,
            st.sampled_from(["", "0", "1", "-1"]),
            st.sampled_from(["", "2", "-1"]),
            st.sampled_from(["", ":2", ":-1", ":0"]),
        ).map(lambda t: f"{t[0]}[{t[1]}:{t[2]}{t[3]}]"),
    )


MIXED = st.recursive(_MIXED_LEAVES, _mixed, max_leaves=10)


@settings(max_examples=400, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(MIXED)
def test_logic_strings_and_containers_match_python(source: str) -> None:
    expected = python_oracle(source)
    if expected is None:
        refused(source)
    else:
        assert run(source) == expected


def roslaunch_auto(value: str) -> object:
    """roslaunch's convert_value(value, 'auto'), including its rule for underscores."""
    try:
        if "." in value:
            return float(value)
        if "_" in value:
            raise ValueError(value)
        return int(value)
    except ValueError:
        pass
    if value.lower() in ("true", "false"):
        return value.lower() == "true"
    return value


# fmt: off
ARG_VALUES = st.one_of(
    st.text(max_size=12),
    st.sampled_from([
        "1", "-2", " 3 ", "1.5", "1.", ".5", ".", "1_0", "1_0.5", "1e3", "1.5e3", "inf", "nan",
        "-inf.", "true", "FALSE", "True ", "yes", "0x10", "007", "\u0663", "a.b",
    ]),
)
# fmt: on


@settings(max_examples=300, deadline=None)
@given(ARG_VALUES)
def test_args_are_converted_like_roslaunch(value: str) -> None:
    expected = str(roslaunch_auto(value))
    assert run("x", x=value) == expected
    assert run("arg('x')", x=value) == expected


# fmt: off
_TOKENS = st.sampled_from([
    "1", "2.5", "0", "10", "9", "'a'", "'x'", "'%s'", "x", "e", "pi", "sin", "len", "list", "map",
    "dict", "str", "int", "float", "round", "min", "max", "bool", "abs", "arg", "env", "optenv",
    "None", "True", "(", ")", "[", "]", "{", "}", ",", ":", ".", "+", "-", "*", "**", "/", "//",
    "%", "==", "<", " in ", " and ", " or ", " not ", " if ", " else ",
])
# fmt: on


@settings(max_examples=500, deadline=None)
@given(st.lists(_TOKENS, max_size=25).map("".join))
def test_arbitrary_token_soup_only_ever_raises_eval_error(source: str) -> None:
    try:
        result = evaluate(source, make_scope(args={"x": "3"}, env={"V": "v"}))
    except EvalError:
        return
    assert isinstance(result, str)


# --- roslaunch behaviour ---------------------------------------------------------------


@pytest.mark.parametrize(
    ("source", "args", "expected"),
    [
        # roslaunch's auto conversion turns "true" into True, so this compares a bool to text:
        # a classic launch-file bug that the linter must reproduce, not fix.
        ("arg('use_sim') == 'true'", {"use_sim": "true"}, "False"),
        ("arg('use_sim') == True", {"use_sim": "true"}, "True"),
        ("use_sim", {"use_sim": "TRUE"}, "True"),
        ("not use_sim", {"use_sim": "false"}, "True"),
        ("arg('mode') == 'sim'", {"mode": "sim"}, "True"),
        ("x + 1", {"x": "2"}, "3"),
        ("x * 2", {"x": "1.5"}, "3.0"),
        ("'a' + name", {"name": "b"}, "ab"),
        ("name + '_' + str(x)", {"name": "robot", "x": "7"}, "robot_7"),
        ("x + '!'", {"x": "1_0"}, "1_0!"),
        ("x + '!'", {"x": "1e3"}, "1e3!"),
        ("x + '!'", {"x": "inf"}, "inf!"),
        ("'on' if rate > 10 else 'off'", {"rate": "20"}, "on"),
        ("1 < x < 3", {"x": "2"}, "True"),
        ("1 < x < 3", {"x": "3"}, "False"),
        ("x or 'default'", {"x": ""}, "default"),
        ("x and 'set'", {"x": "0"}, "0"),
    ],
)
def test_roslaunch_examples(source: str, args: dict[str, str], expected: str) -> None:
    assert evaluate(source, make_scope(args=args)) == expected


def test_math_names_come_before_args() -> None:
    assert run("pi/2") == str(math.pi / 2)
    assert run("e", e="5") == str(math.e)
    assert run("pi", pi="3") == str(math.pi)
    assert run("tau + inf") == "inf"


def test_args_come_before_builtins() -> None:
    assert run("len", len="3") == "3"
    assert run("len('abc')") == "3"


@pytest.mark.parametrize(
    ("source", "expected"),
    [
        ("radians(90)", str(math.radians(90))),
        ("degrees(pi)", "180.0"),
        ("atan2(1, 1)", str(math.atan2(1, 1))),
        ("sqrt(2)", str(math.sqrt(2))),
        ("floor(2.7)", "2"),
        ("ceil(2.1)", "3"),
        ("cos(0)", "1.0"),
        ("factorial(20)", "2432902008176640000"),
        ("comb(10, 3)", "120"),
        ("hypot(3, 4)", "5.0"),
        ("fsum([0.1] * 10)", "1.0"),
        ("frexp(8.0)", "(0.5, 4)"),
        ("isnan(nan)", "True"),
        ("log(8, 2)", "3.0"),
        ("gcd(12, 18)", "6"),
    ],
)
def test_math_functions(source: str, expected: str) -> None:
    assert run(source) == expected


@pytest.mark.parametrize(
    ("source", "expected"),
    [
        ("str(1.0)", "1.0"),
        ("str()", ""),
        ("int('7') + int(2.9) + int(True)", "10"),
        ("int('ff', 16)", "255"),
        ("float('2')", "2.0"),
        ("float()", "0.0"),
        ("list('ab')", "['a', 'b']"),
        ("list((1, 2))", "[1, 2]"),
        ("list({'a': 1})", "['a']"),
        ("dict([('a', 1)])['a']", "1"),
        ("dict()", "{}"),
        ("list(map(int, ['1', '2']))", "[1, 2]"),
        ("list(map(max, [1, 5], [4, 2]))", "[4, 5]"),
        ("list(map(sin, [0]))", "[0.0]"),
        ("len([1, 2]) + len('abc') + len({})", "5"),
        ("abs(-2) + abs(-0.5)", "2.5"),
        ("round(2.5)", "2"),
        ("round(2.675, 2)", "2.67"),
        ("round(1234, -2)", "1200"),
        ("round(10 ** 1000, -10 ** 9)", "0"),
        ("min(3, 1, 2)", "1"),
        ("max([1, 5])", "5"),
        ("min('bca')", "a"),
        ("bool('')", "False"),
        ("bool([0])", "True"),
    ],
)
def test_whitelisted_builtins(source: str, expected: str) -> None:
    assert run(source) == expected


@pytest.mark.parametrize(
    ("source", "expected"),
    [
        ("True", "True"),
        ("1 == 1", "True"),
        ("None", "None"),
        ("3/2", "1.5"),
        ("1/3", str(1 / 3)),
        ("0.1 + 0.2", str(0.1 + 0.2)),
        ("2 ** -1", "0.5"),
        ("-7 // 2", "-4"),
        ("-7 % 3", "2"),
        ("'abc'", "abc"),
        ("'ab' * 3", "ababab"),
        ("3 * 'ab'", "ababab"),
        ("'abcdef'[1:4]", "bcd"),
        ("'abcdef'[::-2]", "fdb"),
        ("[1, 2, 3][-1]", "3"),
        ("(1, 2, 3)[::2]", "(1, 3)"),
        ("(1,)", "(1,)"),
        ("[1, 'a', (2.5, None)]", "[1, 'a', (2.5, None)]"),
        ("{'a': [1, 2]}", "{'a': [1, 2]}"),
        ("{'a': 1, 'b': 2}['b']", "2"),
        ("'b' in 'abc'", "True"),
        ("2 not in [1, 2]", "False"),
        ("'k' in {'k': 1}", "True"),
        ("'%s_%03d' % ('cam', 7)", "cam_007"),
        ("'%(a)s!' % {'a': 1}", "1!"),
        ("'100%%' % ()", "100%"),
        ("None is None", "True"),
        ("x is not None", "True"),
        ("  1 + 1", "2"),
        ("\t'indented'", "indented"),
        ("(1 +\n 2)", "3"),
    ],
)
def test_values_print_like_python(source: str, expected: str) -> None:
    assert evaluate(source, make_scope(args={"x": "1"})) == expected


def test_environment_package_anon_and_dirname() -> None:
    scope = make_scope(env={"HOME": "/home/me"}, packages={"demo": "/ws/src/demo"})
    assert evaluate("optenv('HOME2', 'd')", scope) == "d"
    assert evaluate("optenv('HOME2')", scope) == ""
    assert evaluate("optenv('HOME', 'd')", scope) == "/home/me"
    assert evaluate("env('HOME') + '/x'", scope) == "/home/me/x"
    assert evaluate("find('demo') + '/config'", scope) == "/ws/src/demo/config"
    assert evaluate("anon('node')", scope) == "node_host_1234_5678"
    assert evaluate("dirname() + '/a.yaml'", scope) == "/ws/src/demo/launch/a.yaml"


# --- unresolved values -----------------------------------------------------------------


@pytest.mark.parametrize(
    ("source", "name"),
    [
        ("arg('x')", "x"),
        ("x + 1", "x"),
        ("arg('missing')", "missing"),
        ("env('V')", "V"),
        ("find('nopkg')", "nopkg"),
        ("dirname()", "dirname"),
        ("1 if arg('x') else 2", "x"),
    ],
)
def test_unknown_values_are_unresolved(source: str, name: str) -> None:
    scope = make_scope(args={"x": None}, dirname=None)
    with pytest.raises(EvalUnresolved) as info:
        evaluate(source, scope)
    assert info.value.name == name
    assert info.value.reason


def test_short_circuit_skips_unresolved_operands() -> None:
    scope = make_scope(args={"x": None})
    assert evaluate("True or x", scope) == "True"
    assert evaluate("'a' if True else arg('x')", scope) == "a"


def test_undefined_bare_name_is_an_error_not_unresolved() -> None:
    error = refused("missing + 1")
    assert error.reason == "name 'missing' is not defined"


# --- refusals --------------------------------------------------------------------------

HOSTILE = [
    "__import__('os')",
    "().__class__",
    "''.__class__.__mro__[1].__subclasses__()",
    "'a__b'",
    "open('x')",
    "eval('1')",
    "exec('1')",
    "compile('1', 'f', 'eval')",
    "getattr(1, 'real')",
    "globals()",
    "vars()",
    "type(1)",
    "range(10)",
    "9**9**9",
    "10 ** 10 ** 5",
    "'a'*10**9",
    "[1]*10**9",
    "[[1] * 1000] * 10 ** 6",
    "'ab' * 500000 + 'c'",
    "(" * 1000 + "1" + ")" * 1000,
    "[" * 1000 + "1" + "]" * 1000,
    "-" * 1000 + "1",
    "not " * 1000 + "1",
    "-" * 9999 + "1",
    "1+" * 10_000 + "1",
    "'" + "a" * 20_000 + "'",
    "[" + ",".join(["1"] * 2500) + "]",
    "lambda: 1",
    "(lambda: 1)()",
    "[i for i in 'ab']",
    "{i: 1 for i in 'ab'}",
    "(i for i in 'ab')",
    "'abc'.format(1)",
    "(1).bit_length()",
    "'a'.__len__()",
    "x.real",
    "f'{1}'",
    "(y := 1)",
    "[*'ab']",
    "{1, 2}",
    "b'bytes'",
    "1j",
    "...",
    "1 << 10",
    "~1",
    "1 & 1",
    "optenv('A', default='b')",
    "sin",
    "[sin]",
    "map(abs, [1])",
    "str({'f': sin})",
    "'%s' % sin",
    "10.0 ** 400",
    "2 ** 10001",
    "(3 ** 10000) ** 7",
    "(2 ** 10000) ** 5 * (2 ** 10000) ** 6",
    "factorial(10 ** 6)",
    "factorial(100000)",
    "comb(10 ** 6, 500000)",
    "prod([2 ** 9000] * 20)",
    "'%0999999999d' % 1",
    "'%.999999999f' % 1.0",
    "'%*d' % (999999999, 1)",
    "int('9' * 20000)",
    "len(list(map(abs, [0] * 999999)))",
    "(-8) ** 0.5",
    "1/0",
    "1//0",
    "1 % 0",
    "1.0 / 0",
    "'a' + 1",
    "[1] < 'a'",
    "len(1)",
    "1 is 1",
    "[1, 2][5]",
    "{}['k']",
    "'abc'[1.0]",
    "1(2)",
    "1 +",
    "",
]


def _short_id(source: str) -> str:
    return source if len(source) <= 40 else f"{source[:30]}...({len(source)} chars)"


@pytest.mark.parametrize("source", HOSTILE, ids=_short_id)
def test_hostile_and_invalid_input_is_refused(source: str) -> None:
    refused(source, make_scope(args={"x": "1"}))


def test_refusal_reasons_are_specific() -> None:
    assert "double underscore" in refused("__import__('os')").reason
    assert "10,000" in refused("9**9**9").reason
    assert "1,000,000" in refused("'a'*10**9").reason
    assert "10,000 characters" in refused("1+" * 10_000 + "1").reason
    assert "nested" in refused("not " * 1000 + "1").reason
    assert "syntax nodes" in refused("[" + ",".join(["1"] * 2500) + "]").reason
    assert "attribute" in refused("'a'.format()").reason
    assert "builtin 'open'" in refused("open('x')").reason
    assert "division by zero" in refused("1/0").reason
    assert "too much work" in refused("len(list(map(abs, [0] * 999999)))").reason


@pytest.mark.parametrize(
    ("source", "expected"),
    [
        ("len('a' * 1000000)", "1000000"),
        ("len([1] * 1000000)", "1000000"),
        ("len([[1] * 1000] * 1000)", "1000"),
        ("len('' * 10 ** 9)", "0"),
        ("len([] * 10 ** 9)", "0"),
        ("2 ** 10000 > 0", "True"),
        ("(3 ** 10000) ** 6 > 0", "True"),
        ("1 ** 100000", "1"),
        ("(-1) ** 100001", "-1"),
        ("0 ** 100000", "0"),
        ("2.0 ** 0.5", str(2.0**0.5)),
        ("1e308 * 10", "inf"),
    ],
)
def test_values_just_inside_the_bounds(source: str, expected: str) -> None:
    assert run(source) == expected


def test_largest_integer_is_allowed_and_one_more_bit_is_not() -> None:
    assert MAX_INT_BITS == 100_000
    assert run("(2 ** 10000) ** 9 * 2 ** 9999 == 2 ** 9999 * (2 ** 10000) ** 9") == "True"
    refused("(2 ** 10000) ** 9 * 2 ** 10000")


@pytest.mark.parametrize(
    ("source", "expected"),
    [
        ("'_'.join(name.split('/'))", "robot_base_link"),
        ("name.upper()", "ROBOT/BASE_LINK"),
        ("name.replace('/', '_')", "robot_base_link"),
        ("name.split('/')[-1]", "base_link"),
        ("name.startswith('robot')", "True"),
        ("' x '.strip()", "x"),
    ],
)
def test_the_string_methods_launch_files_use(source: str, expected: str) -> None:
    assert evaluate(source, make_scope(args={"name": "robot/base_link"})) == expected


@pytest.mark.parametrize(
    "source",
    [
        "('a' * 1000).replace('a', 'a' * 2000)",
        "'ab'.join(['x' * 500000, 'y' * 600000])",
        "'-'.join([1, 2])",
        "'a'.join(1)",
        "(1).real",
        "[1].append(2)",
    ],
)
def test_string_methods_are_bounded_and_only_on_text(source: str) -> None:
    refused(source)
