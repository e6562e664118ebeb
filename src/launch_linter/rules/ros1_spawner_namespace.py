"""A ROS 1 controller spawner that calls a controller manager where none runs.

## What it does
Reports a ROS 1 `controller_manager` `spawner` node whose controller manager namespace
(its own namespace, or the one its `--namespace` argument gives) is not the namespace of
the controller manager the tree runs: the `gazebo_ros_control` plugin of a description
spawned into Gazebo, which runs it in its `<robotNamespace>` (the one `spawn_model`
writes into it when the description does not say). It judges only a tree where every
such plugin's namespace is known, every node (not a controller or a plugin) is one the
knowledge base knows (an unknown program may run a controller manager of its own) and
the spawner's namespace and arguments are resolved.

## Why is this bad?
The spawner never reaches a controller manager, so no controller is loaded. The spawner
calls `<namespace>/controller_manager/load_controller`, where `<namespace>` is its
`--namespace` argument or, without it, its own namespace (controller_manager's
scripts/spawner, lines 80-81 and 99-124, ros-controls/ros_control noetic-devel 633c374);
it waits for that service and gives up ("Controller Spawner couldn't find the expected
controller_manager ROS interface"). `gazebo_ros_control` creates its controller manager
on a node handle in `<robotNamespace>` (gazebo_ros_control_plugin.cpp lines 85-91, 150,
193-194, ros-simulation/gazebo_ros_pkgs noetic-devel f9e1a46). With no
`joint_state_controller` loaded nothing publishes the joints' states, so
robot_state_publisher sends no transform for the robot's moving links, and nothing
drives the robot (IFL-CAMP/iiwa_stack PR #9: "the controllers would not come up ...
because the namespaces for the controller spawners did not match the namespace in the
URDF"; users' threads gazebo_ros_demos#28 and #30 report the same message).

## Example
```xml
<launch>
  <param name="robot_description" value="&lt;robot name='arm'&gt;&lt;link name='base'/&gt;
    &lt;gazebo&gt;&lt;plugin name='control' filename='libgazebo_ros_control.so'&gt;
    &lt;robotNamespace&gt;/arm&lt;/robotNamespace&gt;&lt;/plugin&gt;&lt;/gazebo&gt;&lt;/robot&gt;"/>
  <node pkg="gazebo_ros" type="spawn_model" name="spawn"
        args="-urdf -param robot_description -model arm"/>
  <node pkg="robot_state_publisher" type="robot_state_publisher" name="rsp"/>
  <node pkg="controller_manager" type="spawner" name="spawner" args="joint_state_controller"/>
</launch>
```

## Use instead
```xml
<launch>
  <param name="robot_description" value="&lt;robot name='arm'&gt;&lt;link name='base'/&gt;
    &lt;gazebo&gt;&lt;plugin name='control' filename='libgazebo_ros_control.so'&gt;
    &lt;robotNamespace&gt;/arm&lt;/robotNamespace&gt;&lt;/plugin&gt;&lt;/gazebo&gt;&lt;/robot&gt;"/>
  <node pkg="gazebo_ros" type="spawn_model" name="spawn"
        args="-urdf -param robot_description -model arm"/>
  <node pkg="robot_state_publisher" type="robot_state_publisher" name="rsp"/>
  <group ns="arm">
    <node pkg="controller_manager" type="spawner" name="spawner" args="joint_state_controller"/>
  </group>
</launch>
```
"""
from __future__ import annotations

from collections.abc import Iterator

from launch_linter.model.diagnostic import Category, Location, Severity
from launch_linter.model.robot import NodeRecord
from launch_linter.rules._api import Finding, RuleContext
from launch_linter.rules._nodes import finding_at_node, nodes_of

ID = "ros1_spawner_namespace"
CATEGORY = Category.LAUNCH
SEVERITY = Severity.WARNING
EXAMPLE_PATH = "example.launch"
GAZEBO_CONTROL = "libgazebo_ros_control.so"
"""The Gazebo plugin that runs a ros_control controller manager in its robot namespace."""
NAMESPACE_OPTION = "--namespace"


def check(context: RuleContext) -> Iterator[Finding]:
    tree = context.tree
    spawners = [n for n in tree.nodes if n.ros == 1 and n.kind == "node"
                and n.package == "controller_manager" and n.executable == "spawner"]
    if not spawners:
        return
    managers = [n for n in tree.nodes if n.kind == "gazebo_plugin"
                and (n.plugin or "").endswith(GAZEBO_CONTROL)]
    if not managers or any(m.namespace is None or not m.condition.always for m in managers):
        return
    if any(n.kind == "node" for n in nodes_of(context).unknown):
        return  # a program the knowledge base does not know may run a controller manager
    served = {_absolute(m.namespace or "/") for m in managers}
    shown = ", ".join(sorted(served))
    related = tuple(Location(m.path, m.line, m.column) for m in managers[:3])
    for spawner in spawners:
        calls = _calls(spawner)
        if calls is None or calls in served or not spawner.condition.always:
            continue
        yield finding_at_node(
            spawner,
            f"controller_manager's spawner calls {_service(calls)}, but the controller "
            f"manager of this tree runs in {shown} (gazebo_ros_control's robot namespace): "
            f"the spawner waits for the service and gives up (\"Controller Spawner "
            f"couldn't find the expected controller_manager ROS interface\"), so no "
            f"controller is loaded: without joint_state_controller nothing publishes the "
            f"joints' states and robot_state_publisher sends no transform for the moving "
            f"links; run the spawner (and its controllers' parameters) in that namespace "
            f"or give it --namespace",
            related,
        )


def _calls(spawner: NodeRecord) -> str | None:
    """The namespace whose controller_manager services the spawner calls, None when its
    namespace or arguments are not known."""
    if spawner.namespace is None or spawner.args is None:
        return None
    given: str | None = None
    words = spawner.args
    for index, word in enumerate(words):
        if word == NAMESPACE_OPTION and index + 1 < len(words):
            given = words[index + 1]
        elif word.startswith(NAMESPACE_OPTION + "="):
            given = word[len(NAMESPACE_OPTION) + 1:]
    if not given:
        return _absolute(spawner.namespace)
    if given.startswith("/"):
        return _absolute(given)
    return _absolute(spawner.namespace.rstrip("/") + "/" + given)


def _absolute(namespace: str) -> str:
    """``/a/b`` for ``a/b/``, ``/a/b``, ``a//b``; ``/`` for the root."""
    parts = [p for p in namespace.split("/") if p]
    return "/" + "/".join(parts)


def _service(namespace: str) -> str:
    return namespace.rstrip("/") + "/controller_manager/load_controller"
