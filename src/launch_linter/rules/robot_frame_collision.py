"""Several robots in one tree whose robot_state_publishers publish the same frames.

## What it does
Reports a launch tree with two or more robot descriptions published by
`robot_state_publisher`s of different namespaces (the same robot launch file included once
per robot, or two robots' files) when the descriptions share frame names and no
`frame_prefix` (ROS 2) or `tf_prefix` (ROS 1) separates them. The finding is at the
second description's launch element and names the shared frames. It also reports one edge
sent by known nodes or simulator plugins of different namespaces after each one's own
prefix (each robot's Gazebo diff-drive plugin sending `odom → base_footprint`), at the
second publisher.

## Why is this bad?
A namespace renames topics, not tf frames: every robot_state_publisher sends
`base_link → laser` under the same names, so the robots' frames overwrite each other in
the one tf tree and every robot is drawn (and localized) wherever the last message put it.
Give each robot its own frame prefix (`frame_prefix: robot1/`), or prefix the links in
the description.

## Example
```xml
<launch>
  <group ns="robot1">
    <param name="robot_description" value="&lt;robot name='r'&gt;
      &lt;joint name='j' type='fixed'&gt;&lt;parent link='base_link'/&gt;
      &lt;child link='laser'/&gt;&lt;/joint&gt;&lt;/robot&gt;"/>
    <node pkg="robot_state_publisher" type="robot_state_publisher" name="rsp"/>
  </group>
  <group ns="robot2">
    <param name="robot_description" value="&lt;robot name='r'&gt;
      &lt;joint name='j' type='fixed'&gt;&lt;parent link='base_link'/&gt;
      &lt;child link='laser'/&gt;&lt;/joint&gt;&lt;/robot&gt;"/>
    <node pkg="robot_state_publisher" type="robot_state_publisher" name="rsp"/>
  </group>
</launch>
```

## Use instead
```xml
<launch>
  <group ns="robot1">
    <param name="tf_prefix" value="robot1"/>
    <param name="robot_description" value="&lt;robot name='r'&gt;
      &lt;joint name='j' type='fixed'&gt;&lt;parent link='base_link'/&gt;
      &lt;child link='laser'/&gt;&lt;/joint&gt;&lt;/robot&gt;"/>
    <node pkg="robot_state_publisher" type="robot_state_publisher" name="rsp"/>
  </group>
  <group ns="robot2">
    <param name="tf_prefix" value="robot2"/>
    <param name="robot_description" value="&lt;robot name='r'&gt;
      &lt;joint name='j' type='fixed'&gt;&lt;parent link='base_link'/&gt;
      &lt;child link='laser'/&gt;&lt;/joint&gt;&lt;/robot&gt;"/>
    <node pkg="robot_state_publisher" type="robot_state_publisher" name="rsp"/>
  </group>
</launch>
```

## Known problems
An error: robots overwriting each other's frames is a wrong tree, and the finding needs
proof (both descriptions read, every prefix parameter read; a prefix whose value the
linter cannot resolve counts as a prefix). Its false findings judged so far (17 of 18)
had the two causes below, now silent; on 38 whole public multi-robot repositories nobody
had used it then found nothing, the prefixes being right
(docs/evaluation/tree_judged.jsonl, docs/evaluation/multi-robot-trial.md). Two
publishers of one edge written as two launch elements are `duplicate_publisher`'s; this
rule takes the edge of one element run once per robot (a spawn file included per robot,
a plugin in the description each robot spawns). It says nothing
about a tree roslaunch refuses (husky's multi-robot playpen passes an argument its spawn
file no longer declares) or a root that its package only hands to
`roslaunch_add_file_check` and never installs (abb's and universal_robot's
`tests/roslaunch_test*.xml`: one group per launch file, only parsed), nor about a
description a ROS 2 node other than robot_state_publisher is given (joint_state_publisher
reads it to list the joints and publishes `/joint_states`, never tf: its copy, beside the
robot_state_publisher of the same robot, is no second robot). A prefix whose value
the linter cannot resolve counts as a prefix (the rule stays silent). Only the parameter the
node's ROS version reads counts: ROS 1 robot_state_publisher ignores a `frame_prefix`
(ros/robot_state_publisher#192) and finds `tf_prefix` from its private namespace up; ROS 2's
has no `tf_prefix`, and no `frame_prefix` before 2.5.0 (dashing, eloquent). ROS 1 gazebo_ros
drive plugins (diff-drive, skid-steer, planar-move) prefix their `odom → base` edge with the
`tf_prefix` found from the robot's namespace (theirs, else spawn_model's), not with one given
to robot_state_publisher only; ROS 2 plugins prefix nothing. Robots started one launch
command each (a spawn file run per robot) are separate trees: never compared.
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import Tuple

from launch_linter.model.diagnostic import Category, Location, Severity
from launch_linter.model.launch import LaunchTree
from launch_linter.model.robot import DescriptionSource, NodeRecord, RobotJoint
from launch_linter.rules._api import Finding, RuleContext, summarised_lazily
from launch_linter.rules._nodes import NodeEdge, finding_at_node, nodes_of
from launch_linter.rules._prefixes import PUBLISHER, publisher_prefix

ID = "robot_frame_collision"
CATEGORY = Category.TF
SEVERITY = Severity.ERROR
REFUSED = "roslaunch_error"


def _prefixed(node: NodeRecord, distro: str | None = None) -> bool:
    """Whether robot_state_publisher ``node`` prefixes its frames, or may (unknown)."""
    return publisher_prefix(node, distro) != ""


def check(context: RuleContext) -> Iterator[Finding]:
    tree = context.tree
    if tree.parse_check_only or any(p.rule == REFUSED for p in tree.problems):
        # Not one running system: a test only parses the root, or roslaunch refuses the
        # whole tree (that refusal is reported on its own).
        return
    yield from _descriptions(tree, context.distro)
    yield from _node_edges(context)


def _descriptions(tree: LaunchTree, distro: str | None) -> Iterator[Finding]:
    """The same URDF frames from robot_state_publishers of different namespaces."""
    publishers = [n for n in tree.nodes if n.package == PUBLISHER and n.kind == "node"]
    namespaces = {n.namespace for n in publishers}
    if len(publishers) < 2 or len(namespaces) < 2 or None in namespaces:
        return
    if any(_prefixed(n, distro) for n in publishers):
        return
    by_source: dict[int, list[RobotJoint]] = {}
    sources: list[DescriptionSource] = []
    unpublished = _given_to_other_programs(tree)
    for joint in tree.joints:
        if _site(joint.source) in unpublished:
            continue
        # Joints come per description entry: the same entry (an include per robot) twice
        # is two entries of equal value, told apart by position.
        if not sources or sources[-1] is not joint.source:
            sources.append(joint.source)
        by_source.setdefault(len(sources) - 1, []).append(joint)
    if len(by_source) < 2:
        return
    first = {j.child: j for j in by_source[0] if j.child is not None}
    for index in range(1, len(by_source)):
        shared = [j for j in by_source[index] if j.child in first
                  and not j.condition.excludes(first[j.child].condition)]
        if not shared:
            continue
        source = sources[index]
        names = sorted({j.child for j in shared if j.child is not None})
        listed = ", ".join(summarised_lazily((f"'{n}'" for n in names), len(names)))
        earlier = sources[0]
        if (earlier.path, earlier.line) == (source.path, source.line):
            # One launch file included once per robot: name the other robot, not the line.
            other = (f"this same description included for namespace '{earlier.namespace}'"
                     if earlier.namespace else "this same description included again")
        else:
            other = f"the one at {earlier.path}:{earlier.line}"
        message = (f"this robot description publishes {listed} under the same names as "
                   f"{other}, from "
                   f"robot_state_publishers in different namespaces; tf frames are not "
                   f"namespaced: give each robot a frame_prefix (ROS 2) or tf_prefix "
                   f"(ROS 1)")
        publisher = _publisher_of(source, publishers)
        if publisher is None:
            yield Finding(path=source.path, line=source.line, column=source.column,
                          message=message)
        else:
            # At the publisher, where the prefix is missing; the description beside it.
            yield finding_at_node(publisher, message,
                                  related=(Location(source.path, source.line, source.column),))


Site = Tuple[str, int, int, Tuple[Location, ...]]


def _site(source: DescriptionSource) -> Site:
    return source.path, source.line, source.column, source.included_at


def _given_to_other_programs(tree: LaunchTree) -> set[Site]:
    """Where a ROS 2 node other than robot_state_publisher is given a robot_description
    (a launch_ros ``Node`` is given its parameters at its own element): the description
    is that node's copy (joint_state_publisher's, ros2_control_node's), not frames it
    publishes; the same description given to robot_state_publisher at that element
    still counts."""
    def at(node: NodeRecord) -> Site:
        return node.path, node.line, node.column, node.included_at

    nodes = [n for n in tree.nodes if n.kind == "node"]
    publishing = {at(n) for n in nodes if n.package == PUBLISHER}
    return {at(n) for n in nodes if n.package != PUBLISHER} - publishing


def _publisher_of(source: DescriptionSource,
                  publishers: list[NodeRecord]) -> NodeRecord | None:
    """The one robot_state_publisher that reads ``source`` by its relative name (a ROS 1
    ``robot_description`` set in the publisher's namespace); None when not one."""
    if source.namespace is None:
        return None
    found = [n for n in publishers
             if (n.namespace or "").strip("/") == source.namespace.strip("/")]
    return found[0] if len(found) == 1 else None


def _node_edges(context: RuleContext) -> Iterator[Finding]:
    """One edge, after each publisher's own prefix, from known nodes or simulator plugins
    of different namespaces (one plugin block of a description spawned once per robot)."""
    first: dict[tuple[str, str], NodeEdge] = {}
    for edge in nodes_of(context).edges:
        namespace = edge.node.namespace
        if edge.assumed or namespace is None:
            continue
        key = (edge.parent, edge.child)
        seen = first.get(key)
        if seen is None:
            first[key] = edge
            continue
        other = seen.node.namespace or ""
        if (other.strip("/") == namespace.strip("/") or seen.location != edge.location
                or seen.node.condition.excludes(edge.node.condition)):
            # Two elements publishing one edge are duplicate_publisher's finding.
            continue
        yield finding_at_node(
            edge.node,
            f"{edge.describe()} in namespace '{namespace}' publishes {edge.parent} -> "
            f"{edge.child}, the same edge as {seen.describe()} in namespace '{other}': "
            f"tf frames are not namespaced, so the robots overwrite each other's "
            f"{edge.child}; give each robot its own frame names"
            + (" (a tf_prefix set in the robot's namespace, where the plugin finds it)"
               if edge.node.kind == "gazebo_plugin" and edge.node.ros == 1 else ""),
            related=(seen.location,))
        first[key] = edge
