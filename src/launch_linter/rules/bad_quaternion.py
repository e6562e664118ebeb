"""A quaternion that is zero, not finite, or not of unit length.

## What it does
Reports a static transform written with a quaternion (`qx qy qz qw`) that is zero, holds a
NaN or infinite value, or whose squared norm differs from 1 by 0.01 or more (error). A
smaller deviation above 1e-6 is reported as info.

## Why is this bad?
tf2 drops a transform whose quaternion is not normalised within 0.01
(`TF_DENORMALIZED_QUATERNION`) or holds NaN (`TF_NAN_INPUT`), so the child frame never
appears. A quaternion slightly off unit length is accepted but distorts every point
transformed through it; `roswtf` warns about it.

## Example
```xml
<launch>
  <node pkg="tf2_ros" type="static_transform_publisher" name="laser_tf"
        args="0 0 0.2 0 0 0 0 base_link laser"/>
</launch>
```

## Use instead
```xml
<launch>
  <node pkg="tf2_ros" type="static_transform_publisher" name="laser_tf"
        args="0 0 0.2 0 0 0 1 base_link laser"/>
</launch>
```

## Fix
Unsafe: a quaternion that is not of unit length (and not zero or infinite) is replaced
by its normalised form; whether the direction written is the one meant is for a human to
judge.
"""
from __future__ import annotations

import math
from collections.abc import Iterator

from launch_linter.model.diagnostic import Applicability, Category, Fix, Severity
from launch_linter.model.transform import NULL_TOLERANCE, Field, RotationKind, StaticTransform
from launch_linter.rules._api import Finding, RuleContext, finding_at
from launch_linter.rules._fixes import fixable, number_text, replace_words, value_index
from launch_linter.rules.bad_number import separated_number

ID = "bad_quaternion"
CATEGORY = Category.TF
SEVERITY = Severity.ERROR

TF2_TOLERANCE = 0.01
"""tf2's ``QUATERNION_NORMALIZATION_TOLERANCE`` on abs(|q|² - 1)."""
ROSWTF_TOLERANCE = 1e-6
QUATERNION_SLOTS = (3, 4, 5, 6)
"""Indices of qx, qy, qz, qw among the numeric arguments."""

FIX = Applicability.UNSAFE


def _normalise_fix(transform: StaticTransform, values: tuple[float, ...]) -> Fix | None:
    if not fixable(transform) or not all(math.isfinite(v) for v in values):
        return None
    norm = math.sqrt(sum(v * v for v in values))
    if norm <= NULL_TOLERANCE:
        return None
    edits = []
    for position, value in enumerate(values):
        index = value_index(transform, 3 + position)
        if index is None:
            return None
        try:
            if float(transform.tokens[index]) != value:
                return None
        except ValueError:
            return None
        written = number_text(value / norm)
        if written != transform.tokens[index]:
            edits.append((index, index + 1, written))
    if not edits:
        return None
    return replace_words(transform, FIX, "normalise the quaternion", edits)


def _written(values: tuple[float, ...]) -> str:
    return f"({', '.join(f'{v:g}' for v in values)})"


def _problem(values: tuple[float, ...]) -> tuple[Severity, str] | None:
    if not all(math.isfinite(v) for v in values):
        return SEVERITY, "is not finite: tf2 drops it (TF_NAN_INPUT)"
    if all(abs(v) <= NULL_TOLERANCE for v in values):
        return SEVERITY, (
            "is zero, which is no rotation at all: tf2 drops it "
            "(TF_DENORMALIZED_QUATERNION); write 0 0 0 1 for the identity"
        )
    squared = sum(v * v for v in values)
    deviation = abs(squared - 1.0)
    if deviation <= ROSWTF_TOLERANCE:
        return None  # the usual case: nothing to say, nothing to format
    norm = math.sqrt(squared)
    unit = " ".join(f"{v / norm:.7g}" for v in values)
    if deviation >= TF2_TOLERANCE:
        return SEVERITY, (
            f"has squared norm {squared:.6g}, not 1 within tf2's tolerance of "
            f"{TF2_TOLERANCE:g}: tf2 drops it (TF_DENORMALIZED_QUATERNION); normalised it "
            f"is {unit}"
        )
    if deviation > ROSWTF_TOLERANCE:
        return Severity.INFO, (
            f"has squared norm {squared:.9g}: tf2 accepts it, but it is not quite unit "
            f"length; normalised it is {unit}"
        )
    return None


def _rejected_word(transform: StaticTransform) -> bool:
    return any(
        issue.index in QUATERNION_SLOTS and not separated_number(issue.written)
        for issue in transform.number_issues
    )


def check(context: RuleContext) -> Iterator[Finding]:
    for transform in context.tree.transforms:
        rotation = transform.rotation
        if rotation is None or rotation.kind is not RotationKind.QUATERNION:
            continue
        if transform.is_unresolved(Field.ROTATION):
            continue
        if not context.study and _rejected_word(transform):
            # One root cause, one finding: bad_number already says that a component is
            # not a number, and the norm of what atof made of it is no advice.
            continue
        found = _problem(rotation.values)
        if found is None:
            continue
        severity, problem = found
        yield finding_at(
            transform,
            f"quaternion (qx, qy, qz, qw) = {_written(rotation.values)} {problem}",
            severity=severity,
            fix=_normalise_fix(transform, rotation.values),
        )
