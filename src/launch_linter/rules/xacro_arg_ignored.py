"""A `name:=value` given to xacro that no file of the robot description names.

## What it does
Reports a mapping of a launch file's xacro call (`Command(['xacro ', file, ' prefix:=',
...])`, `<param command="xacro file prefix:=...">`) whose name no file the description
reads writes anywhere: no `<xacro:arg name="prefix">`, no `$(arg prefix)`, no
`xacro.arg('prefix')`, not even in a macro never called or a comment. It reports at the
mapping where the launch file writes it once, else at the description's line, with the
description's close arg names (the usual cause is a renamed arg: `prefix` became
`tf_prefix`). A description whose expansion could not be followed (an include not read, a
value not known) or that includes more files than it read is not judged.

## Why is this bad?
xacro keeps every `name:=value` of its command line in its table of args without checking
it against anything (ros/xacro ros2 9d05b0e, `cli.py` `load_mappings` and `__init__.py`
`process_doc`; noetic-devel the same): a mapping nothing reads is dropped without a word.
What the launch file meant by it never reaches the robot: with `prefix:=ur3` given to a
description that reads `tf_prefix`, robot_state_publisher still publishes `base_link`,
`shoulder_link`, ... unprefixed, and a second arm's frames collide with them
(Universal_Robots_ROS2_GZ_Simulation#19). It is an info: a dropped mapping matters only
when its value should change the robot, which the linter cannot tell (a judged sample:
docs/evaluation/xacro_arg_ignored.md).

## Example
```xml
<launch>
  <param name="robot_description" command="xacro $(dirname)/arm.urdf.xacro prefix:=ur3_"/>
  <node pkg="robot_state_publisher" type="robot_state_publisher" name="rsp"/>
</launch>
```

with `arm.urdf.xacro`:

```xml
<robot name="arm" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:arg name="tf_prefix" default=""/>
  <link name="$(arg tf_prefix)base_link"/>
</robot>
```

## Use instead
```xml
<launch>
  <param name="robot_description" command="xacro $(dirname)/arm.urdf.xacro tf_prefix:=ur3_"/>
  <node pkg="robot_state_publisher" type="robot_state_publisher" name="rsp"/>
</launch>
```

```xml
<robot name="arm" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:arg name="tf_prefix" default=""/>
  <link name="$(arg tf_prefix)base_link"/>
</robot>
```
"""

from __future__ import annotations

import os
from collections.abc import Iterator

from launch_linter.model.diagnostic import Category, Location, Severity
from launch_linter.rules._api import Finding, RuleContext
from launch_linter.rules._robot import robots_of

ID = "xacro_arg_ignored"
CATEGORY = Category.TF
SEVERITY = Severity.INFO
EXAMPLE_PATH = "example.launch"
EXAMPLE_INCLUDED = "arm.urdf.xacro"


def check(context: RuleContext) -> Iterator[Finding]:
    seen: set[tuple[str, int, str]] = set()
    for robot in robots_of(context):
        source = robot.source
        for ignored in robot.ignored_args:
            if ignored.line:
                path, line, column = ignored.path, ignored.line, ignored.column
                related: tuple[Location, ...] = (
                    Location(source.path, source.line, source.column),)
            else:
                path, line, column, related = source.path, source.line, source.column, ()
            if (path, line, ignored.name) in seen:
                continue
            seen.add((path, line, ignored.name))
            described = os.path.basename(source.file) if source.file else "the description"
            close = ("; it declares " + ", ".join(f"'{n}'" for n in ignored.close)
                     if ignored.close else "")
            yield Finding(
                path, line, column,
                f"xacro is given {ignored.name}:=..., but no file of {described} names "
                f"'{ignored.name}' (no <xacro:arg>, no $(arg {ignored.name})){close}: xacro "
                f"keeps the mapping and nothing reads it, so the value never reaches the "
                f"robot's links and joints",
                None, related,
            )
