"""MoveItConfigsBuilder's robot description (precision trial, moveit/moveit_resources: the
demo of every MoveIt 2 config package gives robot_state_publisher
``moveit_config.robot_description``, which was never read)."""

from __future__ import annotations

from pathlib import Path

import pytest

from launch_linter import LintOptions, lint_paths
from launch_linter.model.launch import LaunchTree

XACRO = """<robot name="arm" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:arg name="tool" default="hand"/>
  <link name="base"/><link name="$(arg tool)"/>
  <joint name="j" type="fixed"><parent link="base"/><child link="$(arg tool)"/></joint>
</robot>
"""
PACKAGE = """<package format="3"><name>{name}</name><version>1.0.0</version>
<export><build_type>ament_cmake</build_type></export></package>
"""
LAUNCH = """from launch import LaunchDescription
from launch_ros.actions import Node
from moveit_configs_utils import MoveItConfigsBuilder


def generate_launch_description():
    moveit_config = (
        MoveItConfigsBuilder({builder})
        {description}
        .robot_description_semantic(file_path="config/arm.srdf")
        .trajectory_execution(file_path="config/moveit_controllers.yaml")
        .to_moveit_configs()
    )
    return LaunchDescription([
        Node(package="robot_state_publisher", executable="robot_state_publisher",
             parameters=[moveit_config.robot_description]),
        Node(package="moveit_ros_move_group", executable="move_group",
             parameters=[moveit_config.to_dict()]),
    ])
"""


def lint(tmp_path: Path, builder: str, description: str) -> LaunchTree:
    package = tmp_path / "src" / "arm_moveit_config"
    (package / "config").mkdir(parents=True)
    (package / "package.xml").write_text(PACKAGE.format(name="arm_moveit_config"))
    (package / "CMakeLists.txt").write_text(
        "project(arm_moveit_config)\ninstall(DIRECTORY config launch DESTINATION "
        "share/${PROJECT_NAME})\n")
    (package / "config" / "arm.urdf.xacro").write_text(XACRO)
    (package / "launch").mkdir()
    launch = package / "launch" / "demo.launch.py"
    launch.write_text(LAUNCH.format(builder=builder, description=description))
    options = LintOptions(package_paths=(str(tmp_path / "src"),))
    return lint_paths([str(launch)], options).trees[0]


@pytest.mark.parametrize("builder", ['"arm"', 'robot_name="x", package_name="arm_moveit_config"'])
def test_the_builder_robot_description_is_read(tmp_path: Path, builder: str) -> None:
    tree = lint(tmp_path, builder, '.robot_description(file_path="config/arm.urdf.xacro", '
                                   'mappings={"tool": "gripper"})')
    assert [(j.parent, j.child) for j in tree.joints] == [("base", "gripper")]
    assert not [p for p in tree.problems if p.rule != "unresolved"]


def test_the_default_description_is_unknown_not_absent(tmp_path: Path) -> None:
    # With no file_path the builder reads .setup_assistant: not modelled, never guessed.
    tree = lint(tmp_path, '"arm"', "")
    assert tree.joints == ()
    assert not [p for p in tree.problems if p.rule != "unresolved"]
    assert any(".setup_assistant" in p.message for p in tree.problems)


def test_a_missing_file_in_a_found_package_is_not_a_joint(tmp_path: Path) -> None:
    tree = lint(tmp_path, '"arm"', '.robot_description(file_path="config/other.urdf.xacro")')
    assert tree.joints == ()
