"""A ROS 2 parameter file's value of another type than the node declares: the node dies.

## What it does
Reports a value in a ROS 2 parameter file whose type rclcpp reads differently from the
type the node declares the parameter with, for the nodes whose declarations the knowledge
base lists (`parameter_types`, read from each node's source): an integer (`30`) or a
boolean where the node declares a double, a number or a boolean where it declares an
integer and the text is not one (`30.5`), a number where it declares a boolean. It reports
at the value's key, the node related. Only the node's effective value is judged (a later
setting wins), only when it is written in a parameter file (values given through launch
arguments can change), and a string value is left alone (a quoted `"30"` and a plain `30`
read the same to the linter).

## Why is this bad?
rcl's YAML parser gives `30` the type integer and `30.0` the type double
(rcl_yaml_param_parser), and rclcpp never converts between them: a node that declares
`declare_parameter("frequency", 30.0)` takes its value with `.get<double>()`, which throws
`ParameterTypeException` ("expected [double] got [integer]") on Dashing, and
`InvalidParameterTypeException` from Foxy on (rclcpp/include/rclcpp/node_impl.hpp,
`Node::declare_parameter<ParameterT>`: dashing 403aac9 lines 248-260, foxy b0c25d5 155-173,
humble 99f1d8d 193-211, rolling a0a2a06 231-249). Uncaught in the node's constructor, it
kills the process ("process has died ... exit code -6"), so whatever the node publishes (a
filter's `odom → base_link`, navsat_transform's `utm` transform) never comes
(cra-ros-pkg/robot_localization#533).

## Example
```xml
<launch>
  <node pkg="robot_localization" exec="navsat_transform_node" name="navsat_transform_node">
    <param from="$(dirname)/params.yaml"/>
  </node>
</launch>
```

```yaml
navsat_transform_node:
  ros__parameters:
    frequency: 30
```

## Use instead
```xml
<launch>
  <node pkg="robot_localization" exec="navsat_transform_node" name="navsat_transform_node">
    <param from="$(dirname)/params.yaml"/>
  </node>
</launch>
```

```yaml
navsat_transform_node:
  ros__parameters:
    frequency: 30.0
```

## Known problems
Only the nodes whose `parameter_types` the knowledge base lists are checked (robot_localization's
filters and navsat_transform_node); other nodes are unknown and not judged.
"""

from __future__ import annotations

import re
from collections.abc import Iterator

from launch_linter.model.diagnostic import Category, Severity
from launch_linter.model.robot import UNKNOWN_VALUE
from launch_linter.rules._api import Finding, RuleContext
from launch_linter.rules._nodes import entry_of, finding_at_param, program_of

ID = "ros2_param_type"
CATEGORY = Category.LAUNCH
SEVERITY = Severity.ERROR
EXAMPLE_PATH = "example.launch.xml"
EXAMPLE_INCLUDED = "params.yaml"

_INTEGER = re.compile(r"^[-+]?[0-9]+$")
_DOUBLE = re.compile(r"^[-+]?([0-9]+\.[0-9]*|\.[0-9]+)([eE][-+]?[0-9]+)?$")
_BOOLEAN = ("true", "false")
_PARAMETER_FILE = (".yaml", ".yml")


def written_type(value: str) -> str | None:
    """The type rclcpp gives a parameter file's value as the linter reads it back (PyYAML's
    scalar as text): ``integer``, ``double`` or ``bool``; None for text (a string, or a
    number PyYAML kept as text)."""
    if value in _BOOLEAN:
        return "bool"
    if _INTEGER.match(value):
        return "integer"
    if _DOUBLE.match(value):
        return "double"
    return None


def check(context: RuleContext) -> Iterator[Finding]:
    for node in context.tree.nodes:
        if node.ros != 2 or node.kind != "node":
            continue
        entry = entry_of(context, node)
        if entry is None or not entry.parameter_types:
            continue
        for name, declared in entry.parameter_types:
            value = node.given(name)
            where = node.where_set(name)
            if value is None or value == UNKNOWN_VALUE or where is None or \
                    not where[0].endswith(_PARAMETER_FILE):
                continue
            given = written_type(value)
            if given is None or given == declared or declared == "string":
                continue
            yield finding_at_param(node, name, (
                f"{program_of(node)} declares '{name}' a {declared}, but the parameter file "
                f"gives it {value}, which rclcpp reads as {_article(given)} {given}: "
                f"rclcpp never converts it, the node throws a parameter type exception "
                f"while it starts and dies; write it as {_as(declared, value)}"))


def _article(kind: str) -> str:
    return "an" if kind[0] in "aeiou" else "a"


def _as(declared: str, value: str) -> str:
    if declared == "double" and _INTEGER.match(value):
        return f"{value}.0"
    return f"a {declared}"
