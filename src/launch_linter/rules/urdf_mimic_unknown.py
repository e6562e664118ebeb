"""A URDF joint that mimics a joint the description does not define.

## What it does
Reports a `<mimic joint="...">` of an expanded robot description that names no `<joint>`
of the description, with the closest joint names when there are any (a prefix the macro
call gave the joints but not the mimic, a misspelling). A `<mimic>` under an undecided
`xacro:if` is not judged, nor a description whose expansion could not be followed (an
include not read, a name not known).

## Why is this bad?
urdfdom accepts the name without checking it, so the fault shows only at run time:
robot_state_publisher computes a mimic joint's position from the position of the joint it
names (joint_state_listener.cpp in ROS 1, robot_state_publisher.cpp in ROS 2), and with
no such joint the mimic joint's child link gets no transform unless something publishes
that joint's own state. joint_state_publisher (ROS 1 and ROS 2) looks the named joint up
among the robot's movable joints (`self.free_joints[parent]`) and stops with a
`KeyError`: it then publishes no joint state at all, and every movable joint's frame is
missing. MoveIt refuses the mimic (`Joint 'x' cannot mimic unknown joint 'y'`). With
joint_state_publisher in the launch tree this is an error; otherwise a warning.

## Example
```xml
<robot name="demo">
  <link name="palm"/>
  <link name="left_finger"/>
  <link name="right_finger"/>
  <joint name="gripper_joint" type="revolute">
    <parent link="palm"/>
    <child link="left_finger"/>
    <limit lower="0" upper="0.8" effort="10" velocity="1"/>
  </joint>
  <joint name="right_finger_joint" type="revolute">
    <parent link="palm"/>
    <child link="right_finger"/>
    <limit lower="0" upper="0.8" effort="10" velocity="1"/>
    <mimic joint="gripper" multiplier="-1"/>
  </joint>
</robot>
```

## Use instead
```xml
<robot name="demo">
  <link name="palm"/>
  <link name="left_finger"/>
  <link name="right_finger"/>
  <joint name="gripper_joint" type="revolute">
    <parent link="palm"/>
    <child link="left_finger"/>
    <limit lower="0" upper="0.8" effort="10" velocity="1"/>
  </joint>
  <joint name="right_finger_joint" type="revolute">
    <parent link="palm"/>
    <child link="right_finger"/>
    <limit lower="0" upper="0.8" effort="10" velocity="1"/>
    <mimic joint="gripper_joint" multiplier="-1"/>
  </joint>
</robot>
```
"""
from __future__ import annotations

from collections.abc import Iterator

from launch_linter.model.diagnostic import Category, Severity
from launch_linter.model.robot import RobotModel
from launch_linter.rules._api import Finding, RuleContext
from launch_linter.rules._robot import close_names, defined_phrase, judged, robots_of, written_place

ID = "urdf_mimic_unknown"
CATEGORY = Category.TF
SEVERITY = Severity.ERROR
EXAMPLE_PATH = "example.urdf"

JOINT_STATE_PUBLISHERS = frozenset({
    ("joint_state_publisher", "joint_state_publisher"),
    ("joint_state_publisher_gui", "joint_state_publisher_gui"),
})
"""The programs that stop on a mimic of an unknown joint (joint_state_publisher's
``self.free_joints[parent]``: noetic-devel 7cb7069 __init__.py, ros2 fb29caa
joint_state_publisher.py; the GUI runs the same class)."""
MAX_SUGGESTED = 20
"""Unknown names per description for which close names are looked for (each look is a
pass over every joint name)."""


def check(context: RuleContext) -> Iterator[Finding]:
    stops = any((node.package, node.executable) in JOINT_STATE_PUBLISHERS
                for node in context.tree.nodes if node.kind == "node")
    seen: set[tuple[str, int, int]] = set()
    for robot in robots_of(context):
        if not robot.complete or not judged(robot):
            continue
        joints = _joint_names(robot)
        if joints is None:
            continue
        defined = frozenset(joints)
        owner: str | None = None
        suggested = 0
        for element in robot.elements:
            if element.kind == "joint":
                owner = element.name
                continue
            if (element.kind != "mimic" or element.name is None or element.name in defined
                    or not element.condition.always):
                continue
            shown = written_place(element, seen)
            if shown is None:
                continue
            place, related = shown
            close = close_names(element.name, joints) if suggested < MAX_SUGGESTED else []
            suggested += 1
            yield Finding(
                place[0], place[1], place[2],
                f"joint '{owner}' mimics joint '{element.name}', which the description does "
                f"not define{defined_phrase(close)}: robot_state_publisher cannot compute "
                f"'{owner}' from it (its child link gets no transform unless '{owner}' "
                f"itself is in /joint_states), joint_state_publisher stops on it with a "
                f"KeyError and MoveIt refuses the mimic",
                owner, related,
                severity=None if stops and not robot.standalone else Severity.WARNING,
            )


def _joint_names(robot: RobotModel) -> list[str] | None:
    """Every joint name of the description (under any condition: a joint that may be
    defined is not missing), None when a joint's name is unknown."""
    names: list[str] = []
    for element in robot.elements:
        if element.kind == "joint":
            if element.name is None:
                return None
            names.append(element.name)
    return names
