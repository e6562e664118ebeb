"""A robot description that defines no link: macros loaded as the robot.

## What it does
Reports the launch element that gives `robot_description` when the description it gives,
once expanded, has no `<link>` at all, for instance a xacro file that only defines macros
(a sensor or arm library) loaded instead of the file that calls them. A description whose
expansion could not be followed, or a `.urdf`/`.xacro` file linted on its own (a macro
library is fine as a file), is not judged.

## Why is this bad?
urdfdom refuses a description without links (`No link elements found in urdf file`):
robot_state_publisher stops at start-up and publishes none of the robot's frames.

## Example
```xml
<launch>
  <param name="robot_description" value="&lt;robot name='demo'&gt;&lt;/robot&gt;"/>
  <node pkg="robot_state_publisher" type="robot_state_publisher" name="rsp"/>
</launch>
```

## Use instead
```xml
<launch>
  <param name="robot_description"
         value="&lt;robot name='demo'&gt;&lt;link name='base_link'/&gt;&lt;/robot&gt;"/>
  <node pkg="robot_state_publisher" type="robot_state_publisher" name="rsp"/>
</launch>
```
"""
from __future__ import annotations

from collections.abc import Iterator

from launch_linter.model.diagnostic import Category, Severity
from launch_linter.model.paths import shown_path
from launch_linter.rules._api import Finding, RuleContext
from launch_linter.rules._robot import refused, robots_of

ID = "urdf_empty_robot"
CATEGORY = Category.TF
SEVERITY = Severity.ERROR


def check(context: RuleContext) -> Iterator[Finding]:
    for robot in robots_of(context):
        if robot.standalone or not robot.complete or robot.links:
            continue
        source = robot.source
        what = f"'{shown_path(source.file)}'" if source.file else "the literal robot description"
        macros = " (it only defines macros: nothing calls them)" if robot.defines_macros else ""
        yield Finding(
            source.path, source.line, source.column,
            f"robot_description: {what} defines no link{macros}; "
            + refused("No link elements found in urdf file"),
            source.node,
        )
