"""A node whose executable its package's release for the target distribution lacks.

## What it does
Reports a launched node (ROS 1 `type`, ROS 2 `executable`) of a package whose installed
executables for the target distribution (`--ros-distro`, the `ros-distro` key or
`ROS_DISTRO`) the knowledge base knows, read from the package's build file
(`knowledge/programs.json`, docs/knowledge.md), when that executable is not among them:
robot_state_publisher's `state_publisher`, built until Melodic (1.14) and gone from
Noetic's release (1.15.0 installs `robot_state_publisher` alone; ROS 2 never had it);
controller_manager's `spawner.py`, Foxy's and Galactic's, gone from Humble on (2.3.0 installs
the console scripts `spawner`, `unspawner`). In a Python launch file the finding is at the
line of the `executable=` keyword, the word to change.
An error when the distribution is known; without one, an info when a known ROS 1
release no longer installs it. The release decides only for a package not in the linted
workspace: when the package's source is under a linted root (a `package.xml` of that
name), that checkout shadows the installed release and its own build file decides (an
older or patched copy may build `state_publisher`; in a ROS 1 devel space every
`add_executable` target and script is runnable without install). For a ROS 2 package of
the linted workspace, what its `CMakeLists.txt` or `setup.py`/`setup.cfg` install into
`lib/<package>`, read statically (docs/workspace.md), decides: an error when that
reading is complete and names no such executable. A ROS 1 package of the workspace is
not judged (its catkin build file is not read for this).

## Why is this bad?
roslaunch cannot start the node ("cannot launch node of type [robot_state_publisher/
state_publisher]: can't locate node [state_publisher]") and launches the rest without
it; ros2 launch stops at the executable it cannot find in the package's libexec folder.
Nothing then publishes what the node would: for robot_state_publisher, the robot's link
transforms.

## Example
```xml
<launch>
  <node name="robot_state_publisher" pkg="robot_state_publisher" type="state_publisher"/>
</launch>
```

## Use instead
```xml
<launch>
  <node name="robot_state_publisher" pkg="robot_state_publisher"
        type="robot_state_publisher"/>
</launch>
```

## Known problems
A ROS 1 package whose source is in the workspace is left unjudged, even when its
`CMakeLists.txt` provably builds no such executable.
"""

from __future__ import annotations

from collections.abc import Iterator

from launch_linter.model.diagnostic import Category, Location, Severity
from launch_linter.model.distro import ROS1_DISTROS, ROS2_DISTROS
from launch_linter.model.record import replace
from launch_linter.model.robot import NodeRecord
from launch_linter.rules._api import Finding, RuleContext, frontend_findings
from launch_linter.rules._nodes import finding_at_node

ID = "node_executable_missing"
CATEGORY = Category.LAUNCH
SEVERITY = Severity.ERROR
EXAMPLE_PATH = "example.launch"
EXAMPLE_DISTRO = "noetic"


def _distro_of(context: RuleContext, ros: int | None) -> str | None:
    """The target distribution when it is one of the node's ROS version."""
    distro = context.distro
    if (ros == 1 and distro in ROS1_DISTROS) or (ros == 2 and distro in ROS2_DISTROS):
        return distro
    return None


def _at_executable(node: NodeRecord, message: str) -> Finding:
    """At the line that writes the executable (the word to change), the node's element
    as related when that is another line."""
    finding = finding_at_node(node, message)
    if not node.executable_line or node.executable_line == node.line:
        return finding
    return replace(finding, line=node.executable_line, column=1,
                   related=(Location(node.path, node.line, node.column),))


def check(context: RuleContext) -> Iterator[Finding]:
    yield from frontend_findings(context, ID)
    knowledge = context.knowledge
    built_here = frozenset(context.tree.built_here)
    for node in context.tree.nodes:
        if (node.kind != "node" or node.plugin is not None or not node.executable
                or node.package in built_here):
            continue
        distro = _distro_of(context, node.ros)
        if distro is not None:
            fact = knowledge.installed(node.package, node.ros, distro)
            if fact is None or node.executable in fact.executables:
                continue
            yield _at_executable(node, (
                f"{node.package}'s release for {distro.capitalize()} installs no "
                f"executable '{node.executable}' (only {', '.join(fact.executables)}): "
                f"the node cannot start; use "
                f"{node.package}/{fact.executables[0]}"))
            continue
        if node.ros != 1 or context.distro is not None:
            continue
        newest = knowledge.installed(node.package, 1, ROS1_DISTROS[-1])
        if newest is None or node.executable in newest.executables:
            continue
        gone_from = next((d for d in ROS1_DISTROS
                          if (f := knowledge.installed(node.package, 1, d)) is not None
                          and node.executable not in f.executables), ROS1_DISTROS[-1])
        yield Finding(node.path, node.line, node.column, (
            f"{node.package} installs no executable '{node.executable}' from "
            f"{gone_from.capitalize()} on (only {', '.join(newest.executables)}): there the "
            f"node cannot start (set --ros-distro to know); use "
            f"{node.package}/{newest.executables[0]}"), node=node.name,
            severity=Severity.INFO)
