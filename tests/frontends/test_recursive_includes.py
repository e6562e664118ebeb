"""Recursive includes (issue 27): a cycle is the same file given the same argument values;
a recursion whose condition turns false ends; unknown values are unresolved, not errors."""

from __future__ import annotations

from pathlib import Path

from launch_linter.frontends.dispatch import load_tree
from launch_linter.frontends.ros1 import LoadOptions
from launch_linter.model.launch import LaunchTree

ROS1 = """<launch>
  <arg name="robot_id" {default}/>
  <node pkg="tf2_ros" type="static_transform_publisher" name="tf_$(arg robot_id)"
        args="0 0 0 0 0 0 map robot_$(arg robot_id)/odom"/>
  <include file="$(dirname)/multi.launch" {condition}>
    <arg name="robot_id" value="{value}"/>
  </include>
</launch>
"""
ROS2 = """<launch>
  <arg name="n" default="3"/>
  <node pkg="tf2_ros" exec="static_transform_publisher" name="tf_$(var n)"
        args="--frame-id map --child-frame-id r$(var n)"/>
  <include file="$(dirname)/multi.launch.xml" if="$(eval '$(var n) > 1')">
    <arg name="n" value="$(eval '$(var n) - 1')"/>
  </include>
</launch>
"""


def ros1(tmp_path: Path, default: str, condition: str, value: str) -> LaunchTree:
    path = tmp_path / "multi.launch"
    path.write_text(ROS1.format(default=default, condition=condition, value=value))
    return load_tree(str(path), LoadOptions())


def rules(tree: LaunchTree) -> list[str]:
    return [p.rule for p in tree.problems]


def test_a_recursion_that_counts_down_ends_and_starts_every_robot(tmp_path: Path) -> None:
    tree = ros1(tmp_path, 'default="3"', """if="$(eval arg('robot_id') > 1)\"""",
                "$(eval arg('robot_id') - 1)")
    assert [t.child for t in tree.transforms] == ["robot_3/odom", "robot_2/odom",
                                                  "robot_1/odom"]
    assert "roslaunch_error" not in rules(tree)


def test_a_recursion_on_an_unknown_value_is_unresolved(tmp_path: Path) -> None:
    tree = ros1(tmp_path, "", """if="$(eval arg('robot_id') > 1)\"""",
                "$(eval arg('robot_id') - 1)")
    assert "roslaunch_error" not in rules(tree)
    assert any("repeats with the same unknown argument values" in p.message
               for p in tree.problems if p.rule == "unresolved")


def test_the_same_file_with_the_same_values_is_a_cycle(tmp_path: Path) -> None:
    tree = ros1(tmp_path, 'default="3"', "", "3")
    errors = [p.message for p in tree.problems if p.rule == "roslaunch_error"]
    assert [e for e in errors if e.startswith("include cycle:")]


def test_a_recursion_that_never_ends_is_cut_at_the_depth_bound(tmp_path: Path) -> None:
    tree = ros1(tmp_path, 'default="3"', "", "$(eval arg('robot_id') + 1)")
    assert "roslaunch_error" not in rules(tree)
    assert any("nested deeper than" in p.message for p in tree.problems)


def test_ros2_recursion_counts_down(tmp_path: Path) -> None:
    path = tmp_path / "multi.launch.xml"
    path.write_text(ROS2)
    tree = load_tree(str(path), LoadOptions())
    assert sorted(str(t.child) for t in tree.transforms) == ["r1", "r2", "r3"]
    assert "roslaunch_error" not in rules(tree)
