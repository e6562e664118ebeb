"""A numeric argument that is not a number.

## What it does
Reports each numeric argument of a `static_transform_publisher` (displacement, rotation,
period) that the program does not read as written: text such as `pi/2`, `1,57` or `0.1m`,
or a value that is not finite. ROS 1 reads numbers with C `atof`, which takes the longest
numeric prefix and reads junk as 0, so the message says which value the program will
really use. A number followed only by a separator (`1.57,`, as in comma-separated
lists) is read as meant and is reported as a warning.

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
from __future__ import annotations

import math
import re
from collections.abc import Iterator

from launch_linter.model.diagnostic import Category, Severity
from launch_linter.model.transform import NumberIssue, StaticTransform
from launch_linter.rules._api import Finding, RuleContext, finding_at

ID = "bad_number"
CATEGORY = Category.TF
SEVERITY = Severity.ERROR

_NUMERIC_START = re.compile(r"\s*[+-]?(\d|\.\d|inf|nan)", re.IGNORECASE)
_PLAIN_NUMBER = re.compile(r"[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?")
SEPARATORS = ",;"

SLOTS = {
    "ypr": ("x", "y", "z", "yaw", "pitch", "roll", "parent", "child", "period_ms"),
    "quaternion": ("x", "y", "z", "qx", "qy", "qz", "qw", "parent", "child", "period_ms"),
}


def _slot(transform: StaticTransform, index: int) -> str:
    names = SLOTS.get(transform.form, ())
    return names[index] if index < len(names) else f"argument {index + 1}"


def separated_number(written: str) -> bool:
    """True for a finite plain number followed only by list separators (``1.57,``)."""
    number = written.rstrip(SEPARATORS)
    return (
        number != written
        and _PLAIN_NUMBER.fullmatch(number) is not None
        and math.isfinite(float(number))
    )


def _effect(transform: StaticTransform, issue: NumberIssue) -> str:
    read = "" if issue.read_as is None else f"{issue.read_as:g}"
    if separated_number(issue.written):
        return (
            f"the program reads {read} as meant, but a separator in the arguments is "
            f"fragile (without the space after it, two arguments become one): remove it"
        )
    if issue.read_as is not None and not math.isfinite(issue.read_as):
        return f"it is read as {read}, which is not a usable value"
    if _NUMERIC_START.match(issue.written) is None:
        if transform.ros_version == 2:
            return "the program cannot read it and stops with an error"
        return "the program reads it as 0 (C atof)"
    return f"the program reads only its numeric start, {read}"


def _separator_level(context: RuleContext) -> Severity:
    # atof reads "0.5," as 0.5: the robot gets what was meant, so a stray separator is
    # style (info); the study's profile kept it at warning.
    return Severity.WARNING if context.study else Severity.INFO


def check(context: RuleContext) -> Iterator[Finding]:
    for transform in context.tree.transforms:
        for issue in transform.number_issues:
            yield finding_at(
                transform,
                f"{_slot(transform, issue.index)} '{issue.written}' is not a number: "
                f"{_effect(transform, issue)}",
                severity=_separator_level(context) if separated_number(issue.written) else None,
            )
