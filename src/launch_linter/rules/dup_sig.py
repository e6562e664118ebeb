"""The same (parent, child) pair published twice in one file.

## What it does
Reports a static transform whose (parent, child) frame pair, compared without one leading
`/`, was already published by an earlier static transform in the same file. The diagnostic
is on the later node and points at the earlier one. Namespaces are ignored, because `ns`
renames nodes but not frame ids. Transforms under mutually exclusive conditions
(`if="$(arg a)"` and `unless="$(arg a)"`) are never launched together and are not compared.

## Why is this bad?
tf2 keeps one transform per (parent, child) pair. When the two disagree, which one wins
depends on which publisher happens to start last, so the robot's geometry changes from run
to run. When they agree, one is a leftover copy that will silently drift from the other the
next time someone edits only one of them.

## Example
```xml
<launch>
  <node pkg="tf2_ros" type="static_transform_publisher" name="camera_tf"
        args="0.1 0 0.3 0 0 0 base_link camera_link"/>
  <node pkg="tf2_ros" type="static_transform_publisher" name="camera_tf_old"
        args="0.12 0 0.3 0 0 0 /base_link camera_link"/>
</launch>
```

## Use instead
```xml
<launch>
  <node pkg="tf2_ros" type="static_transform_publisher" name="camera_tf"
        args="0.1 0 0.3 0 0 0 base_link camera_link"/>
</launch>
```
"""
from __future__ import annotations

from collections.abc import Iterator

from launch_linter.model.diagnostic import Category, Severity
from launch_linter.model.transform import Field, StaticTransform
from launch_linter.rules._api import (
    Finding,
    RuleContext,
    can_coexist,
    finding_at,
    place,
    same_element,
    transforms_by_file,
)

ID = "dup_sig"
CATEGORY = Category.MUST
SEVERITY = Severity.ERROR


def _agreement(a: StaticTransform, b: StaticTransform) -> str:
    if any(t.is_unresolved(Field.TRANSLATION, Field.ROTATION) for t in (a, b)):
        return "tf2 keeps only one of them"
    if a.translation == b.translation and a.rotation == b.rotation:
        return "with the same values, so one of them is a redundant copy"
    return "with different values: tf2 keeps whichever starts last"


def check(context: RuleContext) -> Iterator[Finding]:
    for transforms in context.shared(transforms_by_file).values():
        seen: dict[tuple[str, str], list[StaticTransform]] = {}
        # Of the earlier transforms of one element under one condition only the first can
        # be named (the search takes the first that qualifies, and they qualify alike):
        # one element reached through 2^k includes is one candidate, not 2^k.
        kept: set[tuple[object, ...]] = set()
        for transform in transforms:
            signature = transform.signature
            if signature is None:
                continue
            earlier = seen.setdefault(signature, [])
            first = next(
                (
                    t
                    for t in earlier
                    if can_coexist(t, transform) and not same_element(t, transform)
                ),
                None,
            )
            key = (signature, transform.path, transform.line, transform.column,
                   transform.condition)
            if key not in kept:
                kept.add(key)
                earlier.append(transform)
            if first is None:
                continue
            maybe = " if both are launched" if first.condition != transform.condition else ""
            yield finding_at(transform,
                f"transform '{signature[0]}' -> '{signature[1]}' is already published at "
                f"{place(first, transform)}{maybe}, {_agreement(first, transform)}",
                (first,),
            )
