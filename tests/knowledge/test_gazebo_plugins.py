"""<gazebo><plugin> blocks of a description: Gazebo plugins that publish tf and stamp
frames, read when the tree spawns the description into a simulator."""

from __future__ import annotations

import json
from pathlib import Path

from launch_linter.engine import LintOptions, lint_paths
from launch_linter.frontends.robot.urdf import SENSOR_LINK_PARAM
from launch_linter.frontends.robot.xacro_values import PLUGIN_TEXT_TAGS, TF_PREFIX_PARAM
from launch_linter.knowledge import bundled, bundled_path
from launch_linter.model.robot import NodeRecord
from launch_linter.rules._nodes import view_of

URDF = """<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:arg name="odom_tf" default="true"/>
  <link name="base_footprint"/><link name="base_link"/>
  <joint name="j" type="fixed"><parent link="base_footprint"/><child link="base_link"/></joint>
  <gazebo>
    <plugin name="diff" filename="libgazebo_ros_diff_drive.so">
      {body}
    </plugin>
  </gazebo>
</robot>
"""
ROS1 = """<launch>
  <param name="robot_description" command="xacro $(dirname)/r.urdf.xacro"/>
  <node pkg="robot_state_publisher" type="robot_state_publisher" name="rsp"/>
  {spawn}
  <node pkg="robot_localization" type="ekf_localization_node" name="ekf">
    <param name="base_link_frame" value="base_footprint"/>
    <param name="odom0" value="odom"/>
  </node>
</launch>
"""
SPAWN1 = ('<node pkg="gazebo_ros" type="spawn_model" name="spawn" '
          'args="-urdf -param robot_description -model r"/>')


def lint(tmp_path: Path, urdf: str, launch: str, name: str = "a.launch"
         ) -> list[tuple[str, int, str]]:
    (tmp_path / "r.urdf.xacro").write_text(urdf)
    (tmp_path / name).write_text(launch)
    options = LintOptions(package_paths=(), select=frozenset({"duplicate_publisher"}))
    found = lint_paths([str(tmp_path / name)], options).diagnostics
    return [(Path(d.path).name, d.line, d.message) for d in found]


def plugins(tmp_path: Path, name: str = "a.launch") -> list[NodeRecord]:
    result = lint_paths([str(tmp_path / name)], LintOptions(package_paths=()))
    return [n for t in result.trees for n in t.nodes if n.kind == "gazebo_plugin"]


def test_ros1_diff_drive_plugin_and_an_ekf_both_publish_odom(tmp_path: Path) -> None:
    body = ("<odometryFrame>odom</odometryFrame>"
            "<publishOdomTF>$(arg odom_tf)</publishOdomTF>"
            "<robotBaseFrame>base_footprint</robotBaseFrame>")
    found = lint(tmp_path, URDF.format(body=body), ROS1.format(spawn=SPAWN1))
    assert [(f, line) for f, line, _ in found] == [("r.urdf.xacro", 6)]
    assert "Gazebo plugin libgazebo_ros_diff_drive.so" in found[0][2]
    # Fixed: the plugin's tf switched off (as written, read through xacro's $(arg)).
    fixed = URDF.format(body=body).replace('default="true"', 'default="false"')
    assert lint(tmp_path, fixed, ROS1.format(spawn=SPAWN1)) == []


def test_a_description_not_spawned_into_a_simulator_runs_no_plugin(tmp_path: Path) -> None:
    """On the real robot robot_state_publisher reads the same description: no plugin
    runs there."""
    body = "<robotBaseFrame>base_footprint</robotBaseFrame>"
    assert lint(tmp_path, URDF.format(body=body), ROS1.format(spawn="")) == []
    assert plugins(tmp_path) == []


def test_ros2_plugin_namespace_and_parameters(tmp_path: Path) -> None:
    body = ("<ros><namespace>/robot1</namespace><remapping>odom:=odom1</remapping></ros>"
            "<publish_odom_tf>true</publish_odom_tf>"
            "<odometry_frame>robot1/odom</odometry_frame>"
            "<robot_base_frame>base_footprint</robot_base_frame>")
    (tmp_path / "r.urdf.xacro").write_text(URDF.format(body=body))
    (tmp_path / "a.launch.py").write_text(
        "import os\n"
        "from launch import LaunchDescription\n"
        "from launch.substitutions import Command\n"
        "from launch_ros.actions import Node\n"
        "def generate_launch_description():\n"
        "    f = os.path.join(os.path.dirname(__file__), 'r.urdf.xacro')\n"
        "    return LaunchDescription([\n"
        "        Node(package='robot_state_publisher', executable='robot_state_publisher',\n"
        "             parameters=[{'robot_description': Command(['xacro ', f])}]),\n"
        "        Node(package='gazebo_ros', executable='spawn_entity.py',\n"
        "             arguments=['-topic', 'robot_description', '-entity', 'r']),\n"
        "    ])\n")
    (plugin,) = plugins(tmp_path, "a.launch.py")
    assert (plugin.plugin, plugin.namespace, plugin.ros) == (
        "libgazebo_ros_diff_drive.so", "/robot1", 2)
    assert plugin.given("publish_odom_tf") == "true"
    result = lint_paths([str(tmp_path / "a.launch.py")], LintOptions(package_paths=()))
    edges = view_of(result.trees[0], bundled()).edges
    assert [(e.parent, e.child, e.entry.id) for e in edges] == [
        ("robot1/odom", "base_footprint", "gazebo_ros_diff_drive")]


def test_a_simulated_ros2_control_plugin_gives_its_controllers(tmp_path: Path) -> None:
    (tmp_path / "controllers.yaml").write_text(
        "controller_manager:\n  ros__parameters:\n    diff_cont:\n"
        "      type: diff_drive_controller/DiffDriveController\n"
        "diff_cont:\n  ros__parameters:\n    base_frame_id: base_footprint\n")
    urdf = URDF.replace('filename="libgazebo_ros_diff_drive.so"',
                        'filename="libgazebo_ros2_control.so"').format(
        body=f"<parameters>{tmp_path / 'controllers.yaml'}</parameters>")
    (tmp_path / "r.urdf.xacro").write_text(urdf)
    (tmp_path / "a.launch.xml").write_text(
        '<launch><node pkg="robot_state_publisher" exec="robot_state_publisher">'
        f'<param name="robot_description" value="$(command \'xacro {tmp_path}/r.urdf.xacro\')"/>'
        '</node><node pkg="ros_gz_sim" exec="create" args="-topic robot_description"/>'
        '</launch>')
    result = lint_paths([str(tmp_path / "a.launch.xml")], LintOptions(package_paths=()))
    (tree,) = result.trees
    edges = view_of(tree, bundled()).edges
    assert [(e.parent, e.child, e.node.kind) for e in edges] == [
        ("odom", "base_footprint", "controller")]


def test_every_plugin_parameter_of_the_knowledge_base_is_read() -> None:
    """The expander keeps the text of the plugin parameters the knowledge base names (a
    ROS 1 plugin's tf_prefix comes from the launch tree)."""
    path = bundled_path()
    assert path is not None
    with open(path, encoding="utf-8") as handle:
        entries = json.load(handle)["entries"]
    for entry in entries:
        if entry["kind"] == "gazebo_plugin":
            for name in entry.get("parameters", {}):
                assert name in PLUGIN_TEXT_TAGS or name in (SENSOR_LINK_PARAM, TF_PREFIX_PARAM), (
                    entry["id"], name)


def test_plugins_and_frame_chains_are_bounded(tmp_path: Path) -> None:
    """20,000 camera plugins on a 20,000-joint chain: at most MAX_PLUGINS records per
    description, and the rotation walk stops at its depth cap (the frame is then judged
    by name)."""
    from launch_linter.frontends.robot.urdf import MAX_PLUGINS

    count = 20000
    links = "".join(f'<link name="l{i}"/>' for i in range(count + 1))
    joints = "".join(f'<joint name="j{i}" type="fixed"><parent link="l{i}"/>'
                     f'<child link="l{i + 1}"/></joint>' for i in range(count))
    plugins = "".join(
        f'<gazebo reference="l{i}"><sensor type="camera" name="c{i}"><plugin name="p{i}" '
        f'filename="libgazebo_ros_camera.so"><frame_name>l{count}</frame_name></plugin>'
        f'</sensor></gazebo>' for i in range(count))
    path = tmp_path / "big.urdf"
    path.write_text(f'<robot name="r">{links}{joints}{plugins}</robot>')
    options = LintOptions(package_paths=(), select=frozenset({"camera_frame_not_optical"}))
    result = lint_paths([str(path)], options)
    (robot,) = result.trees[0].robots
    assert len(robot.plugins) == MAX_PLUGINS
    assert [d.rule for d in result.diagnostics] == ["camera_frame_not_optical"]
