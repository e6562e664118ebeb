"""ROS 2 static_transform_publisher arguments, decoded as the program reads them."""

from __future__ import annotations

import math

import pytest
from hypothesis import given
from hypothesis import strategies as st

from launch_linter.decode_ros2 import ComponentParam, decode_component, decode_ros2, stod
from launch_linter.model.transform import ArgIssue, NumberIssue, Rotation, RotationKind
from launch_linter.rules import (
    component_default_frames,
    py_arguments_single_string,
    ros2_bad_flag,
    ros2_positional_args,
)

_WORDING = (ros2_positional_args, ros2_bad_flag, py_arguments_single_string,
            component_default_frames)


def message(issue: ArgIssue) -> str:
    """The decoder gives facts; the issue's rule words them."""
    return next(m for m in (rule.message(issue) for rule in _WORDING) if m is not None)


def argv(words: str) -> list[str]:
    return words.split()


def kinds(words: str | list[str]) -> list[str]:
    items = words.split() if isinstance(words, str) else words
    return [issue.kind for issue in decode_ros2(items).arg_issues]


# -- std::stod ---------------------------------------------------------------------------


@pytest.mark.parametrize(("word", "expected"), [
    ("1.5", (1.5, "ok")),
    (" -2", (-2.0, "ok")),
    (".5e1", (5.0, "ok")),
    ("0x1p3", (8.0, "ok")),
    ("1.5m", (1.5, "partial")),
    ("pi/2", (None, "invalid")),
    ("", (None, "invalid")),
    ("1e400", (None, "range")),
    ("1e-400", (None, "range")),
    ("0e-999", (0.0, "ok")),
    # Short plain decimals (read directly) and what looks like one but is not.
    ("1.", (1.0, "ok")),
    ("+.25", (0.25, "ok")),
    ("-0", (-0.0, "ok")),
    ("0.000000000000000001", (1e-18, "ok")),
    ("1..5", (1.0, "partial")),
    ("1 ", (1.0, "partial")),
    # Digits of other scripts are not digits to the C library.
    ("\u0663", (None, "invalid")),
    ("1\u0663", (1.0, "partial")),
])
def test_stod(word: str, expected: tuple[float | None, str]) -> None:
    assert stod(word) == expected


def test_stod_reads_nan_and_inf() -> None:
    nan, status = stod("nan")
    assert nan is not None and math.isnan(nan) and status == "ok"
    assert stod("-inf") == (-math.inf, "ok")


@given(st.floats(allow_nan=False, allow_infinity=False))
def test_stod_reads_what_python_prints(number: float) -> None:
    value, status = stod(repr(number))
    if number != 0 and abs(number) < 2.2250738585072014e-308:
        assert status == "range"  # glibc reports subnormal results as out of range
    else:
        assert (value, status) == (number, "ok")


# -- flags -------------------------------------------------------------------------------


def test_flags() -> None:
    decoded = decode_ros2(
        argv("--x 1 --y -2 --z 0.5 --roll 0.1 --pitch 0.2 --yaw 0.3 "
        "--frame-id base_link --child-frame-id laser")
    )
    assert (decoded.form, decoded.parent, decoded.child) == ("ypr", "base_link", "laser")
    assert decoded.translation == (1.0, -2.0, 0.5)
    assert decoded.rotation == Rotation(RotationKind.YPR, (0.3, 0.2, 0.1))
    assert (decoded.arity_issue, decoded.number_issues, decoded.arg_issues) == (None, (), ())


def test_flags_default_to_the_identity() -> None:
    decoded = decode_ros2(["--frame-id", "map", "--child-frame-id", "odom"])
    assert decoded.translation == (0.0, 0.0, 0.0)
    assert decoded.rotation is not None and decoded.rotation.is_null


def test_quaternion_flags() -> None:
    decoded = decode_ros2(
        argv("--qz 0.7071068 --qw 0.7071068 --frame-id a --child-frame-id b")
    )
    assert decoded.form == "quaternion"
    assert decoded.rotation == Rotation(RotationKind.QUATERNION, (0.0, 0.0, 0.7071068, 0.7071068))
    assert decoded.arg_issues == ()


def test_a_partial_quaternion_that_is_not_unit_length() -> None:
    decoded = decode_ros2(argv("--qx 1 --frame-id a --child-frame-id b"))
    assert decoded.rotation == Rotation(RotationKind.QUATERNION, (1.0, 0.0, 0.0, 1.0))
    assert [i.kind for i in decoded.arg_issues] == ["partial_quaternion"]
    assert "(1, 0, 0, 1)" in message(decoded.arg_issues[0])


def test_rpy_together_with_a_quaternion() -> None:
    decoded = decode_ros2(argv("--yaw 1 --qw 1 --frame-id a --child-frame-id b"))
    assert kinds("--yaw 1 --qw 1 --frame-id a --child-frame-id b") == ["rpy_and_quaternion"]
    assert decoded.rotation is None


@pytest.mark.parametrize(("words", "suggestion"), [
    ("--yaw_deg 90", "'--yaw'"),
    ("--frame_id x", "'--frame-id'"),
    ("-- yaw 1", "'--yaw', without the space"),
])
def test_unknown_flags_with_a_suggestion(words: str, suggestion: str) -> None:
    decoded = decode_ros2(argv(f"--x 1 {words} --frame-id a --child-frame-id b"))
    (issue,) = decoded.arg_issues
    assert issue.kind == "unknown_flag" and suggestion in message(issue)
    assert "Extra unparsed arguments" in message(issue)
    assert decoded.arity_issue is None
    assert (decoded.parent, decoded.child, decoded.translation) == ("a", "b", (1.0, 0.0, 0.0))


def test_negative_numbers_are_not_flags() -> None:
    assert kinds("--x -1 --y -0.5e-3 --frame-id a --child-frame-id b") == []


def test_missing_frames() -> None:
    decoded = decode_ros2(argv("--x 1"))
    assert [i.kind for i in decoded.arg_issues] == ["missing_frame", "missing_frame"]
    assert (decoded.parent, decoded.child) == (None, None)
    assert "Child frame id must not be empty" in message(decoded.arg_issues[1])
    assert kinds(["--frame-id", "", "--child-frame-id", "b"]) == ["missing_frame"]


def test_a_flag_value_may_look_like_a_flag() -> None:
    decoded = decode_ros2(argv("--frame-id --child-frame-id b"))
    assert decoded.parent == "--child-frame-id"
    assert decoded.arity_issue is not None and "extra argument(s) 'b'" in decoded.arity_issue


def test_a_flag_without_its_value() -> None:
    decoded = decode_ros2(argv("--frame-id a --child-frame-id b --x"))
    assert decoded.arity_issue is not None
    assert "Not enough arguments for --x" in decoded.arity_issue


def test_help_publishes_nothing() -> None:
    decoded = decode_ros2(["--help"])
    assert decoded.form == "invalid" and decoded.arity_issue is not None


def test_bad_numbers_have_their_slot() -> None:
    decoded = decode_ros2(argv("--y abc --yaw 1.5rad --frame-id a --child-frame-id b"))
    assert decoded.number_issues == (NumberIssue(1, "abc", None), NumberIssue(3, "1.5rad", 1.5))


def test_ros_arguments_are_removed() -> None:
    decoded = decode_ros2(
        argv("--frame-id a --ros-args -r __node:=tf -p x:=1 -- --child-frame-id b")
    )
    assert (decoded.parent, decoded.child, decoded.arg_issues) == ("a", "b", ())


# -- old-style positional arguments -----------------------------------------------------


def test_positional_ypr() -> None:
    decoded = decode_ros2(argv("0.1 0 0.2 1.57 0 0 base_link laser"))
    assert (decoded.form, decoded.parent, decoded.child) == ("ypr", "base_link", "laser")
    assert decoded.rotation == Rotation(RotationKind.YPR, (1.57, 0.0, 0.0))
    (issue,) = decoded.arg_issues
    assert issue.kind == "positional"
    assert message(issue).endswith(
        "write: --x 0.1 --y 0 --z 0.2 --yaw 1.57 --pitch 0 --roll 0 "
        "--frame-id base_link --child-frame-id laser"
    )


def test_positional_quaternion() -> None:
    decoded = decode_ros2(argv("0 0 0 0 0 0 1 map odom"))
    assert decoded.form == "quaternion" and (decoded.parent, decoded.child) == ("map", "odom")
    assert "--qw 1 --frame-id map --child-frame-id odom" in message(decoded.arg_issues[0])


def test_a_ros1_period_fails_on_qw() -> None:
    decoded = decode_ros2(argv("0 0 0.2 0 0 0 base_link laser 100"))
    assert decoded.form == "ypr" and (decoded.parent, decoded.child) == ("base_link", "laser")
    assert decoded.arity_issue is not None
    assert "reads 'base_link' as qw" in decoded.arity_issue


def test_ten_positionals_are_extra() -> None:
    decoded = decode_ros2(argv("0 0 0 0 0 0 1 map odom 100"))
    assert decoded.arity_issue is not None and "no period" in decoded.arity_issue
    assert (decoded.parent, decoded.child) == ("map", "odom")


@pytest.mark.parametrize("count", [1, 3, 6, 7, 11])
def test_other_positional_counts_are_rejected(count: int) -> None:
    decoded = decode_ros2(["0"] * count)
    assert decoded.form == "invalid"
    assert decoded.arity_issue is not None and f"not {count}" in decoded.arity_issue


def test_flags_mixed_with_positionals() -> None:
    assert kinds("--x 1 0 0 0 0 0 0 a b") == ["mixed_styles", "positional"]
    decoded = decode_ros2(argv("--roll 1 0 0 0 0 0 0 a b"))
    assert "silently replaces" in message(decoded.arg_issues[0])


def test_one_item_with_all_the_words() -> None:
    decoded = decode_ros2(["0 0 0.2 0 0 0 base_link laser"])
    assert [i.kind for i in decoded.arg_issues] == ["single_string", "positional"]
    assert (decoded.parent, decoded.child, decoded.translation) == (
        "base_link", "laser", (0.0, 0.0, 0.2),
    )
    assert decoded.number_issues == ()


# -- unresolved items ----------------------------------------------------------------------


def test_unresolved_items_mark_the_fields_they_feed() -> None:
    decoded = decode_ros2(
        ["--x", "$(var x)", "--frame-id", "base", "--child-frame-id", "$(var c)"],
        frozenset({1, 5}),
    )
    assert set(decoded.unresolved) == {"translation", "child"}
    assert decoded.number_issues == ()


def test_one_substitution_is_one_argument() -> None:
    decoded = decode_ros2(["$(var tf_args)"], frozenset({0}))
    assert decoded.arity_issue is not None and "a substitution is one argument" in (
        decoded.arity_issue
    )


# -- the component ------------------------------------------------------------------------


def test_component_parameters() -> None:
    decoded = decode_component({
        "translation.z": ComponentParam("0.2", False),
        "rotation.z": ComponentParam("0.7071068", False),
        "rotation.w": ComponentParam("0.7071068", False),
        "frame_id": ComponentParam("base_link", True),
        "child_frame_id": ComponentParam("laser", True),
    })
    assert (decoded.parent, decoded.child, decoded.translation) == (
        "base_link", "laser", (0.0, 0.0, 0.2),
    )
    assert decoded.rotation == Rotation(RotationKind.QUATERNION, (0.0, 0.0, 0.7071068, 0.7071068))
    assert decoded.arg_issues == ()


def test_component_defaults() -> None:
    decoded = decode_component({"child_frame_id": ComponentParam("laser", True)})
    assert (decoded.parent, decoded.child) == ("/frame", "laser")
    (issue,) = decoded.arg_issues
    assert issue.kind == "default_frames" and "frame_id" in message(issue)


def test_component_parameters_from_a_file_may_set_the_frames() -> None:
    decoded = decode_component({}, complete=False)
    assert decoded.arg_issues == ()
    assert set(decoded.unresolved) == {"translation", "rotation", "parent", "child"}


def test_component_string_for_a_number() -> None:
    decoded = decode_component({"translation.x": ComponentParam("abc", True)})
    assert decoded.number_issues == (NumberIssue(0, "abc", None),)


# -- every occurrence of a repeated flag, empty frames in every form -----------------------


@pytest.mark.parametrize(("words", "bad"), [
    (["--x", "abc", "--x", "1"], [NumberIssue(0, "abc", None)]),
    (["--yaw", "1e999", "--yaw", "0.5"], [NumberIssue(3, "1e999", None)]),
    (["--qw", "one", "--qw", "1"], [NumberIssue(6, "one", None)]),
    (["--x", "1m", "--x", "1"], []),  # stod reads '1' and the value is replaced anyway
    (["--x", "1", "--x", "2"], []),
])
def test_an_earlier_occurrence_of_a_flag_is_parsed_too(words: list[str],
                                                       bad: list[NumberIssue]) -> None:
    decoded = decode_ros2([*words, "--frame-id", "a", "--child-frame-id", "b"])
    assert list(decoded.number_issues) == bad
    assert decoded.arg_issues == ()


def test_the_last_frame_flag_wins_even_when_empty() -> None:
    assert kinds(["--frame-id", "a", "--child-frame-id", "b", "--frame-id", ""]) == [
        "missing_frame"]
    assert kinds(["--frame-id", "", "--child-frame-id", "b", "--frame-id", "a"]) == []


@pytest.mark.parametrize(("words", "expected"), [
    (["0"] * 6 + ["", "b"], "'Frame id must not be empty'"),
    (["0"] * 6 + ["a", ""], "'Child frame id must not be empty'"),
    (["0"] * 6 + ["1", "a", ""], "'Child frame id must not be empty'"),
])
def test_empty_positional_frames(words: list[str], expected: str) -> None:
    decoded = decode_ros2(words)
    (issue,) = [i for i in decoded.arg_issues if i.kind == "missing_frame"]
    assert expected in message(issue)


def test_empty_component_frames() -> None:
    decoded = decode_component({"frame_id": ComponentParam("", True),
                                "child_frame_id": ComponentParam("laser", True)})
    assert [i.kind for i in decoded.arg_issues] == ["missing_frame"]
    assert "TF_NO_FRAME_ID" in message(decoded.arg_issues[0])
