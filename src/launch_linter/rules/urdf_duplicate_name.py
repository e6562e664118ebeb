"""Two links, two joints or two top-level materials of one robot description with one name.

## What it does
Reports each `<link>`, `<joint>` or `<material>` directly under `<robot>` of an expanded
robot description whose name an earlier one of the same kind already has, pointing at the
first. A material inside a link's `<visual>` is not compared (urdfdom keeps it apart), and
two materials of one name are reported even when they are written alike. Elements under
an undecided `xacro:if` are not compared. A file included twice is reported at its second
include, pointing at the first; an element a macro makes at each call is reported at the
second call, pointing at the first call and at the element in the macro; when both come
from the same line, the message says so: a macro instantiated twice with the same prefix.

## Why is this bad?
urdfdom keeps links, joints and top-level materials by name and refuses a description
that repeats one (`link 'x' is not unique.`, `joint 'x' is not unique.`, `material 'x' is
not unique.`; urdf_parser/src/model.cpp, `parseURDF`): robot_state_publisher stops at
start-up and publishes none of the robot's frames, and `check_urdf` fails. A top-level
material written inside a macro, or in a file that two others include, is made twice as
soon as the macro is called twice or both files are included.

## Example
```xml
<robot name="demo">
  <link name="base_link"/>
  <link name="base_link"/>
</robot>
```

## Use instead
```xml
<robot name="demo">
  <link name="base_link"/>
</robot>
```
"""
from __future__ import annotations

from collections.abc import Iterator

from launch_linter.model.diagnostic import Category, Location, Severity
from launch_linter.model.robot import RobotElement, RobotModel
from launch_linter.rules._api import Finding, RuleContext
from launch_linter.rules._robot import judged, level, refused, robots_of, where

ID = "urdf_duplicate_name"
CATEGORY = Category.TF
SEVERITY = Severity.ERROR
EXAMPLE_PATH = "example.urdf"
NAMED_KINDS = ("link", "joint", "material")
"""What urdfdom keeps by name (the description's other elements are not compared)."""


def _place(path: str, line: int, seen_from: str) -> str:
    return f"line {line}" if path == seen_from else f"{path}:{line}"


def _again(robot: RobotModel, earlier: RobotElement, element: RobotElement) -> Finding:
    """The finding for ``element``, which repeats the name of ``earlier``."""
    what = f"{element.kind} '{element.name}'"
    urdfdom = refused(f"{what} is not unique.")
    same_place = ((earlier.path, earlier.line, earlier.column)
                  == (element.path, element.line, element.column))
    site, first_site = element.included, earlier.included
    if same_place and site is not None and site != first_site:
        # One file included twice: the second include is what to remove.
        first = first_site or (earlier.path, earlier.line, earlier.column)
        return Finding(
            site[0], site[1], site[2],
            f"{what} (written at {_place(element.path, element.line, site[0])}) is made "
            f"again by this include: the file is also included at "
            f"{_place(first[0], first[1], site[0])}; {urdfdom}", element.name,
            (Location(*first), Location(element.path, element.line, element.column)),
            severity=level(robot))
    related = [Location(earlier.path, earlier.line, earlier.column)]
    if same_place:
        how = ("made again by the same line: a macro instantiated twice with the same "
               "prefix or name")
    else:
        how = f"already defined at {where(earlier, element)}"
    if element.defined is not None and element.defined == earlier.defined:
        how += (f" (each call of the macro makes the {element.kind} written at "
                f"{_place(element.defined[0], element.defined[1], element.path)})")
        related.append(Location(*element.defined))
    return Finding(element.path, element.line, element.column, f"{what} is {how}; {urdfdom}",
                   element.name, tuple(related), severity=level(robot))


def check(context: RuleContext) -> Iterator[Finding]:
    for robot in robots_of(context):
        if not judged(robot):
            continue
        first: dict[tuple[str, str], RobotElement] = {}
        for element in robot.elements:
            if (element.name is None or not element.condition.always
                    or element.kind not in NAMED_KINDS):
                continue
            earlier = first.setdefault((element.kind, element.name), element)
            if earlier is not element:
                yield _again(robot, earlier, element)
