"""A ROS 2 node launched under a namespace whose name was pushed twice.

## What it does
Reports a node whose namespace as launched ends in the same name pushed twice: a group or
include pushes the robot's namespace (`PushRosNamespace(namespace)`) around a file that
pushes it again, or a node's relative `namespace=` repeats the one pushed around it, so
the node runs under `/robot1/robot1`. It reports at the inner push, the outer push and
the node related. An error when it provably moves the node's transforms off the robot's
tree: the node's tf goes to a relative `tf` (remapped `('/tf', 'tf')`), so
`/robot1/robot1/tf`, while the tree's other nodes under `/robot1` use `/robot1/tf`.
Info otherwise (its topics and the parameter-file keys rooted at `/robot1` miss it, but
tf may still be shared).

## Why is this bad?
launch_ros pushes a relative namespace under the one already pushed (`PushRosNamespace`,
a node's `namespace=`), so two pushes of one name stack. A node whose tf is relative then
publishes and listens on a topic nobody else uses: SLAM's `map -> odom` never reaches the
robot's tree, and the robot's transforms never reach it. turtlebot/turtlebot4_simulator#57:
"Don't push namespace to nav, it is handled in the nav launch files and was being applied
twice".

## Example
```python
from launch import LaunchDescription
from launch.actions import GroupAction
from launch_ros.actions import Node, PushRosNamespace


def generate_launch_description():
    return LaunchDescription([GroupAction([
        PushRosNamespace("robot1"),
        Node(package="tf2_ros", executable="static_transform_publisher",
             arguments=["--frame-id", "base_link", "--child-frame-id", "laser"],
             remappings=[("/tf", "tf"), ("/tf_static", "tf_static")]),
        GroupAction([
            PushRosNamespace("robot1"),
            Node(package="slam_toolbox", executable="async_slam_toolbox_node",
                 name="slam_toolbox", remappings=[("/tf", "tf")]),
        ]),
    ])])
```

## Use instead
```python
from launch import LaunchDescription
from launch.actions import GroupAction
from launch_ros.actions import Node, PushRosNamespace


def generate_launch_description():
    return LaunchDescription([GroupAction([
        PushRosNamespace("robot1"),
        Node(package="tf2_ros", executable="static_transform_publisher",
             arguments=["--frame-id", "base_link", "--child-frame-id", "laser"],
             remappings=[("/tf", "tf"), ("/tf_static", "tf_static")]),
        Node(package="slam_toolbox", executable="async_slam_toolbox_node",
             name="slam_toolbox", remappings=[("/tf", "tf")]),
    ])])
```

## Known problems
ROS 2 only (Python, XML and YAML launch files). A remapping the linter cannot resolve
leaves the node's tf topic unknown: the finding stays info. A namespace deliberately
nested under a namespace of the same name (`/camera/camera`) is reported at info too.
"""

from __future__ import annotations

from collections.abc import Iterator

from launch_linter.model.diagnostic import Category, Location, Severity
from launch_linter.rules._api import Finding, RuleContext

ID = "namespace_pushed_twice"
CATEGORY = Category.TF
SEVERITY = Severity.ERROR
EXAMPLE_PATH = "example.launch.py"


def check(context: RuleContext) -> Iterator[Finding]:
    for doubled in context.tree.doubled_namespaces:
        outer, inner = doubled.pushes
        once = doubled.namespace.rstrip("/").rsplit("/", 1)[0] or "/"
        who = f"{doubled.program}" + (f" ({doubled.node})" if doubled.node else "")
        # Apart because of the second push: the node's tf is under the doubled namespace.
        apart = (doubled.tf_topic is not None and doubled.tree_tf_topic is not None
                 and doubled.tf_topic.startswith(doubled.namespace.rstrip("/") + "/")
                 and doubled.tf_topic != doubled.tree_tf_topic)
        pushed = (f"{who} runs under {doubled.namespace}: the namespace {once} pushed at "
                  f"{outer.path}:{outer.line} is pushed again here")
        node_place = Location(doubled.path, doubled.line, doubled.column)
        if apart:
            yield Finding(inner.path, inner.line, inner.column, (
                f"{pushed}, so its tf goes to {doubled.tf_topic} while the tree's nodes "
                f"under {once} use {doubled.tree_tf_topic}: its transforms never join the "
                f"robot's tree; push the namespace once"), node=doubled.node or None,
                related=(outer, node_place))
            continue
        yield Finding(inner.path, inner.line, inner.column, (
            f"{pushed}: its topics and the parameter-file keys rooted at {once} miss it; "
            f"push the namespace once"), node=doubled.node or None,
            related=(outer, node_place), severity=Severity.INFO)
