"""A Gazebo plugin library that the tree's ROS version of gazebo_plugins does not install.

## What it does
Reports a `<plugin filename="...">` of a description that a tree spawns into Gazebo
classic when its library is one that `gazebo_plugins` (or `gazebo_ros_control`) builds
for the other ROS version only: a ROS 1 library (`libgazebo_ros_laser.so`,
`libgazebo_ros_openni_kinect.so`, `libgazebo_ros_control.so`, ...) in a ROS 2 tree, or a
ROS 2 one (`libgazebo_ros_ray_sensor.so`, `libgazebo_ros2_control.so`, ...) in a ROS 1
tree. It judges only a tree whose ROS version is known and a plugin outside an undecided
condition.

## Why is this bad?
Gazebo loads a plugin by its library's file name from its plugin path; the ROS packages
put there only the libraries their build makes, and a name no installed package makes
fails to load ("Failed to load plugin"), so the sensor publishes nothing and a drive
moves nothing. The libraries are the `add_library` targets of gazebo_plugins'
CMakeLists.txt: ROS 1 (ros-simulation/gazebo_ros_pkgs melodic-devel 1d43682 and
noetic-devel f9e1a46, the same list) builds gazebo_ros_laser, gazebo_ros_gpu_laser,
gazebo_ros_block_laser, gazebo_ros_depth_camera, gazebo_ros_openni_kinect,
gazebo_ros_imu, gazebo_ros_skid_steer_drive, gazebo_ros_range, gazebo_ros_f3d,
gazebo_ros_prosilica, gazebo_ros_multicamera and the triggered cameras, which ROS 2's
(foxy b6f7bf1 and ros2 d52f7c4, the same list) does not: there a ray sensor is
gazebo_ros_ray_sensor, a depth camera gazebo_ros_camera, an IMU gazebo_ros_imu_sensor;
ROS 2 builds gazebo_ros_ray_sensor, gazebo_ros_gps_sensor and gazebo_ros_ackermann_drive,
which ROS 1 does not. ros_control's Gazebo plugin is gazebo_ros_control in ROS 1
(gazebo_ros_pkgs noetic-devel) and gazebo_ros2_control in ROS 2 (its own repository).
A description ported from one ROS version to the other keeps the old names
(jackal/jackal#129: a ROS 2 description loading libgazebo_ros_laser.so, "it is not
possible to simulate a Laserscan").

## Example
```xml
<launch>
  <!-- a ROS 1 tree given a description written for ROS 2 -->
  <param name="robot_description" value="&lt;robot name='demo'&gt;&lt;link name='base'/&gt;
    &lt;gazebo reference='base'&gt;&lt;sensor name='lidar' type='ray'&gt;
    &lt;plugin name='scan' filename='libgazebo_ros_ray_sensor.so'/&gt;
    &lt;/sensor&gt;&lt;/gazebo&gt;&lt;/robot&gt;"/>
  <node pkg="gazebo_ros" type="spawn_model" name="spawn"
        args="-urdf -param robot_description -model demo"/>
  <node pkg="robot_state_publisher" type="robot_state_publisher" name="rsp"/>
</launch>
```

## Use instead
```xml
<launch>
  <param name="robot_description" value="&lt;robot name='demo'&gt;&lt;link name='base'/&gt;
    &lt;gazebo reference='base'&gt;&lt;sensor name='lidar' type='ray'&gt;
    &lt;plugin name='scan' filename='libgazebo_ros_laser.so'/&gt;
    &lt;/sensor&gt;&lt;/gazebo&gt;&lt;/robot&gt;"/>
  <node pkg="gazebo_ros" type="spawn_model" name="spawn"
        args="-urdf -param robot_description -model demo"/>
  <node pkg="robot_state_publisher" type="robot_state_publisher" name="rsp"/>
</launch>
```
"""
from __future__ import annotations

from collections.abc import Iterator

from launch_linter.model.diagnostic import Category, Severity
from launch_linter.model.robot import NodeRecord
from launch_linter.rules._api import Finding, RuleContext
from launch_linter.rules._nodes import finding_at_node

ID = "sim_plugin_missing"
CATEGORY = Category.TF
SEVERITY = Severity.WARNING
EXAMPLE_PATH = "example.launch"

ROS1_ONLY = frozenset(f"lib{name}.so" for name in (
    "gazebo_ros_laser", "gazebo_ros_gpu_laser", "gazebo_ros_block_laser",
    "gazebo_ros_depth_camera", "gazebo_ros_openni_kinect", "gazebo_ros_imu",
    "gazebo_ros_skid_steer_drive", "gazebo_ros_range", "gazebo_ros_f3d",
    "gazebo_ros_prosilica", "gazebo_ros_multicamera", "gazebo_ros_triggered_camera",
    "gazebo_ros_triggered_multicamera", "gazebo_ros_control",
))
"""Libraries ROS 1's gazebo_plugins and gazebo_ros_control build and ROS 2's do not."""
ROS2_ONLY = frozenset(f"lib{name}.so" for name in (
    "gazebo_ros_ray_sensor", "gazebo_ros_gps_sensor", "gazebo_ros_ackermann_drive",
    "gazebo_ros2_control",
))
"""Libraries ROS 2's gazebo_plugins and gazebo_ros2_control build and ROS 1's do not."""
INSTEAD = {
    "libgazebo_ros_laser.so": "libgazebo_ros_ray_sensor.so",
    "libgazebo_ros_gpu_laser.so": "libgazebo_ros_ray_sensor.so",
    "libgazebo_ros_block_laser.so": "libgazebo_ros_ray_sensor.so",
    "libgazebo_ros_depth_camera.so": "libgazebo_ros_camera.so",
    "libgazebo_ros_openni_kinect.so": "libgazebo_ros_camera.so",
    "libgazebo_ros_imu.so": "libgazebo_ros_imu_sensor.so",
    "libgazebo_ros_multicamera.so": "libgazebo_ros_camera.so",
    "libgazebo_ros_control.so": "libgazebo_ros2_control.so",
    "libgazebo_ros_ray_sensor.so": "libgazebo_ros_laser.so",
    "libgazebo_ros2_control.so": "libgazebo_ros_control.so",
}


def check(context: RuleContext) -> Iterator[Finding]:
    ros = next((n.ros for n in context.tree.nodes if n.ros is not None), None)
    if ros not in (1, 2):
        return
    missing = ROS2_ONLY if ros == 1 else ROS1_ONLY
    seen: set[tuple[str, int, int]] = set()
    for robot in context.tree.robots:
        for plugin in robot.plugins:
            library = (plugin.plugin or "").rsplit("/", 1)[-1]
            if library in missing and plugin.condition.always:
                yield from _once(plugin, library, ros, seen)


def _once(plugin: NodeRecord, library: str, ros: int,
          seen: set[tuple[str, int, int]]) -> Iterator[Finding]:
    """The finding for ``plugin``, unless its place was shown already (a macro's plugin
    written once, called many times)."""
    place = (plugin.path, plugin.line, plugin.column)
    if place in seen:
        return
    seen.add(place)
    other = 2 if ros == 1 else 1
    instead = INSTEAD.get(library)
    yield finding_at_node(
        plugin,
        f"{library} is a ROS {other} Gazebo plugin: the ROS {ros} gazebo_plugins "
        f"and ros_control packages build no library of that name, so Gazebo fails to "
        f"load it (\"Failed to load plugin\") and what it should publish or drive is "
        f"missing"
        + (f"; its ROS {ros} counterpart is {instead}, with its own parameters"
           if instead else ""),
    )
