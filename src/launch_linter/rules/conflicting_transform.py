"""The same parent -> child edge published by two sources with different values.

## What it does
Follows the whole launch tree of an entry point, with the URDF joints of the robot
descriptions that its `robot_state_publisher` publishes, and reports an edge (parent →
child, frame ids compared without one leading `/`) published by two sources with different
translation or rotation: two static transforms in different files (within one file it is
`dup_sig`), or a static transform and a URDF joint. An edge that the URDF makes a movable
joint and a launch file also publishes as a static transform is reported whatever the
values. Sources under mutually exclusive conditions are never compared.

## Why is this bad?
tf2 keeps one transform per edge. With two publishers that disagree, the sensor mount or
the robot's body is wherever the last message put it, and for a movable joint the static
transform overwrites the joint's motion. The usual cause is a bringup file and an included
sensors file (or the URDF) that both describe the same mount, one of them out of date.

## Example
```xml
<launch>
  <param name="robot_description" value="&lt;robot name='r'&gt;
    &lt;joint name='laser_joint' type='fixed'&gt;
      &lt;parent link='base_link'/&gt;&lt;child link='laser'/&gt;
      &lt;origin xyz='0.1 0 0.2'/&gt;
    &lt;/joint&gt;&lt;/robot&gt;"/>
  <node pkg="robot_state_publisher" type="robot_state_publisher" name="rsp"/>
  <node pkg="tf2_ros" type="static_transform_publisher" name="laser_tf"
        args="0.1 0 0.3 0 0 0 base_link laser"/>
</launch>
```

## Use instead
```xml
<launch>
  <param name="robot_description" value="&lt;robot name='r'&gt;
    &lt;joint name='laser_joint' type='fixed'&gt;
      &lt;parent link='base_link'/&gt;&lt;child link='laser'/&gt;
      &lt;origin xyz='0.1 0 0.2'/&gt;
    &lt;/joint&gt;&lt;/robot&gt;"/>
  <node pkg="robot_state_publisher" type="robot_state_publisher" name="rsp"/>
</launch>
```

## Known problems
Two launch files that publish the same edge with the same values are not reported (the
copy is redundant, not wrong). Values that are not resolved are not compared.
"""

from __future__ import annotations

import collections
from collections.abc import Iterator

from launch_linter.model.diagnostic import Category, Severity
from launch_linter.rules._api import Finding, RuleContext
from launch_linter.rules._tree import Edge, coexist, edges_of, finding_on

ID = "conflicting_transform"
CATEGORY = Category.TF
SEVERITY = Severity.ERROR


def _conflict(a: Edge, b: Edge) -> str:
    """Why the two sources conflict, or an empty text when they do not."""
    if a.joint is not None and b.joint is not None:
        return ""
    if a.joint is None and b.joint is None and a.location.path == b.location.path:
        return ""  # dup_sig's case
    movable = a if a.dynamic else b if b.dynamic else None
    if movable is not None and movable.joint is not None:
        return (f"the URDF makes it the movable {movable.joint.joint_type} joint "
                f"'{movable.joint.name}', and the static transform freezes it")
    same = a.same_values(b)
    if same is None or same:
        return ""
    return "with different values; tf2 keeps whichever arrives last"


class _Sources:
    """The edges seen so far for one (parent, child): URDF joints, and launch transforms by
    file, each file's only the first of each condition and values (a later one with the
    same would conflict exactly when that one does, and comes after it), with positions."""

    def __init__(self) -> None:
        self.joints: list[tuple[int, Edge]] = []
        self.launch: dict[str, list[tuple[int, Edge]]] = {}
        self.kinds: dict[str, set[object]] = {}

    def add(self, position: int, edge: Edge) -> None:
        if edge.joint is not None:
            self.joints.append((position, edge))
            return
        path = edge.location.path
        kind = (edge.condition, edge.translation, edge.rotation)
        kinds = self.kinds.setdefault(path, set())
        if kind not in kinds:
            kinds.add(kind)
            self.launch.setdefault(path, []).append((position, edge))

    def first_conflict(self, edge: Edge) -> tuple[Edge, str] | None:
        """The earliest edge that conflicts with ``edge``, and why. Two joints never
        conflict, nor two transforms of one file (dup_sig's case): those are not looked at."""
        groups = [known for path, known in self.launch.items()
                  if edge.joint is not None or path != edge.location.path]
        if edge.joint is None:
            groups.append(self.joints)
        best: tuple[int, Edge, str] | None = None
        for known in groups:
            for position, other in known:
                if best is not None and position > best[0]:
                    break
                why = _conflict(other, edge) if coexist(other, edge) else ""
                if why:
                    best = (position, other, why)
                    break
        return None if best is None else (best[1], best[2])


def check(context: RuleContext) -> Iterator[Finding]:
    edges = edges_of(context)
    # Only an edge published more than once can conflict (most are published once).
    counts = collections.Counter((edge.parent, edge.child) for edge in edges)
    seen: dict[tuple[str, str], _Sources] = {}
    for position, edge in enumerate(edges):
        key = (edge.parent, edge.child)
        if counts[key] < 2:
            continue
        sources = seen.setdefault(key, _Sources())
        conflict = sources.first_conflict(edge)
        sources.add(position, edge)
        if conflict is not None:
            other, why = conflict
            yield finding_on(
                edge,
                f"'{edge.parent}' -> '{edge.child}' is also published by "
                f"{other.describe()}, {why}",
                (other,),
            )
