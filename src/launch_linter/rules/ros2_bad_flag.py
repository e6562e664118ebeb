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

from launch_linter.model.diagnostic import Category, Severity
from launch_linter.model.distro import NO_FLAGS, uses_flags
from launch_linter.model.transform import ArgIssue, ArgIssueKind, Field
from launch_linter.rules._api import Finding, RuleContext, finding_at

ID = "ros2_bad_flag"
CATEGORY = Category.TF
SEVERITY = Severity.ERROR

_EMPTY_FRAME = {"--frame-id": "Frame id", "--child-frame-id": "Child frame id"}
"""The program's words for each frame flag in 'X must not be empty'."""


def _suggestion(issue: ArgIssue) -> str:
    if not issue.others:
        return ""
    if issue.split:
        return f" (did you mean '{issue.others[0]}', without the space?)"
    return f" (did you mean '{issue.others[0]}'?)"


def _missing_frame(issue: ArgIssue) -> str:
    """An absent or empty frame id, by how it was written (see ``ArgIssue``)."""
    name, how = issue.words[0], issue.others
    if how[:1] == ("parameter",):
        child = "CHILD_" if name.startswith("child") else ""
        return (f"the {name} parameter is empty: tf2 rejects a transform without a frame id "
                f"(TF_NO_{child}FRAME_ID)")
    stops = f"the program stops with '{_EMPTY_FRAME[name]} must not be empty'"
    if how[:1] == ("positional",):
        which = "parent" if name == "--frame-id" else "child"
        return f"the {which} frame id (argument {how[1]}) is empty: {stops}"
    if how[:1] == ("empty",):
        return f"{name} is empty: {stops}"
    return f"no {name}: {stops}"


def message(issue: ArgIssue) -> str | None:
    """The diagnostic for ``issue``, or None when it is another rule's kind."""
    kind, words = issue.kind, issue.words
    if kind is ArgIssueKind.UNKNOWN_FLAG:
        return (
            f"unknown flag '{words[0]}'{_suggestion(issue)}: the program stops with "
            f"'Extra unparsed arguments on command-line'"
        )
    if kind is ArgIssueKind.MIXED_STYLES:
        effect = (
            "the program stops with 'Cannot specify both new-style (flags) and old-style "
            "(arguments)'" if issue.fatal
            else "the program silently replaces them with the positional rotation"
        )
        return f"flags ({', '.join(words)}) together with old-style positional arguments: {effect}"
    if kind is ArgIssueKind.RPY_AND_QUATERNION:
        return (
            f"{', '.join(words)} together with {', '.join(issue.others)}: the program stops "
            f"with 'Cannot specify both quaternion and Euler rotations'"
        )
    if kind is ArgIssueKind.PARTIAL_QUATERNION:
        return (
            f"quaternion without {', '.join(words)}: missing components stay at "
            f"(0, 0, 0, 1), giving ({', '.join(f'{v:g}' for v in issue.values)}), which is "
            f"not unit length and tf2 rejects"
        )
    if kind is ArgIssueKind.MISSING_FRAME:
        return _missing_frame(issue)
    return None


def check(context: RuleContext) -> Iterator[Finding]:
    no_flags = context.distro in NO_FLAGS and not context.study
    for transform in context.tree.transforms:
        if transform.is_unresolved(Field.ARITY):
            continue
        if no_flags and transform.ros_version == 2 and uses_flags(transform.tokens):
            distro = str(context.distro).capitalize()
            yield finding_at(
                transform,
                f"flags (--frame-id ...) on {distro}: its static_transform_publisher knows "
                f"only the positional form x y z yaw pitch roll parent child (flags arrived "
                f"in Humble): it prints its usage and exits 2, no transform is published",
            )
            continue
        for issue in transform.arg_issues:
            text = message(issue)
            if text is not None:
                yield finding_at(transform, text)
