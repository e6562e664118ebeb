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
URDF joints count when a `robot_state_publisher` of the same launch tree publishes the
description (`robot_description` from xacro, a URDF file or literal text); a parent given
by a node that publishes tf at run time (odometry, localization) is not seen.
"""
from __future__ import annotations

from collections.abc import Iterator

from launch_linter.model.diagnostic import Category, Severity
from launch_linter.rules._api import MAX_LISTED, MAX_RELATED, Finding, RuleContext, summarised
from launch_linter.rules._tree import Edge, coexist, edges_of, finding_on, place

ID = "multiple_parents"
CATEGORY = Category.TF
SEVERITY = Severity.ERROR


def check(context: RuleContext) -> Iterator[Finding]:
    by_child: dict[str, list[tuple[str, Edge]]] = {}
    for edge in edges_of(context):
        parent, child = edge.parent, edge.child
        if parent == child:
            continue
        earlier = by_child.setdefault(child, [])
        rivals: dict[str, Edge] = {}
        for other_parent, other in earlier:
            if other_parent != parent and coexist(other, edge):
                rivals.setdefault(other_parent, other)
        earlier.append((parent, edge))
        if not rivals:
            continue
        others = " and ".join(summarised(
            [f"'{p}' ({_where(t, edge)})" for p, t in rivals.items()], MAX_LISTED))
        conditional = any(not t.condition.always for t in (edge, *rivals.values()))
        gets = "may get" if conditional else "gets"
        here = "here" if edge.joint is None else f"here (URDF joint '{edge.joint.name}')"
        yield finding_on(
            edge,
            f"frame '{child}' {gets} {len(rivals) + 1} parents: '{parent}' {here} and "
            f"{others}; a tf frame has exactly one parent, and tf2 keeps whichever "
            f"transform arrives last",
            tuple(list(rivals.values())[:MAX_RELATED]),
        )


def _where(edge: Edge, seen_from: Edge) -> str:
    if edge.joint is None:
        return place(edge, seen_from)
    return f"URDF joint '{edge.joint.name}', {edge.location.path}:{edge.location.line}"
