"""Node N usually has zero rotation, this one does not.

## What it does
Uses the mined `name_null_rot` beliefs: "static transform nodes named N have no
rotation". It reports every node with such a name whose rotation is known and not the
identity. The message gives the belief's support: `n` nodes of mature repositories have
the name, `e` of them no rotation, and the z-score (p0 = 0.9). Only beliefs with z at or
above `--min-z` (default 1.0) are used.

## Why is this bad?
A name like `base_link_to_laser` is copied from project to project together with its
values, and nearly always with the laser aligned to the base. A rotation under such a
name is often a value typed into the wrong field, or a unit or sign mistake.

## Example
```xml
<launch>
  <node pkg="tf" type="static_transform_publisher" name="base_link_to_laser"
        args="0.2 0 0.15 3.1416 0 0 base_link laser 100"/>
</launch>
```

## Use instead
```xml
<launch>
  <node pkg="tf" type="static_transform_publisher" name="base_link_to_laser"
        args="0.2 0 0.15 0 0 0 base_link laser 100"/>
</launch>
```

## Known problems
The laser may really be mounted turned; the belief only says this is unusual for the
name (the study found such a case, where a comment explained the change). Nodes whose
name or rotation is unresolved are not judged.
"""
from __future__ import annotations

from collections.abc import Iterator

from launch_linter.model.diagnostic import Category, Severity
from launch_linter.rules._api import Finding, RuleContext
from launch_linter.rules._may_implied import name_of, null_rotations

ID = "name_null_rot"
CATEGORY = Category.MAY_IMPLIED
SEVERITY = Severity.WARNING


def check(context: RuleContext) -> Iterator[Finding]:
    return null_rotations(context, ID, name_of, "node")
