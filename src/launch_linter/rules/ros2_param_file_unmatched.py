"""A ROS 2 parameter file given to a node none of whose node keys names that node.

## What it does
Reports a ROS 2 parameter file passed to a node (`Node(parameters=[file])`, `<param
from="file"/>` in XML, `param: [{from: file}]` in YAML launch, `ComposableNode(parameters=
[file])`) when the file has node keys (the keys above `ros__parameters`, nested namespace
keys joined) and none of them matches the node's fully qualified name as launched: its
`name=` under its namespace (its own and the namespaces pushed around it). Keys are
matched as rclcpp matches them: a leading `/` added, `/*` one name, `/**` any number of
names. It reports at the file's first node key, the node related. Only nodes whose name
is written in the launch file are checked (the name an executable gives itself is read
from its source, which the linter does not have), and not a node whose arguments may
remap its name or namespace (`__node:=`, `__ns:=`, or arguments not known). A file shared
by several nodes is judged for each node apart: only a node for which no key matches is
reported. Left out: processes that run other nodes under their own names in the same
process, since those nodes take the file's other sections: a controller manager (its
controllers), a component container (its components), the nav2 servers that run a costmap
node (`controller_server`, `planner_server`).

## Why is this bad?
rclcpp applies a parameter file's entries only under the keys that match the node's fully
qualified name: `parameter_map_from` skips every other key
(rclcpp/src/rclcpp/parameter_map.cpp 54-68 and detail/resolve_parameter_overrides.cpp 54-60,
ros2/rclcpp a0a2a06); launch_ros's composable node loader keeps only `**` and the exact
`namespace/name` (launch_ros/utilities/to_parameters_list.py 77-95, ros2/launch_ros
f9ab937). Nothing warns: the node starts on its built-in defaults, so every frame,
`publish_tf` and topic in the file is silently ignored. AutonomyLab/create_robot#79 (the
file keyed `create_node` for the driver named `create_driver`: "nothing changed"),
ros-perception/depthimage_to_laserscan#71, husky/husky#244 (`imu_filter_node` for the
node named `imu_filter`: the filter kept `publish_tf` true and published a second parent
of `imu_link`).

## Example
```xml
<launch>
  <node pkg="depthimage_to_laserscan" exec="depthimage_to_laserscan_node"
        name="depthimage_to_laserscan_node">
    <param from="$(dirname)/params.yaml"/>
  </node>
</launch>
```

```yaml
depthimage_to_laserscan:
  ros__parameters:
    output_frame: camera_depth_frame
```

## Use instead
```xml
<launch>
  <node pkg="depthimage_to_laserscan" exec="depthimage_to_laserscan_node"
        name="depthimage_to_laserscan">
    <param from="$(dirname)/params.yaml"/>
  </node>
</launch>
```

```yaml
depthimage_to_laserscan:
  ros__parameters:
    output_frame: camera_depth_frame
```

## Known problems
A node whose name the launch file does not write is not checked, even where its
executable's default name is known. A file without any `ros__parameters` key is left to
rcl (it refuses such a file at start-up). rclpy nodes are judged with rclcpp's matching
(the wider one: what it does not match, an exact or `/**` match does not match either).
"""

from __future__ import annotations

from collections.abc import Iterator

from launch_linter.model.diagnostic import Category, Location, Severity
from launch_linter.rules._api import Finding, RuleContext

ID = "ros2_param_file_unmatched"
CATEGORY = Category.LAUNCH
SEVERITY = Severity.WARNING
EXAMPLE_PATH = "example.launch.xml"
EXAMPLE_INCLUDED = "params.yaml"
"""The parameter file the documented example reads: the second block of its sections."""

def check(context: RuleContext) -> Iterator[Finding]:
    # The front-end leaves out processes that run other nodes under their own names.
    for unmatched in context.tree.unmatched_param_files:
        keys = sorted(unmatched.keys, key=lambda k: (k[1], k[2]))
        written = [(key, line, column) for key, line, column in keys if line]
        names = ", ".join(key for key, _, _ in keys[:5])
        more = "" if len(unmatched.keys) <= 5 else f" and {len(unmatched.keys) - 5} more"
        message = (f"none of this parameter file's node keys ({names}{more}) matches the "
                   f"node {unmatched.node} ({unmatched.package} {unmatched.executable}) it "
                   f"is given to: rclcpp applies only the keys that match the node's name, "
                   f"so the node runs on its defaults; key the file {unmatched.node} (or "
                   f"/**), or name the node as the file does")
        node_place = Location(unmatched.path, unmatched.line, unmatched.column)
        if not written:
            yield Finding(path=unmatched.path, line=unmatched.line, column=unmatched.column,
                          message=message, node=unmatched.node)
            continue
        _, line, column = written[0]
        yield Finding(path=unmatched.file, line=line, column=column, message=message,
                      node=unmatched.node, related=(node_place,))
