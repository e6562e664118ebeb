"""A quaternion written `1 0 0 0`: the identity in w-first order, or a half turn about x.

## What it does
Reports (as info) a static transform whose quaternion is written `1 0 0 0` (or
`-1 0 0 0`), that is `qx = ±1` and every other component zero.

## Why is this bad?
`static_transform_publisher` reads a quaternion as `qx qy qz qw`, but Eigen, many papers
and `tf.transformations` helpers print it as `w x y z`, where `1 0 0 0` is the identity.
Read as `qx qy qz qw` it is a half turn about x: the child frame is upside down. An
upside-down sensor or a NED frame is written exactly this way on purpose, so the
linter only points at it.

## Example
```xml
<launch>
  <node pkg="tf2_ros" type="static_transform_publisher" name="laser_tf"
        args="0.2 0 0.1 1 0 0 0 base_link laser"/>
</launch>
```

## Use instead
```xml
<launch>
  <node pkg="tf2_ros" type="static_transform_publisher" name="laser_tf"
        args="0.2 0 0.1 0 0 0 1 base_link laser"/>
</launch>
```

## Fix
Unsafe: reorders the four values from `w x y z` to `x y z w` (`0 0 0 1`), which is
wrong when the half turn was meant.
"""

from __future__ import annotations

from collections.abc import Iterator

from launch_linter.model.diagnostic import Applicability, Category, Fix, Severity
from launch_linter.model.transform import NULL_TOLERANCE, Field, RotationKind, StaticTransform
from launch_linter.rules._api import Finding, RuleContext, finding_at
from launch_linter.rules._fixes import fixable, number_text, replace_words, value_index

ID = "quaternion_order"
CATEGORY = Category.TF
SEVERITY = Severity.INFO
FIX = Applicability.UNSAFE


def _is_w_first_identity(values: tuple[float, ...]) -> bool:
    qx, qy, qz, qw = values
    return abs(abs(qx) - 1.0) <= NULL_TOLERANCE and all(
        abs(v) <= NULL_TOLERANCE for v in (qy, qz, qw)
    )


def _reorder_fix(transform: StaticTransform, values: tuple[float, ...]) -> Fix | None:
    if not fixable(transform):
        return None
    indices = [value_index(transform, 3 + position) for position in range(4)]
    if any(i is None for i in indices):
        return None
    reordered = (values[1], values[2], values[3], values[0])
    edits = []
    for index, value in zip(indices, reordered):
        assert index is not None
        text = number_text(value)
        if text != transform.tokens[index]:
            edits.append((index, index + 1, text))
    return replace_words(transform, FIX, "read the quaternion as w x y z", edits)


def check(context: RuleContext) -> Iterator[Finding]:
    for transform in context.tree.transforms:
        rotation = transform.rotation
        if rotation is None or rotation.kind is not RotationKind.QUATERNION:
            continue
        if transform.is_unresolved(Field.ROTATION) or not _is_w_first_identity(rotation.values):
            continue
        yield finding_at(
            transform,
            "quaternion (qx, qy, qz, qw) = (1, 0, 0, 0) is a half turn about x (the child "
            "is upside down); if it was meant as the identity written w x y z, write 0 0 0 1",
            fix=_reorder_fix(transform, rotation.values),
        )
