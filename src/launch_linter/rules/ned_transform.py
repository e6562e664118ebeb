"""A `*_ned` child frame with a displacement, or without a rotation.

## What it does
Reports a static transform whose child frame ends with `_ned` (any case) when the
displacement is not zero, or when the rotation is null (zero yaw, pitch and roll, or the
quaternion ±(0, 0, 0, 1)).

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
from launch_linter.model.transform import Field
from launch_linter.rules._api import Finding, RuleContext, finding_at

ID = "ned_transform"
CATEGORY = Category.MAY_SEMANTIC
SEVERITY = Severity.WARNING

SUFFIX = "_ned"


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
        if not problems:
            continue
        yield finding_at(transform,
            f"NED frame '{child}' {' and '.join(problems)}: a '_ned' child should only "
            f"re-orient its parent's axes to north-east-down (REP 103), with zero "
            f"displacement and a non-null rotation",
        )
