"""A `<gazebo reference="...">` naming no link or joint of the robot description.

## What it does
Reports a `<gazebo reference="X">` element (straight under `<robot>` of the expanded
description) whose `X` is the name of no `<link>` and no `<joint>` of that description.
It judges only a description whose every link name and joint end is known, whose joints
name links it defines (one that does not is a fragment or refused: `urdf_missing_link`
says so), and only a reference written outside an undecided `xacro:if`; a link or joint
of that name under any condition keeps it silent. A block that holds a `<sensor>` or a
`<plugin>` is a warning; one that holds only simulation properties (a material, friction,
damping) is info: nothing of the tf tree or of the robot's data is lost.

## Why is this bad?
Gazebo converts the URDF to SDFormat when the robot is spawned, and the converter puts a
`<gazebo>` element's content only into the link or joint its reference names:
`URDF2SDF::ParseSDFExtension` stores each `<gazebo>` by its `reference` string, and
`InsertSDFExtensionLink` / `InsertSDFExtensionJoint` copy an extension into a link or
joint only when the stored string equals that link's or joint's name (src/parser_urdf.cc,
gazebosim/sdformat 2ace536; the same code in the sdformat 6/9 releases Gazebo classic
uses, and gz-sim reads URDF through it). A reference that names nothing is dropped
without a message: the sensor it holds is never created, its plugin never loads (no
data, no frames), and its material, friction or gravity settings do nothing. It happens
when a link is renamed and its `<gazebo>` block is not (bit-bots/wolfgang_robot PR #9:
the IMU sensor in `<gazebo reference="L_IMU">` after the link became `imu_frame`, "imu
was not published in simulation"; Kinovarobotics/kinova-movo#67: the Kinect's camera in
`<gazebo reference="${prefix}_ir_link">`, a link the description does not have).

## Example
```xml
<robot name="demo">
  <link name="base_link"/>
  <link name="imu_frame"/>
  <joint name="imu_joint" type="fixed">
    <parent link="base_link"/>
    <child link="imu_frame"/>
  </joint>
  <gazebo reference="L_IMU">
    <sensor name="imu" type="imu"/>
  </gazebo>
</robot>
```

## Use instead
```xml
<robot name="demo">
  <link name="base_link"/>
  <link name="imu_frame"/>
  <joint name="imu_joint" type="fixed">
    <parent link="base_link"/>
    <child link="imu_frame"/>
  </joint>
  <gazebo reference="imu_frame">
    <sensor name="imu" type="imu"/>
  </gazebo>
</robot>
```
"""
from __future__ import annotations

from collections.abc import Iterator

from launch_linter.model.diagnostic import Category, Severity
from launch_linter.model.robot import RobotModel
from launch_linter.rules._api import Finding, RuleContext
from launch_linter.rules._robot import (
    close_names,
    defined_phrase,
    judged,
    robots_of,
    written_place,
)

ID = "gazebo_reference_unknown"
CATEGORY = Category.TF
SEVERITY = Severity.WARNING
EXAMPLE_PATH = "example.urdf"
KINDS = ("gazebo_reference", "gazebo_properties")
"""A block holding a sensor or plugin (warning: data and frames are lost), and one holding
only simulation properties (info: a material or a friction setting does nothing)."""
MAX_SUGGESTED = 20
"""Close names are offered for this many findings of one description (each costs a scan
of its names)."""


def check(context: RuleContext) -> Iterator[Finding]:
    seen: set[tuple[str, int, int]] = set()
    for robot in robots_of(context):
        names = _whole_names(robot)
        if names is None:
            continue
        known = sorted(names)
        suggested = 0
        for element in robot.elements:
            if (element.kind not in KINDS or element.name is None
                    or element.name in names or not element.condition.always):
                continue
            holds_sensor = element.kind == "gazebo_reference"
            shown = written_place(element, seen)
            if shown is None:
                continue
            place, related = shown
            close = close_names(element.name, known) if suggested < MAX_SUGGESTED else []
            suggested += 1
            yield Finding(
                place[0], place[1], place[2],
                f"<gazebo reference=\"{element.name}\"> names no link or joint of the "
                f"description{defined_phrase(close)}: Gazebo's URDF reader (sdformat) puts a "
                f"<gazebo> element's content only into the link or joint its reference "
                f"names, so this one is dropped without a message: "
                + ("the sensor or plugin in it is never created (no data, no frames)"
                   if holds_sensor else
                   "the simulation properties in it (material, friction, damping) do "
                   "nothing"),
                element.name, related,
                severity=None if holds_sensor else Severity.INFO,
            )


def _whole_names(robot: RobotModel) -> frozenset[str] | None:
    """The link and joint names of a description Gazebo would load whole (under any
    condition); None when it is not judged: xacro refuses it, a link name or joint end is
    unknown, it has no link, or a joint names a link it does not define (a fragment, or
    a description urdfdom refuses)."""
    if not judged(robot) or not robot.complete:
        return None
    links = frozenset(e.name for e in robot.elements if e.kind == "link" and e.name)
    if not links:
        return None
    for joint in robot.joints:
        if joint.parent not in links or joint.child not in links:
            return None
    joints = frozenset(e.name for e in robot.elements if e.kind == "joint" and e.name)
    return links | joints
