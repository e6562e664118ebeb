"""An edge of the tf tree that a node publishes and something else publishes too.

## What it does
Reports a parent → child edge that a launched node publishes at run time (by the knowledge
base, docs/knowledge.md: its parameters and defaults) when another source of the same tree
publishes it as well: a second node (amcl and a robot_localization filter both sending
`map → odom`; diff_drive_controller or Gazebo's diff-drive plugin and an EKF both sending
`odom → base_link`), a joint of the robot description that robot_state_publisher sends (a
camera driver with `publish_tf` on beside the URDF's camera joints), or a static transform
for an edge that is not REP 105's localization or odometry edge (those are
`frame_authority`'s). It also reports two ROS 2 `robot_state_publisher`s of one namespace
and one `frame_prefix` whose descriptions share joints. The finding is at the second
publisher; sources under mutually exclusive conditions are not compared. One launch line
run through two different includes (a file that starts robot_state_publisher included by
both the spawn and the controller launch files) is two publishers: the finding is then at
the second of the two includes, with the first include and the node's line as related
places.

## Why is this bad?
tf2 keeps one transform per edge: two publishers overwrite each other and the frame jumps
between their values (for odometry, between two estimates of the robot's pose). The usual
fix is to switch one off (`publish_tf: false`, `enable_odom_tf: false`, the driver's
`publish_tf:=false`) or to remove the duplicate joint.

## Example
```xml
<launch>
  <node pkg="amcl" type="amcl" name="amcl"/>
  <node pkg="robot_localization" type="ekf_localization_node" name="ekf_map">
    <param name="world_frame" value="map"/>
    <param name="pose0" value="gps/pose"/>
  </node>
</launch>
```

## Use instead
```xml
<launch>
  <node pkg="amcl" type="amcl" name="amcl">
    <param name="tf_broadcast" value="false"/>
  </node>
  <node pkg="robot_localization" type="ekf_localization_node" name="ekf_map">
    <param name="world_frame" value="map"/>
    <param name="pose0" value="gps/pose"/>
  </node>
</launch>
```

## Known problems
Each finding says whether it is *proven*: both publishers known and every parameter that
switches their publishing read (set in the launch and parameter files the linter read, or
left at the node's documented default with no unread parameter source). A finding that
rests on a default an unread parameter file may change (PyYAML absent, a file missing, an
unresolved substitution, parameters built in Python) is reported at info and names the
node, the parameters and the file. A proven finding is an error: the tree the robot runs
is wrong (one edge with two values), and proof is what the severity policy asks of an
error. On 95 whole public repositories (2,196 launch files) the rule gave 24 findings;
the proven ones were 10 true of 14, and 10 of 10 once the false and harmless causes found
there were fixed (a filter with no input publishes nothing; realsense's alternative
drivers; a root only ``roslaunch_add_file_check`` parses)
(docs/evaluation/duplicate_publisher.md). The corpus's 5,518 distinct files give 1 finding
(true). A root that only ``roslaunch_add_file_check`` parses is not one running
system and is left out. One line run twice is reported only when the two runs come through
different include actions into one namespace (robots told apart by namespace are
`robot_frame_collision`'s), and proven only when both includes run unconditionally; runs
that share their whole include chain (a Python loop over one include) may be the linter's
own reading twice and are never reported. In ROS 1 one node line run twice in one
namespace is a duplicate node name, which roslaunch refuses (`roslaunch_error`).
"""

from __future__ import annotations

from collections.abc import Iterator

from launch_linter.knowledge import PLACEHOLDER, condition_parameters
from launch_linter.model.diagnostic import Category, Severity
from launch_linter.model.record import replace
from launch_linter.rules._api import Finding, RuleContext
from launch_linter.rules._nodes import (
    AUTHORITIES,
    NodeEdge,
    finding_at_node,
    nodes_of,
    program_of,
    rivals,
)
from launch_linter.rules._tree import edges_of, finding_on
from launch_linter.rules._twins import at_second_run, twin_descriptions, unproven_runs

ID = "duplicate_publisher"
CATEGORY = Category.TF
SEVERITY = Severity.ERROR
MAX_NAMED_PARAMETERS = 4
PROVEN = "both publishers known and their parameters read"
"""Said at the end of a proven finding (the rule's level); an unproven one says instead
which parameter file was not read and is reported at info."""


def _switches(edge: NodeEdge) -> list[str]:
    """The parameters that decide whether and what ``edge`` publishes: its conditions'
    names and the frame parameters of its templates, in the knowledge base's order."""
    names: list[str] = []
    spec = edge.spec
    if spec is None:
        return names
    words = [w for c in spec.when for w in condition_parameters(c)]
    words += PLACEHOLDER.findall(spec.parent) + PLACEHOLDER.findall(spec.child)
    for name in words:
        if name and name not in names:
            names.append(name)
    return names


def unproven(edge: NodeEdge) -> str | None:
    """Why ``edge`` is not proven (None when it is): it rests on defaults that a parameter
    file of the node the linter did not read may change; names the file and parameters."""
    if not edge.assumed:
        return None
    node = edge.node
    defaults = [n for n in _switches(edge) if node.given(n) is None][:MAX_NAMED_PARAMETERS]
    what = ", ".join(f"'{n}'" for n in defaults) or "its parameters"
    why = node.unread[0] if node.unread else "a parameter source was not read"
    return (f"{program_of(node)} ({node.path}:{node.line}) is assumed to keep its default "
            f"{what}: {why}")


def _evidence(found: Finding, *edges: NodeEdge) -> Finding:
    """``found`` with its proof said: proven at the rule's level, else info naming what
    was not read."""
    reasons = [r for r in (unproven(e) for e in edges) if r is not None]
    if len(edges) == 2:
        runs = unproven_runs(edges[0].node, edges[1].node)
        if runs is not None:
            reasons.append(runs)
    if not reasons:
        return replace(found, message=f"{found.message} ({PROVEN})")
    return replace(found, message=f"{found.message} (not proven: {'; '.join(reasons)})",
                   severity=Severity.INFO)


def check(context: RuleContext) -> Iterator[Finding]:
    if context.tree.parse_check_only:
        # Only parsed by roslaunch_add_file_check, never started: not one running system.
        return
    yield from twin_descriptions(context.tree)
    view = nodes_of(context)
    if not view.edges:
        return
    by_edge: dict[tuple[str, str], list[NodeEdge]] = {}
    for node_edge in view.edges:
        key = (node_edge.parent, node_edge.child)
        earlier = by_edge.setdefault(key, [])
        other = next((e for e in earlier if rivals(e, node_edge)), None)
        earlier.append(node_edge)
        if other is not None:
            yield _evidence(at_second_run(
                node_edge.node, other.node,
                f"'{node_edge.parent}' -> '{node_edge.child}' is published by "
                f"{node_edge.describe()} and by {other.describe()}; tf2 keeps whichever "
                f"arrives last: switch one of them off",
            ), node_edge, other)
    for edge in edges_of(context):
        for node_edge in by_edge.get((edge.parent, edge.child), ()):
            if node_edge.node.condition.excludes(edge.condition):
                continue
            if edge.joint is not None:
                yield _evidence(finding_at_node(
                    node_edge.node,
                    f"'{edge.parent}' -> '{edge.child}' is published by "
                    f"{node_edge.describe()} and by the {edge.describe()} that "
                    f"robot_state_publisher sends; tf2 keeps whichever arrives last",
                    (edge.location,),
                ), node_edge)
            elif node_edge.role not in AUTHORITIES:
                found = finding_on(
                    edge,
                    f"static '{edge.parent}' -> '{edge.child}' while {node_edge.describe()} "
                    f"publishes it; tf2 keeps whichever arrives last",
                )
                yield _evidence(replace(found, related=(node_edge.location,)), node_edge)
            break
