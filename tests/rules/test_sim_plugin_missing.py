from __future__ import annotations

import time
from pathlib import Path

from launch_linter import LintOptions, lint_paths
from launch_linter.frontends.robot.urdf import MAX_PLUGINS
from launch_linter.model import Diagnostic

RULE = "sim_plugin_missing"


def _sensor(library: str) -> str:
    return (f'<gazebo reference="base_link"><sensor name="lidar" type="ray">'
            f'<plugin name="scan" filename="{library}"/></sensor></gazebo>')


def _robot(body: str) -> str:
    return f'<robot name="demo"><link name="base_link"/>{body}</robot>\n'


def _ros1(tmp_path: Path, body: str) -> tuple[Diagnostic, ...]:
    (tmp_path / "robot.urdf").write_text(_robot(body), encoding="utf-8")
    (tmp_path / "sim.launch").write_text(
        '<launch><param name="robot_description" textfile="$(dirname)/robot.urdf"/>'
        '<node pkg="robot_state_publisher" type="robot_state_publisher" name="rsp"/>'
        '</launch>', encoding="utf-8")
    options = LintOptions(package_paths=(), select=frozenset({RULE}))
    return lint_paths([str(tmp_path / "sim.launch")], options).diagnostics


def _ros2(tmp_path: Path, body: str) -> tuple[Diagnostic, ...]:
    (tmp_path / "robot.urdf.xacro").write_text(_robot(body), encoding="utf-8")
    (tmp_path / "sim.launch.py").write_text(
        "import os\n"
        "from launch import LaunchDescription\n"
        "from launch.substitutions import Command\n"
        "from launch_ros.actions import Node\n\n\n"
        "def generate_launch_description():\n"
        "    xacro_file = os.path.join(os.path.dirname(__file__), 'robot.urdf.xacro')\n"
        "    return LaunchDescription([Node(\n"
        "        package='robot_state_publisher', executable='robot_state_publisher',\n"
        "        parameters=[{'robot_description': Command(['xacro ', xacro_file])}])])\n",
        encoding="utf-8")
    options = LintOptions(package_paths=(), select=frozenset({RULE}))
    return lint_paths([str(tmp_path / "sim.launch.py")], options).diagnostics


def test_a_ros1_laser_library_in_a_ros2_tree_does_not_load(tmp_path: Path) -> None:
    """jackal#129: a ROS 2 description loading libgazebo_ros_laser.so."""
    (found,) = _ros2(tmp_path, _sensor("libgazebo_ros_laser.so"))
    assert found.severity.value == "warning" and found.path.endswith("robot.urdf.xacro")
    assert "ROS 1 Gazebo plugin" in found.message
    assert "libgazebo_ros_ray_sensor.so" in found.message
    assert _ros2(tmp_path, _sensor("libgazebo_ros_ray_sensor.so")) == ()


def test_a_ros2_library_in_a_ros1_tree_does_not_load(tmp_path: Path) -> None:
    control = '<gazebo><plugin name="c" filename="libgazebo_ros2_control.so"/></gazebo>'
    (found,) = _ros1(tmp_path, control)
    assert "ROS 2 Gazebo plugin" in found.message and "libgazebo_ros_control.so" in found.message
    assert _ros1(tmp_path, control.replace("ros2_control", "ros_control")) == ()
    # Libraries both versions build, and names of other packages, are not judged.
    assert _ros1(tmp_path, _sensor("libgazebo_ros_imu_sensor.so")) == ()
    assert _ros1(tmp_path, _sensor("libmy_lidar.so")) == ()


def test_a_description_linted_alone_is_not_judged(tmp_path: Path) -> None:
    (tmp_path / "robot.urdf").write_text(_robot(_sensor("libgazebo_ros_laser.so")),
                                         encoding="utf-8")
    options = LintOptions(package_paths=(), select=frozenset({RULE}))
    assert lint_paths([str(tmp_path / "robot.urdf")], options).diagnostics == ()


def test_many_plugins_are_judged_in_linear_time(tmp_path: Path) -> None:
    """Hostile: 20,000 <gazebo> plugins of ROS 2 in a ROS 1 tree: the description keeps
    its first MAX_PLUGINS, each one finding."""
    body = "".join(f'<gazebo><plugin name="p{i}" filename="libgazebo_ros_ray_sensor.so"/>'
                   f'</gazebo>\n' for i in range(20_000))
    start = time.process_time()
    found = _ros1(tmp_path, body)
    assert time.process_time() - start < 60.0
    assert len(found) == MAX_PLUGINS
