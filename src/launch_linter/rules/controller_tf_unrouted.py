"""A ros2_control controller that sends its odometry transform on a topic nothing brings to /tf.

## What it does
Reports a ROS 2 controller that a spawner of the tree starts and whose odometry transform
goes to a topic of its own, when no remapping of its process brings that topic to `/tf`:
the ackermann, bicycle and tricycle steering controllers (steering_controllers_library)
and mecanum_drive_controller publish `odom -> base_link` on `<controller>/tf_odometry`
(knowledge `tf_topic`). It looks at every
place the controller is loaded from (the controller manager node's `remappings=`, a
simulator plugin's `<ros><remapping>`, a spawner's `--controller-ros-args`), reports at the
controller's load site, and says nothing when a rule there brings the topic to `/tf` (or a
namespaced `…/tf`), when one of them is not resolved, when a relay may republish it (a
topic_tools node, or any node given a `tf_odometry` name), or when another publisher of the
tree sends the same edge (then the controller's copy is simply unused).

## Why is this bad?
Unlike diff_drive_controller (`/tf`), steering_controllers_library creates its transform
publisher on `~/tf_odometry` (ros2_controllers steering_controllers_library.cpp, humble
ad559d9 172-173, master 94e74de 314-315; mecanum_drive_controller.cpp 212-213), so with
`enable_odom_tf: true` the transform is sent where no tf listener reads it: the odometry
topic comes through but `odom` is missing from the tree, and everything looking up
`odom -> base_link` (navigation, SLAM, RViz) fails. ros-controls/gz_ros2_control#504: "the
odom frame was not present in the TF tree ... although the odometry data was published as
a topic", fixed by remapping the topic to `/tf` (#506); ros-controls/ros2_controllers#762.

## Example
```xml
<launch>
  <node pkg="controller_manager" exec="ros2_control_node">
    <param from="$(dirname)/controllers.yaml"/>
  </node>
  <node pkg="controller_manager" exec="spawner" args="ackermann_steering_controller"/>
</launch>
```

```yaml
controller_manager:
  ros__parameters:
    ackermann_steering_controller:
      type: ackermann_steering_controller/AckermannSteeringController
```

## Use instead
```xml
<launch>
  <node pkg="controller_manager" exec="ros2_control_node">
    <param from="$(dirname)/controllers.yaml"/>
    <remap from="/ackermann_steering_controller/tf_odometry" to="/tf"/>
  </node>
  <node pkg="controller_manager" exec="spawner" args="ackermann_steering_controller"/>
</launch>
```

```yaml
controller_manager:
  ros__parameters:
    ackermann_steering_controller:
      type: ackermann_steering_controller/AckermannSteeringController
```

## Known problems
ROS 2 only. A controller only named in the manager's file, with no spawner in the tree (a
bringup split over several launch commands), is not judged; neither is any controller of
a tree whose spawner arguments are not all resolved. `SetRemap` actions are not read: a
launch file that routes the topic that way is reported. A relay of the user's own that
names the topic in its code, not in a parameter, is not seen. The controller manager of
jazzy warns that remappings given to it are deprecated in favour of the spawner's
`--controller-ros-args`; both are read.
"""

from __future__ import annotations

from collections.abc import Iterator

from launch_linter.knowledge.publish import published
from launch_linter.model.diagnostic import Category, Location, Severity
from launch_linter.rules._api import Finding, RuleContext
from launch_linter.rules._nodes import (
    entry_of,
    finding_at_node,
    nodes_of,
    program_of,
    routes_of,
)
from launch_linter.rules._tf_topics import LOST, own_topic

ID = "controller_tf_unrouted"
CATEGORY = Category.TF
SEVERITY = Severity.WARNING
EXAMPLE_PATH = "example.launch.xml"
EXAMPLE_INCLUDED = "controllers.yaml"
SWITCH = "enable_odom_tf"


def check(context: RuleContext) -> Iterator[Finding]:
    if not context.tree.spawned:
        return  # no controller is started here, or a spawner's words are not all read
    spawned = set(context.tree.spawned)
    lost = {key for key, way in routes_of(context).items() if way == LOST and key[0] in spawned}
    if not lost:
        return
    view = nodes_of(context)
    sent = {(edge.parent, edge.child) for edge in view.edges}
    reported: set[tuple[str | None, str | None]] = set()
    for node in context.tree.nodes:
        key = (node.name, node.namespace)
        if node.kind != "controller" or key not in lost or key in reported:
            continue
        entry = entry_of(context, node)
        if entry is None:
            continue
        edges = [e.signature for e in published(entry, node, distro=context.distro)[0]
                 if e.signature is not None]
        if not edges or any(edge in sent for edge in edges):
            continue  # nothing sent, or another publisher gives the tree that edge
        reported.add(key)
        parent, child = edges[0]
        topic = own_topic(entry, node)
        where = node.where_set(SWITCH)
        related = () if where is None else (Location(*where),)
        message = (
            f"{node.name} ({program_of(node)}) sends {parent} -> {child} on {topic}, and no "
            f"remapping brings that topic to /tf: the odometry transform never reaches the "
            f"tree ({parent} is missing for everything that looks it up); remap it where the "
            f"controller runs (the controller manager's remappings, the simulator plugin's "
            f"<ros><remapping>, or the spawner's --controller-ros-args "
            f"\"-r {topic}:=/tf\")")
        yield finding_at_node(node, message, related)
