"""A ROS 1 launch argument declared for its user that nothing in its file reads.

## What it does
Reports an `<arg>` a ROS 1 launch file declares with a `default` (or with no value),
directly under `<launch>` or a `<group>`, when nothing in the same file reads it: no
`$(arg NAME)` in any attribute or `<rosparam>` text, no word of an `$(eval ...)` naming
it, whatever the conditions (a read in a skipped branch counts). A file with an
`<include pass_all_args="true">`, or a `<rosparam file=... subst_value="true">` (its
file may read arguments), is not judged. When the file passes an `<include>` an
argument of the same name with another value, the declared argument was meant to go
there: that is a warning, with the include's argument as related place; otherwise it is
info.

## Why is this bad?
roslaunch scopes arguments to their file and accepts a setting of any declared one, so
`roslaunch pkg file.launch NAME:=value` (or an including file's `<arg name="NAME">`) is
silently dropped: the user believes the camera's frames, a port or a switch are set
and they are not. ifm3d-ros#40: `camera.launch` declared `frame_id_base` but passed the
included `nodelet.launch` a fixed `$(arg ns)/$(arg nn)`, so the camera's frames never
followed the argument.

## Example
```xml
<launch>
  <arg name="frame_id_base" default="camera"/>
  <include file="$(dirname)/driver.launch">
    <arg name="frame_id_base" value="camera"/>
  </include>
</launch>
```

## Use instead
```xml
<launch>
  <arg name="frame_id_base" default="camera"/>
  <include file="$(dirname)/driver.launch">
    <arg name="frame_id_base" value="$(arg frame_id_base)"/>
  </include>
</launch>
```

## Known problems
An argument kept for compatibility with callers that still pass it (deprecated, now
unused on purpose) is reported at info. Arguments read only by a file the linter does
not parse (a YAML file loaded without `subst_value` reads none) are not missed: roslaunch
substitutes nowhere else. Judged in docs/evaluation/camera_frames.md.
"""

from __future__ import annotations

from collections.abc import Iterator

from launch_linter.model.diagnostic import Category, Severity
from launch_linter.model.record import replace
from launch_linter.rules._api import Finding, RuleContext, frontend_findings

ID = "ros1_unused_arg"
CATEGORY = Category.LAUNCH
SEVERITY = Severity.WARNING
EXAMPLE_PATH = "example.launch"

UNPASSED_LEVEL = Severity.INFO
"""An unused argument no include of its file is passed under its name: dead, or kept for
callers on purpose; a convention (docs/severity.md)."""


def check(context: RuleContext) -> Iterator[Finding]:
    if context.study:
        return
    for finding in frontend_findings(context, ID):
        # The front-end names the include's argument as the related place when the file
        # passes one of the same name (ros1_base._unused_args).
        yield finding if finding.related else replace(finding, severity=UNPASSED_LEVEL)
