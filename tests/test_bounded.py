"""The bounded operations and limits shared by the two interpreters of launch-file Python."""

from __future__ import annotations

import pytest

from launch_linter.frontends.ros2_python import evaluator, launch_api, values
from launch_linter.resolve import bounded, eval_interpreter, safe_eval
from launch_linter.resolve.bounded import (
    Refused,
    check_join,
    format_fields,
    percent_refusal,
    string_method,
)


def test_both_interpreters_take_their_limits_from_one_module() -> None:
    assert safe_eval.MAX_ITEMS is bounded.EVAL_MAX_ITEMS
    assert eval_interpreter.MAX_WORK is bounded.EVAL_MAX_WORK
    assert evaluator.MAX_TEXT is bounded.PYTHON_MAX_TEXT
    assert evaluator.MAX_STEPS is bounded.PYTHON_MAX_STEPS


@pytest.mark.parametrize("template", ["%s", "%5.2f", "%-3d%%", "%(name)s", "100%% sure"])
def test_bounded_percent_fields_pass(template: str) -> None:
    assert percent_refusal(template, 999) is None


@pytest.mark.parametrize(
    ("template", "words"),
    [("%*d", "'*' field widths"), ("%1000s", "above 999"), ("%.5000f", "above 999"),
     ("%9999999s", "above 999")],
)
def test_unbounded_percent_fields_are_refused(template: str, words: str) -> None:
    refusal = percent_refusal(template, 999)
    assert refusal is not None and words in refusal


def test_format_fields_give_texts_and_argument_indices() -> None:
    assert list(format_fields("a{}b{}c")) == [("a", 0), ("b", 1), ("c", None)]
    assert list(format_fields("{1}-{0}")) == [("", 1), ("-", 0)]
    assert list(format_fields("plain")) == [("plain", None)]


@pytest.mark.parametrize(("template", "words"),
                         [("{:>99999}", "not interpreted"), ("{0!r}", "not interpreted"),
                          ("{a.b}", "not interpreted"), ("{", "malformed")])
def test_format_fields_refuse_specs_lookups_and_bad_templates(template: str, words: str) -> None:
    with pytest.raises(Refused) as refused:
        list(format_fields(template))
    assert words in refused.value.reason


def test_string_methods_are_sized_before_they_run() -> None:
    assert string_method("robot/base", "split", ("/",), 100) == ["robot", "base"]
    assert string_method("a_b", "replace", ("_", "/"), 100) == "a/b"
    with pytest.raises(Refused, match="too long"):
        string_method("a" * 50, "replace", ("a", "bbb"), 100)
    with pytest.raises(Refused, match="not supported"):
        string_method("a", "center", (10**9,), 100)
    with pytest.raises(Refused, match="empty separator"):
        string_method("a b", "split", ("",), 100)
    with pytest.raises(Refused, match="too long"):
        check_join("--", ["x" * 40, "y" * 40], 80)
    check_join("--", ["x" * 39, "y" * 39], 80)


def test_the_launch_api_is_an_explicit_table() -> None:
    assert values.ACTION_NAMES.issubset(launch_api.HANDLERS)
    assert launch_api.HANDLERS["Node"] is launch_api.Interpreter.launch_Node
    assert launch_api.HANDLERS["PushROSNamespace"] is launch_api.HANDLERS["PushRosNamespace"]
    assert all(callable(handler) for handler in launch_api.HANDLERS.values())
