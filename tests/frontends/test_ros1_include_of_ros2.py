"""A ROS 1 file that includes ROS 2 launch XML (precision trial, mavlink/mavros: the ROS 2
branch keeps its old ROS 1 tests, whose ``$(find mavros)`` lands on the ROS 2 package):
the include is not followed and nothing in the ROS 2 file is reported as roslaunch's."""

from __future__ import annotations

from pathlib import Path

from launch_linter.frontends.dispatch import load_tree
from launch_linter.frontends.ros1 import LoadOptions

ROS1_TEST = """<launch>
  <include file="$(dirname)/node.launch"><arg name="fcu_url" value="udp://"/></include>
  <node pkg="tf2_ros" type="static_transform_publisher" name="w" args="0 0 0 0 0 0 fcu world"/>
</launch>
"""
ROS2_NODE = """<launch>
  <arg name="fcu_url"/>
  <node pkg="mavros" exec="mavros_node"><param name="fcu_url" value="$(var fcu_url)"/></node>
</launch>
"""
ROS1_NODE = """<launch>
  <arg name="fcu_url"/>
  <node pkg="mavros" type="mavros_node" name="mavros">
    <param name="fcu_url" value="$(arg fcu_url)"/>
  </node>
  <node pkg="tf2_ros" type="static_transform_publisher" name="m" args="0 0 0 0 0 0 fcu imu"/>
</launch>
"""


def load(tmp_path: Path, included: str) -> tuple[list[str], list[str], list[str | None]]:
    (tmp_path / "test.launch").write_text(ROS1_TEST)
    (tmp_path / "node.launch").write_text(included)
    tree = load_tree(str(tmp_path / "test.launch"), LoadOptions())
    return ([p.rule for p in tree.problems], [p.message for p in tree.problems],
            [t.child for t in tree.transforms])


def test_an_include_of_ros2_launch_xml_is_unresolved_not_an_error(tmp_path: Path) -> None:
    rules, messages, children = load(tmp_path, ROS2_NODE)
    assert "roslaunch_error" not in rules
    assert any("ROS 2 launch XML" in m for m in messages)
    assert children == ["world"]


def test_an_include_of_ros1_launch_xml_is_still_followed(tmp_path: Path) -> None:
    rules, messages, children = load(tmp_path, ROS1_NODE)
    assert not any("ROS 2 launch XML" in m for m in messages)
    assert children == ["imu", "world"]
    broken = ROS1_NODE.replace('name="mavros"', "")
    rules, _, _ = load(tmp_path, broken)
    assert "roslaunch_error" in rules
