"""A ROS 2 parameter file given to a node none of whose node keys names that node.

## What it does
Reports a ROS 2 parameter file passed to a node (`Node(parameters=[file])`, `<param
from="file"/>` in XML, `param: [{from: file}]` in YAML launch, `ComposableNode(parameters=
[file])`) when the file has node keys (the keys above `ros__parameters`, nested namespace
keys joined) and none of them matches the node's fully qualified name as launched: its
`name=` under its namespace (its own and the namespaces pushed around it). Keys are
matched as rclcpp matches them: a leading `/` added, `/*` one name, `/**` any number of
names, any other `*` a repeat of the character before it (rclcpp builds a `std::regex`:
`/lio_sam*` reaches `/lio_sam`, never `/lio_sam_x`). It reports at the file's first node
key, the node related. A node whose name the launch file does not write is checked under
the names its program gives its nodes when the linter knows them from the program's
source (the knowledge base's `node_names` entries, `knowledge/programs.json`, which a
user's knowledge file extends: mavros_node's nodes and its plugins' nodes, LIO-SAM's,
static_transform_publisher's), else not; and not a node whose arguments may
remap its name or namespace (`__node:=`, `__ns:=`, or arguments not known). A file given
to several nodes is reported only when it reaches none of them (teleop_twist_joy's launch
file gives `joy_node` the teleop node's file: written for the other node, nothing of
`joy_node`'s is lost), and not when one of them has a name the linter does not know. Left
out: processes that run other nodes under their own names in the same process, since
those nodes take the file's other sections: a controller manager (its controllers), a
component container (its components), the nav2 servers that run a costmap node
(`controller_server`, `planner_server`).

Error when no launch argument can change the outcome: the node's name is written as text
(or fixed by its program) and every key is a bare node name other than it (a bare key is
`/name`: it reaches only a node of that name in the root namespace). Info otherwise (the
name comes from a launch argument, a key has a namespace part or a wildcard, or is the
node's own name under another namespace): it holds for the default launch arguments.

## Why is this bad?
rclcpp applies a parameter file's entries only under the keys that match the node's fully
qualified name: `parameter_map_from` skips every other key
(rclcpp/src/rclcpp/parameter_map.cpp 54-68 and detail/resolve_parameter_overrides.cpp 54-60,
ros2/rclcpp a0a2a06); launch_ros's composable node loader keeps only `**` and the exact
`namespace/name` (launch_ros/utilities/to_parameters_list.py 77-95, ros2/launch_ros
f9ab937). Nothing warns: the node starts on its built-in defaults, so every frame,
`publish_tf` and topic in the file is silently ignored. AutonomyLab/create_robot#79 (the
file keyed `create_node` for the driver named `create_driver`: "nothing changed"),
ros-perception/depthimage_to_laserscan#71, husky/husky#244 (`imu_filter_node` for the
node named `imu_filter`: the filter kept `publish_tf` true and published a second parent
of `imu_link`).

## Example
```xml
<launch>
  <node pkg="depthimage_to_laserscan" exec="depthimage_to_laserscan_node"
        name="depthimage_to_laserscan_node">
    <param from="$(dirname)/params.yaml"/>
  </node>
</launch>
```

```yaml
depthimage_to_laserscan:
  ros__parameters:
    output_frame: camera_depth_frame
```

## Use instead
```xml
<launch>
  <node pkg="depthimage_to_laserscan" exec="depthimage_to_laserscan_node"
        name="depthimage_to_laserscan">
    <param from="$(dirname)/params.yaml"/>
  </node>
</launch>
```

```yaml
depthimage_to_laserscan:
  ros__parameters:
    output_frame: camera_depth_frame
```

## Known problems
A node whose name the launch file does not write is checked only for the programs whose
node names the linter knows (velodyne's launch files name no node; their files are keyed
by the executables' default names, which are not listed yet). Judged sample
(docs/evaluation/ros2_param_file_unmatched.md): 3 real faults found (create_robot#79,
depthimage_to_laserscan#71, husky#244); on 57 whole public repositories nobody had used,
28 node/file pairs checked, one finding, judged not a defect (the joy_node file above),
removed by the shared-file condition: no finding is left there, far from the 20 a warning
needs, so the level rests on the proof (rclcpp's and launch_ros's source), not on a
measured precision. A `LifecycleNode` is not read as a node (not checked). A file
without any `ros__parameters` key is left to rcl (it refuses such a file at start-up).
rclpy nodes are judged with rclcpp's matching (the wider one: what it does not match, an
exact or `/**` match does not match either).
"""

from __future__ import annotations

import re
from collections.abc import Iterator

from launch_linter.model.diagnostic import Category, Location, Severity
from launch_linter.model.launch import UnmatchedParamFile
from launch_linter.rules._api import Finding, RuleContext

ID = "ros2_param_file_unmatched"
CATEGORY = Category.LAUNCH
SEVERITY = Severity.ERROR
EXAMPLE_PATH = "example.launch.xml"
EXAMPLE_INCLUDED = "params.yaml"
"""The parameter file the documented example reads: the second block of its sections."""


def proven(unmatched: UnmatchedParamFile) -> bool:
    """Whatever the launch arguments: the node's names are known (written as text, or
    those its program gives its nodes) and every key is a bare node name (``/name`` once
    a ``/`` is added, matching only a node in the root namespace; a ``*`` in it repeats
    the character before it, as in rclcpp's regex) that matches none of the node's
    names, so no namespace can make one match."""
    names = unmatched.names or (unmatched.node.rsplit("/", 1)[-1],)
    return unmatched.name_literal and all(
        _root_only(key.lstrip("/")) and not any(_bare_match(key.lstrip("/"), name)
                                                for name in names)
        for key, _, _ in unmatched.keys)


def _root_only(key: str) -> bool:
    """A key without a namespace part or a wildcard name (``*`` first, ``/*``)."""
    return bool(key) and "/" not in key and not key.startswith("*") and "**" not in key


def _bare_match(key: str, name: str) -> bool:
    """Whether the bare key reaches a root-namespace node called ``name`` (a ``*`` of a
    name the program makes up: any name)."""
    if "*" in name or "/" in name:
        return True
    pattern = "*".join(re.escape(part) for part in key.split("*"))
    return re.fullmatch(pattern, name) is not None


def check(context: RuleContext) -> Iterator[Finding]:
    # The front-end leaves out processes that run other nodes under their own names, and
    # files that reach another node of the tree they are given to.
    for unmatched in context.tree.unmatched_param_files:
        keys = sorted(unmatched.keys, key=lambda k: (k[1], k[2]))
        written = [(key, line, column) for key, line, column in keys if line]
        names = ", ".join(key for key, _, _ in keys[:5])
        more = "" if len(keys) <= 5 else f" and {len(keys) - 5} more"
        sure = proven(unmatched)
        if unmatched.names:
            target = (f"any node {unmatched.package} {unmatched.executable} runs when the "
                      f"launch file names none ({unmatched.node})")
            key_as = "/** (or with the name of one of these nodes)"
        else:
            target = (f"the node {unmatched.node} ({unmatched.package} "
                      f"{unmatched.executable})")
            key_as = f"{unmatched.node} (or /**)"
        message = (f"none of this parameter file's node keys ({names}{more}) matches "
                   f"{target} it is given to"
                   f"{'' if sure else ' with the default launch arguments'}: "
                   f"rclcpp applies only the keys that match the node's name, so the node "
                   f"runs on its defaults; key the file {key_as}, or name "
                   f"the node as the file does")
        severity = None if sure else Severity.INFO
        node_place = Location(unmatched.path, unmatched.line, unmatched.column)
        if not written:
            yield Finding(path=unmatched.path, line=unmatched.line, column=unmatched.column,
                          message=message, node=unmatched.node, severity=severity)
            continue
        _, line, column = written[0]
        yield Finding(path=unmatched.file, line=line, column=column, message=message,
                      node=unmatched.node, related=(node_place,), severity=severity)
