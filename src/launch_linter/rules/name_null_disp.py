"""Node N usually has zero displacement, this one does not.

## What it does
Uses the mined `name_null_disp` beliefs: "static transform nodes named N have a zero
translation". It reports every node with such a name whose translation is known and not
zero. The message gives the belief's support: `n` nodes of mature repositories have the
name, `e` of them a zero translation, and the z-score (p0 = 0.9). Only beliefs with z at
or above `--min-z` (default 1.0) are used.

## Why is this bad?
Some node names stand for a transform that is an identity by convention, such as the
`virtual_joint_broadcaster_0` that MoveIt's setup assistant generates to fix a robot to
the world. A non-zero offset under that name is usually a value copied into the wrong
node, or a name copied onto a node that does something else.

## Example
```xml
<launch>
  <node pkg="tf" type="static_transform_publisher" name="virtual_joint_broadcaster_0"
        args="0 0 0.75 0 0 0 world base_link 100"/>
</launch>
```

## Use instead
```xml
<launch>
  <node pkg="tf" type="static_transform_publisher" name="virtual_joint_broadcaster_0"
        args="0 0 0 0 0 0 world base_link 100"/>
</launch>
```

## Known problems
Names are chosen freely; a node may keep a conventional name for a deliberate offset.
Nodes whose name or translation is unresolved are not judged.
"""
from __future__ import annotations

from collections.abc import Iterator

from launch_linter.model.diagnostic import Category, Severity
from launch_linter.rules._api import Finding, RuleContext
from launch_linter.rules._may_implied import name_of, null_displacements

ID = "name_null_disp"
CATEGORY = Category.MAY_IMPLIED
SEVERITY = Severity.WARNING


def check(context: RuleContext) -> Iterator[Finding]:
    return null_displacements(context, ID, name_of, "node")
