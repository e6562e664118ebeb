"""An empty list in the parameter file of an rclcpp node: the node dies while it starts.

## What it does
Reports a parameter set to `[]` in a ROS 2 parameter file, in a section that reaches the
node it is given to (`Node(parameters=[file])`, `<param from="file"/>`), when the node's
package is proven to build rclcpp nodes: its `package.xml` builds with `ament_cmake`,
depends on `rclcpp` and names `rclpy` in none of its dependencies. It reports at the
parameter's key, the node related; a node under a condition is not judged.

## Why is this bad?
rcl's YAML parser reads `[]` as a parameter whose value has no type: an empty sequence
adds no element, so no array type is ever chosen (rcl_yaml_param_parser `parse.c`,
ros2/rcl rolling c19dab55 lines 833-852). While the node is built, rclcpp converts every
parameter of each matching section (`resolve_parameter_overrides` → `parameter_map_from`),
and `parameter_value_from` throws `InvalidParameterValueException("No parameter value
set")` for it (rclcpp/src/rclcpp/parameter_map.cpp: foxy line 127, humble 99f1d8d and jazzy
985e320 line 147), whatever type the node declares. The exception leaves the constructor
and the process aborts, so nothing the node publishes ever comes
(selfpatch/ros2_medkit#444; PlanSys2/ros2_planning_system#122: "all the nodes that read
the YAML crash"; ros2/rclcpp#1955 asks for empty lists to be allowed). rclpy reads the
same value as "not set" without raising, so Python nodes are not judged.

## Example
```python
import os

from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package="bridge", executable="bridge_node", name="bridge",
             parameters=[os.path.join(os.path.dirname(__file__), "bridge.yaml")]),
    ])
```

```yaml
bridge:
  ros__parameters:
    exclude_topics: []
```

```xml
<package format="3">
  <name>bridge</name>
  <depend>rclcpp</depend>
  <export><build_type>ament_cmake</build_type></export>
</package>
```

## Use instead
```python
import os

from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package="bridge", executable="bridge_node", name="bridge",
             parameters=[os.path.join(os.path.dirname(__file__), "bridge.yaml")]),
    ])
```

```yaml
bridge:
  ros__parameters:
    exclude_topics: ["/debug"]
```

```xml
<package format="3">
  <name>bridge</name>
  <depend>rclcpp</depend>
  <export><build_type>ament_cmake</build_type></export>
</package>
```

## Known problems
A node whose package is not in the linted paths (an installed package), an `ament_python`
package, or one that depends on both `rclcpp` and `rclpy` is not judged. Empty lists in a
`parameters=[{...}]` dictionary and in composable nodes' parameters (which launch_ros
reads itself) are not judged.
"""

from __future__ import annotations

from collections.abc import Iterable

from launch_linter.model.diagnostic import Category, Severity
from launch_linter.rules._api import Finding, RuleContext, frontend_findings

ID = "ros2_param_empty_list"
CATEGORY = Category.LAUNCH
SEVERITY = Severity.ERROR
EXAMPLE_PATH = "example.launch.py"
EXAMPLE_INCLUDED = ("bridge.yaml", "package.xml")
"""The parameter file and the manifest the documented example's node reads."""


def check(context: RuleContext) -> Iterable[Finding]:
    return frontend_findings(context, ID)
