"""An argument count that the package's program rejects or misreads.

## What it does
Reports a `static_transform_publisher` whose argument count does not fit its package:
ROS 1 `tf` takes 9 (`x y z yaw pitch roll parent child period_ms`) or 10 (with a
quaternion) arguments; ROS 1 `tf2_ros` takes 8, 9 (with a quaternion) or 1 (a parameter
name), and no period. Some wrong counts make the program print its usage and exit; others
are silently misread: `tf2_ros` given `... parent child 100` reads a quaternion whose `qw`
is the parent frame (0), takes the child as the parent and `100` as the child frame. The
message says what the program does with the arguments as written. `name:=value` words
are ROS remappings and are not counted.

## Why is this bad?
In both cases the transform that was meant never reaches tf: the node dies at start-up, or
it publishes a transform between the wrong frames with an invalid quaternion that tf2
rejects. Nothing in the launch output points at the cause.

## Example
```xml
<launch>
  <node pkg="tf2_ros" type="static_transform_publisher" name="laser_tf"
        args="0 0 0.2 0 0 0 base_link laser 100"/>
</launch>
```

## Use instead
```xml
<launch>
  <node pkg="tf2_ros" type="static_transform_publisher" name="laser_tf"
        args="0 0 0.2 0 0 0 base_link laser"/>
</launch>
```

## Fix
Safe: removes the period given to ROS 1 `tf2_ros`, which then reads the transform that
was meant.
"""
from __future__ import annotations

from collections.abc import Iterator

from launch_linter.model.diagnostic import Applicability, Category, Fix, Severity
from launch_linter.model.transform import ArgForm, Field, StaticTransform
from launch_linter.rules._api import Finding, RuleContext, finding_at
from launch_linter.rules._fixes import fixable, number_text, replace_words

ID = "bad_arity"
CATEGORY = Category.TF
SEVERITY = Severity.ERROR
FIX = Applicability.SAFE


def _period_fix(transform: StaticTransform) -> Fix | None:
    """Drop the last non-remapping word: the period ROS 1 tf2_ros misreads."""
    if not (
        transform.ros_version == 1
        and transform.package == "tf2_ros"
        and transform.form in (ArgForm.YPR, ArgForm.QUATERNION)
        and transform.period_ms is not None
        and fixable(transform)
    ):
        return None
    words = [i for i, t in enumerate(transform.tokens) if ":=" not in t]
    if len(words) not in (9, 10):
        return None
    last = words[-1]
    try:
        if float(transform.tokens[last]) != transform.period_ms:
            return None
    except ValueError:
        return None
    message = f"remove the period {number_text(transform.period_ms)}"
    return replace_words(transform, FIX, message, [(last, last + 1, "")])


def _fix(transform: StaticTransform) -> str:
    """What to write instead, for the ROS 1 forms whose intent is clear."""
    if transform.ros_version != 1 or transform.form not in (ArgForm.YPR, ArgForm.QUATERNION):
        return ""
    if transform.package == "tf2_ros" and transform.period_ms is not None:
        return f"; remove the period '{transform.period_ms:g}' (tf2_ros publishes once, latched)"
    if transform.package == "tf" and transform.period_ms is None:
        return "; add a period in milliseconds after the child frame, or use tf2_ros"
    return ""


def check(context: RuleContext) -> Iterator[Finding]:
    for transform in context.tree.transforms:
        if transform.arity_issue is None or transform.is_unresolved(Field.ARITY):
            continue
        yield finding_at(
            transform, transform.arity_issue + _fix(transform), fix=_period_fix(transform)
        )
