"""A node's frame parameter with a leading slash, where the node looks the frame up in tf2.

## What it does
Reports a frame parameter given to a ROS 2 node (`global_frame`, `odom_frame_id`,
`base_link_frame`, … as the knowledge base names them, docs/knowledge.md) whose value
starts with `/`: the node passes it to tf2 as it is, and tf2 frame ids cannot start with
`/`. ROS 1 nodes are left out (tf 1, and ROS 1 amcl, strip the slash), as are nodes whose
source strips it and the nodes' own defaults.

## Why is this bad?
tf2 refuses a frame id that starts with `/` ("frame_ids cannot start with a '/'"): every
lookup of that frame fails, and a transform the node publishes under it is not the frame
the rest of the tree calls by its name without the slash. The slash is a habit from tf 1,
whose `tf_prefix` resolution accepted it; costmaps, map_server, slam_toolbox and
robot_localization on tf2 do not.

## Example
```xml
<launch>
  <node pkg="nav2_amcl" exec="amcl" name="amcl">
    <param name="global_frame_id" value="/map"/>
  </node>
</launch>
```

## Use instead
```xml
<launch>
  <node pkg="nav2_amcl" exec="amcl" name="amcl">
    <param name="global_frame_id" value="map"/>
  </node>
</launch>
```

## Known problems
Reported at info until measured: it gave no finding on the corpus (mostly ROS 1, whose
nodes it leaves out) nor on 17 whole repositories (docs/evaluation/tree_judged.jsonl).
"""

from __future__ import annotations

from collections.abc import Iterator

from launch_linter.knowledge import Entry
from launch_linter.model.diagnostic import Category, Severity
from launch_linter.model.robot import UNKNOWN_VALUE, NodeRecord
from launch_linter.rules._api import Finding, RuleContext
from launch_linter.rules._nodes import entry_of, finding_at_node, frame_parameters

ID = "frame_param_slash"
CATEGORY = Category.TF
SEVERITY = Severity.INFO
EXAMPLE_PATH = "example.launch.xml"


def _slashed(entry: Entry, node: NodeRecord) -> Iterator[tuple[str, str]]:
    for name in frame_parameters(entry):
        value = node.given(name)
        if value is not None and value != UNKNOWN_VALUE and value.startswith("/"):
            yield name, value


def check(context: RuleContext) -> Iterator[Finding]:
    for node in context.tree.nodes:
        entry = entry_of(context, node)
        if node.ros != 2 or entry is None or entry.strips_leading_slash:
            continue
        for name, value in _slashed(entry, node):
            program = node.plugin or f"{node.package}/{node.executable}"
            yield finding_at_node(
                node,
                f"{program} parameter '{name}' is '{value}': tf2 frame ids cannot start "
                f"with '/', so the node's lookups of it fail; write '{value.lstrip('/')}'",
            )
