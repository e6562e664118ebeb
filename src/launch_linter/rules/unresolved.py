"""A value the linter could not resolve statically.

## What it does
Reports a static transform (or an `<include>`) whose values depend on something the linter
cannot know without running roslaunch: an `$(arg)` that is never set, an `$(env)` variable
not given with `--env`, a `$(find)` package that is not under the package path, or an
`$(eval)` outside the safe expression language. The message names what really blocks the
value: the innermost unknown (the environment variable behind a launch argument's default,
not the `LaunchConfiguration` that passes it on), each cause once; in included text it
names the include that gave the values, once per place in a tree however often the file
is included; a description given to several nodes is reported once. Rules that need an
unknown value stay silent about it.

## Why is this bad?
It is not a fault in itself: it tells you what the linter could not check, so that a
clean result is not mistaken for a checked one.

## Example
```xml
<launch>
  <node pkg="tf2_ros" type="static_transform_publisher" name="laser_tf"
        args="0 0 0.2 0 0 0 base_link $(arg laser_frame)"/>
</launch>
```

## Use instead
```xml
<launch>
  <arg name="laser_frame" default="laser"/>
  <node pkg="tf2_ros" type="static_transform_publisher" name="laser_tf"
        args="0 0 0.2 0 0 0 base_link $(arg laser_frame)"/>
</launch>
```
or give the value on the command line: `launch-linter check --arg laser_frame:=laser`.
"""
from __future__ import annotations

from collections.abc import Iterable

from launch_linter.model.diagnostic import Category, Severity
from launch_linter.rules._api import Finding, RuleContext, frontend_findings

ID = "unresolved"
CATEGORY = Category.LAUNCH
SEVERITY = Severity.INFO


def check(context: RuleContext) -> Iterable[Finding]:
    return frontend_findings(context, ID)
