"""A node's frame parameter with a leading slash, where the node hands the frame to tf2.

## What it does
Reports a frame parameter given to a node (`global_frame`, `odom_frame_id`,
`base_link_frame`, a map's `frame_id`, a costmap observation source's `sensor_frame`, … as
the knowledge base names them, docs/knowledge.md) whose value starts with `/`, and a frame
prefix that does (robot_state_publisher's `frame_prefix`: every frame it publishes then
starts with `/`).
ROS 2 nodes are checked unless their source strips the slash. A ROS 1 node is checked
only where the knowledge base says from which release its frames reach tf2 as written
(move_base's costmaps and map_server from Melodic; Kinetic's costmaps resolved the slash
with tf 1): a warning when the target distribution (`--ros-distro`) is that release or
later, info when it is not known. The nodes' own defaults are not reported.

## Why is this bad?
tf2 refuses a frame id that starts with `/` ("Invalid argument "/map" passed to
canTransform argument target_frame in tf2 frame_ids cannot start with a '/'"): every
lookup of that frame fails. A transform *published* under it is kept without the slash by
tf2 buffers (`BufferCore::setTransformImpl` strips one leading `/`, geometry2 on every
ROS 2 distribution), but the messages on `/tf` carry it: tools that build the tree from
`/tf` themselves (Foxglove, bag tools) show two trees that never join. The slash is
a habit from tf 1, whose `tf_prefix` resolution accepted it; costmaps, map_server's map,
slam_toolbox and robot_localization on tf2 do not, nor a `frame_prefix` built as
`namespace + '/'` with an empty namespace.

## Example
```xml
<launch>
  <node pkg="nav2_amcl" exec="amcl" name="amcl">
    <param name="global_frame_id" value="/map"/>
  </node>
</launch>
```

## Use instead
```xml
<launch>
  <node pkg="nav2_amcl" exec="amcl" name="amcl">
    <param name="global_frame_id" value="map"/>
  </node>
</launch>
```

## Known problems
The finding is at the ROS 1 `<param>` that sets the value; a value from a parameter file
or from ROS 2 parameters is reported at the node's launch element (the linter does not
keep where in the file each parameter was written).
"""

from __future__ import annotations

from collections.abc import Iterator

from launch_linter.knowledge import ROS1_DISTROS, Entry
from launch_linter.model.diagnostic import Category, Severity
from launch_linter.model.record import replace
from launch_linter.model.robot import UNKNOWN_VALUE, NodeRecord
from launch_linter.rules._api import Finding, RuleContext
from launch_linter.rules._nodes import entry_of, finding_at_param, frame_parameters, program_of

ID = "frame_param_slash"
CATEGORY = Category.TF
SEVERITY = Severity.WARNING
EXAMPLE_PATH = "example.launch.xml"


def _slashed(entry: Entry, node: NodeRecord) -> Iterator[tuple[str, str]]:
    names = frame_parameters(entry, node)
    if entry.prefix is not None and entry.prefix.param not in names:
        names.append(entry.prefix.param)
    for name in names:
        value = node.given(name)
        if value is not None and value != UNKNOWN_VALUE and value.startswith("/"):
            yield name, value


def _ros1_level(entry: Entry, distro: str | None) -> Severity | None:
    """The level for a ROS 1 node: None when its frames are not known to reach tf2 as
    written on the target distribution."""
    first = entry.ros1_tf2_from
    if first is None:
        return None
    if distro not in ROS1_DISTROS:
        return Severity.INFO
    return Severity.WARNING if ROS1_DISTROS.index(distro) >= ROS1_DISTROS.index(first) else None


def check(context: RuleContext) -> Iterator[Finding]:
    for node in context.tree.nodes:
        entry = entry_of(context, node)
        if entry is None or node.ros not in (1, 2):
            continue
        level: Severity | None = None
        if node.ros == 1:
            level = _ros1_level(entry, context.distro)
            if level is None:
                continue
        elif entry.strips_leading_slash:
            continue
        for name, value in _slashed(entry, node):
            yield _finding(entry, node, name, value, level)


def _finding(entry: Entry, node: NodeRecord, name: str, value: str,
             level: Severity | None) -> Finding:
    program = program_of(node)
    when = (f" (from {str(entry.ros1_tf2_from).capitalize()} on; set --ros-distro to know)"
            if level is Severity.INFO else "")
    if entry.prefix is not None and name == entry.prefix.param:
        what = (f"{program} parameter '{name}' is '{value}': every frame it publishes "
                f"starts with '/', which tf2 frame ids cannot{when}; tf2 buffers drop the "
                f"slash they receive, but /tf carries it, so tools that read /tf "
                f"themselves (Foxglove, bag tools) show a second tree; add the slash only "
                f"to a non-empty prefix")
    else:
        what = (f"{program} parameter '{name}' is '{value}': tf2 frame ids cannot start "
                f"with '/', so lookups of it fail{when}; write '{value.lstrip('/')}'")
    found = finding_at_param(node, name, what)
    return found if level is None else replace(found, severity=level)
