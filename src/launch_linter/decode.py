"""Decode ``static_transform_publisher`` argument lists exactly as each program reads them.

ROS 1 ``tf`` takes 9 (ypr) or 10 (quaternion) arguments, the last being the period in ms.
ROS 1 ``tf2_ros`` takes 8 (ypr), 9 (quaternion) or 1 (a parameter name), and no period.
Numbers go through C ``atof``: junk reads as 0. ``name:=value`` words are ROS remappings
that ``ros::init`` removes before the program counts its arguments.

The decoded record keeps the developer's intended reading (the tf convention matching the
written count) and, in ``arity_issue``, what the program really does with it.
"""

from __future__ import annotations

import math
import re

from launch_linter.model.record import MutableRecord
from launch_linter.model.transform import ArgForm, NumberIssue, Rotation, RotationKind

# What C's strtod (hence atof) reads, in the "C" locale. Hexadecimal comes first because a
# regex alternation takes the first branch that matches, and "0x10" must not stop at "0".
_NUMBER = re.compile(
    r"""[+-]?(
        0[xX]([0-9a-fA-F]+\.?[0-9a-fA-F]*|\.[0-9a-fA-F]+)([pP][+-]?[0-9]+)?
      | ([0-9]+\.?[0-9]*|\.[0-9]+)([eE][+-]?[0-9]+)?
      | inf(inity)? | nan(\([0-9A-Za-z_]*\))?
    )""",
    re.VERBOSE | re.IGNORECASE | re.ASCII,
)
_C_SPACE = " \t\n\v\f\r"


_ATOF_MEMO: dict[str, tuple[float, bool]] = {}
_ATOF_MEMO_SIZE = 4096


def atof(text: str) -> tuple[float, bool]:
    """C ``atof``: the longest numeric prefix (0.0 if none), and whether all of it was read."""
    # The same few numbers ("0", "0.0", "100" …) fill most argument lists.
    known = _ATOF_MEMO.get(text)
    if known is None:
        if len(_ATOF_MEMO) >= _ATOF_MEMO_SIZE:
            _ATOF_MEMO.clear()
        known = _ATOF_MEMO[text] = _read_number(text)
    return known


def _read_number(text: str) -> tuple[float, bool]:
    # Python's float() reads the same numbers as strtod from ASCII text without blanks or
    # underscores, except hexadecimal and NaN payloads, which it refuses (then the slow way).
    if text.isascii() and "_" not in text and text == text.strip():
        try:
            return float(text), True
        except ValueError:
            pass
    stripped = text.lstrip(_C_SPACE)
    match = _NUMBER.match(stripped)
    if match is None:
        return 0.0, False
    number = match.group(0)
    sign = -1.0 if number.startswith("-") else 1.0
    body = number.lstrip("+-").lower()
    if body.startswith("nan"):
        value = math.nan
    elif body.startswith("0x"):
        try:
            value = sign * float.fromhex(body)
        except OverflowError:
            value = sign * math.inf
    else:
        value = sign * float(body)
    return value, match.end() == len(stripped) and stripped == text


def is_number(text: str) -> bool:
    _, whole = atof(text)
    return whole


class Decoded(MutableRecord):
    """What the program makes of the words (treat as read-only)."""

    form: ArgForm
    parent: str | None
    child: str | None
    translation: tuple[float, float, float] | None
    rotation: Rotation | None
    period_ms: float | None
    arity_issue: str | None
    number_issues: tuple[NumberIssue, ...]
    numeric_indices: tuple[int, ...]
    parent_index: int | None
    child_index: int | None

    __slots__ = (
        "form", "parent", "child", "translation", "rotation", "period_ms", "arity_issue",
        "number_issues", "numeric_indices", "parent_index", "child_index",
    )

    def __init__(
        self,
        form: ArgForm,
        parent: str | None,
        child: str | None,
        translation: tuple[float, float, float] | None,
        rotation: Rotation | None,
        period_ms: float | None,
        arity_issue: str | None,
        number_issues: tuple[NumberIssue, ...],
        numeric_indices: tuple[int, ...],
        parent_index: int | None,
        child_index: int | None,
    ) -> None:
        self.form = form
        self.parent = parent
        self.child = child
        self.translation = translation
        self.rotation = rotation
        self.period_ms = period_ms
        self.arity_issue = arity_issue
        self.number_issues = number_issues
        self.numeric_indices = numeric_indices
        self.parent_index = parent_index
        self.child_index = child_index


def program_words(tokens: tuple[str, ...]) -> tuple[str, ...]:
    """The words the program counts: ``ros::init`` removes ``name:=value`` remappings."""
    if ":=" not in " ".join(tokens):
        return tokens
    return tuple(t for t in tokens if ":=" not in t)


def _numbers(words: tuple[str, ...], count: int) -> tuple[list[float], list[NumberIssue]]:
    values: list[float] = []
    issues: list[NumberIssue] = []
    for index in range(count):
        word = words[index]
        value, whole = _ATOF_MEMO.get(word) or atof(word)
        if not whole or value - value != 0.0:  # junk, or inf/nan
            issues.append(NumberIssue(index, word, value))
        values.append(value)
    return values, issues


# Which words are numbers, by (rotation size, whether a period follows the frames).
_NUMERIC_INDICES = {
    (size, with_period): tuple(range(3 + size)) + ((5 + size,) if with_period else ())
    for size in (3, 4) for with_period in (False, True)
}


def _layout(
    words: tuple[str, ...], rotation_size: int, with_period: bool, form: ArgForm, issue: str | None
) -> Decoded:
    numeric = 3 + rotation_size
    values, issues = _numbers(words, numeric)
    period: float | None = None
    if with_period:
        period, whole = atof(words[numeric + 2])
        if not whole:
            issues.append(NumberIssue(numeric + 2, words[numeric + 2], period))
    kind = RotationKind.YPR if rotation_size == 3 else RotationKind.QUATERNION
    return Decoded(
        form=form,
        parent=words[numeric],
        child=words[numeric + 1],
        translation=(values[0], values[1], values[2]),
        rotation=Rotation(kind, tuple(values[3:numeric])),
        period_ms=period,
        arity_issue=issue,
        number_issues=tuple(issues),
        numeric_indices=_NUMERIC_INDICES[rotation_size, with_period],
        parent_index=numeric,
        child_index=numeric + 1,
    )


def _invalid(issue: str) -> Decoded:
    return Decoded(ArgForm.INVALID, None, None, None, None, None, issue, (), (), None, None)


def decode_ros1(package: str, tokens: tuple[str, ...]) -> Decoded:
    """Decode the argument words of a ROS 1 ``tf`` or ``tf2_ros`` static_transform_publisher."""
    words = program_words(tokens)
    count = len(words)
    if package == "tf":
        if count == 9:
            if not is_number(words[8]) and is_number(words[6]):
                return _layout(
                    words, 4, False, ArgForm.QUATERNION,
                    f"tf needs a period after the child frame: with 9 arguments it reads "
                    f"'{words[6]}' as the parent frame, '{words[7]}' as the child and "
                    f"'{words[8]}' as the period",
                )
            return _layout(words, 3, True, ArgForm.YPR, None)
        if count == 10:
            return _layout(words, 4, True, ArgForm.QUATERNION, None)
        if count == 8:
            return _layout(
                words, 3, False, ArgForm.YPR,
                "tf needs 9 or 10 arguments (the last is the period in ms); "
                "with 8 it prints its usage and exits",
            )
        return _invalid(
            f"tf takes 9 (x y z yaw pitch roll parent child period_ms) or 10 "
            f"(x y z qx qy qz qw parent child period_ms) arguments, not {count}"
        )
    if count == 8:
        return _layout(words, 3, False, ArgForm.YPR, None)
    if count == 9:
        if not is_number(words[6]) and is_number(words[8]):
            return _layout(
                words, 3, True, ArgForm.YPR,
                f"tf2_ros takes no period: with 9 arguments it reads a quaternion with "
                f"qw='{words[6]}' ({atof(words[6])[0]:g}), parent '{words[7]}' and child "
                f"'{words[8]}'",
            )
        return _layout(words, 4, False, ArgForm.QUATERNION, None)
    if count == 10:
        return _layout(
            words, 4, True, ArgForm.QUATERNION,
            "tf2_ros takes no period: with 10 arguments it prints its usage and exits",
        )
    if count == 1:
        return Decoded(ArgForm.PARAM, None, None, None, None, None, None, (), (), None, None)
    return _invalid(
        f"tf2_ros takes 8 (x y z yaw pitch roll parent child), 9 "
        f"(x y z qx qy qz qw parent child) or 1 (/param_name) arguments, not {count}"
    )
