"""A frame given two different parents in one launch tree.

## What it does
Follows includes and conditions through the whole launch tree and reports a static
transform whose child frame already has a different parent from an earlier static
transform (frame ids compared without one leading `/`). The diagnostic is on the later
transform and points at the earlier ones. When either transform is only launched under a
condition the linter cannot decide, the message says the frame *may* get two parents;
transforms under mutually exclusive conditions are never compared.

## Why is this bad?
tf frames form a tree: each frame has exactly one parent (REP 105). With two static
parents tf2 keeps whichever transform arrived last, so the frame jumps between two places
depending on start-up order, and lookups through the other parent fail. Typical causes: a
driver's launch file publishes `base_link -> laser` while the robot's own launch file
publishes `base_footprint -> laser`, or the two frames of one transform were swapped.

## Example
```xml
<launch>
  <node pkg="tf2_ros" type="static_transform_publisher" name="laser_tf"
        args="0 0 0.2 0 0 0 base_link laser"/>
  <node pkg="tf2_ros" type="static_transform_publisher" name="laser_mount_tf"
        args="0 0 0.3 0 0 0 base_footprint laser"/>
</launch>
```

## Use instead
```xml
<launch>
  <node pkg="tf2_ros" type="static_transform_publisher" name="base_tf"
        args="0 0 0.1 0 0 0 base_footprint base_link"/>
  <node pkg="tf2_ros" type="static_transform_publisher" name="laser_tf"
        args="0 0 0.2 0 0 0 base_link laser"/>
</launch>
```

## Known problems
Only static transforms are seen: a parent given by a URDF (`robot_state_publisher`) or by
a node that publishes tf at run time is not.
"""
from __future__ import annotations

from collections.abc import Iterator

from launch_linter.model.diagnostic import Category, Severity
from launch_linter.model.transform import StaticTransform
from launch_linter.rules._api import Finding, RuleContext, can_coexist, finding_at, place

ID = "multiple_parents"
CATEGORY = Category.TF
SEVERITY = Severity.ERROR


def check(context: RuleContext) -> Iterator[Finding]:
    by_child: dict[str, list[tuple[str, StaticTransform]]] = {}
    for transform in context.tree.transforms:
        signature = transform.signature
        if signature is None or signature[0] == signature[1]:
            continue
        parent, child = signature
        earlier = by_child.setdefault(child, [])
        rivals: dict[str, StaticTransform] = {}
        for other_parent, other in earlier:
            if other_parent != parent and can_coexist(other, transform):
                rivals.setdefault(other_parent, other)
        earlier.append((parent, transform))
        if not rivals:
            continue
        others = " and ".join(f"'{p}' ({place(t, transform)})" for p, t in rivals.items())
        conditional = any(not t.condition.always for t in (transform, *rivals.values()))
        gets = "may get" if conditional else "gets"
        yield finding_at(transform,
            f"frame '{child}' {gets} {len(rivals) + 1} parents: '{parent}' here and "
            f"{others}; a tf frame has exactly one parent, and tf2 keeps whichever "
            f"transform arrives last",
            rivals.values(),
        )
