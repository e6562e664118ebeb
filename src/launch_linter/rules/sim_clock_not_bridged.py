"""ROS 2 nodes on simulated time beside Gazebo Sim, and nothing that gives them `/clock`.

## What it does
Reports a ROS 2 launch tree that starts Gazebo Sim (ros_gz_sim's `gz_sim.launch.py` or
`gz_server.launch.py`, ros_ign_gazebo's `ign_gazebo.launch.py`, a `ros_gz_sim create`
spawner or the `gzserver` node) and gives nodes `use_sim_time` true, while nothing in the
tree publishes or bridges `/clock`: no `ros_gz_bridge`/`ros_ign_bridge` node, no
`ros_gz_sim.launch.py` (which starts a bridge), no Gazebo classic (`gazebo_ros`, whose
`gazebo_ros_init` publishes `/clock`). What each program and launch file does with the
clock is knowledge read from its source (docs/knowledge.md, `knowledge/programs.json`):
ros_gz_sim's `gz_sim.launch.py` runs `gz sim` and nothing else in every branch.
The proof must be complete: a node the knowledge base does not know, or an include not
followed (other than the known launch files), could bridge the clock, so the tree stays
open and the rule says so once, at info. A `gz sim`, `ros2 bag play --clock` or bridge
started by an `ExecuteProcess` that is not `ros2 run` is not seen.

## Why is this bad?
Gazebo Sim publishes its clock on its own transport only; ROS 2 nodes given
`use_sim_time` true take their time from the ROS `/clock` topic alone, and their time is
zero until a message arrives there (ros2/design, "Clock and Time"). Without a
`ros_gz_bridge parameter_bridge /clock@rosgraph_msgs/msg/Clock[gz.msgs.Clock`,
robot_state_publisher stamps transforms at time zero, timers on ROS time never fire, and
tf lookups against the simulator's sensor stamps fail (gz_ros2_control added such bridges
to its demos: ros-controls/gz_ros2_control#443, "We need a parameter bridge for receiving
the simulation time in the ROS world").

## Example
```python
from launch import LaunchDescription
from launch.actions import IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch_ros.actions import Node
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    return LaunchDescription([
        IncludeLaunchDescription(PythonLaunchDescriptionSource(
            [FindPackageShare("ros_gz_sim"), "/launch/gz_sim.launch.py"])),
        Node(package="robot_state_publisher", executable="robot_state_publisher",
             parameters=[{"use_sim_time": True}]),
    ])
```

## Use instead
```python
from launch import LaunchDescription
from launch.actions import IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch_ros.actions import Node
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    return LaunchDescription([
        IncludeLaunchDescription(PythonLaunchDescriptionSource(
            [FindPackageShare("ros_gz_sim"), "/launch/gz_sim.launch.py"])),
        Node(package="robot_state_publisher", executable="robot_state_publisher",
             parameters=[{"use_sim_time": True}]),
        Node(package="ros_gz_bridge", executable="parameter_bridge",
             arguments=["/clock@rosgraph_msgs/msg/Clock[gz.msgs.Clock"]),
    ])
```

## Known problems
A bridge started from another terminal or another launch file is not seen, nor an
include whose file the message shows cut short (its target is then unknown: the tree
stays open). Info until a judged sample of 20 findings sets a level: 2 findings judged so
far, both true (docs/evaluation/sim_clock_judged.md).
"""

from __future__ import annotations

import re
from collections.abc import Iterator

from launch_linter.knowledge.publish import truth
from launch_linter.model.diagnostic import Category, Location, Severity
from launch_linter.model.robot import UNKNOWN_VALUE, NodeRecord
from launch_linter.model.transform import Condition
from launch_linter.rules._api import Finding, RuleContext
from launch_linter.rules._nodes import entry_of, program_of

ID = "sim_clock_not_bridged"
CATEGORY = Category.TF
SEVERITY = Severity.INFO
EXAMPLE_PATH = "example.launch.py"
PARAMETER = "use_sim_time"
MAX_SHOWN = 3
_NOT_FOLLOWED = re.compile(r"^include file (['\"])(.*)\1 not followed")
_PACKAGE = re.compile(
    r"(?:FindPackageShare|get_package_share_directory|find-pkg-share|find)\W*([A-Za-z0-9_]+)")


def _include_target(text: str) -> tuple[str, str] | None:
    """The package and the path in its share folder of an include written ``text``
    (``FindPackageShare("p")/launch/x.launch.py`` and the like), None when not told."""
    found = _PACKAGE.search(text)
    if found is None:
        return None
    path = re.sub(r"[^A-Za-z0-9_.-]+", "/", text[found.end():]).strip("/")
    if not path:
        return None
    return found.group(1), path


class _Evidence:
    """Gazebo Sim started without a bridge: where, and under which condition."""

    def __init__(self, place: Location, condition: Condition, how: str) -> None:
        self.place = place
        self.condition = condition
        self.how = how


def _on_sim_time(node: NodeRecord) -> bool:
    given = node.given(PARAMETER)
    return given is not None and given != UNKNOWN_VALUE and truth(given) is True


def check(context: RuleContext) -> Iterator[Finding]:
    tree = context.tree
    nodes = [n for n in tree.nodes if n.kind == "node"]
    if not nodes or any(n.ros != 2 for n in nodes):
        return
    includes: list[_Evidence] = []
    spawners: list[_Evidence] = []
    open_because: str | None = None
    for problem in tree.problems:
        if problem.rule != "unresolved" or "not followed" not in problem.message:
            continue
        matched = _NOT_FOLLOWED.match(problem.message)
        target = _include_target(matched.group(2)) if matched else None
        launch_fact = context.knowledge.clock_launch(*target) if target else None
        if launch_fact is None or target is None:
            open_because = open_because or (
                f"the include at {problem.path}:{problem.line} is not followed")
            continue
        if launch_fact.clock != "gz_sim":
            return
        includes.append(_Evidence(Location(problem.path, problem.line, problem.column),
                                  Condition(), f"{target[0]}'s {target[1]}"))
    for node in nodes:
        fact = context.knowledge.clock_program(node.package, node.executable)
        if fact is not None and fact.clock in ("publishes", "may_bridge"):
            return
        if fact is not None and fact.clock == "gz_sim":
            spawners.append(_Evidence(Location(node.path, node.line, node.column),
                                      node.condition, program_of(node)))
        elif fact is None and entry_of(context, node) is None:
            open_because = open_because or (
                f"{program_of(node)} ({node.path}:{node.line}) is not known to the "
                f"knowledge base")
    evidence = (includes + spawners)[:1]
    if not evidence:
        return
    simulator = evidence[0]
    waiting = [n for n in nodes if _on_sim_time(n)
               and context.knowledge.clock_program(n.package, n.executable) is None
               and not simulator.condition.excludes(n.condition)]
    if not waiting:
        return
    shown = ", ".join(f"{program_of(n)} ({n.path}:{n.line})" for n in waiting[:MAX_SHOWN])
    more = f" and {len(waiting) - MAX_SHOWN} more" if len(waiting) > MAX_SHOWN else ""
    related = tuple(Location(n.path, n.line, n.column) for n in waiting[:MAX_SHOWN])
    started = f"Gazebo Sim is started ({simulator.how}, {simulator.place.path}:" \
              f"{simulator.place.line})"
    if open_because is not None:
        yield Finding(simulator.place.path, simulator.place.line, simulator.place.column,
                      f"{started} and {shown}{more} run on use_sim_time true, and no /clock "
                      f"bridge is known in the tree; not decided: {open_because} (it could "
                      f"bridge the clock)", related=related)
        return
    yield Finding(simulator.place.path, simulator.place.line, simulator.place.column,
                  f"{started} and {shown}{more} run on use_sim_time true, but nothing in "
                  f"the launch tree bridges Gazebo's clock to /clock (Gazebo Sim publishes "
                  f"it on its own transport only): their time stays at zero; add a "
                  f"ros_gz_bridge parameter_bridge for "
                  f"/clock@rosgraph_msgs/msg/Clock[gz.msgs.Clock", related=related)
