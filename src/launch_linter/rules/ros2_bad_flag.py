"""ROS 2 static_transform_publisher flags that the program rejects or misreads.

## What it does
Reports the flag mistakes that stop the ROS 2 `static_transform_publisher` or change what
it publishes: an unknown or misspelled flag (`--yaw_deg`, `--frame_id`, `-- yaw` with a
space), flags mixed with positional arguments, `--roll`/`--pitch`/`--yaw` together with
`--qx`/`--qy`/`--qz`/`--qw`, a quaternion given in part (the missing components stay at
0, 0, 0, 1, which leaves it not unit length), and a missing `--frame-id` or
`--child-frame-id`. The message quotes what the program prints. When the target
distribution is Foxy or Galactic (`--ros-distro`, the `ros-distro` key or `ROS_DISTRO`),
any flag is reported: flags arrived in tf2_ros 0.19.0 (ros2/geometry2#392), first released
in Humble; the older program counts its arguments, prints its usage and exits with status
2 (the `galactic` branch's `static_transform_broadcaster_program.cpp`).

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

from launch_linter.distro import NO_FLAGS
from launch_linter.model.diagnostic import Category, Diagnostic, Severity
from launch_linter.rules._api import RuleContext, diagnostic_at

ID = "ros2_bad_flag"
CATEGORY = Category.TF
SEVERITY = Severity.ERROR
KINDS = ("unknown_flag", "mixed_styles", "rpy_and_quaternion", "partial_quaternion",
         "missing_frame")


def _uses_flags(tokens: tuple[str, ...]) -> bool:
    return any(t.startswith("--") and t != "--ros-args" for t in tokens)


def check(context: RuleContext) -> Iterator[Diagnostic]:
    no_flags = context.distro in NO_FLAGS and not context.study
    for transform in context.tree.transforms:
        if "arity" in transform.unresolved:
            continue
        if no_flags and transform.ros_version == 2 and _uses_flags(transform.tokens):
            distro = str(context.distro).capitalize()
            yield diagnostic_at(
                ID, CATEGORY, SEVERITY, transform,
                f"flags (--frame-id ...) on {distro}: its static_transform_publisher knows "
                f"only the positional form x y z yaw pitch roll parent child (flags arrived "
                f"in Humble): it prints its usage and exits 2, no transform is published",
            )
            continue
        for issue in transform.arg_issues:
            if issue.kind in KINDS:
                yield diagnostic_at(ID, CATEGORY, SEVERITY, transform, issue.message)
