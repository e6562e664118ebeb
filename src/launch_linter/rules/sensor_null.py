"""A velodyne, kinect, openni or imu transform that is all zero.

## What it does
Reports a static transform whose node name, parent frame or child frame contains the word
`velodyne`, `kinect`, `openni` or `imu` (any case) and whose displacement and rotation are
both null. Words are split at non-letters and at camelCase humps, so `base_imu_link`,
`velodyne2` and `radarToIMU` hold a sensor word and `simulation` does not.

## Why is this bad?
These names stand for physical sensors, which sit somewhere on the robot and are rarely
mounted exactly at the origin of their parent frame and aligned with it. A null transform
usually means the real mounting pose was never measured and entered, so the sensor's data
is placed at the wrong spot of the robot.

## Example
```xml
<launch>
  <node pkg="tf2_ros" type="static_transform_publisher" name="imu_tf"
        args="0 0 0 0 0 0 base_link imu_link"/>
</launch>
```

## Use instead
```xml
<launch>
  <node pkg="tf2_ros" type="static_transform_publisher" name="imu_tf"
        args="0.05 0 0.12 0 0 0 base_link imu_link"/>
</launch>
```

## Known problems
A null transform is sometimes meant, to give a sensor frame a second name (an alias).
"""
from __future__ import annotations

import re
from collections.abc import Iterator

from launch_linter.model.diagnostic import Category, Severity
from launch_linter.model.transform import Field, StaticTransform
from launch_linter.rules._api import Finding, RuleContext, finding_at, is_world_fixed

ID = "sensor_null"
CATEGORY = Category.MAY_SEMANTIC
SEVERITY = Severity.INFO

SENSOR_WORDS = frozenset({"velodyne", "kinect", "openni", "imu"})
# A run of capitals (IMU), a capitalised word (Imu) or a lower-case word (imu).
_WORD = re.compile(r"[A-Z]+(?![a-z])|[A-Z]?[a-z]+")


def sensor_words(text: str) -> set[str]:
    """The sensor words of ``text``: whole words only (not the "imu" of "simulation")."""
    return {w.lower() for w in _WORD.findall(text)} & SENSOR_WORDS


def _explained(transform: StaticTransform) -> bool:
    """A null transform that is not a forgotten mount: the sensor word is only in the
    parent (the child is another frame of that device, or a frame under it), the parent
    is fixed in the world (a bare sensor displayed in ``map``), or parent and child name
    the same device (an alias between two frames of one sensor)."""
    parent, child = transform.parent, transform.child
    if parent is None or child is None:
        return False
    if is_world_fixed(parent):
        return True
    in_parent, in_child = sensor_words(parent), sensor_words(child)
    in_name = sensor_words(transform.name or "") if transform.knows(Field.NAME) else set()
    if in_parent and not in_child and not (in_name - in_parent):
        return True
    return bool(in_parent & in_child)


def check(context: RuleContext) -> Iterator[Finding]:
    for transform in context.tree.transforms:
        if transform.null_displacement is not True or transform.null_rotation is not True:
            continue
        labels = [
            text
            for text, field in (
                (transform.name, Field.NAME),
                (transform.parent, Field.PARENT),
                (transform.child, Field.CHILD),
            )
            if text is not None and transform.knows(field)
        ]
        sensors = sorted(set().union(*(sensor_words(text) for text in labels)))
        if not sensors:
            continue
        if not context.study and _explained(transform):
            continue
        yield finding_at(transform,
            f"transform '{transform.parent}' -> '{transform.child}' of a sensor "
            f"({', '.join(sensors)}) has zero displacement and zero rotation: the sensor's "
            f"mounting pose was probably never entered",
        )
