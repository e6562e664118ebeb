"""A ROS 1 launch attribute or tag roslaunch does not read where it is written: no effect.

## What it does
Reports an attribute of a tag roslaunch reads (`<node>`, `<test>`, `<include>`, `<group>`,
`<arg>`, `<param>`, `<rosparam>`, `<remap>`, `<env>`, `<machine>`) that is not among the
attributes roslaunch reads for that tag (`if` and `unless` are read on every one). A
warning when the attribute is one roslaunch reads on another tag and the tag starts, sets
or passes something (`args` on an `<include>`, `from`/`to` on a `<param>`, `name` on a
`<rosparam>`): the author expected an effect there. Info otherwise: a label on a `<group>`
(`name="odometry"`), a word no tag reads (`description` on an `<arg>`). The same for a
child tag roslaunch skips where it is written: a warning for one it reads elsewhere (an
`<arg>` inside a `<node>`; a `<param>` or `<remap>` inside an `<include>` when it passes
on one of the file's arguments, `value="$(arg port)"`, which then does nothing whatever a
user gives: written literally it may restate the included file's own value, info) or for one
no tag reads that holds a `<node>`, `<test>` or `<include>` (another tool's `<foreach>`
around nodes: none of them starts), info for others (`<sphinxdoc>`).

## Why is this bad?
roslaunch's `XmlLoader._check_attrs` compares each tag's attributes with its list and, for
any other, only records `unknown <tag> attribute 'x'`, printed as a warning among the
start-up messages; the launch goes on without it (ros/ros_comm
tools/roslaunch/src/roslaunch/xmlloader.py, the same lists on kinetic-devel 25af588,
melodic-devel 2a92e3d and noetic-devel 845f746). So `<include file="..."
args="gui:=false">` passes nothing: the included file runs with its defaults (an
`<include>` takes its arguments from `<arg>` elements); `<node ... display="screen">`
shows nothing (the attribute is `output`). Inside an `<include>` roslaunch reads `<arg>` and
`<env>` only (`_include_tag`), inside a `<node>` `<remap>`, `<param>`, `<rosparam>` and
`<env>` (`_node_tag`); any other child is skipped with a printed warning, so a `<param>`
meant for the included nodes is never set.

## Example
```xml
<launch>
  <include file="$(find gazebo_ros)/launch/empty_world.launch" args="gui:=false"/>
</launch>
```

## Use instead
```xml
<launch>
  <include file="$(find gazebo_ros)/launch/empty_world.launch">
    <arg name="gui" value="false"/>
  </include>
</launch>
```
"""
from __future__ import annotations

from collections.abc import Iterator

from launch_linter.model.diagnostic import Category, Severity
from launch_linter.model.record import replace
from launch_linter.rules._api import Finding, RuleContext, frontend_findings

ID = "ros1_ignored_attribute"
CATEGORY = Category.LAUNCH
SEVERITY = Severity.WARNING
EXAMPLE_PATH = "example.launch"

MISTAKEN_PREFIX = "roslaunch reads "
"""How the front-end's message of an attribute roslaunch reads on another tag starts
(frontends/ros1_attributes.py ``MISTAKEN_PREFIX``, the same words)."""
OTHER_LEVEL = Severity.INFO
"""A label or a word no tag reads: it does nothing, and nothing was expected of it."""


def check(context: RuleContext) -> Iterator[Finding]:
    for finding in frontend_findings(context, ID):
        yield (finding if finding.message.startswith(MISTAKEN_PREFIX)
               else replace(finding, severity=OTHER_LEVEL))
