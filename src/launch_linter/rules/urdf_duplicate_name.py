"""Two links, or two joints, of one robot description with the same name.

## What it does
Reports each `<link>` or `<joint>` of an expanded robot description whose name an earlier
link (or joint) of the same description already has, pointing at the first. Elements
under an undecided `xacro:if` are not compared. When both come from the same line, the
message says so: a macro instantiated twice with the same prefix.

## Why is this bad?
urdfdom keeps links and joints by name and refuses a description that repeats one (`link
'x' is not unique.`, `joint 'x' is not unique.`): robot_state_publisher stops at start-up
and publishes none of the robot's frames, and `check_urdf` fails.

## Example
```xml
<robot name="demo">
  <link name="base_link"/>
  <link name="base_link"/>
</robot>
```

## Use instead
```xml
<robot name="demo">
  <link name="base_link"/>
</robot>
```
"""
from __future__ import annotations

from collections.abc import Iterator

from launch_linter.model.diagnostic import Category, Severity
from launch_linter.model.robot import RobotElement
from launch_linter.rules._api import Finding, RuleContext
from launch_linter.rules._robot import finding_at, judged, refused, robots_of, where

ID = "urdf_duplicate_name"
CATEGORY = Category.TF
SEVERITY = Severity.ERROR
EXAMPLE_PATH = "example.urdf"


def check(context: RuleContext) -> Iterator[Finding]:
    for robot in robots_of(context):
        if not judged(robot):
            continue
        first: dict[tuple[str, str], RobotElement] = {}
        for element in robot.elements:
            if element.name is None or not element.condition.always:
                continue
            earlier = first.setdefault((element.kind, element.name), element)
            if earlier is element:
                continue
            if (earlier.path, earlier.line, earlier.column) == (element.path, element.line,
                                                                element.column):
                how = ("made again by the same line: a macro instantiated twice with the "
                       "same prefix or name")
            else:
                how = f"already defined at {where(earlier, element)}"
            yield finding_at(
                robot, element,
                f"{element.kind} '{element.name}' is {how}; "
                + refused(f"{element.kind} '{element.name}' is not unique."),
                [earlier],
            )
