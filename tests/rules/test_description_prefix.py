"""robot_state_publisher's prefix on the URDF frames it sends (ROS 1 ``tf_prefix`` found
by searchParam, ROS 2 ``frame_prefix``), and the Kobuki Gazebo plugin's odometry edge
(with GazeboRos' namespace prefix up to melodic)."""

from __future__ import annotations

from pathlib import Path

from launch_linter.engine import LintOptions, lint_paths
from launch_linter.knowledge import bundled
from launch_linter.model.robot import NodeRecord
from launch_linter.report.published import published
from launch_linter.rules._nodes import view_of
from launch_linter.rules._prefixes import prefixed, publisher_prefix

URDF = """<robot name="r">
  <link name="base_footprint"/><link name="base_link"/>
  <joint name="base_joint" type="fixed">
    <parent link="base_footprint"/><child link="base_link"/>
  </joint>
</robot>
"""
ROS1 = """<launch>
  <group ns="robot_1">
    <param name="robot_description" textfile="$(dirname)/r.urdf"/>
    <node pkg="robot_state_publisher" type="robot_state_publisher" name="rsp">
      {rsp}
    </node>
  </group>
  <node pkg="tf" type="static_transform_publisher" name="s"
        args="0 0 0 0 0 0 {parent} {child} 100"/>
</launch>
"""


def lint(tmp_path: Path, launch: str, distro: str | None = None,
         name: str = "a.launch") -> list[tuple[str, int, str, str]]:
    (tmp_path / "r.urdf").write_text(URDF)
    (tmp_path / name).write_text(launch)
    options = LintOptions(package_paths=(), ros_distro=distro)
    found = lint_paths([str(tmp_path / name)], options).diagnostics
    return [(Path(d.path).name, d.line, d.rule, d.message) for d in found
            if d.severity.value != "info"]


def test_ros1_tf_prefix_puts_the_urdf_frames_under_the_robot(tmp_path: Path) -> None:
    rsp = '<param name="tf_prefix" value="robot_1"/>'
    # A second parent for the prefixed frame: found at the static transform.
    launch = ROS1.format(rsp=rsp, parent="robot_1/map", child="robot_1/base_link")
    found = lint(tmp_path, launch)
    assert [(f, line, rule) for f, line, rule, _ in found] == [
        ("a.launch", 8, "multiple_parents")]
    assert "'robot_1/base_footprint'" in found[0][3]
    # The unprefixed frame is another frame: no second parent.
    assert lint(tmp_path, ROS1.format(rsp=rsp, parent="map", child="base_link")) == []


def test_without_a_prefix_the_frames_are_as_written(tmp_path: Path) -> None:
    assert [rule for _, _, rule, _ in lint(
        tmp_path, ROS1.format(rsp="", parent="map", child="base_link"))] == ["multiple_parents"]
    assert lint(tmp_path, ROS1.format(rsp="", parent="robot_1/map",
                                      child="robot_1/base_link")) == []


def test_a_tf_prefix_set_in_the_group_reaches_robot_state_publisher(tmp_path: Path) -> None:
    group = '<group ns="robot_1">'
    launch = ROS1.format(rsp="", parent="robot_1/map", child="robot_1/base_link").replace(
        group, group + '\n    <param name="tf_prefix" value="robot_1"/>')
    assert [rule for _, _, rule, _ in lint(tmp_path, launch)] == ["multiple_parents"]


def test_an_unknown_prefix_leaves_the_frames_unknown_and_the_tree_open(tmp_path: Path) -> None:
    launch = ROS1.format(rsp='<param name="tf_prefix" value="$(env ROBOT)"/>',
                         parent="map", child="base_link")
    assert lint(tmp_path, launch) == []
    result = lint_paths([str(tmp_path / "a.launch")], LintOptions(package_paths=()))
    view = view_of(result.trees[0], bundled())
    assert view.open_because is not None
    assert view.open_because.package == "robot_state_publisher"


def test_transforms_lists_the_prefixed_frames(tmp_path: Path) -> None:
    lint(tmp_path, ROS1.format(rsp='<param name="tf_prefix" value="/robot_1"/>',
                               parent="map", child="odom"))
    result = lint_paths([str(tmp_path / "a.launch")], LintOptions(package_paths=()))
    edges = {(e.edge.parent, e.edge.child) for e in published(result)}
    assert ("robot_1/base_footprint", "robot_1/base_link") in edges


def test_ros2_frame_prefix_as_written_and_not_before_2_5(tmp_path: Path) -> None:
    (tmp_path / "r.urdf").write_text(URDF)
    launch = f"""from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    description = open('{tmp_path / "r.urdf"}').read()
    return LaunchDescription([
        Node(package='robot_state_publisher', executable='robot_state_publisher',
             parameters=[{{'robot_description': description, 'frame_prefix': 'r1_'}}]),
        Node(package='tf2_ros', executable='static_transform_publisher',
             arguments=['0', '0', '0', '0', '0', '0', 'map', 'r1_base_link']),
    ])
"""
    (tmp_path / "a.launch.py").write_text(launch)
    for distro, expected in (("humble", ["multiple_parents"]), ("eloquent", [])):
        options = LintOptions(package_paths=(), ros_distro=distro)
        found = lint_paths([str(tmp_path / "a.launch.py")], options).diagnostics
        assert [d.rule for d in found if d.severity.value != "info"] == expected, distro


def node(ros: int, **params: str) -> NodeRecord:
    return NodeRecord("a.launch", 1, 1, "robot_state_publisher", "robot_state_publisher",
                      name="rsp", params=tuple(params.items()), ros=ros)


def test_prefix_rules_of_each_version() -> None:
    assert prefixed("/r1", "base_link", 1) == "r1/base_link"
    assert prefixed("r1", "/base_link", 1) == "base_link"
    assert prefixed("r1_", "base_link", 2) == "r1_base_link"
    assert prefixed("", "base_link", 1) == "base_link"
    assert publisher_prefix(node(1, frame_prefix="x")) == ""
    assert publisher_prefix(node(2, tf_prefix="x")) == ""
    assert publisher_prefix(node(2, frame_prefix="x"), "dashing") == ""
    assert publisher_prefix(node(2, frame_prefix="x"), "jazzy") == "x"


KOBUKI_URDF = """<robot name="kobuki">
  <link name="base_footprint"/><link name="base_link"/>
  <joint name="base_joint" type="fixed">
    <parent link="base_footprint"/><child link="base_link"/>
  </joint>
  <gazebo>
    <plugin name="kobuki_controller" filename="libgazebo_ros_kobuki.so">
      {publish_tf}
      <left_wheel_joint_name>wheel_left_joint</left_wheel_joint_name>
    </plugin>
  </gazebo>
</robot>
"""
KOBUKI = """<launch>
  <group ns="robot_1">
    <param name="robot_description" textfile="$(dirname)/k.urdf"/>
    <node pkg="gazebo_ros" type="spawn_model" name="spawn"
          args="-urdf -param robot_description -model robot_1"/>
    <node pkg="robot_state_publisher" type="robot_state_publisher" name="rsp">
      <param name="tf_prefix" value="robot_1"/>
    </node>
  </group>
  <node pkg="tf" type="static_transform_publisher" name="s"
        args="0 0 0 0 0 0 {parent} {child} 100"/>
</launch>
"""


def kobuki(tmp_path: Path, publish_tf: str, parent: str, child: str,
           distro: str | None) -> list[tuple[str, int, str, str]]:
    (tmp_path / "k.urdf").write_text(KOBUKI_URDF.format(publish_tf=publish_tf))
    return lint(tmp_path, KOBUKI.format(parent=parent, child=child), distro, "k.launch")


def test_kobuki_plugin_publishes_odometry_under_its_namespace_up_to_melodic(
        tmp_path: Path) -> None:
    """rrt_exploration#15: a static map -> base_footprint beside the Kobuki plugin's
    odom -> base_footprint, in robot_1's namespace (GazeboRos' tf_prefix fallback)."""
    on = "<publish_tf>1</publish_tf>"
    found = kobuki(tmp_path, on, "robot_1/map", "robot_1/base_footprint", "melodic")
    assert [(f, line, rule) for f, line, rule, _ in found] == [
        ("k.launch", 10, "node_second_parent")]
    assert "libgazebo_ros_kobuki.so" in found[0][3]
    # No tf without <publish_tf> (false when absent), or with it false.
    assert kobuki(tmp_path, "", "robot_1/map", "robot_1/base_footprint", "melodic") == []
    assert kobuki(tmp_path, "<publish_tf>0</publish_tf>", "robot_1/map",
                  "robot_1/base_footprint", "melodic") == []
    # Noetic's GazeboRos (2.9.2 on) takes no namespace prefix: the plugin sends
    # odom -> base_footprint, and the robot's prefixed frame has one parent.
    assert kobuki(tmp_path, on, "robot_1/map", "robot_1/base_footprint", "noetic") == []
    found = kobuki(tmp_path, on, "map", "base_footprint", "noetic")
    assert [rule for _, _, rule, _ in found] == ["node_second_parent"]


TWO_ROBOTS = """<launch>
  <param name="robot_description" textfile="$(dirname)/r.urdf"/>
  <group ns="robot_0">
    <param name="tf_prefix" value="robot_0"/>
    <node pkg="robot_state_publisher" type="robot_state_publisher" name="rsp"/>
  </group>
  <group ns="robot_1">
    <param name="tf_prefix" value="robot_1"/>
    <node pkg="robot_state_publisher" type="robot_state_publisher" name="rsp"/>
  </group>
</launch>
"""
FAULTY = """<robot name="r">
  <link name="base_link"/><link name="camera_link"/><link name="other"/>
  <joint name="camera_joint" type="fixed">
    <parent link="base_link"/><child link="camera_link"/>
    <origin xyz="0 0 0" rpy="0 0 3.14"/>
  </joint>
  <joint name="second" type="fixed">
    <parent link="other"/><child link="camera_link"/>
  </joint>
</robot>
"""


def test_a_description_fault_is_one_finding_however_many_publishers_prefix_it(
        tmp_path: Path) -> None:
    """One description published under two prefixes (one robot_state_publisher per
    robot, each finding the root description): its own faults are found once, under its
    frames as written, as on the description alone."""
    (tmp_path / "r.urdf").write_text(FAULTY)
    (tmp_path / "a.launch").write_text(TWO_ROBOTS)
    found = lint_paths([str(tmp_path / "a.launch")], LintOptions(package_paths=())).diagnostics
    rules = sorted(d.rule for d in found if d.rule in ("rounded_pi", "multiple_parents"))
    assert rules == ["multiple_parents", "rounded_pi"]
    assert not [d for d in found if d.rule in rules
                and ("robot_0" in d.message or "robot_1" in d.message)]
    result = lint_paths([str(tmp_path / "a.launch")], LintOptions(package_paths=()))
    edges = {(e.edge.parent, e.edge.child) for e in published(result)}
    assert {("robot_0/base_link", "robot_0/camera_link"),
            ("robot_1/base_link", "robot_1/camera_link")} <= edges


def test_searchparam_order_own_tf_prefix_then_the_closest_namespace(tmp_path: Path) -> None:
    """robot_state_publisher's own ``tf_prefix`` wins over its group's, and a group's over
    the root's, whatever the order of the ``<param>`` lines."""
    (tmp_path / "r.urdf").write_text(URDF)
    description = '<param name="robot_description" textfile="$(dirname)/r.urdf"/>'
    rsp = '<node pkg="robot_state_publisher" type="robot_state_publisher" name="rsp">{}</node>'
    (tmp_path / "a.launch").write_text(f"""<launch>
  <param name="tf_prefix" value="top"/>
  <group ns="r1"><param name="tf_prefix" value="group"/>{description}
    {rsp.format('<param name="tf_prefix" value="own"/>')}</group>
  <group ns="r2">{description}{rsp.format('')}</group>
  <group ns="r3"><group ns="inner">{description}{rsp.format('')}</group>
    <param name="tf_prefix" value="three"/></group>
</launch>
""")
    result = lint_paths([str(tmp_path / "a.launch")], LintOptions(package_paths=()))
    children = sorted(e.edge.child for e in published(result))
    assert children == ["own/base_link", "three/base_link", "top/base_link"]
