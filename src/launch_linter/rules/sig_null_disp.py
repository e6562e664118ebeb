"""(A→B) usually has zero displacement, this one does not.

## What it does
Uses the mined `sig_null_disp` beliefs: "transforms of signature (parent → child) have a
zero translation". It reports every transform with such a signature whose translation is
known and not zero. The message gives the belief's support: `n` transforms of mature
repositories have the signature, `e` of them a zero translation, and the z-score
(p0 = 0.9). Only beliefs with z at or above `--min-z` (default 1.0) are used.

## Why is this bad?
Some frame pairs are aliases or conventions rather than physical offsets (`world → map`,
`odom → map` in a single-map setup, `base_link → base_footprint` on flat ground in many
robots). An offset on such a pair is often a value meant for another transform, or a
sign or order mistake in the argument list.

## Example
```xml
<launch>
  <node pkg="tf2_ros" type="static_transform_publisher" name="world_to_map"
        args="2 1 0 0 0 0 world map"/>
</launch>
```

## Use instead
```xml
<launch>
  <node pkg="tf2_ros" type="static_transform_publisher" name="world_to_map"
        args="0 0 0 0 0 0 world map"/>
</launch>
```

## Known problems
A convention is not a law: a map that is deliberately placed off the world origin is
right. Transforms whose translation is unresolved are not judged.
"""
from __future__ import annotations

from collections.abc import Iterator

from launch_linter.model.diagnostic import Category, Severity
from launch_linter.rules._api import Finding, RuleContext
from launch_linter.rules._may_implied import null_displacements, signature_of

ID = "sig_null_disp"
CATEGORY = Category.MAY_IMPLIED
SEVERITY = Severity.WARNING


def check(context: RuleContext) -> Iterator[Finding]:
    return null_displacements(context, ID, signature_of, "transform")
