"""A URDF joint whose parent or child link the description does not define.

## What it does
Reports a joint of an expanded robot description that names a parent or child link no
`<link>` of the description defines, with the closest link names when there are any (a
prefix the macro call did not give, a misspelling). A joint under an undecided `xacro:if`
is not judged, nor a description whose expansion could not be followed (an include not
read, a link name not known).

## Why is this bad?
urdfdom refuses a joint to a link that is not defined (`child link [b] of joint [j] not
found`, `parent link [a] of joint [j] not found`): robot_state_publisher stops at
start-up and publishes none of the robot's frames, and `check_urdf` fails. A frequent
cause is a macro called with a `prefix` that its joints use but its links do not, or a
sensor macro attached to a link of another robot's naming.

## Example
```xml
<robot name="demo">
  <link name="base_link"/>
  <link name="laser"/>
  <joint name="laser_joint" type="fixed">
    <parent link="base"/>
    <child link="laser"/>
  </joint>
</robot>
```

## Use instead
```xml
<robot name="demo">
  <link name="base_link"/>
  <link name="laser"/>
  <joint name="laser_joint" type="fixed">
    <parent link="base_link"/>
    <child link="laser"/>
  </joint>
</robot>
```
"""
from __future__ import annotations

from collections.abc import Iterator

from launch_linter.model.diagnostic import Category, Location, Severity
from launch_linter.model.robot import FaultKind
from launch_linter.rules._api import Finding, RuleContext
from launch_linter.rules._robot import (
    close_names,
    defined_phrase,
    first_by_name,
    judged,
    level,
    refused,
    robots_of,
)

ID = "urdf_missing_link"
CATEGORY = Category.TF
SEVERITY = Severity.ERROR
EXAMPLE_PATH = "example.urdf"


MAX_SUGGESTED = 20
"""Missing links per description for which close names are looked for (each look is a
pass over every link name)."""


def check(context: RuleContext) -> Iterator[Finding]:
    for robot in robots_of(context):
        if not robot.complete or not judged(robot):
            continue
        links = first_by_name(robot.links)
        # Calls xacro left unexpanded (no xacro: prefix) may be what defines the link.
        calls = [f for f in robot.faults if f.kind is FaultKind.UNEXPANDED and f.name][:3]
        unexpanded = "".join(f"; <{f.name}> at {f.path}:{f.line}, xacro written without "
                             "xacro:, is not expanded and may be what defines it"
                             for f in calls)
        suggested = 0
        for joint in robot.joints:
            if not joint.condition.always:
                continue
            # urdfdom looks for the child first, and stops at the first missing link.
            for end, name in (("child", joint.child), ("parent", joint.parent)):
                if name is None or name in links:
                    continue
                close = close_names(name, list(links)) if suggested < MAX_SUGGESTED else []
                suggested += 1
                said = (f"child link [{name}] of joint [{joint.name}] not found"
                        if end == "child" else
                        f"parent link [{name}] of joint [{joint.name}] not found")
                yield Finding(
                    joint.path, joint.line, joint.column,
                    f"joint '{joint.name}' names {end} link '{name}', which the description "
                    f"does not define{defined_phrase(close)}{unexpanded}; " + refused(said),
                    joint.name,
                    tuple(Location(links[n].path, links[n].line, links[n].column)
                          for n in close) + tuple(Location(f.path, f.line, 1) for f in calls),
                    severity=level(robot),
                )
                break
