"""A ROS 2 `Node` given Foxy-era keywords (`node_executable=`, ...) on a later distribution.

## What it does
Reports a Python launch file whose `Node(...)` (or `LifecycleNode`,
`ComposableNodeContainer`) uses `node_executable=`, `node_name=` or `node_namespace=`, or
whose `ComposableNode(...)` uses `node_plugin=`, `node_name=` or `node_namespace=`, when
the target distribution (`--ros-distro`, the `ros-distro` key, or `ROS_DISTRO`) is
Galactic or later, at the first such keyword (the word to change), and names the keyword
that replaced each one (`executable=`, `plugin=`, `name=`, `namespace=`). With no target
given, these keywords are taken as evidence that the file targets Foxy and nothing is
reported, unless a `static_transform_publisher` of the tree is given flags (`--frame-id`
...): the flags arrived in Humble, so no distribution runs the file, and the keyword is
reported (rather than the flags as Foxy's mistake). Keywords under a Python `if` the
linter cannot decide (a branch for Dashing or Eloquent) are not taken as that evidence;
with a distribution given, such a branch is decided where it reads `ROS_DISTRO` and the
keywords are judged otherwise.

## Why is this bad?
launch_ros renamed the keywords in Foxy and removed the old ones afterwards: on Humble,
`Node(node_executable=...)` raises "unexpected keyword argument" and `ros2 launch`
refuses the whole file, so none of its transforms is published.

## Example
With `--ros-distro humble`:
```python
from launch import LaunchDescription
from launch_ros.actions import Node

def generate_launch_description():
    return LaunchDescription([
        Node(package="tf2_ros", node_executable="static_transform_publisher",
             arguments=["--frame-id", "base_link", "--child-frame-id", "laser"]),
    ])
```

## Use instead
```python
from launch import LaunchDescription
from launch_ros.actions import Node

def generate_launch_description():
    return LaunchDescription([
        Node(package="tf2_ros", executable="static_transform_publisher",
             arguments=["--frame-id", "base_link", "--child-frame-id", "laser"]),
    ])
```
"""

from __future__ import annotations

from collections.abc import Iterator

from launch_linter.model.diagnostic import Category, Severity
from launch_linter.model.distro import LEGACY_KEYWORDS_OK, ROS1_DISTROS, uses_flags
from launch_linter.model.record import replace
from launch_linter.model.transform import StaticTransform
from launch_linter.rules._api import Finding, RuleContext, frontend_findings

ID = "ros2_removed_keyword"
CATEGORY = Category.LAUNCH
SEVERITY = Severity.ERROR
EXAMPLE_PATH = "example.launch.py"
EXAMPLE_DISTRO = "humble"


def _flags_at(context: RuleContext) -> StaticTransform | None:
    """A ROS 2 static transform of the tree given flags (Humble's), if any."""
    return next((t for t in context.tree.transforms
                 if t.ros_version == 2 and uses_flags(t.tokens)), None)


def check(context: RuleContext) -> Iterator[Finding]:
    # A ROS 1 target (a mixed repository linted with --ros-distro noetic) says nothing
    # about the ROS 2 distribution that runs this file: judged as with no target.
    distro = None if context.distro in ROS1_DISTROS else context.distro
    if context.study or distro in LEGACY_KEYWORDS_OK:
        return
    flagged = _flags_at(context) if distro is None else None
    if distro is None and flagged is None:
        return
    for note in frontend_findings(context, ID):
        if flagged is not None:
            where = (f"line {flagged.line}" if flagged.path == note.path
                     else f"{flagged.path}:{flagged.line}")
            yield replace(note, message=(
                f"{note.message} were removed after Foxy, but the "
                f"static_transform_publisher flags at {where} arrived in Humble: on every "
                f"distribution that reads those flags, ros2 launch refuses the whole file"
            ))
        else:
            yield replace(note, message=(
                f"{note.message} were removed after Foxy: on "
                f"{str(distro).capitalize()} ros2 launch refuses the whole file"
            ))
