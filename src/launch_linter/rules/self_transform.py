"""A static transform whose parent and child are the same frame.

## What it does
Reports a `static_transform_publisher` whose parent frame and child frame are the same
frame id (compared without one leading `/`, as tf2 compares them).

## Why is this bad?
A transform from a frame to itself says nothing, and tf2 refuses it
(`TF_SELF_TRANSFORM: Ignoring transform ... because they are the same`). The author almost
always meant a different parent or child, so the frame that was meant never joins the tree.

## Example
```xml
<launch>
  <node pkg="tf2_ros" type="static_transform_publisher" name="laser_tf"
        args="0 0 0.2 0 0 0 laser /laser"/>
</launch>
```

## Use instead
```xml
<launch>
  <node pkg="tf2_ros" type="static_transform_publisher" name="laser_tf"
        args="0 0 0.2 0 0 0 base_link laser"/>
</launch>
```
"""
from __future__ import annotations

from collections.abc import Iterator

from launch_linter.model.diagnostic import Category, Severity
from launch_linter.rules._api import Finding, RuleContext, finding_at

ID = "self_transform"
CATEGORY = Category.MUST
SEVERITY = Severity.ERROR


def check(context: RuleContext) -> Iterator[Finding]:
    for transform in context.tree.transforms:
        signature = transform.signature
        if signature is None or signature[0] != signature[1]:
            continue
        yield finding_at(transform,
            f"parent and child are the same frame '{signature[0]}': tf2 ignores a transform "
            f"from a frame to itself (TF_SELF_TRANSFORM); one of the two frames is wrong",
        )
