"""plugin_frame_unprefixed: a Gazebo plugin of a prefixed robot naming its frame without
the robot's prefix."""

from __future__ import annotations

import time
from pathlib import Path

from launch_linter.engine import LintOptions, lint_paths

RULE = "plugin_frame_unprefixed"
ROS1_URDF = """<robot name="r">
  <link name="base_footprint"/><link name="{laser_link}"/>
  <joint name="j" type="fixed"><parent link="base_footprint"/><child link="{laser_link}"/></joint>
  <gazebo reference="{laser_link}"><sensor type="ray" name="s">
    <plugin name="p" filename="libgazebo_ros_laser.so">
      <frameName>{frame}</frameName>
    </plugin>
  </sensor></gazebo>
</robot>
"""
ROS1_LAUNCH = """<launch>
  <group ns="{group}">
    {group_prefix}
    <param name="robot_description" textfile="$(dirname)/r.urdf"/>
    <node pkg="robot_state_publisher" type="robot_state_publisher" name="rsp">
      {rsp_prefix}
    </node>
    <node pkg="gazebo_ros" type="spawn_model" name="spawn"
          args="-urdf -param robot_description -model r"/>
  </group>
</launch>
"""
ROS2_URDF = """<robot name="r">
  <link name="{base}"/><link name="{prefix}wheel"/><link name="{prefix}caster"/>
  <joint name="a" type="fixed"><parent link="{base}"/><child link="{prefix}wheel"/></joint>
  <joint name="b" type="fixed"><parent link="{base}"/><child link="{prefix}caster"/></joint>
  <gazebo>
    <plugin name="diff" filename="libgazebo_ros_diff_drive.so">
      <publish_odom_tf>true</publish_odom_tf>
      <odometry_frame>{odom}</odometry_frame>
      <robot_base_frame>{frame}</robot_base_frame>
    </plugin>
  </gazebo>
</robot>
"""
ROS2_LAUNCH = """import os
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    description = open(os.path.join(os.path.dirname(__file__), 'r.urdf')).read()
    return LaunchDescription([
        Node(package='robot_state_publisher', executable='robot_state_publisher',
             namespace='robot1',
             parameters=[{{'robot_description': description{frame_prefix}}}]),
        Node(package='gazebo_ros', executable='spawn_entity.py',
             arguments=['-topic', 'robot1/robot_description', '-entity', 'robot1']),
    ])
"""


def found(tmp_path: Path, urdf: str, launch: str, name: str) -> list[tuple[str, int, str]]:
    (tmp_path / "r.urdf").write_text(urdf)
    (tmp_path / name).write_text(launch)
    options = LintOptions(package_paths=(), select=frozenset({RULE}))
    return [(Path(d.path).name, d.line, d.message)
            for d in lint_paths([str(tmp_path / name)], options).diagnostics]


def ros1(tmp_path: Path, frame: str, group: str = "/", group_prefix: str = "",
         rsp_prefix: str = '<param name="tf_prefix" value="mir"/>',
         laser_link: str = "front_laser_link") -> list[tuple[str, int, str]]:
    return found(tmp_path, ROS1_URDF.format(frame=frame, laser_link=laser_link),
                 ROS1_LAUNCH.format(group=group, group_prefix=group_prefix,
                                    rsp_prefix=rsp_prefix), "a.launch")


def test_ros1_laser_frame_without_the_tf_prefix_given_to_robot_state_publisher(
        tmp_path: Path) -> None:
    """DFKI-NI/mir_robot#65: the plugin finds no tf_prefix from the spawner's namespace."""
    assert [(f, line) for f, line, _ in ros1(tmp_path, "front_laser_link")] == [("r.urdf", 6)]
    assert "'mir/front_laser_link'" in ros1(tmp_path, "front_laser_link")[0][2]
    assert ros1(tmp_path, "mir/front_laser_link") == []


def test_ros1_laser_plugin_puts_the_tf_prefix_it_finds_before_its_frame(tmp_path: Path) -> None:
    """tf_prefix set in the robot's namespace: the plugin's tf::resolve prefixes the frame
    itself, unless it is written with a leading slash."""
    group = dict(group="mir", group_prefix='<param name="tf_prefix" value="mir"/>', rsp_prefix="")
    assert ros1(tmp_path, "front_laser_link", **group) == []
    assert len(ros1(tmp_path, "/front_laser_link", **group)) == 1


def test_an_unprefixed_robot_is_not_judged(tmp_path: Path) -> None:
    assert ros1(tmp_path, "laser", rsp_prefix="") == []


def ros2(tmp_path: Path, frame: str, frame_prefix: str = "", prefix: str = "",
         odom: str = "odom") -> list[tuple[str, int, str]]:
    base = prefix + "base_footprint"
    urdf = ROS2_URDF.format(base=base, prefix=prefix, frame=frame, odom=odom)
    given = f", 'frame_prefix': '{frame_prefix}'" if frame_prefix else ""
    return found(tmp_path, urdf, ROS2_LAUNCH.format(frame_prefix=given), "a.launch.py")


def test_ros2_diff_drive_base_frame_without_frame_prefix(tmp_path: Path) -> None:
    """ROS 2 gazebo_ros plugins put no prefix before their frames."""
    result = ros2(tmp_path, "base_footprint", frame_prefix="robot1/")
    assert [(f, line) for f, line, _ in result] == [("r.urdf", 9)]
    assert "'robot1/base_footprint'" in result[0][2]
    assert ros2(tmp_path, "robot1/base_footprint", frame_prefix="robot1/") == []
    assert ros2(tmp_path, "base_footprint") == []


def test_ros2_xacro_prefix_on_every_link(tmp_path: Path) -> None:
    assert len(ros2(tmp_path, "base_footprint", prefix="robot1_")) == 1
    assert ros2(tmp_path, "robot1_base_footprint", prefix="robot1_") == []
    # A frame nothing of the robot is named like: not this rule's.
    assert ros2(tmp_path, "chassis", prefix="robot1_") == []


def test_many_links_are_bounded(tmp_path: Path) -> None:
    """20,000 prefixed links (the description's element cap leaves room for a few
    plugins; their number is capped by MAX_PLUGINS anyway): one pass over the edges."""
    count = 20000
    links = "".join(f'<link name="r1_l{i}"/>' for i in range(count + 1))
    joints = "".join(f'<joint name="j{i}" type="fixed"><parent link="r1_l{i}"/>'
                     f'<child link="r1_l{i + 1}"/></joint>' for i in range(count))
    plugins = "".join(
        f'<gazebo reference="r1_l{i}"><sensor type="ray" name="s{i}"><plugin name="p{i}" '
        f'filename="libgazebo_ros_ray_sensor.so"><frame_name>l{i}</frame_name></plugin>'
        f'</sensor></gazebo>' for i in range(5))
    urdf = f'<robot name="r">{links}{joints}{plugins}</robot>'
    start = time.process_time()
    result = found(tmp_path, urdf, ROS2_LAUNCH.format(frame_prefix=""), "a.launch.py")
    assert time.process_time() - start < 60
    assert [message.split("'")[1] for _, _, message in result] == [f"l{i}" for i in range(5)]


def test_ros1_camera_plugin_prefixes_its_frame_with_the_tf_prefix_it_finds(
        tmp_path: Path) -> None:
    """gazebo_ros_camera_utils.cpp resolves frameName with the tf_prefix found from the
    plugin's namespace, as the laser plugin does."""
    camera = ROS1_URDF.replace('type="ray"', 'type="camera"').replace(
        "libgazebo_ros_laser.so", "libgazebo_ros_camera.so")
    launch = ROS1_LAUNCH.format(group="mir", group_prefix='<param name="tf_prefix" value="mir"/>',
                                rsp_prefix="")
    assert found(tmp_path, camera.format(frame="cam", laser_link="cam"), launch, "a.launch") == []
    launch = ROS1_LAUNCH.format(group="/", group_prefix="",
                                rsp_prefix='<param name="tf_prefix" value="mir"/>')
    assert len(found(tmp_path, camera.format(frame="cam", laser_link="cam"), launch,
                     "a.launch")) == 1
