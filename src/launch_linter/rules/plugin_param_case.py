"""A Gazebo plugin parameter spelt with other capitals than the plugin reads: ignored.

## What it does
Reports an element of a Gazebo `<plugin>` whose name is one of the plugin's parameters
the knowledge base knows, but written with other capitals (`<publishTF>` for
gazebo_ros_diff_drive's `publishTf`, `<frameID>` for a `frameId`). Plugins the knowledge
base does not know, and parameters it does not list, are not judged.

## Why is this bad?
A plugin reads its parameters by name from its SDF element (`_sdf->HasElement("publishTf")`
in gazebo_ros_diff_drive.cpp, `GazeboRos::getParameter` in gazebo_ros_utils.cpp), and SDF
element names are case-sensitive: the misspelt element is not found, the plugin logs that
the parameter is missing and keeps its default, whatever the element says. For
gazebo_ros_diff_drive (ROS 1), `publishTf` switches odometry, and the odometry transform
with it, on and off (noetic-devel f9e1a46, lines 118-123 and 272): `<publishTF>false`
leaves both on.

## Example
```xml
<robot name="demo">
  <link name="base_footprint"/>
  <gazebo>
    <plugin name="diff_drive" filename="libgazebo_ros_diff_drive.so">
      <robotNamespace>/</robotNamespace>
      <publishTF>false</publishTF>
    </plugin>
  </gazebo>
</robot>
```

## Use instead
```xml
<robot name="demo">
  <link name="base_footprint"/>
  <gazebo>
    <plugin name="diff_drive" filename="libgazebo_ros_diff_drive.so">
      <robotNamespace>/</robotNamespace>
      <publishTf>false</publishTf>
    </plugin>
  </gazebo>
</robot>
```
"""
from __future__ import annotations

from collections.abc import Iterator

from launch_linter.model.diagnostic import Category, Severity
from launch_linter.rules._api import Finding, RuleContext
from launch_linter.rules._nodes import entry_of, finding_at_param, program_of

ID = "plugin_param_case"
CATEGORY = Category.TF
SEVERITY = Severity.WARNING
EXAMPLE_PATH = "example.urdf"


def check(context: RuleContext) -> Iterator[Finding]:
    # A description's plugins, whether or not a simulator is given it (a spawned one's
    # are in the tree's nodes too, once per place).
    plugins = [p for robot in context.tree.robots for p in robot.plugins]
    plugins += [n for n in context.tree.nodes if n.kind == "gazebo_plugin"]
    seen: set[tuple[str, int, str]] = set()
    for node in plugins:
        entry = entry_of(context, node)
        if entry is None:
            continue
        known = {name.lower(): name for name, _ in entry.parameters}
        for key, _ in node.params:
            meant = known.get(key.lower())
            place = (node.path, node.line, key)
            if meant is None or meant == key or place in seen:
                continue
            seen.add(place)
            default = entry.default(meant)
            shown = "" if default is None else f" ({str(default).lower()})"
            yield finding_at_param(node, key, (
                f"{program_of(node)} reads <{meant}>, not <{key}>: SDF element names are "
                f"case-sensitive, so the plugin finds no <{meant}>, keeps its default"
                f"{shown} and ignores this value; write <{meant}>"))
