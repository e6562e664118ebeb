"""A node name that reads child-to-parent, the reverse of what the transform does.

## What it does
Reports a static transform whose node name, compared case-insensitively, is
`<child><sep><parent>` with `<sep>` one of `_to_`, `2`, `_2_` or `_` (e.g. `odom_to_map`
on the transform map → odom), unless the name also reads `<parent><sep><child>`. Frame ids
are compared without one leading `/`.

## Why is this bad?
A static transform goes from the parent frame (first frame argument) to the child frame
(second). A name that says the opposite means either the name is wrong, which misleads the
next reader, or the frames were swapped and the transform is the inverse of the one meant.

## Example
```xml
<launch>
  <node pkg="tf2_ros" type="static_transform_publisher" name="map_to_odom"
        args="0 0 0 0 0 0 odom map"/>
</launch>
```

## Use instead
```xml
<launch>
  <node pkg="tf2_ros" type="static_transform_publisher" name="map_to_odom"
        args="0 0 0 0 0 0 map odom"/>
</launch>
```
"""
from __future__ import annotations

from collections.abc import Iterator

from launch_linter.model.diagnostic import Category, Severity
from launch_linter.model.transform import Field
from launch_linter.rules._api import Finding, RuleContext, finding_at, goes_down_from_world

ID = "reversed_name"
CATEGORY = Category.MAY_SEMANTIC
SEVERITY = Severity.INFO

SEPARATORS = ("_to_", "2", "_2_", "_")


def _joins(name: str, first: str, second: str) -> str | None:
    """The separator with which ``name`` is ``first<sep>second``, if any."""
    for separator in SEPARATORS:
        if name == f"{first}{separator}{second}":
            return separator
    return None


def check(context: RuleContext) -> Iterator[Finding]:
    for transform in context.tree.transforms:
        signature = transform.signature
        if signature is None or transform.name is None or transform.is_unresolved(Field.NAME):
            continue
        parent, child = (frame.lower() for frame in signature)
        name = transform.name.lower()
        separator = _joins(name, child, parent)
        if separator is None or _joins(name, parent, child) is not None:
            continue
        if not context.study and goes_down_from_world(parent, child):
            # "base_to_world" on world -> base reads "base attached to world": the usual
            # way to name a robot's or a map's place in a world-fixed frame. The transform
            # goes the right way, whatever the name says.
            continue
        yield finding_at(transform,
            f"name '{transform.name}' reads '{signature[1]}' -> '{signature[0]}', but the "
            f"transform goes from parent '{signature[0]}' to child '{signature[1]}': either "
            f"the frames are swapped or the name should be "
            f"'{signature[0]}{separator}{signature[1]}'",
        )
