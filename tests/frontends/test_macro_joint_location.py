"""A joint made by a xacro macro is shown at the call that made it (the outermost call,
in the file that instantiates it), with the ``<joint>`` in the macro as related place."""

from __future__ import annotations

from pathlib import Path

from launch_linter import LintOptions, lint_paths

HEAD = '<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">'
PARTS = HEAD + """
<xacro:macro name="sensor" params="parent name">
  <link name="${name}"/>
  <joint name="${name}_joint" type="fixed">
    <parent link="${parent}"/><child link="${name}"/>
  </joint>
</xacro:macro>
<xacro:macro name="mount" params="name">
  <xacro:sensor parent="base_link" name="${name}"/>
</xacro:macro>
</robot>"""
ROBOT = HEAD + """
<xacro:include filename="parts.xacro"/>
<link name="base_link"/>
<xacro:mount name="laser"/>
</robot>"""
LAUNCH = """<launch>
  <param name="robot_description" command="xacro $(dirname)/robot.xacro"/>
  <node pkg="robot_state_publisher" type="robot_state_publisher" name="rsp"/>
  <node pkg="tf2_ros" type="static_transform_publisher" name="s"
        args="0 0 0 0 0 0 odom laser"/>
</launch>
"""


def test_the_joint_points_at_the_outermost_call_and_the_macro(tmp_path: Path) -> None:
    (tmp_path / "parts.xacro").write_text(PARTS, encoding="utf-8")
    (tmp_path / "robot.xacro").write_text(ROBOT, encoding="utf-8")
    (tmp_path / "a.launch").write_text(LAUNCH, encoding="utf-8")
    result = lint_paths([str(tmp_path / "a.launch")], LintOptions())
    (joint,) = [j for tree in result.trees for j in tree.joints]
    assert (Path(joint.path).name, joint.line) == ("robot.xacro", 4)
    assert joint.defined is not None
    assert (Path(joint.defined[0]).name, joint.defined[1]) == ("parts.xacro", 4)
    (found,) = [d for d in result.diagnostics if d.rule == "multiple_parents"]
    places = {(Path(r.path).name, r.line) for r in (found, *found.related)}
    assert ("robot.xacro", 4) in places and ("parts.xacro", 4) in places


def test_an_angle_typed_in_the_macro_is_shown_where_it_is_typed(tmp_path: Path) -> None:
    """``rounded_pi`` is about the written number: it points at the macro's ``<joint>``
    (once, however many robots call it), with the call as the related place."""
    parts = PARTS.replace('<child link="${name}"/>',
                          '<child link="${name}"/><origin xyz="0.1 0 0" rpy="-1.57 0 -1.57"/>')
    (tmp_path / "parts.xacro").write_text(parts, encoding="utf-8")
    (tmp_path / "robot.xacro").write_text(ROBOT.replace("laser", "camera_link"),
                                          encoding="utf-8")
    (tmp_path / "a.launch").write_text(LAUNCH.replace(" laser", " other"), encoding="utf-8")
    result = lint_paths([str(tmp_path / "a.launch")], LintOptions())
    (found,) = [d for d in result.diagnostics if d.rule == "rounded_pi"]
    assert (Path(found.path).name, found.line) == ("parts.xacro", 4)
    assert [(Path(r.path).name, r.line) for r in found.related] == [("robot.xacro", 4)]


TWO_PARENTS = HEAD + """
<xacro:macro name="arm" params="prefix">
  <link name="${prefix}link_6"/><link name="${prefix}flange"/><link name="${prefix}tool0"/>
  <joint name="${prefix}joint_6-tool0" type="fixed">
    <parent link="${prefix}link_6"/>
    <child link="${prefix}tool0"/>
  </joint>
  <joint name="${prefix}joint_6-flange" type="fixed">
    <parent link="${prefix}link_6"/><child link="${prefix}flange"/>
  </joint>
  <joint name="${prefix}flange-tool0" type="fixed">
    <parent link="${prefix}flange"/>
    <child link="${prefix}tool0"/>
  </joint>
</xacro:macro>
</robot>"""
ARM = HEAD + """
<xacro:include filename="parts.xacro"/>
<xacro:arm prefix=""/>
</robot>"""
ARM_LAUNCH = """<launch>
  <param name="robot_description" command="xacro $(dirname)/robot.xacro"/>
  <node pkg="robot_state_publisher" type="robot_state_publisher" name="rsp"/>
</launch>
"""


def test_two_parents_one_macro_call_made_are_shown_in_the_macro(tmp_path: Path) -> None:
    """staubli_experimental #37: the TX90 macro gives tool0 two parents; every call of it
    does, so the finding is at the macro's second ``<child>``, the call related."""
    (tmp_path / "parts.xacro").write_text(TWO_PARENTS, encoding="utf-8")
    (tmp_path / "robot.xacro").write_text(ARM, encoding="utf-8")
    (tmp_path / "a.launch").write_text(ARM_LAUNCH, encoding="utf-8")
    result = lint_paths([str(tmp_path / "a.launch")], LintOptions())
    (found,) = [d for d in result.diagnostics if d.rule == "multiple_parents"]
    assert (Path(found.path).name, found.line) == ("parts.xacro", 13)
    assert [(Path(r.path).name, r.line) for r in found.related][:2] == [
        ("robot.xacro", 3), ("parts.xacro", 6)]


def test_parents_from_two_calls_stay_at_the_call(tmp_path: Path) -> None:
    """Two calls each giving the frame a parent: the calls are what to fix."""
    (tmp_path / "parts.xacro").write_text(PARTS, encoding="utf-8")
    robot = ROBOT.replace('<xacro:mount name="laser"/>',
                          '<link name="top"/>\n<xacro:sensor parent="top" name="laser"/>'
                          '\n<xacro:mount name="laser"/>')
    (tmp_path / "robot.xacro").write_text(robot, encoding="utf-8")
    (tmp_path / "a.launch").write_text(ARM_LAUNCH, encoding="utf-8")
    result = lint_paths([str(tmp_path / "a.launch")], LintOptions())
    (found,) = [d for d in result.diagnostics if d.rule == "multiple_parents"]
    assert Path(found.path).name == "robot.xacro"
