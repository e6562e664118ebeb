"""The ROS 1 loader resolves every substitution as roslaunch does, within the launch tree."""

from __future__ import annotations

import textwrap
from pathlib import Path

from launch_linter.frontends.dispatch import load_tree
from launch_linter.frontends.ros1 import LoadOptions
from launch_linter.model.launch import LaunchTree
from launch_linter.model.transform import StaticTransform
from launch_linter.workspace.packages import PackageIndex

TF2 = 'pkg="tf2_ros" type="static_transform_publisher"'


def load(tmp_path: Path, xml: str, name: str = "t.launch", **options: object) -> LaunchTree:
    path = tmp_path / name
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(textwrap.dedent(xml).strip() + "\n")
    return load_tree(str(path), LoadOptions(**options))  # type: ignore[arg-type]


def by_name(tree: LaunchTree) -> dict[str | None, StaticTransform]:
    return {t.name: t for t in tree.transforms}


def rules(tree: LaunchTree) -> list[str]:
    return [d.rule for d in tree.problems]


def test_arg_default_is_used_when_no_value_is_given(tmp_path: Path) -> None:
    tree = load(tmp_path, f"""
        <launch>
          <arg name="parent" default="base_link"/>
          <node {TF2} name="n" args="0 0 0 0 0 0 $(arg parent) laser"/>
        </launch>""")
    assert by_name(tree)["n"].parent == "base_link"


def test_command_line_args_override_defaults_and_can_be_undeclared(tmp_path: Path) -> None:
    xml = f"""
        <launch>
          <arg name="parent" default="base_link"/>
          <node {TF2} name="n" args="0 0 0 0 0 0 $(arg parent) $(arg extra)"/>
        </launch>"""
    tree = load(tmp_path, xml, args={"parent": "chassis", "extra": " gps "})
    transform = by_name(tree)["n"]
    assert (transform.parent, transform.child) == ("chassis", "gps")
    assert transform.unresolved_names == ()


def test_command_line_private_and_empty_args_are_ignored(tmp_path: Path) -> None:
    xml = f"""
        <launch>
          <node {TF2} name="n" args="0 0 0 0 0 0 $(arg _private) $(arg empty)"/>
        </launch>"""
    transform = by_name(load(tmp_path, xml, args={"_private": "p", "empty": ""}))["n"]
    assert "parent" in transform.unresolved and "child" in transform.unresolved


def test_arg_value_cannot_be_overridden(tmp_path: Path) -> None:
    xml = f"""
        <launch>
          <arg name="child" value="imu"/>
          <node {TF2} name="n" args="0 0 0 0 0 0 base $(arg child)"/>
        </launch>"""
    tree = load(tmp_path, xml, args={"child": "other"})
    assert by_name(tree)["n"].child == "other"
    assert any("cannot override arg 'child'" in d.message for d in tree.problems)


def test_required_arg_without_default_is_unresolved_until_given(tmp_path: Path) -> None:
    xml = f"""
        <launch>
          <arg name="frame"/>
          <arg name="never_used"/>
          <node {TF2} name="n" args="0 0 0 0 0 0 world $(arg frame)"/>
        </launch>"""
    missing = by_name(load(tmp_path, xml))["n"]
    assert missing.unresolved_names == ("child",)
    assert missing.child_written == "$(arg frame)"
    assert "--arg frame:=VALUE" in missing.unresolved_reasons[0]
    given = by_name(load(tmp_path, xml, args={"frame": "base"}))["n"]
    assert (given.child, given.unresolved_names) == ("base", ())


def test_eval_through_the_safe_interpreter(tmp_path: Path) -> None:
    tree = load(tmp_path, f"""
        <launch>
          <arg name="deg" default="90"/>
          <arg name="robot" default="r2"/>
          <node {TF2} name="$(eval robot + '_imu')"
                args="$(eval '0 0 0 ' + str(radians(deg)) + ' 0 0 base imu')"/>
          <node {TF2} name="bomb" args="$(eval 9**9**9)"/>
        </launch>""")
    transforms = by_name(tree)
    imu = transforms["r2_imu"]
    assert imu.rotation is not None
    assert abs(imu.rotation.values[0] - 1.5707963267948966) < 1e-12
    bomb = transforms["bomb"]
    assert "arity" in bomb.unresolved
    assert any("not evaluated" in r for r in bomb.unresolved_reasons)


def test_eval_with_double_underscore_is_a_roslaunch_error(tmp_path: Path) -> None:
    tree = load(tmp_path, f"""
        <launch>
          <node {TF2} name="$(eval __import__('os').getcwd())" args="0 0 0 0 0 0 a b"/>
        </launch>""")
    assert "roslaunch_error" in rules(tree)
    (transform,) = tree.transforms
    assert "name" in transform.unresolved


def test_find_through_package_xml_under_the_package_roots(tmp_path: Path) -> None:
    package = tmp_path / "ws" / "src" / "some_folder"
    (package / "launch").mkdir(parents=True)
    (package / "package.xml").write_text("<package><name>my_robot</name></package>")
    (package / "launch" / "inc.launch").write_text(
        f'<launch><node {TF2} name="inc" args="0 0 0 0 0 0 a b"/></launch>'
    )
    xml = f"""
        <launch>
          <include file="$(find my_robot)/launch/inc.launch"/>
          <node {TF2} name="n" args="0 0 0 0 0 0 base $(find my_robot)_x"/>
          <node {TF2} name="m" args="0 0 0 0 0 0 base $(find absent)/x"/>
        </launch>"""
    roots = PackageIndex([str(tmp_path / "ws" / "src")])
    transforms = by_name(load(tmp_path, xml, packages=roots))
    assert transforms["inc"].path.endswith("inc.launch")
    assert transforms["n"].child_written == f"{package}/_x"
    absent = transforms["m"]
    assert absent.unresolved_names == ("child",)
    assert "package 'absent' not found" in absent.unresolved_reasons[0]


def test_find_without_package_roots_is_unresolved(tmp_path: Path) -> None:
    tree = load(tmp_path, """
        <launch>
          <include file="$(find my_robot)/launch/inc.launch"/>
        </launch>""")
    (diagnostic,) = tree.problems
    assert diagnostic.rule == "unresolved"
    assert "not followed" in diagnostic.message and "my_robot" in diagnostic.message


def test_env_and_optenv_read_only_the_given_mapping(tmp_path: Path) -> None:
    xml = f"""
        <launch>
          <node {TF2} name="n" args="0 0 0 0 0 0 $(env PARENT) $(optenv CHILD child_default)"/>
          <node {TF2} name="words" args="0 0 0 0 0 0 $(optenv CHILD two   words)"/>
        </launch>"""
    tree = load(tmp_path, xml)
    unset = by_name(tree)["n"]
    assert unset.unresolved_names == ("parent",) and unset.child == "child_default"
    assert by_name(tree)["words"].tokens[-2:] == ("two", "words")
    given = by_name(load(tmp_path, xml, env={"PARENT": "p", "CHILD": "c"}))["n"]
    assert (given.parent, given.child, given.unresolved_names) == ("p", "c", ())


def test_dirname_is_the_folder_of_the_file_holding_the_attribute(tmp_path: Path) -> None:
    (tmp_path / "sub").mkdir()
    (tmp_path / "sub" / "child.launch").write_text(f"""<launch>
      <arg name="from_parent"/>
      <node {TF2} name="c" args="0 0 0 0 0 0 $(arg from_parent) $(dirname)"/>
    </launch>""")
    tree = load(tmp_path, """
        <launch>
          <include file="$(dirname)/sub/child.launch">
            <arg name="from_parent" value="$(dirname)"/>
          </include>
        </launch>""")
    child = by_name(tree)["c"]
    assert (child.parent_written, child.child_written) == (str(tmp_path), str(tmp_path / "sub"))


def test_anon_names_follow_roslaunch_scoping(tmp_path: Path) -> None:
    (tmp_path / "inc.launch").write_text(
        f'<launch><node {TF2} name="$(anon n)" args="0 0 0 0 0 0 a inc"/></launch>'
    )
    tree = load(tmp_path, f"""
        <launch>
          <group ns="g1"><node {TF2} name="$(anon n)" args="0 0 0 0 0 0 a b1"/></group>
          <group ns="g2"><node {TF2} name="$(anon n)" args="0 0 0 0 0 0 a b2"/></group>
          <node {TF2} name="$(anon n)" args="0 0 0 0 0 0 a b3"/>
          <group ns="g3"><node {TF2} name="$(anon n)" args="0 0 0 0 0 0 a b4"/></group>
          <include file="$(dirname)/inc.launch"/>
        </launch>""")
    names = {t.child: t.name for t in tree.transforms}
    assert names == {"b1": "n_anon1", "b2": "n_anon2", "b3": "n_anon3", "b4": "n_anon3",
                     "inc": "n_anon4"}


def test_anon_counts_attributes_of_other_tags_in_order(tmp_path: Path) -> None:
    tree = load(tmp_path, f"""
        <launch>
          <param name="p" value="$(anon first)"/>
          <node {TF2} name="n" args="0 0 0 0 0 0 $(anon second) $(anon first)"/>
        </launch>""")
    transform = by_name(tree)["n"]
    assert (transform.parent, transform.child) == ("second_anon2", "first_anon1")


def test_nested_and_adjacent_substitutions(tmp_path: Path) -> None:
    tree = load(tmp_path, f"""
        <launch>
          <arg name="a" default="front"/>
          <arg name="b" default="_laser"/>
          <arg name="ab" default="$(arg a)$(arg b)"/>
          <node {TF2} name="n" args="0 0 0 0 0 0 $(arg ab) $(arg a)$(arg b)_$(arg a)"/>
          <node {TF2} name="m" args="0 0 0 0 0 0 $$(arg a) x"/>
        </launch>""")
    transforms = by_name(tree)
    assert (transforms["n"].parent, transforms["n"].child) == ("front_laser",
                                                                "front_laser_front")
    assert transforms["m"].parent == "$front"


def test_lexer_errors_are_roslaunch_errors_and_leave_holes(tmp_path: Path) -> None:
    tree = load(tmp_path, f"""
        <launch>
          <arg name="x" default="1"/>
          <node {TF2} name="n" args="0 0 0 0 0 0 a $(arg $(arg x))"/>
          <node {TF2} name="m" args="0 0 0 0 0 0 a $(unknown x)"/>
        </launch>""")
    messages = [d.message for d in tree.problems if d.rule == "roslaunch_error"]
    assert any("Dollar signs" in m for m in messages)
    assert any("Unknown substitution command [unknown x]" in m for m in messages)
    for transform in tree.transforms:
        assert "arity" in transform.unresolved or "child" in transform.unresolved
