"""A file has the (A→B) transform but not the (C→D) that usually comes with it.

## What it does
Uses the mined `sig_implication` beliefs: "a file with a transform of signature
(parent → child) A also has one of signature B". For each file that has A but no B, it
reports the first transform with A. The message gives the belief's support: `n` files of
mature repositories have A, `e` of them also have B, and the z-score (p0 = 0.9) of that
ratio. Only beliefs with z at or above `--min-z` (default 1.0) are used.

## Why is this bad?
Frames come in families: a camera driver's frames, a robot base's footprint, a SLAM
stack's map and odometry frames. When most files that publish one member of such a
family also publish another, a file that does not has probably forgotten it, or spelt
it differently (`base_stabilized` against `_base_stabilized`), and whatever expects the
missing frame will wait for a transform that never comes.

## Example
```xml
<launch>
  <node pkg="tf" type="static_transform_publisher" name="camera_rotation"
        args="0 0 0 0 0 -1.5708 camera_link camera_rotated 100"/>
</launch>
```

## Use instead
```xml
<launch>
  <node pkg="tf" type="static_transform_publisher" name="camera_rotation"
        args="0 0 0 0 0 -1.5708 camera_link camera_rotated 100"/>
  <node pkg="tf" type="static_transform_publisher" name="camera_mount"
        args="0.3 0 1.2 0 0 0 camera_rotated world 100"/>
</launch>
```

## Known problems
The beliefs are conventions of the mined corpus, not laws of tf: a file may publish the
other half of the family from somewhere else (an included file, a URDF, a driver). A
file whose frames depend on unresolved substitutions is not judged.
"""
from __future__ import annotations

from collections.abc import Iterator

from launch_linter.model.diagnostic import Category, Severity
from launch_linter.rules._api import Finding, RuleContext
from launch_linter.rules._may_implied import implications, signature_of, signature_unresolved

ID = "sig_implication"
CATEGORY = Category.MAY_IMPLIED
SEVERITY = Severity.WARNING


def check(context: RuleContext) -> Iterator[Finding]:
    return implications(context, ID, signature_of, signature_unresolved, "transform")
