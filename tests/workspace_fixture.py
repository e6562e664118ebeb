"""A colcon/catkin workspace, written into a temporary folder by the tests that need it.

It is built at test time, not stored: the repository's own ``.gitignore`` ignores
``build/`` folders, so a stored copy would lose them. Layout::

    ws/.gitignore                      ignores scratch/ and *.tmp.launch
    ws/build/ ws/install/ ws/log/      colcon output (copies of the launch files)
    ws/src/ros2_pkg/package.xml        ament_cmake
    ws/src/ros2_pkg/launch/bringup_launch.py
    ws/src/ros2_pkg/launch/env.xml     <launch> root, ROS 2's $(env NAME default)
    ws/src/ros2_pkg/launch/sensors_launch.xml
    ws/src/ros1_pkg/package.xml        catkin
    ws/src/ros1_pkg/launch/main.launch includes part.launch
    ws/src/ros1_pkg/launch/part.launch a leading slash (one finding, linted twice)
    ws/src/ros1_pkg/launch/robot.launch.xml
    ws/src/ros1_pkg/config/params.xml  XML that is not a launch file
    ws/src/scratch/x.launch            ignored by .gitignore
    ws/src/ros1_pkg/launch/old.tmp.launch  ignored by .gitignore
    ws/src/ros1_pkg/build/keep.launch  a package folder named build (not a workspace's)
"""

from __future__ import annotations

from pathlib import Path

AMENT = """<?xml version="1.0"?>
<package format="3">
  <name>ros2_pkg</name>
  <version>0.0.1</version>
  <description>d</description>
  <maintainer email="a@b.c">a</maintainer>
  <license>BSD</license>
  <buildtool_depend>ament_cmake</buildtool_depend>
  <export><build_type>ament_cmake</build_type></export>
</package>
"""
CATKIN = """<?xml version="1.0"?>
<package format="2">
  <name>ros1_pkg</name>
  <version>0.0.1</version>
  <description>d</description>
  <maintainer email="a@b.c">a</maintainer>
  <license>BSD</license>
  <buildtool_depend>catkin</buildtool_depend>
</package>
"""
BRINGUP = """from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='tf2_ros', executable='static_transform_publisher',
             arguments=['--x', '1', '--frame-id', 'base_link', '--child-frame-id', 'lidar']),
    ])
"""
ENV_XML = """<launch>
  <arg name="frame" default="$(env ROBOT_FRAME base_link)"/>
  <include file="$(find-pkg-share ros2_pkg)/launch/sensors_launch.xml"/>
</launch>
"""
SENSORS = """<launch>
  <node pkg="tf2_ros" exec="static_transform_publisher" name="imu_tf"
        args="--z 0.1 --frame-id base_link --child-frame-id imu"/>
</launch>
"""
MAIN = """<launch>
  <include file="$(find ros1_pkg)/launch/part.launch"/>
</launch>
"""
PART = """<launch>
  <node pkg="tf2_ros" type="static_transform_publisher" name="laser_tf"
        args="0 0 0.2 0 0 0 base_link /laser"/>
</launch>
"""
ROBOT_XML = """<launch>
  <node pkg="tf" type="static_transform_publisher" name="cam_tf"
        args="0 0 0.3 0 0 0 base_link camera 100"/>
</launch>
"""
PARAMS = """<config><launch>not a launch file: the root is config</launch></config>
"""

FILES = {
    ".gitignore": "scratch/\n*.tmp.launch\n",
    "src/ros2_pkg/package.xml": AMENT,
    "src/ros2_pkg/launch/bringup_launch.py": BRINGUP,
    "src/ros2_pkg/launch/env.xml": ENV_XML,
    "src/ros2_pkg/launch/sensors_launch.xml": SENSORS,
    "src/ros1_pkg/package.xml": CATKIN,
    "src/ros1_pkg/launch/main.launch": MAIN,
    "src/ros1_pkg/launch/part.launch": PART,
    "src/ros1_pkg/launch/robot.launch.xml": ROBOT_XML,
    "src/ros1_pkg/config/params.xml": PARAMS,
    "src/ros1_pkg/launch/old.tmp.launch": PART,
    "src/ros1_pkg/build/keep.launch": ROBOT_XML,
    "src/scratch/x.launch": PART,
    "build/ros1_pkg/launch/part.launch": PART,
    "install/ros2_pkg/share/ros2_pkg/launch/bringup_launch.py": BRINGUP,
    "install/COLCON_IGNORE": "",
    "log/latest_build/events.launch": PART,
}

LINTED = (
    "src/ros1_pkg/build/keep.launch",
    "src/ros1_pkg/launch/main.launch",
    "src/ros1_pkg/launch/part.launch",
    "src/ros1_pkg/launch/robot.launch.xml",
    "src/ros2_pkg/launch/bringup_launch.py",
    "src/ros2_pkg/launch/env.xml",
    "src/ros2_pkg/launch/sensors_launch.xml",
)
"""What folder discovery finds in the workspace, relative to its root, sorted."""


def build_workspace(root: Path) -> Path:
    """Write the workspace under ``root/ws`` and return that folder."""
    workspace = root / "ws"
    for relative, text in FILES.items():
        path = workspace / relative
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text, encoding="utf-8")
    return workspace
