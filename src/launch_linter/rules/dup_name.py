"""Two static transform nodes with the same name in the same namespace.

## What it does
Reports a `static_transform_publisher` node whose resolved name, in its resolved namespace,
is already used by an earlier one in the same file, or elsewhere in the same launch tree
(the file and everything it includes). The diagnostic is on the later node and points at
the earlier one. Nodes in different namespaces (`<group ns="robot1">` and
`<group ns="robot2">`) may share a name, and nodes under mutually exclusive conditions
(`if="$(arg a)"` and `unless="$(arg a)"`) are never launched together. A file included
twice into the same namespace declares its nodes twice, and is reported too.

## Why is this bad?
ROS 1 `roslaunch` refuses to start the whole launch when two nodes have the same
namespace and name (`roslaunch file contains multiple nodes named [...]`). ROS 2 launch
starts both but warns, and the two nodes then share one name for logging, parameters and
services. Either way the second transform was probably meant to have its own name, or is a
copy that should be removed.

## Example
```xml
<launch>
  <node pkg="tf2_ros" type="static_transform_publisher" name="wheel_tf"
        args="0 0.36 0.2 0 0 0 base_link wheel_left"/>
  <node pkg="tf2_ros" type="static_transform_publisher" name="wheel_tf"
        args="0 -0.36 0.2 0 0 0 base_link wheel_right"/>
</launch>
```

## Use instead
```xml
<launch>
  <node pkg="tf2_ros" type="static_transform_publisher" name="wheel_left_tf"
        args="0 0.36 0.2 0 0 0 base_link wheel_left"/>
  <node pkg="tf2_ros" type="static_transform_publisher" name="wheel_right_tf"
        args="0 -0.36 0.2 0 0 0 base_link wheel_right"/>
</launch>
```

## Known problems
Only static transform nodes are compared: a static transform publisher that shares its
name with another kind of node is not seen.
"""
from __future__ import annotations

from collections.abc import Iterator

from launch_linter.model.diagnostic import Category, Severity
from launch_linter.model.transform import Field, StaticTransform
from launch_linter.rules._api import (
    Finding,
    RuleContext,
    can_coexist,
    finding_at,
    place,
    same_element,
)

ID = "dup_name"
CATEGORY = Category.MUST
SEVERITY = Severity.ERROR


def _consequence(transform: StaticTransform, qualified: str) -> str:
    if transform.ros_version == 2:
        return "ROS 2 launch starts both but warns, and they share one node name"
    return (
        f"roslaunch refuses to start "
        f"('roslaunch file contains multiple nodes named [{qualified}]')"
    )


def _message(later: StaticTransform, first: StaticTransform, qualified: str) -> str:
    consequence = _consequence(later, qualified)
    if same_element(later, first):
        places = " and ".join(
            f"{t.included_from[0]}:{t.included_from[1]}"
            for t in (first, later)
            if t.included_from is not None
        )
        return (
            f"node name '{qualified}' is declared twice because {later.path} is included "
            f"twice into the same namespace ({places}): {consequence}"
        )
    scope = "" if later.path == first.path else " of the same launch tree"
    maybe = " if both are launched" if first.condition != later.condition else ""
    return (
        f"node name '{qualified}' is already used at {place(first, later)}{scope}"
        f"{maybe}: {consequence}"
    )


def check(context: RuleContext) -> Iterator[Finding]:
    seen: dict[str, list[StaticTransform]] = {}
    for transform in context.tree.transforms:
        qualified = transform.qualified_name
        if qualified is None or transform.is_unresolved(Field.NAME) or (
            transform.is_unresolved(Field.NAMESPACE)
        ):
            continue
        earlier = seen.setdefault(qualified, [])
        first = next((t for t in earlier if can_coexist(t, transform)), None)
        earlier.append(transform)
        if first is None:
            continue
        # ROS 2 launch starts both nodes (it only warns), so both transforms are published:
        # a convention issue at info; the study's profile kept it at warning.
        ros2_level = Severity.WARNING if context.study else Severity.INFO
        severity = ros2_level if transform.ros_version == 2 else None
        related = () if same_element(transform, first) else (first,)
        yield finding_at(
            transform, _message(transform, first, qualified), related, severity=severity
        )
