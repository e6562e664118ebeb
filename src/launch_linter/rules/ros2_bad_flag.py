"""ROS 2 static_transform_publisher flags that the program rejects or misreads.

## What it does
Reports the flag mistakes that stop the ROS 2 `static_transform_publisher` or change what
it publishes: an unknown or misspelled flag (`--yaw_deg`, `--frame_id`, `-- yaw` with a
space), flags mixed with positional arguments, `--roll`/`--pitch`/`--yaw` together with
`--qx`/`--qy`/`--qz`/`--qw`, a quaternion given in part (the missing components stay at
0, 0, 0, 1, which leaves it not unit length), and a missing `--frame-id` or
`--child-frame-id`. The message quotes what the program prints.

## Why is this bad?
The program stops at start-up with "Extra unparsed arguments on command-line", "Cannot
specify both ...", or "Frame id must not be empty", or tf2 rejects the transform it
publishes, so the transform never reaches tf. The launch itself goes on, and nothing
points at the node that died.

## Example
```xml
<launch>
  <node pkg="tf2_ros" exec="static_transform_publisher" name="gps_tf"
        args="--x 0.3 --yaw_deg 90 --frame-id base_link --child-frame-id gps"/>
</launch>
```

## Use instead
```xml
<launch>
  <node pkg="tf2_ros" exec="static_transform_publisher" name="gps_tf"
        args="--x 0.3 --yaw 1.5708 --frame-id base_link --child-frame-id gps"/>
</launch>
```
"""
from __future__ import annotations

from collections.abc import Iterator

from launch_linter.model.diagnostic import Category, Diagnostic, Severity
from launch_linter.rules._api import RuleContext, diagnostic_at

ID = "ros2_bad_flag"
CATEGORY = Category.TF
SEVERITY = Severity.ERROR
KINDS = ("unknown_flag", "mixed_styles", "rpy_and_quaternion", "partial_quaternion",
         "missing_frame")


def check(context: RuleContext) -> Iterator[Diagnostic]:
    for transform in context.tree.transforms:
        if "arity" in transform.unresolved:
            continue
        for issue in transform.arg_issues:
            if issue.kind in KINDS:
                yield diagnostic_at(ID, CATEGORY, SEVERITY, transform, issue.message)
