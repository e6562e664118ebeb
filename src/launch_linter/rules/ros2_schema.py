"""A ROS 2 launch XML/YAML action with an attribute or nested tag launch does not accept.

## What it does
Checks every action of a ROS 2 XML or YAML launch file against what the `parse` methods
of `launch` and `launch_ros` read (the table is in `frontends/ros2_schema.py`, with the
source file of each entry): a misspelled attribute (`namespce=`), a ROS 1 leftover
(`type=` or `ns=` on a `<node>`, a top-level `<param>` or `<rosparam>`), a nested tag
the action does not read (`<remapp>`), or a tag no launch package exposes under that
spelling (`<set-env>`). The file's static transforms are then left out of the
`transforms` output and of every other rule, as launch starts none of them.

## Why is this bad?
Since launch 0.14 (back-ported to Foxy) the front-end refuses the whole file when any
action has something its parser did not read ("Unexpected attribute(s) found in
`node`"), so the robot gets none of the file's nodes and transforms.

## Example
```xml
<launch>
  <node pkg="tf2_ros" exec="static_transform_publisher" namespce="robot"
        args="--frame-id base_link --child-frame-id laser"/>
</launch>
```

## Use instead
```xml
<launch>
  <node pkg="tf2_ros" exec="static_transform_publisher" namespace="robot"
        args="--frame-id base_link --child-frame-id laser"/>
</launch>
```
"""

from __future__ import annotations

from collections.abc import Iterable

from launch_linter.model.diagnostic import Category, Severity
from launch_linter.rules._api import Finding, RuleContext
from launch_linter.rules._refusals import refusal_findings

ID = "ros2_schema"
CATEGORY = Category.LAUNCH
SEVERITY = Severity.ERROR


def check(context: RuleContext) -> Iterable[Finding]:
    return refusal_findings(context, ID)
