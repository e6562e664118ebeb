"""joint_state_publisher beside another publisher of the same /joint_states topic.

## What it does
Reports a ROS 2 `joint_state_publisher` (or `joint_state_publisher_gui`) without a
`source_list` that publishes on the same `joint_states` topic as another publisher of
joint states in the tree: a joint_state_broadcaster a spawner of the tree starts, the
Gazebo `gazebo_ros_joint_state_publisher` plugin of a spawned robot, or a driver the
knowledge base knows to publish joint states. Topics are compared after the namespaces
and the remappings each one is given; publishers under exclusive conditions are not
compared. It reports at joint_state_publisher, with the other publisher related. Info:
none on 15 whole repositories (docs/evaluation/controller_tf_unrouted.md); round 8, 90
more: 3 findings, all true, in two repositories (two copies of one husky GPS tutorial
file and Clearpath's husky_gazebo display launch; docs/evaluation/samples-round8.md): too
few to raise it to a warning.

## Why is this bad?
joint_state_publisher publishes every movable joint of the robot description on
`joint_states` at its `rate`, at zero (or its `zeros`) unless it merges a `source_list`
(ros/joint_state_publisher ros2 fb29caa `joint_state_publisher.py` 417-428, 470-535);
joint_state_broadcaster publishes the measured positions on `joint_states` too
(ros2_controllers joint_state_broadcaster.cpp, humble ad559d9 149-152, jazzy ed360c9
139-142). robot_state_publisher takes whichever came last, so the wheels and arm joints
jump between zero and their real positions: flickering frames in RViz and wrong sensor
poses for everything mounted on them. automaticaddison/yahboom_rosmaster#4: "both are
publishing to /joint_states. So sometimes there are zeros in between", fixed the same day
by starting joint_state_publisher only on request.

## Example
```xml
<launch>
  <node pkg="joint_state_publisher" exec="joint_state_publisher"/>
  <node pkg="controller_manager" exec="ros2_control_node">
    <param from="$(dirname)/controllers.yaml"/>
  </node>
  <node pkg="controller_manager" exec="spawner" args="joint_state_broadcaster"/>
</launch>
```

```yaml
controller_manager:
  ros__parameters:
    joint_state_broadcaster:
      type: joint_state_broadcaster/JointStateBroadcaster
```

## Use instead
```xml
<launch>
  <node pkg="controller_manager" exec="ros2_control_node">
    <param from="$(dirname)/controllers.yaml"/>
  </node>
  <node pkg="controller_manager" exec="spawner" args="joint_state_broadcaster"/>
</launch>
```

```yaml
controller_manager:
  ros__parameters:
    joint_state_broadcaster:
      type: joint_state_broadcaster/JointStateBroadcaster
```

## Known problems
ROS 2 only. A broadcaster started otherwise than by a spawner (`ros2 control
load_controller` in an `ExecuteProcess`) is not seen; neither is any of a tree whose
spawner arguments are not all resolved. A joint_state_publisher given a `source_list` is
not judged (it may merge the other publisher's states; the two may still alternate).
"""

from __future__ import annotations

from collections.abc import Iterator

from launch_linter.model.diagnostic import Category, Location, Severity
from launch_linter.model.robot import NodeRecord
from launch_linter.rules._api import Finding, RuleContext
from launch_linter.rules._nodes import (
    JOINT_STATE_CONTROLLERS,
    entry_of,
    finding_at_node,
    program_of,
)
from launch_linter.rules._tf_topics import remapped

ID = "joint_states_two_publishers"
CATEGORY = Category.TF
SEVERITY = Severity.INFO
EXAMPLE_PATH = "example.launch.xml"
EXAMPLE_INCLUDED = "controllers.yaml"

JSP_PACKAGES = ("joint_state_publisher", "joint_state_publisher_gui")
TOPIC = "joint_states"
MERGING = "source_list"
LOCAL_TOPICS = "use_local_topics"
"""joint_state_broadcaster's switch to its own ``~/joint_states``."""
NOT_JOINT_STATE_NODES = ("controller_manager",)
"""Packages the knowledge base marks as publishing joint states only through the
controllers they load (judged here by the controllers themselves)."""


def _others(context: RuleContext) -> list[tuple[NodeRecord, str]]:
    """Every other joint-states publisher of the tree, with the topic it publishes on."""
    spawned = set(context.tree.spawned or ())
    out: list[tuple[NodeRecord, str]] = []
    for node in context.tree.nodes:
        if node.package in JSP_PACKAGES:
            continue
        if node.kind == "controller":
            if (node.plugin not in JOINT_STATE_CONTROLLERS or node.name not in spawned
                    or (node.given(LOCAL_TOPICS) or "").lower() == "true"):
                continue
        else:
            entry = entry_of(context, node)
            if (entry is None or not entry.publishes_joint_states
                    or node.package in NOT_JOINT_STATE_NODES):
                continue
        topic = remapped(TOPIC, node)
        if topic is not None:
            out.append((node, topic))
    return out


def check(context: RuleContext) -> Iterator[Finding]:
    publishers = [node for node in context.tree.nodes
                  if node.package in JSP_PACKAGES and node.kind == "node" and node.ros == 2
                  and (node.given(MERGING) or "[]").strip() in ("", "[]")]
    if not publishers:
        return
    others = _others(context)
    for jsp in publishers:
        topic = remapped(TOPIC, jsp)
        if topic is None:
            continue
        rival = next((node for node, theirs in others if theirs == topic
                      and not jsp.condition.excludes(node.condition)), None)
        if rival is None:
            continue
        yield finding_at_node(jsp, (
            f"{program_of(jsp)} publishes every movable joint of the description on {topic} "
            f"(at zero unless it merges a source_list), and {rival.name or program_of(rival)} "
            f"({program_of(rival)}) publishes the measured joint states on {topic} too: "
            f"robot_state_publisher takes whichever came last, so the joints' frames jump "
            f"between the two; run one publisher (drop {program_of(jsp)} where a controller "
            f"or the simulator gives joint states, or have it merge them with source_list)"),
            related=(Location(rival.path, rival.line, rival.column),))
