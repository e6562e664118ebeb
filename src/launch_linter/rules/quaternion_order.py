"""A quaternion that looks written w-first, such as `1 0 0 0` for the identity.

## What it does
Reports a static transform written with a quaternion whose x is ±1 and y, z and w are 0,
i.e. `qx qy qz qw` = `1 0 0 0`: read in tf's order (x, y, z, w) it is a half turn about
x, while in w-first order (Eigen's constructor, many papers) it is the identity.

## Why is this bad?
static_transform_publisher reads `qx qy qz qw`. Copying a quaternion from code or a paper
that writes w first turns "no rotation" into a 180° roll: the sensor is upside down, and
nothing fails at run time.

## Example
```xml
<launch>
  <node pkg="tf2_ros" type="static_transform_publisher" name="imu_tf"
        args="0 0 0.1 1 0 0 0 base_link imu_link"/>
</launch>
```

## Use instead
```xml
<launch>
  <node pkg="tf2_ros" type="static_transform_publisher" name="imu_tf"
        args="0 0 0.1 0 0 0 1 base_link imu_link"/>
</launch>
```

## Known problems
A deliberate half turn about x written as a quaternion is reported too; write it as
`0 0 3.14159` (yaw pitch roll) to make the intent plain.
"""

from __future__ import annotations

from collections.abc import Iterator

from launch_linter.model.diagnostic import Category, Severity
from launch_linter.model.transform import Field, RotationKind
from launch_linter.rules._api import Finding, RuleContext, finding_at

ID = "quaternion_order"
CATEGORY = Category.TF
SEVERITY = Severity.INFO

_TOLERANCE = 1e-9


def check(context: RuleContext) -> Iterator[Finding]:
    for transform in context.tree.transforms:
        rotation = transform.rotation
        if (rotation is None or rotation.kind is not RotationKind.QUATERNION
                or transform.is_unresolved(Field.ROTATION) or len(rotation.values) != 4):
            continue
        qx, qy, qz, qw = rotation.values
        if abs(abs(qx) - 1.0) > _TOLERANCE or any(abs(v) > _TOLERANCE for v in (qy, qz, qw)):
            continue
        yield finding_at(
            transform,
            "quaternion qx qy qz qw = 1 0 0 0 is a half turn about x; if the identity was "
            "meant, it is written w-first: static_transform_publisher reads x y z w, so the "
            "identity is 0 0 0 1",
        )
