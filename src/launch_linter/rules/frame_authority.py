"""A static transform for an edge that a running localization or odometry node publishes.

## What it does
Reports a static transform for an edge that a node of the same launch tree publishes as
localization (`map → odom` by amcl, slam_toolbox, gmapping, karto, hector_mapping, rtabmap,
a robot_localization filter whose `world_frame` is its map frame, …) or as odometry
(`odom → base_link` by a robot_localization filter in `odom`, rf2o, rtabmap's odometry,
diff_drive_controller and the other odometry controllers, Gazebo's diff-drive plugin, …).
Which node publishes which edge comes from the knowledge base (docs/knowledge.md): the
edge is the one the node's frame parameters name, with the node's own defaults, read from
`<param>`, `<rosparam>` (text and files) and ROS 2 parameters and parameter files.
hector_mapping with `odom_frame` set to `base_link` publishes `map → base_link`, not
`map → odom`; a node given `publish_tf`, `tf_broadcast`, `pub_map_odom_transform` false
(or a publishing period of 0) publishes nothing.

When a node's parameter file cannot be read, its defaults are assumed except where the
knowledge base says they are not (a robot_localization filter's `world_frame`, which the
dual-filter setup sets in that file). A frame parameter the linter cannot resolve leaves
the node out. Node and transform under mutually exclusive conditions are not compared.

## Why is this bad?
REP 105 gives each of these edges one authority: localization corrects `map → odom`,
odometry integrates `odom → base_link`. A static transform for the same edge gives tf two
publishers that disagree: the robot jumps between the localized and the frozen pose.
Static `map → odom` is a common stand-in while testing without localization, left in
after amcl was added.

## Example
```xml
<launch>
  <node pkg="amcl" type="amcl" name="amcl"/>
  <node pkg="tf2_ros" type="static_transform_publisher" name="map_odom"
        args="0 0 0 0 0 0 map odom"/>
</launch>
```

## Use instead
```xml
<launch>
  <node pkg="amcl" type="amcl" name="amcl"/>
</launch>
```

## Known problems
A node whose parameter file the linter cannot read (unresolved path, no PyYAML) is counted
with its defaults: configured there not to publish tf, it is still counted.
"""

from __future__ import annotations

from collections.abc import Iterator

from launch_linter.model.diagnostic import Category, Severity
from launch_linter.rules._api import Finding, RuleContext
from launch_linter.rules._nodes import AUTHORITIES, NodeEdge, nodes_of, program_of
from launch_linter.rules._tree import edges_of, finding_on

ID = "frame_authority"
CATEGORY = Category.TF
SEVERITY = Severity.INFO


def check(context: RuleContext) -> Iterator[Finding]:
    owned: dict[tuple[str, str], list[NodeEdge]] = {}
    for node_edge in nodes_of(context).edges:
        if node_edge.role in AUTHORITIES:
            owned.setdefault((node_edge.parent, node_edge.child), []).append(node_edge)
    if not owned:
        return
    for edge in edges_of(context):
        if edge.joint is not None:
            continue
        for node_edge in owned.get((edge.parent, edge.child), ()):
            node = node_edge.node
            if node.condition.excludes(edge.condition):
                continue
            what = node_edge.role
            yield finding_on(
                edge,
                f"static '{edge.parent}' -> '{edge.child}' while the {what} node "
                f"{program_of(node)} ({node.path}:{node.line}) publishes it; "
                f"REP 105 gives this edge to {what} alone",
            )
            break
