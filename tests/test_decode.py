"""Decoding ``static_transform_publisher`` arguments as ``tf`` and ``tf2_ros`` read them."""

from __future__ import annotations

import ctypes
import ctypes.util
import math

import pytest
from hypothesis import given
from hypothesis import strategies as st

from launch_linter.decode import atof, decode_ros1, is_number, program_words
from launch_linter.model.transform import RotationKind


def words(text: str) -> tuple[str, ...]:
    return tuple(text.split())


# --- atof ------------------------------------------------------------------------------

_LIBC = ctypes.CDLL(ctypes.util.find_library("c"))
_LIBC.strtod.restype = ctypes.c_double
_LIBC.strtod.argtypes = [ctypes.c_char_p, ctypes.POINTER(ctypes.c_char_p)]


def strtod(text: str) -> tuple[float, bool]:
    """The C library's own answer (the "C" locale), and whether it read every byte."""
    data = text.encode("utf-8")
    buffer = ctypes.create_string_buffer(data)
    end = ctypes.c_char_p()
    value = _LIBC.strtod(buffer, ctypes.byref(end))
    consumed = ctypes.cast(end, ctypes.c_void_p).value - ctypes.addressof(buffer)  # type: ignore[operator]
    return value, consumed == len(data) and len(data) > 0 and not text[0].isspace()


def same(a: float, b: float) -> bool:
    return (math.isnan(a) and math.isnan(b)) or a == b


NUMBERISH = st.text(alphabet="0123456789+-.eExXpPabcdfinINFtyAN()_ \t,/", max_size=14)


@given(NUMBERISH)
def test_atof_agrees_with_the_c_library(text: str) -> None:
    ours, theirs = atof(text), strtod(text)
    assert same(ours[0], theirs[0]), (text, ours, theirs)
    assert ours[1] == theirs[1], (text, ours, theirs)


@given(st.floats(allow_nan=False))
def test_atof_reads_python_float_text(value: float) -> None:
    assert atof(repr(value)) == (value, True)


@pytest.mark.parametrize(
    ("text", "value", "whole"),
    [
        ("1.5", 1.5, True),
        ("1,57", 1.0, False),
        ("pi/2", 0.0, False),
        ("0x10", 16.0, True),
        ("1e3", 1000.0, True),
        ("-inf", -math.inf, True),
        ("base_link", 0.0, False),
        ("", 0.0, False),
        ("1_000", 1.0, False),
        ("\u0663", 0.0, False),
    ],
)
def test_atof_on_junk(text: str, value: float, whole: bool) -> None:
    assert atof(text) == (value, whole)
    assert is_number(text) is whole


def test_atof_nan() -> None:
    value, whole = atof("nan(0x1)")
    assert math.isnan(value) and whole


# --- arities -----------------------------------------------------------------------------


def test_tf_nine_args_is_ypr_with_period() -> None:
    decoded = decode_ros1("tf", words("1 2 3 0.1 0.2 0.3 base laser 100"))
    assert decoded.form == "ypr" and decoded.arity_issue is None
    assert (decoded.parent, decoded.child, decoded.period_ms) == ("base", "laser", 100.0)
    assert decoded.translation == (1.0, 2.0, 3.0)
    assert decoded.rotation is not None
    assert decoded.rotation.kind is RotationKind.YPR
    assert decoded.rotation.values == (0.1, 0.2, 0.3)


def test_tf_ten_args_is_quaternion_with_period() -> None:
    decoded = decode_ros1("tf", words("0 0 0 0 0 0 1 base camera 50"))
    assert decoded.form == "quaternion" and decoded.arity_issue is None
    assert decoded.rotation is not None
    assert decoded.rotation.values == (0.0, 0.0, 0.0, 1.0)
    assert (decoded.parent, decoded.child, decoded.period_ms) == ("base", "camera", 50.0)


def test_tf_without_period_is_a_usage_error() -> None:
    decoded = decode_ros1("tf", words("0 0 0 0 0 0 base laser"))
    assert decoded.form == "ypr"
    assert (decoded.parent, decoded.child, decoded.period_ms) == ("base", "laser", None)
    assert decoded.arity_issue is not None and "with 8" in decoded.arity_issue


def test_tf_quaternion_without_period_is_misread() -> None:
    decoded = decode_ros1("tf", words("0 0 0 0 0 0 1 base camera"))
    assert decoded.form == "quaternion"
    assert (decoded.parent, decoded.child) == ("base", "camera")
    assert decoded.arity_issue is not None and "'1' as the parent frame" in decoded.arity_issue


def test_tf2_eight_and_nine_args() -> None:
    ypr = decode_ros1("tf2_ros", words("0 0 0.5 1.57 0 0 map odom"))
    assert ypr.form == "ypr" and ypr.arity_issue is None and ypr.period_ms is None
    quat = decode_ros1("tf2_ros", words("0 0 0 0 0 0.7071 0.7071 odom base"))
    assert quat.form == "quaternion" and quat.arity_issue is None
    assert (quat.parent, quat.child) == ("odom", "base")


def test_tf2_given_a_period_reads_a_quaternion_with_a_frame_as_qw() -> None:
    decoded = decode_ros1("tf2_ros", words("0 0 0.1 0 0 0 base_link laser 100"))
    assert decoded.form == "ypr"
    assert (decoded.parent, decoded.child, decoded.period_ms) == ("base_link", "laser", 100.0)
    assert decoded.arity_issue is not None
    assert "qw='base_link' (0)" in decoded.arity_issue
    assert "child '100'" in decoded.arity_issue


def test_tf2_quaternion_with_period_is_a_usage_error() -> None:
    decoded = decode_ros1("tf2_ros", words("0 0 0 0 0 0 1 base camera 100"))
    assert decoded.arity_issue is not None and "10 arguments" in decoded.arity_issue


def test_tf2_one_arg_is_the_parameter_form() -> None:
    decoded = decode_ros1("tf2_ros", ("/static_tf/laser",))
    assert decoded.form == "param" and decoded.arity_issue is None
    assert decoded.parent is None and decoded.child is None


@pytest.mark.parametrize(("package", "count"), [("tf", 0), ("tf", 7), ("tf", 11),
                                                ("tf2_ros", 0), ("tf2_ros", 2), ("tf2_ros", 7)])
def test_other_counts_are_invalid(package: str, count: int) -> None:
    decoded = decode_ros1(package, tuple("0" for _ in range(count)))
    assert decoded.form == "invalid"
    assert decoded.arity_issue is not None and f"not {count}" in decoded.arity_issue


def test_remapping_words_are_not_counted() -> None:
    tokens = words("0 0 0 0 0 0 base laser tf_static:=/x __name:=n")
    assert program_words(tokens) == tokens[:8]
    decoded = decode_ros1("tf2_ros", tokens)
    assert decoded.form == "ypr" and decoded.arity_issue is None
    assert decoded.child == "laser"


def test_junk_numbers_are_read_as_atof_and_reported() -> None:
    decoded = decode_ros1("tf2_ros", words("0 0 0 1,57 pi/2 x base laser"))
    assert decoded.rotation is not None
    assert decoded.rotation.values == (1.0, 0.0, 0.0)
    assert [(n.index, n.written, n.read_as) for n in decoded.number_issues] == [
        (3, "1,57", 1.0), (4, "pi/2", 0.0), (5, "x", 0.0),
    ]


def test_non_finite_numbers_are_reported() -> None:
    decoded = decode_ros1("tf", words("nan 0 inf 0 0 0 a b 100"))
    assert [n.index for n in decoded.number_issues] == [0, 2]
