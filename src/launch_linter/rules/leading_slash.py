"""A frame id written with a leading `/`.

## What it does
Reports each parent or child frame id of a static transform that starts with `/`.

## Why is this bad?
Leading slashes are a tf (ROS 1, before tf2) habit. tf2 strips one leading `/` when a
transform is published, so the frame is really called `base_link`, not `/base_link`; a
lookup or a message header that still says `/base_link` fails (`Invalid argument
"/base_link" passed to lookupTransform argument target_frame - in tf2 frame_ids cannot
start with a '/'`), and tools such as cartographer refuse such frame ids outright. Mixing
`/base_link` and `base_link` in one project also hides that they are the same frame.

## Example
```xml
<launch>
  <node pkg="tf" type="static_transform_publisher" name="laser_tf"
        args="0 0 0.2 0 0 0 /base_link /laser 100"/>
</launch>
```

## Use instead
```xml
<launch>
  <node pkg="tf" type="static_transform_publisher" name="laser_tf"
        args="0 0 0.2 0 0 0 base_link laser 100"/>
</launch>
```

## Fix
Safe: strips one leading `/` from the frame id (tf2 strips exactly one, so the frame
is the same).
"""
from __future__ import annotations

from collections.abc import Iterator

from launch_linter.model.diagnostic import Applicability, Category, Fix, Severity
from launch_linter.model.transform import StaticTransform
from launch_linter.rules._api import Finding, RuleContext, finding_at
from launch_linter.rules._fixes import fixable, frame_index, replace_words

ID = "leading_slash"
CATEGORY = Category.TF
SEVERITY = Severity.INFO
FIX = Applicability.SAFE


def _fix(transform: StaticTransform, role: str, written: str) -> Fix | None:
    index = frame_index(transform, role) if fixable(transform) else None
    if index is None or transform.tokens[index] != written:
        return None
    stripped = written[1:]
    return replace_words(transform, FIX, f"write '{stripped}'", [(index, index + 1, stripped)])


def check(context: RuleContext) -> Iterator[Finding]:
    for transform in context.tree.transforms:
        for role, written in (
            ("parent", transform.parent_written),
            ("child", transform.child_written),
        ):
            if written is None or not written.startswith("/"):
                continue
            yield finding_at(transform,
                f"{role} frame '{written}' starts with '/': tf2 names it '{written[1:]}' "
                f"and rejects lookups of '{written}'; write '{written.lstrip('/')}'",
                fix=_fix(transform, role, written),
            )
