"""A ROS 2 node on wall time in a tree that spawns a robot into a simulator.

## What it does
Reports a ROS 2 node that sends or looks up tf (as the knowledge base knows it,
docs/knowledge.md) and runs on wall time, `use_sim_time` neither given nor set by
`SetParameter`, or given false, in a launch tree that spawns a robot into Gazebo
(`gazebo_ros spawn_entity.py`, `ros_gz_sim create`): the simulator then publishes
`/clock`, and the simulated sensors, plugins and controllers stamp their data with it.
Nodes whose parameters are not all read and nodes under a condition that excludes the
spawner's are left out, and so is robot_state_publisher: it stamps movable joints with
the stamps of the `/joint_states` it reads, and fixed joints go to `/tf_static`, whose
stamps tf ignores (robot_state_publisher.cpp, rolling e0f77e6, lines 288-356).

## Why is this bad?
In ROS 2 every node has its own clock: `use_sim_time` is a parameter of each node,
false by default. A node on wall time beside a simulator stamps its transforms about
fifty years after the simulated ones and asks tf for transforms at the wall time:
"Lookup would require extrapolation into the future", costmaps and localization that
never start, an EKF that drops every measurement as too old.

## Example
```xml
<launch>
  <node pkg="gazebo_ros" exec="spawn_entity.py" args="-topic robot_description -entity r"/>
  <node pkg="nav2_amcl" exec="amcl" name="amcl"/>
</launch>
```

## Use instead
```xml
<launch>
  <node pkg="gazebo_ros" exec="spawn_entity.py" args="-topic robot_description -entity r"/>
  <node pkg="nav2_amcl" exec="amcl" name="amcl">
    <param name="use_sim_time" value="true"/>
  </node>
</launch>
```

## Known problems
ROS 1 is left out: there `/use_sim_time` is one global parameter, which gazebo_ros's
`empty_world.launch` sets true by default, and that include is usually not followed
(gazebo_ros is not in the workspace). A simulator started by a separate launch file, or
`ros2 bag play --clock` in a terminal, is not seen: the rule then stays silent.
Reported at info until measured: no finding on the 1,592 latest corpus files nor on 29
whole repositories and nav2_bringup, whose 20 ROS 2 trees that spawn a robot run 3 nodes
that send or look up tf, all on simulated time; nothing to judge yet
(docs/evaluation/tree_judged.jsonl).
"""

from __future__ import annotations

from collections.abc import Iterator

from launch_linter.knowledge.publish import truth
from launch_linter.model.diagnostic import Category, Location, Severity
from launch_linter.model.robot import UNKNOWN_VALUE, NodeRecord, spawns_into_simulator
from launch_linter.rules._api import Finding, RuleContext
from launch_linter.rules._nodes import entry_of, finding_at_node, program_of

ID = "sim_time_mismatch"
CATEGORY = Category.TF
SEVERITY = Severity.INFO
EXAMPLE_PATH = "example.launch.xml"
PARAMETER = "use_sim_time"


def _wall_time(node: NodeRecord) -> bool | None:
    """Whether the node runs on wall time (None: unknown)."""
    given = node.given(PARAMETER)
    if given is None:
        return None if node.unread else True
    if given == UNKNOWN_VALUE:
        return None
    value = truth(given)
    return None if value is None else not value


def check(context: RuleContext) -> Iterator[Finding]:
    nodes = context.tree.nodes
    spawners = [n for n in nodes if spawns_into_simulator(n) and n.ros == 2]
    if not spawners:
        return
    for node in nodes:
        if node.kind != "node" or node.ros != 2 or spawns_into_simulator(node):
            continue
        entry = entry_of(context, node)
        if entry is None or not (entry.publishes or entry.looks_up):
            continue
        together = [s for s in spawners if not s.condition.excludes(node.condition)]
        if not together or not _wall_time(node):
            continue
        spawner = together[0]
        program = program_of(node)
        how = ("is given use_sim_time false" if node.given(PARAMETER) is not None
               else "is not given use_sim_time")
        yield finding_at_node(
            node,
            f"{program} {how}: it runs on wall time while {spawner.package}/"
            f"{spawner.executable} ({spawner.path}:{spawner.line}) spawns the robot into "
            f"a simulator that publishes /clock; its tf stamps and lookups miss the "
            f"simulated ones: set use_sim_time to true",
            related=(Location(spawner.path, spawner.line, spawner.column),),
        )
