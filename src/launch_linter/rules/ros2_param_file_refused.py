"""A ROS 2 parameter file with a value above `ros__parameters`: rcl refuses it, the node dies.

## What it does
Reports a parameter file given to a ROS 2 node (`Node(parameters=[file])`, `<param
from="file"/>`) in which a value stands above `ros__parameters`: at the top level, or under
node-name or namespace keys only (`pizza: mushrooms` with no node key, or `my_node: {rate:
2}` with no `ros__parameters`). It reports at the first such key, the node related. In a
file that launch substitutes first (`allow_substs`), a value made of substitutions is judged
only when they resolve to one plain line; a node under a condition is not judged.

## Why is this bad?
rcl's parser reads every key above `ros__parameters` as a node name or namespace, and a
value there stops it: "Cannot have a value before ros__parameters at line N" (a list:
"Sequences can only be values and not keys in params"; rcl_yaml_param_parser `parse.c`
`parse_file_events`, the same on ros2/rcl foxy, humble 6d0fd90e and rolling c19dab55).
`rcl_parse_arguments` then fails on the node's `--params-file` ("Couldn't parse params
file", rcl/src/rcl/arguments.c `_rcl_parse_param_file`), `rcl_init` fails, and the process
exits before any node starts, whether it is rclcpp's or rclpy's (MetroRobots/rosetta_launch#22).

## Example
```python
import os

from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package="demo", executable="talker", name="talker",
             parameters=[os.path.join(os.path.dirname(__file__), "talker.yaml")]),
    ])
```

```yaml
rate: 2.0
topic: chatter
```

## Use instead
```python
import os

from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package="demo", executable="talker", name="talker",
             parameters=[os.path.join(os.path.dirname(__file__), "talker.yaml")]),
    ])
```

```yaml
talker:
  ros__parameters:
    rate: 2.0
    topic: chatter
```

## Known problems
A value whose substitutions do not resolve (an environment variable, a command's output) in
an `allow_substs` file is not judged: its text could change the file's shape. Parameter files
of composable nodes (which launch_ros reads itself) are not judged.
"""

from __future__ import annotations

from collections.abc import Iterable

from launch_linter.model.diagnostic import Category, Severity
from launch_linter.rules._api import Finding, RuleContext, frontend_findings

ID = "ros2_param_file_refused"
CATEGORY = Category.LAUNCH
SEVERITY = Severity.ERROR
EXAMPLE_PATH = "example.launch.py"
EXAMPLE_INCLUDED = "talker.yaml"
"""The parameter file the documented example's node is given."""


def check(context: RuleContext) -> Iterable[Finding]:
    return frontend_findings(context, ID)
