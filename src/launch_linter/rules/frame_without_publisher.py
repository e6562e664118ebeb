"""A frame a node looks up that nothing in the tree publishes.

## What it does
Reports a frame that a launched node looks up by a frame parameter (a costmap's
`global_frame` and `robot_base_frame`, amcl's `base_frame_id`, a filter's `base_link_frame`,
… as the knowledge base names them, docs/knowledge.md) when no edge of the tree has that
frame at either end: no static transform, no URDF joint that robot_state_publisher sends,
no edge a node publishes. The finding is at the node.

This needs a *closed* tree: one where every launched node is in the knowledge base and its
edges are known. When a node the knowledge base does not know is launched (it may publish
tf), or a known node's edges cannot be worked out, the rule says so once per tree, naming
that node and the frames it could not account for.

In a closed tree each missing frame is said with what decides whether anything else may
publish it. The tree *brings up the whole robot* for the node when a robot_state_publisher
of a description read completely, an odometry source the knowledge base knows (its
frames read) and, for a global frame (a parameter named `global`, `map`, `world` or
`fixed`), a localization all run whenever the node does: then the message names them, and
no launch started beside it is left to give the frame. Otherwise it names what is missing
(no robot_state_publisher, a description not read completely, no odometry source, no
localization), the frame of a movable joint while no node is known to publish
`/joint_states` (robot_state_publisher then sends no such frame), or a default frame of a
sensor driver the knowledge base knows and the tree does not start.

## Why is this bad?
A lookup of a frame that nobody publishes fails forever: the costmap waits for its
transform, amcl drops every scan, the filter ignores its inputs. Usually the parameter
names a frame the robot calls otherwise (`base_link` against `base_footprint`), or the
node that publishes it was left out.

## Example
```xml
<launch>
  <node pkg="tf2_ros" type="static_transform_publisher" name="base"
        args="0 0 0 0 0 0 odom base_footprint"/>
  <node pkg="gmapping" type="slam_gmapping" name="gmapping"/>
</launch>
```

## Use instead
```xml
<launch>
  <node pkg="tf2_ros" type="static_transform_publisher" name="base"
        args="0 0 0 0 0 0 odom base_footprint"/>
  <node pkg="gmapping" type="slam_gmapping" name="gmapping">
    <param name="base_frame" value="base_footprint"/>
  </node>
</launch>
```

## Known problems
Reported at info, the whole-robot findings too. A launch tree is not the whole running
system: on the corpus all 84 findings of an earlier sample (docs/evaluation/tree_judged.jsonl)
and, on whole repositories, all 53 findings judged in closed trees
(docs/evaluation/frame_without_publisher.md) were navigation or mapping launch files meant
to run beside a robot bringup started on its own, which publishes the frame; none of these
trees brings up the whole robot. Trees that do were found in one repository of 56 (4
trees) and none in the corpus, and no frame was missing in them: with no judged
whole-robot finding, that level stays info (`WHOLE_ROBOT_LEVEL`) until a sample of 20 or
more reaches 90%. A simulator spawn without a robot_state_publisher, and gz-sim systems,
do not make a whole robot (their plugins' edges are not read). Trees with a node the
knowledge base does not know are open.
"""

from __future__ import annotations

from collections.abc import Iterator

from launch_linter.model.diagnostic import Category, Severity
from launch_linter.model.record import replace
from launch_linter.rules._api import Finding, RuleContext, summarised_lazily
from launch_linter.rules._nodes import finding_at_node, finding_at_param, nodes_of, program_of
from launch_linter.rules._tree import edges_of
from launch_linter.rules._whole_robot import is_global, outside_frame, whole_robot

ID = "frame_without_publisher"
CATEGORY = Category.TF
SEVERITY = Severity.INFO
WHOLE_ROBOT_LEVEL = Severity.INFO
"""The level of a frame missing from a tree that brings up the whole robot: info until a
judged sample of such findings (docs/evaluation/frame_without_publisher.md) shows the
warning bar (90% on 20 or more)."""


def _info(finding: Finding) -> Finding:
    return replace(finding, severity=Severity.INFO)


def check(context: RuleContext) -> Iterator[Finding]:
    view = nodes_of(context)
    if not view.lookups:
        return
    frames: set[str] = set()
    for edge in edges_of(context):
        frames.update((edge.parent, edge.child))
    for node_edge in view.edges:
        frames.update((node_edge.parent, node_edge.child))
    missing = [lookup for lookup in view.lookups if lookup.frame.lstrip("/") not in frames]
    if not missing:
        return
    opener = view.open_because
    if opener is not None:
        names = sorted({lookup.frame for lookup in missing})
        listed = ", ".join(summarised_lazily((f"'{n}'" for n in names), len(names)))
        first = missing[0].node
        yield _info(finding_at_node(
            first,
            f"no publisher in this tree gives {listed}, which nodes look up; the tree is "
            f"open: {program_of(opener)} ({opener.path}:{opener.line}) may publish tf "
            f"(the knowledge base does not tell its edges)",
        ))
        return
    for lookup in missing:
        said = (f"{program_of(lookup.node)} looks up '{lookup.frame}' (parameter "
                f"'{lookup.param}'), which no static transform, URDF joint or node of this "
                f"tree publishes")
        outside = outside_frame(context, lookup.frame)
        if outside is not None:
            yield _info(finding_at_param(lookup.node, lookup.param, f"{said}: {outside}"))
            continue
        reason, publishers = whole_robot(context, lookup.node, is_global(lookup.param))
        if reason is None:
            yield replace(finding_at_param(
                lookup.node, lookup.param,
                f"{said}, and this tree brings up the whole robot: {publishers}"),
                severity=WHOLE_ROBOT_LEVEL)
        else:
            yield _info(finding_at_param(lookup.node, lookup.param, f"{said} ({reason})"))
