"""A ROS 2 `LifecycleNode` or node container without the `namespace=` launch requires.

## What it does
Reports a Python launch file that constructs `launch_ros.actions.LifecycleNode(...)` or
`ComposableNodeContainer(...)` without the `name=` or the `namespace=` keyword. Error when
the target distribution (`--ros-distro`, the `ros-distro` key, or `ROS_DISTRO`) is
Galactic or later; info with no target (the file runs on Foxy); nothing on Foxy and
before.

## Why is this bad?
From Galactic on, both constructors declare `name` and `namespace` as keyword-only
parameters without a default (launch_ros/actions/lifecycle_node.py and
composable_node_container.py, `def __init__(self, *, name, namespace, ...)`, on the
galactic, humble, iron, jazzy and rolling branches; ros2/launch_ros#157 "Make namespace
parameter mandatory in LifecycleNode constructor"). Python raises `TypeError: ...
missing 1 required keyword-only argument: 'namespace'` while the launch file is loaded,
and `ros2 launch` refuses the whole file: none of its nodes starts (Myzhar/
ldrobot-lidar-ros2#5: "Fix launch error on ROS 2 humble"). Foxy's constructors gave both
a default, so files written for Foxy often leave `namespace=` out.

## Example
With `--ros-distro humble`:
```python
from launch import LaunchDescription
from launch_ros.actions import LifecycleNode

def generate_launch_description():
    return LaunchDescription([
        LifecycleNode(package="ldlidar_node", executable="ldlidar_node", name="ldlidar"),
    ])
```

## Use instead
```python
from launch import LaunchDescription
from launch_ros.actions import LifecycleNode

def generate_launch_description():
    return LaunchDescription([
        LifecycleNode(package="ldlidar_node", executable="ldlidar_node", name="ldlidar",
                      namespace=""),
    ])
```
"""

from __future__ import annotations

from collections.abc import Iterator

from launch_linter.model.diagnostic import Category, Severity
from launch_linter.model.distro import LEGACY_KEYWORDS_OK, ROS1_DISTROS
from launch_linter.model.record import replace
from launch_linter.rules._api import Finding, RuleContext, frontend_findings

ID = "ros2_missing_keyword"
CATEGORY = Category.LAUNCH
SEVERITY = Severity.ERROR
EXAMPLE_PATH = "example.launch.py"
EXAMPLE_DISTRO = "humble"


def check(context: RuleContext) -> Iterator[Finding]:
    # A ROS 1 target (a mixed repository linted with --ros-distro noetic) says nothing
    # about the ROS 2 distribution that runs this file: judged as with no target.
    distro = None if context.distro in ROS1_DISTROS else context.distro
    if distro in LEGACY_KEYWORDS_OK:
        return
    for note in frontend_findings(context, ID):
        if distro is None:
            yield replace(note, severity=Severity.INFO, message=(
                f"{note.message}: launch_ros of Galactic and later requires both keywords "
                f"(ros2 launch refuses the file there); only Foxy's accepts it"))
        else:
            yield replace(note, message=(
                f"{note.message}: launch_ros of {distro.capitalize()} requires both "
                f"keywords, so ros2 launch refuses the whole file (TypeError: missing "
                f"required keyword-only argument); give namespace='' for the root namespace"))
