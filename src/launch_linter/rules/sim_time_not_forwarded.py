"""A ROS 2 launch file passes `use_sim_time` on to some of what it starts, not to a tf node.

## What it does
Reports a ROS 2 node started by a launch file that passes its `use_sim_time` launch
configuration on under the same name (`{'use_sim_time': LaunchConfiguration(
'use_sim_time')}` to a node, `use_sim_time:=$(var use_sim_time)` to an include) when the
node is given no `use_sim_time` at all and its clock reaches tf: it sends or looks up
transforms (the knowledge base, docs/knowledge.md; RViz looks up its displays' frames at
its clock's now()) or publishes the `/joint_states` robot_state_publisher stamps the movable
joints with. The defect does not depend on the value: whatever `use_sim_time` the launch is
given, that node stays on wall time.
Left out: a node given `use_sim_time` in any way (a dictionary, a parameter file that sets
it, `SetParameter` in its scope), a node whose parameters are not all read (a
`RewrittenYaml` or a file not found may set it), composable nodes (a container's and its
components' parameters are not modelled apart), a node under a condition that excludes the
place that passes the configuration on, and a node `sim_time_mismatch` already reports
(a simulator or a node on simulated time beside it: one finding per defect).

## Why is this bad?
In ROS 2 `use_sim_time` is a parameter of each node, false by default. A launch file that
takes the argument and hands it to its other nodes and includes promises that the whole
launch follows it; the node left out runs on wall time when the launch is started with
`use_sim_time:=true` beside a simulator or `ros2 bag play --clock`: its transforms are
stamped decades away from the others, and its lookups ask for times tf does not have
("Lookup would require extrapolation into the future"). ROBOTIS-GIT/turtlebot3#456:
navigation2.launch.py passed `use_sim_time` to the nav2 bringup it includes but started
rviz2 without it.

## Example
```xml
<launch>
  <arg name="use_sim_time" default="false"/>
  <include file="$(find-pkg-share nav2_bringup)/launch/bringup_launch.py">
    <arg name="use_sim_time" value="$(var use_sim_time)"/>
  </include>
  <node pkg="rviz2" exec="rviz2"/>
</launch>
```

## Use instead
```xml
<launch>
  <arg name="use_sim_time" default="false"/>
  <include file="$(find-pkg-share nav2_bringup)/launch/bringup_launch.py">
    <arg name="use_sim_time" value="$(var use_sim_time)"/>
  </include>
  <node pkg="rviz2" exec="rviz2">
    <param name="use_sim_time" value="$(var use_sim_time)"/>
  </node>
</launch>
```

## Known problems
ROS 1 is left out: there `/use_sim_time` is one global parameter that every node reads
(roscpp's `ros::Time::init` and rospy read `/use_sim_time`), so a launch file cannot give it
to some nodes and not to others; a `<param name="use_sim_time">` inside a node's element is
the private `~use_sim_time`, which no node reads.
Only the file that passes the configuration on is searched: a node in another file of the
tree is that file's matter (it may not take the argument at all).
Info: 3 independent findings judged, all true (docs/evaluation/sim_time_judged.jsonl:
rviz2 in IGVC_ROS2's costmap test, the corpus's latest files; joint_state_publisher beside
robot_state_publisher in a course repository; rviz2 beside FAST_LIO's mapping node), on
all 5,518 corpus files and 34 whole public ROS 2 repositories nobody had used: far from
the 20 a warning needs. Where the launch is given `use_sim_time:=true`, the same node is
`sim_time_mismatch`'s (a warning) when something else in the tree runs on simulated time.
"""

from __future__ import annotations

from collections.abc import Iterator

from launch_linter.model.diagnostic import Category, Location, Severity
from launch_linter.model.launch import Forwarded
from launch_linter.model.robot import spawns_into_simulator
from launch_linter.rules._api import Finding, RuleContext
from launch_linter.rules._nodes import finding_at_node, program_of
from launch_linter.rules.sim_time_mismatch import (
    PARAMETER,
    clock_reaches_tf,
    clock_sources,
)

ID = "sim_time_not_forwarded"
CATEGORY = Category.TF
SEVERITY = Severity.INFO
EXAMPLE_PATH = "example.launch.xml"


def _passed_on(forwarded: tuple[Forwarded, ...]) -> dict[str, list[Forwarded]]:
    """The places each file passes use_sim_time on, by file."""
    by_file: dict[str, list[Forwarded]] = {}
    for place in forwarded:
        if place.name == PARAMETER and place.own:
            by_file.setdefault(place.path, []).append(place)
    return by_file


def check(context: RuleContext) -> Iterator[Finding]:
    by_file = _passed_on(context.tree.forwarded)
    if not by_file:
        return
    # A node with a clock source beside it is sim_time_mismatch's (one finding per defect).
    sources = clock_sources(context.tree)
    for node in context.tree.nodes:
        places = by_file.get(node.path)
        if (places is None or node.kind != "node" or node.ros != 2 or not node.executable
                or node.unread or node.given(PARAMETER) is not None
                or spawns_into_simulator(node)):
            continue
        place = next((p for p in places if not p.condition.excludes(node.condition)), None)
        if place is None:
            continue
        effect = clock_reaches_tf(context, node)
        if effect is None or any(s.beside(node) for s in sources):
            continue
        target = "the include" if place.kind == "include" else "a node"
        yield finding_at_node(
            node,
            f"{program_of(node)} is not given use_sim_time, which this file passes on to "
            f"{target} at line {place.line}: whatever use_sim_time the launch is given, "
            f"it stays on wall time; {effect}: pass it on here too "
            f"(use_sim_time: LaunchConfiguration('use_sim_time'))",
            related=(Location(place.path, place.line, place.column),),
        )
