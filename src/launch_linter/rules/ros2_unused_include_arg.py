"""A ROS 2 include passes an argument that the included launch file never uses.

## What it does
Reports an argument of an `IncludeLaunchDescription` (Python `launch_arguments`, the
`<arg>` of an XML `<include>`, the `arg:` of a YAML `include`) that the included launch
file neither declares nor reads, counting the files it includes in turn: no
`DeclareLaunchArgument`/`<arg>`/`arg:`, no `SetLaunchConfiguration`/`<let>`, and no read of
it (`LaunchConfiguration`, `$(var)`, a `PythonExpression` built from them, an
`OpaqueFunction`'s `context.launch_configurations` or `perform(context)`), also in actions
that a false condition skips. The finding is at the argument's line, with the include
as related place. An argument spelt like one the included files declare is
`ros2_include_arg_misspelt`'s.

## Why is this bad?
ROS 2 launch sets each include argument as a launch configuration and never checks that
the included file uses it: the argument is ignored without a word. It is usually a switch
the included file does not have, or no longer has, or spells otherwise; the author
believes something is switched off (or on) that is not. husarion_ugv_ros passed
`publish_robot_state:=False` to a controller launch file that had no such argument, so a
second `robot_state_publisher` kept running in simulation (husarion_ugv_ros#640). ROS 1's
roslaunch refuses the same include (`unused args [...] for include of [...]`, roslaunch's
`loader.post_process_include_args`, called from `xmlloader`'s `<include>` unless
`pass_all_args`), which `roslaunch_error` reports.

## Example
```xml
<launch>
  <arg name="use_sim" default="true"/>
  <include file="$(dirname)/controller.launch.xml">
    <arg name="use_sim" value="$(var use_sim)"/>
    <arg name="publish_robot_state" value="false"/>
  </include>
</launch>
```
where `controller.launch.xml` has no `publish_robot_state`:
```xml
<launch>
  <arg name="use_sim" default="false"/>
  <node pkg="robot_state_publisher" exec="robot_state_publisher"/>
  <node pkg="controller_manager" exec="ros2_control_node" unless="$(var use_sim)"/>
</launch>
```

## Use instead
```xml
<launch>
  <arg name="use_sim" default="true"/>
  <include file="$(dirname)/controller.launch.xml">
    <arg name="use_sim" value="$(var use_sim)"/>
    <arg name="publish_robot_state" value="false"/>
  </include>
</launch>
```
with `controller.launch.xml` declaring the argument and using it (or stop passing it):
```xml
<launch>
  <arg name="use_sim" default="false"/>
  <arg name="publish_robot_state" default="true"/>
  <node pkg="robot_state_publisher" exec="robot_state_publisher"
        if="$(var publish_robot_state)"/>
  <node pkg="controller_manager" exec="ros2_control_node" unless="$(var use_sim)"/>
</launch>
```

## Known problems
An include whose file the linter cannot follow, or that holds anything whose reads it
cannot see (an include not followed or skipped by a false condition, an `OpaqueFunction`
it does not run, a configuration name that is not literal, launch arguments it cannot
read), is never reported. A read of the argument after the include, in the including
file, is not a use by the included file and does not silence the finding.
"""

from __future__ import annotations

from collections.abc import Iterable

from launch_linter.model.diagnostic import Category, Severity
from launch_linter.rules._api import Finding, RuleContext, frontend_findings

ID = "ros2_unused_include_arg"
CATEGORY = Category.LAUNCH
SEVERITY = Severity.INFO
EXAMPLE_PATH = "example.launch.xml"
EXAMPLE_INCLUDED = "controller.launch.xml"
"""The file the documented example includes: the second block of its sections."""


def check(context: RuleContext) -> Iterable[Finding]:
    if context.study:
        return ()
    return frontend_findings(context, ID)
