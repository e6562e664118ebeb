"""A root arg left at an empty default that roslaunch refuses (an empty ``ns``, a file
name built from it) is the command line's to give, like an arg without default: the
linter says so (unresolved) instead of a roslaunch error about a run nobody makes.
Found on Interbotix's hexapod and turret launch files (precision trial 5), run as
``roslaunch ... robot_model:=wxmark4``."""

from __future__ import annotations

import textwrap
from pathlib import Path

from launch_linter.frontends.dispatch import load_tree
from launch_linter.frontends.ros1 import LoadOptions
from launch_linter.model.launch import LaunchTree

STP = 'pkg="tf2_ros" type="static_transform_publisher" args="0 0 0 0 0 0 a b"'


def write(path: Path, xml: str) -> Path:
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(textwrap.dedent(xml).strip() + "\n")
    return path


def load(path: Path, **options: object) -> LaunchTree:
    return load_tree(str(path), LoadOptions(**options))  # type: ignore[arg-type]


def messages(tree: LaunchTree, rule: str) -> list[str]:
    return [d.message for d in tree.problems if d.rule == rule]


ROOT = """
    <launch>
      <arg name="robot_model" default=""/>
      <arg name="robot_name" default="$(arg robot_model)"/>
      <node name="rsp" ns="$(arg robot_name)" {stp}/>
      <rosparam file="$(dirname)/config/$(arg robot_model)_controllers.yaml" command="load"/>
      <include file="$(dirname)/description.launch">
        <arg name="robot_name" value="$(arg robot_name)"/>
      </include>
    </launch>"""
DESCRIPTION = """
    <launch>
      <arg name="robot_name" default="unused"/>
      <node name="jsp" ns="$(arg robot_name)" {stp}/>
    </launch>"""


def test_a_root_default_that_roslaunch_refuses_is_left_to_the_command_line(
        tmp_path: Path) -> None:
    write(tmp_path / "description.launch", DESCRIPTION.format(stp=STP))
    tree = load(write(tmp_path / "root.launch", ROOT.format(stp=STP)))
    assert messages(tree, "roslaunch_error") == []
    unresolved = messages(tree, "unresolved")
    assert sum("empty 'ns' attribute with arg 'robot_model' at its empty default" in m
               and "--arg robot_model:=VALUE" in m for m in unresolved) == 2
    assert any(m.startswith("error loading <rosparam> tag: file does not exist")
               and "arg 'robot_model'" in m for m in unresolved)


def test_the_value_given_is_checked(tmp_path: Path) -> None:
    write(tmp_path / "description.launch", DESCRIPTION.format(stp=STP))
    root = write(tmp_path / "root.launch", ROOT.format(stp=STP))
    given = load(root, args={"robot_model": "x"})
    assert messages(given, "roslaunch_error") == [
        f"error loading <rosparam> tag: file does not exist [{tmp_path}/config/x_controllers.yaml]"]
    (tmp_path / "config").mkdir()
    (tmp_path / "config" / "x_controllers.yaml").write_text("a: 1\n")
    given = load(root, args={"robot_model": "x"})
    assert messages(given, "roslaunch_error") == []
    assert not [m for m in messages(given, "unresolved") if "robot_model" in m]


def test_the_study_profile_keeps_the_error(tmp_path: Path) -> None:
    write(tmp_path / "description.launch", DESCRIPTION.format(stp=STP))
    tree = load(write(tmp_path / "root.launch", ROOT.format(stp=STP)), study_errors=True)
    assert sum("empty 'ns'" in m for m in messages(tree, "roslaunch_error")) == 2


def test_an_empty_value_not_from_a_root_default_stays_an_error(tmp_path: Path) -> None:
    # The included file's own empty default is not the command line's: its includer
    # passes nothing, so roslaunch refuses every run.
    write(tmp_path / "child.launch", f"""
        <launch>
          <arg name="ns" default=""/>
          <node name="c" ns="$(arg ns)" {STP}/>
        </launch>""")
    tree = load(write(tmp_path / "root.launch", f"""
        <launch>
          <arg name="frame" default=""/>
          <node name="literal" ns="" {STP}/>
          <node name="other_attribute" ns="" args="$(arg frame)" pkg="tf2_ros"
                type="static_transform_publisher"/>
          <group ns="$(arg frame)x"><node name="g" {STP}/></group>
          <include file="$(dirname)/child.launch"/>
        </launch>"""))
    errors = messages(tree, "roslaunch_error")
    assert errors.count("<node> tag has an empty 'ns' attribute") == 3


def test_the_refused_attribute_is_the_one_checked(tmp_path: Path) -> None:
    # The node's launch-prefix reads the environment; its ns does not: the empty ns is
    # the root default's, not the environment's.
    tree = load(write(tmp_path / "root.launch", f"""
        <launch>
          <arg name="robot_model" default=""/>
          <node name="pixels" ns="$(arg robot_model)" {STP}
                launch-prefix="sudo -E PYTHONPATH=$(env PYTHONPATH)"/>
          <node name="literal" ns="" {STP} launch-prefix="$(env PREFIX)"/>
        </launch>"""))
    assert messages(tree, "roslaunch_error") == ["<node> tag has an empty 'ns' attribute"]
    (unresolved,) = [m for m in messages(tree, "unresolved") if "empty 'ns'" in m]
    assert "arg 'robot_model'" in unresolved and "environment" not in unresolved
