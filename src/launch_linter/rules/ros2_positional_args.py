"""A ROS 2 static transform written with positional arguments, judged for the target distribution.

## What it does
Reports a ROS 2 `static_transform_publisher` (in a ROS 2 XML, YAML or Python launch file)
whose arguments are the positional form, `x y z yaw pitch roll parent child` (8) or
`x y z qx qy qz qw parent child` (9), and gives the same transform written with flags.
What it reports depends on the target distribution (`--ros-distro`, the `ros-distro`
configuration key, the `ROS_DISTRO` environment variable, or Foxy-era `node_executable=`
in the files):

| target | the program | reported |
|---|---|---|
| Foxy, Galactic (and older) | knows only the positional form | nothing |
| Humble, Iron, Jazzy, Kilted | takes it, warns "Old-style arguments are deprecated" | info |
| Lyrical, Rolling | rejects it: "Frame id must not be empty", no transform | error |
| unknown | — | info, naming the distributions |

Sources: the flags were added to tf2_ros in 0.19.0 (ros2/geometry2#392, October 2021,
after Galactic branched; the `galactic` branch's `static_transform_broadcaster_program.cpp`
has no flags, the `humble`, `iron` and `jazzy` branches print the deprecation at line 258);
the positional form was removed on Rolling by ros2/geometry2#790 (see
moveit/moveit2_tutorials#1122, which quotes the resulting "Frame id must not be empty"),
and Lyrical branched after it (ctu-mrs/mrs_uav_managers#37 rewrites the arguments "for
Lyrical compatibility"). See docs/severity.md.

## Why is this bad?
On Lyrical and Rolling the node stops and the transform is never published; on Humble to Kilted the
program warns at every start. The flags also say which number is which, where the
positional order (yaw before roll, unlike URDF's `rpy`) is easy to get wrong.

## Example
Info with no target given; an error with `--ros-distro rolling`:
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
from launch_linter.model.distro import NO_FLAGS, POSITIONAL_DEPRECATED, POSITIONAL_REMOVED, describe
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
SEVERITY = Severity.INFO
EXAMPLE_PATH = "example.launch.xml"


def _verdict(distro: str | None) -> tuple[Severity, str] | None:
    if distro in NO_FLAGS:
        return None
    if distro in POSITIONAL_REMOVED:
        return Severity.ERROR, (
            f"on {distro.capitalize()} the positional form is removed (ros2/geometry2#790): "
            "the node stops with 'Frame id must not be empty' and publishes nothing"
        )
    if distro in POSITIONAL_DEPRECATED:
        return SEVERITY, (
            f"on {distro.capitalize()} the positional form still works but warns 'Old-style "
            "arguments are deprecated'"
        )
    return SEVERITY, (
        f"positional form: the only one on Foxy and Galactic, deprecated on "
        f"{describe(POSITIONAL_DEPRECATED)}, removed on Lyrical and Rolling (set --ros-distro "
        f"to know)"
    )


def _flags(issue: ArgIssue) -> str:
    # ``others`` names the flag each positional word stands for.
    count = min(len(issue.others), len(issue.words))
    return " ".join(f"{issue.others[i]} {issue.words[i]}" for i in range(count))


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
    """The study's diagnostic for ``issue``, or None when it is another rule's kind."""
    if issue.kind is not ArgIssueKind.POSITIONAL:
        return None
    return (
        "old-style positional arguments are deprecated ('Old-style arguments are "
        "deprecated') and recent ROS 2 distributions reject them ('Frame id must not be "
        f"empty'); write: {_flags(issue)}"
    )


def check(context: RuleContext) -> Iterator[Finding]:
    verdict = (Severity.WARNING, "") if context.study else _verdict(context.distro)
    if verdict is None:
        return
    severity, why = verdict
    for transform in context.tree.transforms:
        for issue in transform.arg_issues:
            text = message(issue)
            if text is None:
                continue
            if why:
                text = f"{why}; write: {_flags(issue)}"
            yield finding_at(transform, text, fix=_flags_fix(transform),
                             severity=None if severity is SEVERITY else severity)
