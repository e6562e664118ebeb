"""A robot description with two root links, or none.

## What it does
Reads every robot description a `robot_state_publisher` of the tree publishes (and every
`.urdf`/`.xacro` file linted on its own) as urdfdom does, after xacro: a root link is a link
that is the child of no joint. Reports the second root link when there are two or more,
naming the others, and a description where every link is the child of a joint (no root:
the joints form a loop, every joint naming links the description defines: a joint to an
undefined link is urdf_missing_link's, which urdfdom meets first). Only what is certain
is reported: a link under an undecided
`xacro:if` is not counted as a root, a joint under one may give a link its parent, and a
description whose expansion could not be followed (an include not read, a name not known)
is not judged. A `<link>` without a `name` attribute counts as urdfdom counts it: a link
named '' ("No name given for the link."), which no joint can name, so a root of its own.

## Why is this bad?
urdfdom builds one tree from one root and refuses anything else (`Two root links found:
[a] and [b]`, `No root link found. The robot xml is not a valid tree.`):
robot_state_publisher (ROS 1 and ROS 2) stops at start-up and publishes none of the
robot's frames, and `check_urdf` fails. Two roots usually mean a sub-assembly (a gripper,
a sensor, a second arm from another macro) attached to nothing: a joint to the rest of
the robot is missing, or its parent link is misspelt.

## Example
```xml
<robot name="demo">
  <link name="base_link"/>
  <link name="gripper_link"/>
</robot>
```

## Use instead
```xml
<robot name="demo">
  <link name="base_link"/>
  <link name="gripper_link"/>
  <joint name="gripper_joint" type="fixed">
    <parent link="base_link"/>
    <child link="gripper_link"/>
  </joint>
</robot>
```
"""
from __future__ import annotations

from collections.abc import Iterator

from launch_linter.model.diagnostic import Category, Severity
from launch_linter.model.robot import RobotElement, RobotModel
from launch_linter.rules._api import Finding, RuleContext, summarised_lazily
from launch_linter.rules._robot import (
    finding_at,
    first_by_name,
    judged,
    refused,
    robots_of,
    where,
)

ID = "urdf_root"
CATEGORY = Category.TF
SEVERITY = Severity.ERROR
EXAMPLE_PATH = "example.urdf"


def _links(robot: RobotModel) -> dict[str, RobotElement]:
    """The links by name as urdfdom keeps them. In a description whose expansion was
    followed (``complete``), a link with no known name has no ``name`` attribute at all:
    urdfdom logs "No name given for the link." and keeps it under the name ''."""
    links = first_by_name(robot.links)
    unnamed = next((link for link in robot.links if link.name is None), None)
    if unnamed is not None and "" not in links:
        links[""] = unnamed
    return links


def _called(link: RobotElement) -> str:
    return f"'{link.name}'" if link.name is not None else "'' (a <link> without a name)"


def check(context: RuleContext) -> Iterator[Finding]:
    for robot in robots_of(context):
        if not robot.complete or not judged(robot):
            continue
        links = _links(robot)
        if not links:
            continue
        children = {joint.child for joint in robot.joints}
        roots = [link for name, link in links.items() if name not in children]
        certain = [link for link in roots if link.condition.always]
        if len(certain) >= 2:
            first, second = sorted(link.name or "" for link in certain)[:2]
            # The link without a name is the fault when there is one; else the second root.
            shown = next((r for r in certain if r.name is None), certain[1])
            others = " and ".join(summarised_lazily(
                (f"{_called(r)} ({where(r, shown)})" for r in certain if r is not shown),
                len(certain) - 1))
            missing = ("; a joint to the rest of the robot is missing" if shown.name is not None
                       else "; give the link its name")
            yield finding_at(
                robot, shown,
                f"link {_called(shown)} is a second root link: it is the child of no "
                f"joint, like {others}; "
                + refused(f"Two root links found: [{first}] and [{second}]") + missing,
                [r for r in certain if r is not shown],
            )
        elif not roots and all(e.condition.always for e in robot.elements
                                   if e.kind in ("link", "joint")) and all(
                end in links for joint in robot.joints for end in (joint.parent, joint.child)):
            # A joint naming a link the description lacks stops urdfdom's initTree before
            # it looks for a root ("parent link [x] of joint [y] not found"), and that
            # link, not a loop, is why no root is left: urdf_missing_link says so.
            link = next(iter(links.values()))
            yield finding_at(
                robot, link,
                "no root link: every link is the child of a joint, so the joints form a "
                "loop; " + refused("No root link found. The robot xml is not a "
                                          "valid tree."),
            )
