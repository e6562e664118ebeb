"""A ROS 2 static transform written with the deprecated positional arguments.

## What it does
Reports a ROS 2 `static_transform_publisher` (in a ROS 2 XML, YAML or Python launch file)
whose arguments are the old positional form, `x y z yaw pitch roll parent child` (8) or
`x y z qx qy qz qw parent child` (9), and gives the same transform written with flags
(`--x --y --z`, `--yaw --pitch --roll` or `--qx --qy --qz --qw`, `--frame-id`,
`--child-frame-id`).

## Why is this bad?
Since Galactic the program warns "Old-style arguments are deprecated" for this form, and
recent distributions have removed it (ros2/geometry2#790): there the node stops with
"Frame id must not be empty", and the transform is never published. The flags also say
which number is which, where the positional order (yaw before roll, unlike URDF's `rpy`)
is easy to get wrong.

## Example
```xml
<launch>
  <node pkg="tf2_ros" exec="static_transform_publisher" name="laser_tf"
        args="0 0 0.2 0 0 0 base_link laser"/>
</launch>
```

## Use instead
```xml
<launch>
  <node pkg="tf2_ros" exec="static_transform_publisher" name="laser_tf"
        args="--z 0.2 --frame-id base_link --child-frame-id laser"/>
</launch>
```

## Fix
Unsafe, or safe when `--ros-distro` (or the `ros-distro` configuration key) names Humble
or a newer distribution: rewrites the positional arguments to the flags. Foxy and older
have no flags, so there the rewrite would break the node.
"""
from __future__ import annotations

from collections.abc import Iterator

from launch_linter.model.diagnostic import Applicability, Category, Fix, Severity
from launch_linter.model.transform import ArgIssue, ArgIssueKind, RotationKind, StaticTransform
from launch_linter.rules._api import Finding, RuleContext, finding_at
from launch_linter.rules._fixes import (
    FLAGS_FROM,
    QUATERNION_FLAGS,
    YPR_FLAGS,
    fixable,
    replace_words,
)

ID = "ros2_positional_args"
CATEGORY = Category.TF
SEVERITY = Severity.WARNING
FIX = Applicability.UNSAFE


def _flags_fix(transform: StaticTransform) -> Fix | None:
    tokens = transform.tokens
    if not fixable(transform) or any(":=" in t or (t.startswith("-") and not _number(t))
                                     for t in tokens):
        return None
    rotation = transform.rotation
    if rotation is None:
        return None
    flags = YPR_FLAGS if rotation.kind is RotationKind.YPR else QUATERNION_FLAGS
    if len(tokens) != len(flags) + 2:
        return None
    words = [f"{flag} {tokens[i]}" for i, flag in enumerate(flags)]
    words.append(f"--frame-id {tokens[-2]} --child-frame-id {tokens[-1]}")
    text = " ".join(words)
    return replace_words(
        transform, FIX, f"write: {text}", [(0, len(tokens), text)], safe_from_distro=FLAGS_FROM
    )


def _number(word: str) -> bool:
    try:
        float(word)
    except ValueError:
        return False
    return True


def message(issue: ArgIssue) -> str | None:
    """The diagnostic for ``issue``, or None when it is another rule's kind."""
    if issue.kind is not ArgIssueKind.POSITIONAL:
        return None
    # ``others`` names the flag each positional word stands for.
    count = min(len(issue.others), len(issue.words))
    flags = " ".join(f"{issue.others[i]} {issue.words[i]}" for i in range(count))
    return (
        "old-style positional arguments are deprecated ('Old-style arguments are "
        "deprecated') and recent ROS 2 distributions reject them ('Frame id must not be "
        f"empty'); write: {flags}"
    )


def check(context: RuleContext) -> Iterator[Finding]:
    for transform in context.tree.transforms:
        for issue in transform.arg_issues:
            text = message(issue)
            if text is not None:
                yield finding_at(transform, text, fix=_flags_fix(transform))
