"""A numeric argument that is not a number.

## What it does
Reports each numeric argument of a `static_transform_publisher` (displacement, rotation,
period) that the program does not read as written: text such as `pi/2`, `1,57` or `0.1m`,
or a value that is not finite. ROS 1 reads numbers with C `atof`, which takes the longest
numeric prefix and reads junk as 0, so the message says which value the program will
really use.

## Why is this bad?
The program does not complain: `pi/2` silently becomes 0 and `1,57` becomes 1, so the
frame is published at a pose nobody wrote down.

## Example
```xml
<launch>
  <node pkg="tf2_ros" type="static_transform_publisher" name="camera_tf"
        args="0.1 0 0.3 pi/2 0 0 base_link camera_link"/>
</launch>
```

## Use instead
```xml
<launch>
  <node pkg="tf2_ros" type="static_transform_publisher" name="camera_tf"
        args="0.1 0 0.3 1.5707963 0 0 base_link camera_link"/>
</launch>
```
Or compute it with `$(eval)`: `args="0.1 0 0.3 $(eval pi/2) 0 0 base_link camera_link"`.
"""

import math
from collections.abc import Iterator

from launch_linter.model.diagnostic import Category, Diagnostic, Severity
from launch_linter.model.transform import NumberIssue, StaticTransform
from launch_linter.rules._api import RuleContext, diagnostic_at

ID = "bad_number"
CATEGORY = Category.TF
SEVERITY = Severity.ERROR

SLOTS = {
    "ypr": ("x", "y", "z", "yaw", "pitch", "roll", "parent", "child", "period_ms"),
    "quaternion": ("x", "y", "z", "qx", "qy", "qz", "qw", "parent", "child", "period_ms"),
}


def _slot(transform: StaticTransform, index: int) -> str:
    names = SLOTS.get(transform.form, ())
    return names[index] if index < len(names) else f"argument {index + 1}"


def _effect(transform: StaticTransform, issue: NumberIssue) -> str:
    if transform.ros_version == 2:
        return "the ROS 2 program cannot parse it and exits"
    if issue.read_as is None:
        return "the program cannot read it"
    if not math.isfinite(issue.read_as):
        return f"it is read as {issue.read_as}, which is not a usable value"
    if issue.read_as == 0:
        return "the program reads it as 0 (C atof)"
    return f"the program reads only its numeric start, {issue.read_as:g} (C atof)"


def check(context: RuleContext) -> Iterator[Diagnostic]:
    for transform in context.tree.transforms:
        for issue in transform.number_issues:
            yield diagnostic_at(
                ID, CATEGORY, SEVERITY, transform,
                f"{_slot(transform, issue.index)} '{issue.written}' is not a number: "
                f"{_effect(transform, issue)}",
            )
