"""A ROS 2 include passes an argument spelt like one the included file declares, not as it.

## What it does
Reports an argument of an `IncludeLaunchDescription` (Python `launch_arguments`, the `<arg>`
of an XML `<include>`, the `arg:` of a YAML `include`) that the included launch file
neither declares nor reads, while it (or a file it includes) declares an argument spelt
alike (`params` beside `params_file`; difflib's ratio of at least 0.8). The finding is at
the argument's line, with the include as related place, and names the declared spelling.
Unlike `ros2_unused_include_arg`, it is reported even when part of what the include runs
is unseen (an include not followed, an `OpaqueFunction`): the included file's own
declaration of the other spelling is the evidence.

## Why is this bad?
ROS 2 launch sets each include argument as a launch configuration and never checks that
the included file uses it, so a misspelt argument is dropped without a word and the
declared one keeps its default. turtlebot3_navigation2's navigation2.launch.py passed its
parameter file to nav2_bringup's bringup_launch.py as `params`; bringup_launch.py declares
`params_file`, so nav2 ran with nav2_bringup's default parameters instead of the
TurtleBot3 ones (turtlebot3#694).

## Example
```xml
<launch>
  <arg name="robot_params" default="$(dirname)/robot.yaml"/>
  <include file="$(dirname)/bringup.launch.xml">
    <arg name="params" value="$(var robot_params)"/>
  </include>
</launch>
```
where `bringup.launch.xml` declares `params_file`:
```xml
<launch>
  <arg name="params_file" default="$(dirname)/default.yaml"/>
  <node pkg="nav2_amcl" exec="amcl" name="amcl">
    <param from="$(var params_file)"/>
  </node>
</launch>
```

## Use instead
```xml
<launch>
  <arg name="robot_params" default="$(dirname)/robot.yaml"/>
  <include file="$(dirname)/bringup.launch.xml">
    <arg name="params_file" value="$(var robot_params)"/>
  </include>
</launch>
```
with `bringup.launch.xml` unchanged:
```xml
<launch>
  <arg name="params_file" default="$(dirname)/default.yaml"/>
  <node pkg="nav2_amcl" exec="amcl" name="amcl">
    <param from="$(var params_file)"/>
  </node>
</launch>
```

## Known problems
An unseen part of the include (an `OpaqueFunction`, an include not followed) could read
the passed spelling too; the linter reports the argument anyway, on the strength of the
declared spelling. Close names are looked for in the first 32 arguments nothing uses.
"""

from __future__ import annotations

from collections.abc import Iterable

from launch_linter.model.diagnostic import Category, Severity
from launch_linter.rules._api import Finding, RuleContext, frontend_findings

ID = "ros2_include_arg_misspelt"
CATEGORY = Category.LAUNCH
SEVERITY = Severity.WARNING
EXAMPLE_PATH = "example.launch.xml"
EXAMPLE_INCLUDED = "bringup.launch.xml"
"""The file the documented example includes: the second block of its sections."""


def check(context: RuleContext) -> Iterable[Finding]:
    if context.study:
        return ()
    return frontend_findings(context, ID)
