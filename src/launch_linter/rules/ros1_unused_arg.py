"""A ROS 1 launch argument declared for its user that nothing in its file reads.

## What it does
Reports an `<arg>` a ROS 1 launch file declares with a `default` (or with no value)
directly under `<launch>` (one in a `<group>` is a branch's local variable, not judged),
when nothing in the same file reads it: no
`$(arg NAME)` in any attribute or `<rosparam>` text, no word of an `$(eval ...)` naming
it, whatever the conditions (a read in a skipped branch counts). A file with an
`<include pass_all_args="true">`, or a `<rosparam file=... subst_value="true">` (its
file may read arguments), is not judged. When the argument names a frame (`frame` in
its name) and the file gives an `<include>`'s argument or a `<param>` of the same name
a value of its own that is the argument's default copied or reads no other argument,
the frame the user sets never reaches what stamps or looks it up: that is a warning,
with that place as related. So is a frame argument (its name ends in `frame`,
`frame_id` or `frame_name`) that nothing of its name is set from, in a file that hands
another frame argument on under its own name (`<param name="left_camera_frame"
value="$(arg left_camera_frame)"/>`, or an include's `<arg>`): the file passes its frames
on that way and missed this one (related: that other frame's place). Any other unread
argument is info: dead, a setting the file fixes on purpose, or a value tied to other
arguments (hector's `odom_frame` given `$(arg base_frame)` when there is no odometry).

## Why is this bad?
roslaunch scopes arguments to their file and accepts a setting of any declared one, so
`roslaunch pkg file.launch NAME:=value` (or an including file's `<arg name="NAME">`) is
silently dropped: the user believes the camera's frames, a port or a switch are set
and they are not. ifm3d-ros#40: `camera.launch` declared `frame_id_base` but passed the
included `nodelet.launch` a fixed `$(arg ns)/$(arg nn)`, so the camera's frames never
followed the argument. zed-ros-wrapper#248 and #392: `zed_camera.launch` and its nodelet
variant handed every camera frame to the node by name but not `imu_frame`, so
`imu_frame:=...` left the ZED-M's IMU on `imu_link`, clashing with the robot's own.

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
unused on purpose) is reported at info. A `$(arg NAME)` inside an XML comment counts as a
read (the file's text is searched for reads before its elements are walked, which keeps
the check cheap), so an argument read only in commented-out XML is not reported.
The second warning (a frame missed beside frames handed on by name) was judged on the
corpus and 8 unseen repositories: 4 groups true, one of them a dead argument no node
reads (docs/evaluation/ros1_unused_arg.jsonl).
Arguments read only by a file the linter does not parse (a YAML file loaded without
`subst_value` reads none) are not missed: roslaunch substitutes nowhere else. Judged in
docs/evaluation/camera_frames.md.
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

OTHER_LEVEL = Severity.INFO
"""An unread argument that is no frame set otherwise in its file: dead, kept for callers,
or a setting the file fixes on purpose (docs/evaluation/camera_frames.md)."""


def check(context: RuleContext) -> Iterator[Finding]:
    if context.study:
        return
    for finding in frontend_findings(context, ID):
        # The front-end names a related place only for a frame the file sets otherwise
        # or misses beside frames it hands on by name (ros1_base._unused_args,
        # UnusedArg.frame_dropped and frame_forgotten).
        yield finding if finding.related else replace(finding, severity=OTHER_LEVEL)
