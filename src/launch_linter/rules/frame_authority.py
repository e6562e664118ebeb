"""A static transform for an edge that a running localization or odometry node publishes.

## What it does
Reports a static `map → odom` while a localization node runs in the same launch tree, and
a static `odom → base_link` (or `odom → base_footprint`) while an odometry node runs. The
nodes (package, executable):

- localization (publishes `map → odom`): `amcl`/`amcl`, `nav2_amcl`/`amcl` (unless
  `tf_broadcast` is false), `slam_toolbox`/any, `gmapping`/`slam_gmapping`,
  `slam_gmapping`/any, `cartographer_ros`/`cartographer_node`, `hector_mapping`/any,
  `slam_karto`/any, `karto`/any, `rtabmap_ros`/`rtabmap`, `rtabmap_slam`/`rtabmap`, and
  `robot_localization`'s `ekf_localization_node`, `ukf_localization_node`, `ekf_node`,
  `ukf_node` with `world_frame` `map`;
- odometry (publishes `odom → base`): `robot_localization`'s filters with `world_frame`
  `odom`, `rf2o_laser_odometry`/any.

A `robot_localization` filter whose `world_frame` the launch file does not give is left out:
the edge it publishes is decided by its YAML parameter file (which the linter does not read),
and the standard dual-filter setup runs one filter in `odom` and one in `map`.

The edge is the one the node's frame parameters name (`map_frame`/`global_frame_id`,
`odom_frame`/`odom_frame_id`, `base_link_frame`/`base_frame_id`/`base_frame`, with
REP 105's names by default): hector_mapping with `odom_frame` set to `base_link`
publishes `map → base_link`, not `map → odom`. A node given `publish_tf`,
`tf_broadcast` or `pub_map_odom_transform` false, or a frame parameter the linter cannot
resolve, is left out. Node and transform under
mutually exclusive conditions are not compared.

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
Node parameters are read from `<param>` (inside the node, or beside it as `NODE/param`) and
inline `<rosparam>` text only; a node
configured in a YAML file not to publish tf is still counted.
"""

from __future__ import annotations

import typing
from collections.abc import Iterator

from launch_linter.model.diagnostic import Category, Severity
from launch_linter.model.robot import UNKNOWN_VALUE, NodeRecord
from launch_linter.rules._api import Finding, RuleContext
from launch_linter.rules._tree import edges_of, finding_on

ID = "frame_authority"
CATEGORY = Category.TF
SEVERITY = Severity.WARNING

ANY = "*"
LOCALIZATION = {
    ("amcl", "amcl"), ("nav2_amcl", "amcl"), ("slam_toolbox", ANY),
    ("gmapping", "slam_gmapping"), ("slam_gmapping", ANY),
    ("cartographer_ros", "cartographer_node"), ("hector_mapping", ANY),
    ("slam_karto", ANY), ("karto", ANY), ("rtabmap_ros", "rtabmap"),
    ("rtabmap_slam", "rtabmap"),
}
ODOMETRY = {("rf2o_laser_odometry", ANY)}
FILTERS = ("ekf_localization_node", "ukf_localization_node", "ekf_node", "ukf_node")
BASES = ("base_link", "base_footprint")
Published = typing.Tuple[str, typing.Tuple[str, ...]]
"""A parent frame and the child frames it may publish."""


def _false(value: str | None) -> bool:
    return value is not None and value.strip().lower() in ("false", "0")


def _frame(node: NodeRecord, names: tuple[str, ...], default: str) -> str | None:
    """The first of the parameters ``names`` that is set, else ``default``; None when the
    one that is set has a value the linter does not know."""
    for name in names:
        value = node.param(name)
        if value is not None:
            return None if value == UNKNOWN_VALUE else value
    return default


def publishes(node: NodeRecord) -> tuple[str, Published] | None:
    """(``localization`` or ``odometry``, the edge it publishes), for the listed nodes
    whose frame parameters are known (a parameter such as hector_mapping's
    ``odom_frame`` set to the base frame moves the edge it publishes)."""
    for switch in ("publish_tf", "tf_broadcast", "pub_map_odom_transform"):
        value = node.param(switch)
        if value == UNKNOWN_VALUE or _false(value):
            return None
    what: str | None = None
    if node.package == "robot_localization" and node.executable in FILTERS:
        # Unset here usually means set in the filter's YAML: odom (odometry) or map
        # (localization) cannot be told apart, so the node is left out.
        if node.param("world_frame") is None:
            return None
        world = _frame(node, ("world_frame",), "") or None
        map_frame = _frame(node, ("map_frame",), "map")
        odom = _frame(node, ("odom_frame",), "odom")
        if world is None:
            return None
        what = "localization" if world is not None and world == map_frame else "odometry"
    else:
        for table, name in ((LOCALIZATION, "localization"), (ODOMETRY, "odometry")):
            if (node.package, node.executable) in table or (node.package, ANY) in table:
                what = name
        map_frame = _frame(node, ("map_frame", "global_frame_id"), "map")
        odom = _frame(node, ("odom_frame", "odom_frame_id"), "odom")
    if what is None or map_frame is None or odom is None:
        return None
    if what == "localization":
        return what, (map_frame, (odom,))
    base = _frame(node, ("base_link_frame", "base_frame_id", "base_frame"), "")
    if base is None:
        return None
    return what, (odom, (base,) if base else BASES)


def check(context: RuleContext) -> Iterator[Finding]:
    publishers = [(n, p) for n in context.tree.nodes if (p := publishes(n)) is not None]
    if not publishers:
        return
    for edge in edges_of(context):
        if edge.joint is not None:
            continue
        for node, (what, (parent, children)) in publishers:
            if (edge.parent != parent or edge.child not in children
                    or node.condition.excludes(edge.condition)):
                continue
            yield finding_on(
                edge,
                f"static '{edge.parent}' -> '{edge.child}' while the {what} node "
                f"{node.package}/{node.executable} ({node.path}:{node.line}) publishes it; "
                f"REP 105 gives this edge to {what} alone",
            )
            break
