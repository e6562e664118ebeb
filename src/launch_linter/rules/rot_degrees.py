"""A yaw, pitch or roll value that looks like degrees.

## What it does
Reports a static transform written with yaw, pitch and roll whose angles include one with
an absolute value above 2π (negative angles included). The message gives the angle read as
degrees and the radians that were probably meant. A multiple of π/2 written in radians
(such as `4.712389` or `9.42478`) is not reported.

## Why is this bad?
`static_transform_publisher` reads yaw, pitch and roll in radians. A value above 2π is
almost always an angle in degrees: `90` turns the frame by 90 radians (14 whole turns and
another 117°), not by a quarter turn, and nothing complains at run time.

## Example
```xml
<launch>
  <node pkg="tf" type="static_transform_publisher" name="laser_tf"
        args="0 0 0.2 0 0 135 base_link laser 100"/>
</launch>
```

## Use instead
```xml
<launch>
  <node pkg="tf" type="static_transform_publisher" name="laser_tf"
        args="0 0 0.2 0 0 2.356194 base_link laser 100"/>
</launch>
```

## Fix
Unsafe: writes each suspect angle in radians. A value above 2π written on purpose (a
full turn and more, in radians) would be changed.

## Known problems
An angle in degrees between -2π and 2π (such as `5`) cannot be told from radians and is
not reported.
"""
from __future__ import annotations

import math
from collections.abc import Iterator

from launch_linter.model.diagnostic import Applicability, Category, Fix, Severity
from launch_linter.model.transform import Field, RotationKind, StaticTransform
from launch_linter.rules._api import Finding, RuleContext, finding_at
from launch_linter.rules._fixes import fixable, number_text, replace_words, value_index

ID = "rot_degrees"
CATEGORY = Category.MAY_SEMANTIC
SEVERITY = Severity.WARNING
FIX = Applicability.UNSAFE

ANGLE_NAMES = ("yaw", "pitch", "roll")
FULL_TURN = 2 * math.pi
# Radians written as k·π/2 carry rounding of π (3.14, 3.1416): allow 0.1 % of the value.
RADIAN_MULTIPLE_TOLERANCE = 1e-3


def is_radian_multiple(value: float) -> bool:
    """True for a non-integer value close to a multiple of π/2 (an integer is degrees)."""
    if value.is_integer():
        return False
    steps = round(value / (math.pi / 2))
    return abs(value - steps * math.pi / 2) <= RADIAN_MULTIPLE_TOLERANCE * abs(value)


def looks_like_degrees(value: float) -> bool:
    return math.isfinite(value) and abs(value) > FULL_TURN and not is_radian_multiple(value)


def _radians_fix(transform: StaticTransform, values: tuple[float, ...]) -> Fix | None:
    if not fixable(transform):
        return None
    edits = []
    for position, value in enumerate(values):
        if not looks_like_degrees(value):
            continue
        index = value_index(transform, 3 + position)
        if index is None or not _reads_as(transform.tokens[index], value):
            return None
        edits.append((index, index + 1, number_text(math.radians(value))))
    if not edits:
        return None
    return replace_words(transform, FIX, "write the angles in radians", edits)


def _reads_as(word: str, value: float) -> bool:
    try:
        return float(word) == value
    except ValueError:
        return False


def check(context: RuleContext) -> Iterator[Finding]:
    for transform in context.tree.transforms:
        rotation = transform.rotation
        if rotation is None or rotation.kind is not RotationKind.YPR:
            continue
        if transform.is_unresolved(Field.ROTATION):
            continue
        suspects = [
            f"{name} {value:g} ({value:g}° is {math.radians(value):.6g} rad)"
            for name, value in zip(ANGLE_NAMES, rotation.values)
            if looks_like_degrees(value)
        ]
        if not suspects:
            continue
        yield finding_at(transform,
            f"{', '.join(suspects)}: static_transform_publisher reads yaw, pitch and roll in "
            f"radians, and an angle above 2π is probably in degrees",
            fix=_radians_fix(transform, rotation.values),
        )
