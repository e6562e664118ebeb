"""Rendering: literals that cannot break out, sorted belief tables, refusal of raw text."""

from __future__ import annotations

import ast

import jinja2
import pytest
from hypothesis import given
from hypothesis import strategies as st
from standalone_helpers import HOSTILE

from launch_linter.generate.embed import Embedding, Module
from launch_linter.generate.render import (
    Code,
    RenderError,
    RenderOptions,
    belief_rows,
    environment,
    py_literal,
    render,
    source_literal,
)
from launch_linter.model.beliefs import BELIEF_CLASSES, BeliefSet
from launch_linter.model.diagnostic import Belief

OPTIONS = RenderOptions("bundled", 1.0, BELIEF_CLASSES, "0.0.test", "launch-linter generate")
TINY = Embedding(
    (Module("launch_linter", "launch_linter/__init__.py", True, '"""Doc."""\n', "0" * 64),),
    ("note: 'quoted' {{ x }}\nnew line",),
)


@given(st.text())
def test_string_literals_read_back_exactly_and_stay_on_one_ascii_line(text: str) -> None:
    literal = py_literal(text)
    assert ast.literal_eval(literal) == text
    assert literal.isascii() and "\n" not in literal and "\r" not in literal


@pytest.mark.parametrize("name", HOSTILE)
def test_hostile_names_become_plain_string_literals(name: str) -> None:
    literal = py_literal((name, "child"))
    node = ast.parse(literal, mode="eval").body
    assert isinstance(node, ast.Tuple) and all(isinstance(e, ast.Constant) for e in node.elts)
    assert ast.literal_eval(literal) == (name, "child")


def test_numbers_and_nested_values() -> None:
    assert py_literal(1.05) == "1.05" and ast.literal_eval(py_literal(0.1 + 0.2)) == 0.1 + 0.2
    assert py_literal(("a",)) == "('a',)"
    assert py_literal([("a", "b"), None, True, 3]) == "[('a', 'b'), None, True, 3]"
    assert py_literal(float("inf")) == "float('inf')"
    with pytest.raises(RenderError):
        py_literal({"a": 1})


@given(st.text())
def test_source_literals_read_back_exactly(text: str) -> None:
    literal = source_literal(text)
    assert ast.literal_eval(literal) == "\n" + text


def test_source_literals_are_raw_when_that_is_exact() -> None:
    source = 'import re\n\nPATTERN = re.compile(r"\\d+")\n"""Doc."""\n'
    assert source_literal(source) == "r'''\n" + source + "'''"
    for awkward in ("a = '''x'''\n", "ends with a backslash \\", "carriage\r\n"):
        literal = source_literal(awkward)
        assert not literal.startswith("r")
        assert ast.literal_eval(literal) == "\n" + awkward


def _belief(cls: str, antecedent: object, consequent: object = None, z: float = 1.5) -> Belief:
    return Belief(cls, antecedent, consequent, 10, 9, z)  # type: ignore[arg-type]


def test_rows_are_sorted_by_antecedent_then_consequent() -> None:
    beliefs = [
        _belief("sig_implication", ("b", "c"), ("x", "y")),
        _belief("sig_implication", ("a", "z"), ("q", "r")),
        _belief("sig_implication", ("a", "z"), ("b", "c"), z=3.0),
        _belief("name_null_rot", "map_to_odom"),
    ]
    rows = [ast.literal_eval(r) for r in belief_rows(beliefs, "sig_implication")]
    assert rows == [
        (("a", "z"), ("b", "c"), 10, 9, 3.0),
        (("a", "z"), ("q", "r"), 10, 9, 1.5),
        (("b", "c"), ("x", "y"), 10, 9, 1.5),
    ]
    assert [ast.literal_eval(r) for r in belief_rows(beliefs, "name_null_rot")] == [
        ("map_to_odom", 10, 9, 1.5)
    ]


def test_a_null_belief_with_a_consequent_is_refused() -> None:
    with pytest.raises(RenderError):
        belief_rows([_belief("sig_null_disp", ("a", "b"), ("c", "d"))], "sig_null_disp")


def test_the_template_environment_refuses_raw_text() -> None:
    env = environment()
    assert env.from_string("x = {{ v|py }}").render(v="a'b\n") == 'x = "a\'b\\n"'
    assert env.from_string("{{ v }}").render(v=Code("ok")) == "ok"
    with pytest.raises(RenderError):
        env.from_string("{{ v }}").render(v="raw")
    with pytest.raises(jinja2.UndefinedError):
        env.from_string("{{ missing }}").render()


def test_render_is_deterministic_and_python() -> None:
    beliefs = BeliefSet("bundled", 1.0, (_belief("name_null_rot", "a"),))
    first, second = render(beliefs, TINY, OPTIONS), render(beliefs, TINY, OPTIONS)
    assert first == second
    tree = ast.parse(first, feature_version=(3, 8))
    assert isinstance(tree, ast.Module)
    # The note went in through py_literal: escaped, on one line.
    assert py_literal(TINY.notes[0]) in first and "\nnew line" not in first


def test_classes_not_selected_leave_empty_tables() -> None:
    beliefs = BeliefSet(
        "bundled", 1.0, (_belief("name_null_rot", "a"), _belief("name_null_disp", "b"))
    )
    options = RenderOptions("bundled", 1.0, ("name_null_rot",), "0", "c")
    text = render(beliefs, TINY, options)
    assert "NAME_NULL_ROT = [\n    # (node name, n, e, z)\n    ('a', 10, 9, 1.5),\n]" in text
    assert "NAME_NULL_DISP = [\n    # (node name, n, e, z)\n]" in text
    with pytest.raises(RenderError):
        render(beliefs, TINY, RenderOptions("bundled", 1.0, ("nonsense",), "0", "c"))


def test_modules_with_unsafe_names_are_refused() -> None:
    bad = Embedding((Module("x\nimport os", "x.py", False, "", "0" * 64),), ())
    with pytest.raises(RenderError):
        render(BeliefSet.empty(), bad, OPTIONS)
