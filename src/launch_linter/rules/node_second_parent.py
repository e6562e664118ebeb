"""A frame that a node's published edge gives a second parent.

## What it does
Reports a frame that a launched node publishes as the child of one parent (by the knowledge
base, docs/knowledge.md) while another source of the same tree gives it another parent: a
static transform, a URDF joint that robot_state_publisher sends, or another node. Typical:
a robot_localization filter or a diff-drive controller publishing `odom → base_link` while
the URDF hangs `base_link` under `base_footprint`, or a static `map → base_link` beside a
localization node's `map → odom` and odometry's `odom → base_link`. The finding is at the
static transform when there is one, else at the node.

## Why is this bad?
A tf frame has exactly one parent (REP 105). With two, tf2 keeps whichever transform
arrived last, and every lookup through the other parent fails or jumps. The node's base
frame parameter (`base_link_frame`, `base_frame_id`, `robot_base_frame`) usually names the
wrong frame: it must be the root of the robot's description (often `base_footprint`).

## Example
```xml
<launch>
  <node pkg="robot_localization" type="ekf_localization_node" name="ekf">
    <param name="odom0" value="wheel/odom"/>
  </node>
  <node pkg="tf2_ros" type="static_transform_publisher" name="footprint"
        args="0 0 0 0 0 0 base_footprint base_link"/>
</launch>
```

## Use instead
```xml
<launch>
  <node pkg="robot_localization" type="ekf_localization_node" name="ekf">
    <param name="odom0" value="wheel/odom"/>
    <param name="base_link_frame" value="base_footprint"/>
  </node>
  <node pkg="tf2_ros" type="static_transform_publisher" name="footprint"
        args="0 0 0 0 0 0 base_footprint base_link"/>
</launch>
```

## Known problems
A node's parameter file that the linter cannot read leaves its defaults assumed (except
where the knowledge base says they are not).
"""

from __future__ import annotations

from collections.abc import Iterator

from launch_linter.model.diagnostic import Category, Severity
from launch_linter.rules._api import Finding, RuleContext
from launch_linter.rules._nodes import NodeEdge, finding_at_node, nodes_of, rivals
from launch_linter.rules._tree import edges_of, finding_on

ID = "node_second_parent"
CATEGORY = Category.TF
SEVERITY = Severity.WARNING
MAX_PUBLISHERS_PER_FRAME = 64
"""Node edges of one child frame each new one is compared with (bounded work: thousands of
controllers of one manager, one launch element, are no rivals of each other)."""


def check(context: RuleContext) -> Iterator[Finding]:
    view = nodes_of(context)
    if not view.edges:
        return
    by_child: dict[str, list[NodeEdge]] = {}
    for node_edge in view.edges:
        earlier = by_child.setdefault(node_edge.child, [])
        other = next((e for e in earlier
                      if e.parent != node_edge.parent and rivals(e, node_edge)), None)
        if len(earlier) < MAX_PUBLISHERS_PER_FRAME:
            earlier.append(node_edge)
        if other is not None:
            yield finding_at_node(
                node_edge.node,
                f"frame '{node_edge.child}' gets 2 parents: '{node_edge.parent}' from "
                f"{node_edge.describe()} and '{other.parent}' from {other.describe()}; a tf "
                f"frame has exactly one parent",
                (other.location,),
            )
    reported: set[tuple[str, str]] = set()
    for edge in edges_of(context):
        for node_edge in by_child.get(edge.child, ()):
            if (node_edge.parent == edge.parent or edge.parent == edge.child
                    or node_edge.node.condition.excludes(edge.condition)):
                continue
            key = (edge.child, edge.parent)
            if key in reported:
                break
            reported.add(key)
            message = (f"frame '{edge.child}' gets 2 parents: '{edge.parent}' from the "
                       f"{edge.describe()} and '{node_edge.parent}' from "
                       f"{node_edge.describe()}; a tf frame has exactly one parent")
            if edge.joint is None:
                yield finding_on(edge, message, ())
            else:
                yield finding_at_node(node_edge.node, message, (edge.location,))
            break
