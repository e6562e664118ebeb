"""An edge that inverts REP 105's chain earth -> map -> odom -> base_link.

## What it does
Reports a static transform or URDF joint whose parent comes after its child in REP 105's
chain `earth → map → odom → base_link` (with `base_footprint` in place of `base_link`),
such as `odom → map` or `base_link → odom`.

## Why is this bad?
REP 105 fixes the direction of these frames: `map` is the parent of `odom`, and `odom` of
the robot's base. Localization (amcl, slam_toolbox, robot_localization) publishes
`map → odom` and odometry publishes `odom → base_link`; an inverted edge gives one of these
frames a second parent or makes a loop, and navigation stacks that look up `map → base_link`
fail.

## Example
```xml
<launch>
  <node pkg="tf2_ros" type="static_transform_publisher" name="odom_map"
        args="0 0 0 0 0 0 odom map"/>
</launch>
```

## Use instead
```xml
<launch>
  <node pkg="tf2_ros" type="static_transform_publisher" name="map_odom"
        args="0 0 0 0 0 0 map odom"/>
</launch>
```

## Known problems
Reported at info: on the judged corpus sample 7 of 18 were defects (the inverted edge beside
amcl, gmapping or an odometry publisher); most others are identity placeholders (`odom → map`
standing in for localization) that nothing else publishes, where the inversion does no harm.
"""

from __future__ import annotations

from collections.abc import Iterator

from launch_linter.model.diagnostic import Category, Severity
from launch_linter.rules._api import Finding, RuleContext
from launch_linter.rules._tree import finding_on, written_edges

ID = "rep105_order"
CATEGORY = Category.TF
SEVERITY = Severity.INFO

CHAIN = {"earth": 0, "map": 1, "odom": 2, "base_link": 3, "base_footprint": 3}


def check(context: RuleContext) -> Iterator[Finding]:
    for edge in written_edges(context):
        parent, child = CHAIN.get(edge.parent), CHAIN.get(edge.child)
        if parent is None or child is None or parent <= child:
            continue
        yield finding_on(
            edge,
            f"'{edge.parent}' -> '{edge.child}' inverts REP 105's chain "
            f"earth -> map -> odom -> base_link: '{edge.child}' should be the parent of "
            f"'{edge.parent}'",
        )
