"""(A→B) usually has zero rotation, this one does not.

## What it does
Uses the mined `sig_null_rot` beliefs: "transforms of signature (parent → child) have no
rotation". It reports every transform with such a signature whose rotation is known and
not the identity (zero yaw, pitch and roll, or the quaternion ±(0, 0, 0, 1)). The message
gives the belief's support: `n` transforms of mature repositories have the signature, `e`
of them no rotation, and the z-score (p0 = 0.9). Only beliefs with z at or above
`--min-z` (default 1.0) are used.

## Why is this bad?
Frames such as `base_footprint` and `base_link` share their axes by convention (REP 105),
and most mounted sensors are aligned with their parent frame. A rotation on such a pair
is often a value meant for the translation, a yaw/pitch/roll order mistake, or degrees
where radians belong.

## Example
```xml
<launch>
  <node pkg="tf2_ros" type="static_transform_publisher" name="footprint"
        args="0 0 0.1 1.5708 0 0 base_footprint base_link"/>
</launch>
```

## Use instead
```xml
<launch>
  <node pkg="tf2_ros" type="static_transform_publisher" name="footprint"
        args="0 0 0.1 0 0 0 base_footprint base_link"/>
</launch>
```

## Known problems
A sensor that is mounted turned (a lidar facing backwards) does need a rotation; the
belief only says that this is unusual. Transforms whose rotation is unresolved are not
judged.
"""
from __future__ import annotations

from collections.abc import Iterator

from launch_linter.model.diagnostic import Category, Severity
from launch_linter.rules._api import Finding, RuleContext
from launch_linter.rules._may_implied import null_rotations, signature_of

ID = "sig_null_rot"
CATEGORY = Category.MAY_IMPLIED
SEVERITY = Severity.WARNING


def check(context: RuleContext) -> Iterator[Finding]:
    return null_rotations(context, ID, signature_of, "transform")
