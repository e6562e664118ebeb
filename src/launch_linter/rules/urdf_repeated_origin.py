"""A second `<origin>` in a `<visual>`, `<collision>`, `<inertial>` or joint: urdfdom ignores it.

## What it does
Reports each `<origin>` after the first inside one `<visual>`, `<collision>` or
`<inertial>` of a link, or inside a `<joint>`, of an expanded robot description, at the
ignored `<origin>` (once, however often a macro writes it; the macro's calls are not
repeated).

## Why is this bad?
URDF gives each of these one pose, and urdfdom reads the first `<origin>` only
(urdf_parser/src/link.cpp `parseVisual`, `parseCollision`, `parseInertial` and joint.cpp
`parseJoint` take `FirstChildElement("origin")`): the others are dropped without a word.
The element then says two things and means the first; whoever edits the second (or
reads it, as urdf_tutorial's readers did, ros/urdf_tutorial#22) changes nothing.

## Example
```xml
<robot name="demo">
  <link name="wheel">
    <visual>
      <origin xyz="0 0 0" rpy="1.5708 0 0"/>
      <origin xyz="0 0 0" rpy="0 0 0"/>
      <geometry><cylinder radius="0.1" length="0.05"/></geometry>
    </visual>
  </link>
</robot>
```

## Use instead
```xml
<robot name="demo">
  <link name="wheel">
    <visual>
      <origin xyz="0 0 0" rpy="1.5708 0 0"/>
      <geometry><cylinder radius="0.1" length="0.05"/></geometry>
    </visual>
  </link>
</robot>
```

## Known problems
Info: a heuristic of intent, not a fault urdfdom refuses; the second `<origin>` may repeat
the first. On 110 repositories with Gazebo cameras (5,857 files) it found 1, two identical
origins (docs/evaluation/urdf_repeated_origin.md): too few to judge a warning.
"""
from __future__ import annotations

from collections.abc import Iterator

from launch_linter.model.diagnostic import Category, Severity
from launch_linter.rules._api import Finding, RuleContext
from launch_linter.rules._robot import robots_of, written_place

ID = "urdf_repeated_origin"
CATEGORY = Category.TF
SEVERITY = Severity.INFO
EXAMPLE_PATH = "example.urdf"


def check(context: RuleContext) -> Iterator[Finding]:
    seen: set[tuple[str, int, int]] = set()
    for robot in robots_of(context):
        for element in robot.elements:
            if element.kind != "origin":
                continue
            shown = written_place(element, seen)
            if shown is None:
                continue
            place, related = shown
            yield Finding(
                place[0], place[1], place[2],
                f"a second <origin> in the {element.name}: urdfdom reads the first "
                f"<origin> only and ignores this one",
                element.name, related)
