"""A `*_ned` child frame with a displacement, or without a rotation.

## What it does
Reports a static transform whose child frame ends with `_ned` (any case) when the
displacement is not zero, when the rotation is null (zero yaw, pitch and roll, or the
quaternion ±(0, 0, 0, 1)), or when the rotation leaves the child's z axis pointing up
from a parent that REP 103 makes ENU (z up: a parent not named `*_ned`, `*_frd` or
optical): a half turn in yaw (`0 0 0 3.14159 0 0`) turns x and y but keeps z up, so the
frame is not north-east-*down*; a body frame's NED twin is a half turn in roll, a world
frame's yaw pi/2 and roll pi (both turn z down).

## Why is this bad?
REP 103: ROS frames are ENU (x east/forward, y north/left, z up); a frame that must be NED
(north, east, down) is a child named with the suffix `_ned`, whose transform only re-orients
the axes of its parent. A null rotation leaves the "NED" frame identical to its ENU parent,
so every consumer reads the axes wrong; a displacement means the frame is a different place,
not the same place seen in NED axes.

## Example
```xml
<launch>
  <node pkg="tf2_ros" type="static_transform_publisher" name="ned_tf"
        args="0 0 0 0 0 0 base_link base_link_ned"/>
</launch>
```

## Use instead
```xml
<launch>
  <node pkg="tf2_ros" type="static_transform_publisher" name="ned_tf"
        args="0 0 0 0.70710678 0.70710678 0 0 base_link base_link_ned"/>
</launch>
```
"""
from __future__ import annotations

from collections.abc import Iterator

from launch_linter.model.diagnostic import Category, Severity
from launch_linter.model.transform import Field, RotationKind, StaticTransform
from launch_linter.rules._api import Finding, RuleContext, finding_at
from launch_linter.rules._tree import normalised, quaternion_from_ypr

ID = "ned_transform"
CATEGORY = Category.MAY_SEMANTIC
SEVERITY = Severity.WARNING

SUFFIX = "_ned"
NOT_ENU = ("_ned", "_frd")
"""Parents whose z axis points down already (REP 103's `_ned`, PX4's `_frd` body frames)."""
DOWN = -0.98
"""Most a `_ned` frame's z axis may point along its parent's z (cos 169°: a rounded pi
still turns it down)."""


def _z_up(transform: StaticTransform, parent: str) -> bool:
    """Whether the rotation keeps the child's z axis pointing up from an ENU parent (the
    z component of the child's z axis, 1 - 2(qx² + qy²), not near -1)."""
    rotation = transform.rotation
    name = parent.lower()
    if rotation is None or name.endswith(NOT_ENU) or "optical" in name:
        return False
    values = rotation.values
    if rotation.kind is RotationKind.YPR and len(values) == 3:
        quaternion = quaternion_from_ypr(values[0], values[1], values[2])
    elif len(values) == 4:
        found = normalised((values[0], values[1], values[2], values[3]))
        if found is None:
            return False
        quaternion = found
    else:
        return False
    qx, qy = quaternion[0], quaternion[1]
    return 1.0 - 2.0 * (qx * qx + qy * qy) > DOWN


def check(context: RuleContext) -> Iterator[Finding]:
    for transform in context.tree.transforms:
        child = transform.child
        if child is None or transform.is_unresolved(Field.CHILD):
            continue
        if not child.lower().endswith(SUFFIX):
            continue
        problems = []
        if transform.null_displacement is False:
            problems.append("has a displacement")
        if transform.null_rotation is True:
            problems.append("has no rotation")
        elif (transform.null_rotation is False and transform.parent is not None
              and not transform.is_unresolved(Field.PARENT)
              and _z_up(transform, transform.parent)):
            problems.append(f"keeps the z axis of its ENU parent '{transform.parent}' up")
        if not problems:
            continue
        yield finding_at(transform,
            f"NED frame '{child}' {' and '.join(problems)}: a '_ned' child should only "
            f"re-orient its parent's axes to north-east-down (REP 103), with zero "
            f"displacement and a rotation that turns z down",
        )
