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
  `odom` or unset (its default), `rf2o_laser_odometry`/any, `laser_scan_matcher`/any.

A node given `publish_tf` (or `tf_broadcast`) false is left out. Node and transform under
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
Node parameters are read from `<param>` and inline `<rosparam>` text only; a node
configured in a YAML file not to publish tf is still counted.
"""

from __future__ import annotations

from collections.abc import Iterator

from launch_linter.model.diagnostic import Category, Diagnostic, Severity
from launch_linter.model.robot import NodeRecord
from launch_linter.rules._api import RuleContext
from launch_linter.rules._tree import diagnostic_on, tree_edges

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
ODOMETRY = {("rf2o_laser_odometry", ANY), ("laser_scan_matcher", ANY)}
FILTERS = ("ekf_localization_node", "ukf_localization_node", "ekf_node", "ukf_node")
BASES = ("base_link", "base_footprint")


def _false(value: str | None) -> bool:
    return value is not None and value.strip().lower() in ("false", "0")


def role(node: NodeRecord) -> str | None:
    """``map`` or ``odom``: the edge this node publishes, if it is one of the list."""
    if _false(node.param("publish_tf")) or _false(node.param("tf_broadcast")):
        return None
    if node.package == "robot_localization" and node.executable in FILTERS:
        world = node.param("world_frame") or node.param("odom_frame") or "odom"
        return "map" if world == (node.param("map_frame") or "map") else "odom"
    for table, name in ((LOCALIZATION, "map"), (ODOMETRY, "odom")):
        if (node.package, node.executable) in table or (node.package, ANY) in table:
            return name
    return None


def check(context: RuleContext) -> Iterator[Diagnostic]:
    nodes = [(n, role(n)) for n in context.tree.nodes]
    publishers = [(n, r) for n, r in nodes if r is not None]
    if not publishers:
        return
    for edge in tree_edges(context.tree):
        if edge.joint is not None:
            continue
        wanted = "map" if (edge.parent, edge.child) == ("map", "odom") else (
            "odom" if edge.parent == "odom" and edge.child in BASES else None)
        if wanted is None:
            continue
        for node, publishes in publishers:
            if publishes != wanted or node.condition.excludes(edge.condition):
                continue
            what = "localization" if wanted == "map" else "odometry"
            yield diagnostic_on(
                ID, CATEGORY, SEVERITY, edge,
                f"static '{edge.parent}' -> '{edge.child}' while the {what} node "
                f"{node.package}/{node.executable} ({node.path}:{node.line}) publishes it; "
                f"REP 105 gives this edge to {what} alone",
            )
            break
