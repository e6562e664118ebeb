"""The controller manager a simulator's ros2_control plugin starts: its ``<parameters>``
files read as a launched ros2_control_node's, its controllers' edges in the tree."""

from __future__ import annotations

import time
from pathlib import Path

from launch_linter.engine import LintOptions, lint_paths
from launch_linter.knowledge import bundled
from launch_linter.rules._nodes import view_of

PACKAGE = ("<?xml version='1.0'?><package format='3'><name>bot</name><version>0.0.0</version>"
           "<description>d</description><maintainer email='a@b.c'>a</maintainer>"
           "<license>MIT</license><buildtool_depend>ament_cmake</buildtool_depend>"
           "<export><build_type>ament_cmake</build_type></export></package>")
URDF = """<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <link name="base_footprint"/><link name="base_link"/>
  <joint name="j" type="fixed"><parent link="base_footprint"/><child link="base_link"/></joint>
  <gazebo>
    <plugin filename="{filename}" name="ros2_control">
      {body}
    </plugin>
  </gazebo>
</robot>
"""
CONTROLLERS = """controller_manager:
  ros__parameters:
    update_rate: 50
    diff_cont:
      type: diff_drive_controller/DiffDriveController
    joint_broad:
      type: joint_state_broadcaster/JointStateBroadcaster
diff_cont:
  ros__parameters:
    base_frame_id: base_link
    enable_odom_tf: {odom_tf}
"""
EKF = """ekf:
  ros__parameters:
    publish_tf: true
    world_frame: odom
    odom_frame: odom
    base_link_frame: base_link
    odom0: /diff_cont/odom
"""
LAUNCH = """import os
from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.substitutions import Command
from launch_ros.actions import Node


def generate_launch_description():
    pkg = get_package_share_directory('bot')
    return LaunchDescription([
        Node(package='robot_state_publisher', executable='robot_state_publisher',
             parameters=[{'robot_description': Command(['xacro ', os.path.join(
                 pkg, 'urdf', 'r.urdf.xacro')])}]),
        Node(package='ros_gz_sim', executable='create', arguments=['-topic', 'robot_description']),
        Node(package='controller_manager', executable='spawner', arguments=['diff_cont']),
        Node(package='robot_localization', executable='ekf_node', name='ekf',
             parameters=[os.path.join(pkg, 'config', 'ekf.yaml')]),
    ])
"""
GZ = "gz_ros2_control-system"
CLASSIC = "libgazebo_ros2_control.so"


def workspace(tmp_path: Path, body: str, filename: str = GZ, odom_tf: str = "true",
              controllers: str = CONTROLLERS) -> Path:
    bot = tmp_path / "bot"
    for folder in ("launch", "urdf", "config"):
        (bot / folder).mkdir(parents=True, exist_ok=True)
    (bot / "package.xml").write_text(PACKAGE)
    (bot / "urdf" / "r.urdf.xacro").write_text(URDF.format(filename=filename, body=body))
    (bot / "config" / "controllers.yaml").write_text(controllers.format(odom_tf=odom_tf))
    (bot / "config" / "ekf.yaml").write_text(EKF)
    (bot / "launch" / "sim.launch.py").write_text(LAUNCH)
    return bot / "launch" / "sim.launch.py"


def run(tmp_path: Path, launch: Path, *rules: str) -> list[tuple[str, str, int, str]]:
    options = LintOptions(package_paths=(str(tmp_path),), select=frozenset(rules))
    return [(d.rule, Path(d.path).name, d.line, d.message)
            for d in lint_paths([str(launch)], options).diagnostics]


def edges(tmp_path: Path, launch: Path) -> list[tuple[str, str, str]]:
    result = lint_paths([str(launch)], LintOptions(package_paths=(str(tmp_path),)))
    (tree,) = result.trees
    return [(e.parent, e.child, e.node.name or "") for e in view_of(tree, bundled()).edges]


FOUND = "<parameters>$(find bot)/config/controllers.yaml</parameters>"


def test_plugin_controllers_and_an_ekf_both_publish_odom(tmp_path: Path) -> None:
    for filename in (GZ, CLASSIC):
        launch = workspace(tmp_path, FOUND, filename)
        assert sorted(edges(tmp_path, launch)) == [
            ("odom", "base_link", "diff_cont"), ("odom", "base_link", "ekf")]
        found = run(tmp_path, launch, "duplicate_publisher")
        assert [(rule, name) for rule, name, _, _ in found] == [
            ("duplicate_publisher", "r.urdf.xacro")], filename
        assert "diff_drive_controller/DiffDriveController" in found[0][3]


def test_enable_odom_tf_false_is_one_publisher(tmp_path: Path) -> None:
    launch = workspace(tmp_path, FOUND, odom_tf="false")
    assert edges(tmp_path, launch) == [("odom", "base_link", "ekf")]
    assert run(tmp_path, launch, "duplicate_publisher") == []


def test_several_parameters_files_are_read_in_order(tmp_path: Path) -> None:
    """The type in one file, the controller's section in another (both --params-file)."""
    launch = workspace(tmp_path, FOUND + "<parameters>$(find bot)/config/diff.yaml</parameters>",
                       controllers=CONTROLLERS.split("diff_cont:\n  ros__")[0])
    (tmp_path / "bot" / "config" / "diff.yaml").write_text(
        "diff_cont:\n  ros__parameters:\n    odom_frame_id: odom_sim\n"
        "    base_frame_id: base_link\n")
    assert ("odom_sim", "base_link", "diff_cont") in edges(tmp_path, launch)


def test_plugin_namespace_selects_the_sections(tmp_path: Path) -> None:
    """The manager runs in <ros><namespace>: a file keyed by /robot1/... reaches it, and a
    bare controller_manager: key does not."""
    body = "<ros><namespace>robot1</namespace></ros>" + FOUND
    launch = workspace(tmp_path, body)
    assert ("odom", "base_link", "diff_cont") not in edges(tmp_path, launch)
    nested = "robot1:\n" + "".join(f"  {line}\n" for line in
                                     CONTROLLERS.format(odom_tf="true").splitlines())
    launch = workspace(tmp_path, body, controllers=nested)
    # diff_drive_controller prefixes its frames with its namespace (tf_frame_prefix empty).
    assert ("robot1/odom", "robot1/base_link", "diff_cont") in edges(tmp_path, launch)


def test_controller_manager_name_renames_the_manager(tmp_path: Path) -> None:
    renamed = CONTROLLERS.replace("controller_manager:", "cm:")
    launch = workspace(tmp_path, FOUND, controllers=renamed)
    assert ("odom", "base_link", "diff_cont") not in edges(tmp_path, launch)
    launch = workspace(tmp_path, FOUND + "<controller_manager_name>cm</controller_manager_name>",
                       controllers=renamed)
    assert ("odom", "base_link", "diff_cont") in edges(tmp_path, launch)


def test_unresolved_parameters_leave_the_tree_open(tmp_path: Path) -> None:
    """A package not found, or a path relative to the simulator's working directory: the
    controllers are unknown, the EKF is not proven alone, and the tree is open (said once)."""
    for body in ("<parameters>$(find elsewhere)/config/controllers.yaml</parameters>",
                 "<parameters>config/controllers.yaml</parameters>",
                 "<parameters>$(find bot)/config/absent.yaml</parameters>"):
        launch = workspace(tmp_path, body)
        result = lint_paths([str(launch)], LintOptions(package_paths=(str(tmp_path),)))
        (tree,) = result.trees
        view = view_of(tree, bundled())
        (plugin,) = [n for n in view.unsure if n.kind == "gazebo_plugin"]
        assert plugin.unread, body
    # Read, the same tree's plugin is known and sure.
    launch = workspace(tmp_path, FOUND)
    result = lint_paths([str(launch)], LintOptions(package_paths=(str(tmp_path),)))
    assert not [n for n in view_of(result.trees[0], bundled()).unsure
                if n.kind == "gazebo_plugin"]


def test_a_controllers_parameters_are_placed_at_their_file_keys(tmp_path: Path) -> None:
    """Findings about a controller's parameter land on the line of its parameter file."""
    launch = workspace(tmp_path, FOUND)
    result = lint_paths([str(launch)], LintOptions(package_paths=(str(tmp_path),)))
    (controller,) = [n for n in result.trees[0].nodes if n.name == "diff_cont"]
    where = controller.where_set("base_frame_id")
    assert where is not None and (Path(where[0]).name, where[1]) == ("controllers.yaml", 10)


def test_many_parameters_files_and_controllers_are_bounded(tmp_path: Path) -> None:
    """20,000 <parameters> elements, and a file of as many controllers as fit (each sending
    its own odom frame to base_link): each file's sections indexed once, not once per
    controller (2,000 controllers took over ten minutes before)."""
    count = 4500  # as many controllers as a parameter file of MAX_PARAM_FILE_BYTES holds
    controllers = "controller_manager:\n  ros__parameters:\n" + "".join(
        f"    c{i}:\n      type: diff_drive_controller/DiffDriveController\n"
        for i in range(count)) + "".join(
        f"c{i}:\n  ros__parameters:\n    odom_frame_id: o{i}\n" for i in range(count))
    launch = workspace(tmp_path, FOUND, controllers=controllers)
    start = time.process_time()
    result = lint_paths([str(launch)], LintOptions(package_paths=(str(tmp_path),)))
    assert time.process_time() - start < 60
    named = [n for n in result.trees[0].nodes if n.kind == "controller"]
    assert len(named) == count and ("odom_frame_id", f"o{count - 1}") in named[-1].params
    small = CONTROLLERS.format(odom_tf="true")
    launch = workspace(tmp_path, FOUND * 20000, controllers=small)
    start = time.process_time()
    result = lint_paths([str(launch)], LintOptions(package_paths=(str(tmp_path),)))
    assert time.process_time() - start < 60
    assert ("odom", "base_link", "diff_cont") in [
        (e.parent, e.child, e.node.name) for e in view_of(result.trees[0], bundled()).edges]


def test_a_launched_controller_manager_with_an_unread_file_leaves_the_tree_open(
        tmp_path: Path) -> None:
    launch = tmp_path / "a.launch.py"
    launch.write_text(
        "from launch import LaunchDescription\n"
        "from launch_ros.actions import Node\n"
        "def generate_launch_description():\n"
        "    return LaunchDescription([Node(package='controller_manager',\n"
        f"        executable='ros2_control_node', parameters=['{tmp_path}/absent.yaml'])])\n")
    result = lint_paths([str(launch)], LintOptions(package_paths=()))
    view = view_of(result.trees[0], bundled())
    assert view.open_because is not None
    assert view.open_because.executable == "ros2_control_node"


def test_a_launched_controller_managers_controllers_are_placed_at_their_file_keys(
        tmp_path: Path) -> None:
    (tmp_path / "c.yaml").write_text(CONTROLLERS.format(odom_tf="true"))
    launch = tmp_path / "a.launch.py"
    launch.write_text(
        "from launch import LaunchDescription\n"
        "from launch_ros.actions import Node\n"
        "def generate_launch_description():\n"
        "    return LaunchDescription([Node(package='controller_manager',\n"
        f"        executable='ros2_control_node', parameters=['{tmp_path}/c.yaml'])])\n")
    result = lint_paths([str(launch)], LintOptions(package_paths=()))
    (controller,) = [n for n in result.trees[0].nodes if n.name == "diff_cont"]
    where = controller.where_set("enable_odom_tf")
    assert where is not None and (Path(where[0]).name, where[1]) == ("c.yaml", 11)
