"""A Gazebo `<plugin>` or `<sensor>` written straight under `<robot>`, outside `<gazebo>`.

## What it does
Reports a `<plugin>` or `<sensor>` element that is a direct child of the expanded robot
description's `<robot>` element instead of the child of a `<gazebo>` element. One under an
undecided `xacro:if` is not judged, nor a description xacro refuses, nor URDF's own
`<sensor>` element (the wiki's urdf/XML/sensor form, fixed to a `<parent link>`), which
describes a sensor and is not meant for Gazebo.

## Why is this bad?
Nothing reads it. urdfdom skips the elements of `<robot>` it does not know
(`parseURDF` in urdf_parser/src/model.cpp reads its `material`, `link` and `joint`
children only; ros/urdfdom 69502d5), and Gazebo, which converts the URDF to SDFormat
when the robot is spawned, takes plugins and sensors only from `<gazebo>` elements
(`URDF2SDF::ParseSDFExtension` in src/parser_urdf.cc loops over
`FirstChildElement("gazebo")` … `NextSiblingElement("gazebo")`; gazebosim/sdformat
d1e19ee; gz-sim reads URDF through the same converter). The plugin is never
loaded, silently: a `gazebo_ros_joint_state_publisher` left outside publishes no joint
state, so robot_state_publisher sends no transform for the wheel it was meant to cover; a
drive plugin left outside drives nothing and publishes no odometry.

## Example
```xml
<robot name="demo">
  <link name="base_link"/>
  <plugin name="joint_states" filename="libgazebo_ros_joint_state_publisher.so">
    <jointName>front_wheel_joint</jointName>
  </plugin>
</robot>
```

## Use instead
```xml
<robot name="demo">
  <link name="base_link"/>
  <gazebo>
    <plugin name="joint_states" filename="libgazebo_ros_joint_state_publisher.so">
      <jointName>front_wheel_joint</jointName>
    </plugin>
  </gazebo>
</robot>
```
"""
from __future__ import annotations

from collections.abc import Iterator

from launch_linter.model.diagnostic import Category, Severity
from launch_linter.rules._api import Finding, RuleContext
from launch_linter.rules._robot import judged, robots_of, written_place

ID = "urdf_plugin_outside_gazebo"
CATEGORY = Category.TF
SEVERITY = Severity.WARNING
EXAMPLE_PATH = "example.urdf"


def check(context: RuleContext) -> Iterator[Finding]:
    seen: set[tuple[str, int, int]] = set()
    for robot in robots_of(context):
        if not judged(robot):
            continue
        for element in robot.elements:
            if element.kind != "outside_gazebo" or not element.condition.always:
                continue
            shown = written_place(element, seen)
            if shown is None:
                continue
            place, related = shown
            yield Finding(
                place[0], place[1], place[2],
                f"{element.name} is written straight under <robot>, outside any <gazebo> "
                f"element: urdfdom skips it and Gazebo reads plugins and sensors only from "
                f"<gazebo> elements, so it is never loaded (what it should publish, joint "
                f"states, odometry or a sensor's data and frames, is missing); put it "
                f"inside <gazebo>",
                None, related,
            )
