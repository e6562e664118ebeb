"""The ROS 1 loader's walk: conditions, namespaces, includes, unresolved values, locations."""

from __future__ import annotations

import textwrap
from pathlib import Path

import pytest

from launch_linter.frontends import ros1
from launch_linter.frontends.dispatch import load_tree
from launch_linter.frontends.ros1 import LoadOptions
from launch_linter.model.launch import FileStatus, LaunchTree
from launch_linter.model.transform import StaticTransform

TF2 = 'pkg="tf2_ros" type="static_transform_publisher"'


def write(path: Path, xml: str) -> Path:
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(textwrap.dedent(xml).strip() + "\n")
    return path


def load(tmp_path: Path, xml: str, **options: object) -> LaunchTree:
    path = write(tmp_path / "t.launch", xml)
    return load_tree(str(path), LoadOptions(**options))  # type: ignore[arg-type]


def by_name(tree: LaunchTree) -> dict[str | None, StaticTransform]:
    return {t.name: t for t in tree.transforms}


def messages(tree: LaunchTree, rule: str) -> list[str]:
    return [d.message for d in tree.problems if d.rule == rule]


# --- if / unless -------------------------------------------------------------------------


def test_if_unless_truthiness(tmp_path: Path) -> None:
    tree = load(tmp_path, f"""
        <launch>
          <node if="true" {TF2} name="a" args="0 0 0 0 0 0 p a"/>
          <node if="0" {TF2} name="b" args="0 0 0 0 0 0 p b"/>
          <node unless=" False " {TF2} name="c" args="0 0 0 0 0 0 p c"/>
          <node unless="1" {TF2} name="d" args="0 0 0 0 0 0 p d"/>
          <group if="false"><node {TF2} name="e" args="0 0 0 0 0 0 p e"/></group>
          <group unless="false"><node {TF2} name="f" args="0 0 0 0 0 0 p f"/></group>
        </launch>""")
    assert [t.name for t in tree.transforms] == ["a", "c", "f"]
    assert all(t.condition.always for t in tree.transforms)
    assert tree.problems == ()


def test_if_that_is_not_a_boolean_is_a_roslaunch_error(tmp_path: Path) -> None:
    tree = load(tmp_path, f"""
        <launch>
          <node if="yes" {TF2} name="a" args="0 0 0 0 0 0 p a"/>
          <node if="true" unless="true" {TF2} name="b" args="0 0 0 0 0 0 p b"/>
        </launch>""")
    errors = messages(tree, "roslaunch_error")
    assert any("yes is not a 'bool' type" in m for m in errors)
    assert any("cannot set both 'if' and 'unless'" in m for m in errors)


def test_unresolved_condition_is_kept_as_the_presence_condition(tmp_path: Path) -> None:
    tree = load(tmp_path, f"""
        <launch>
          <group if="$(arg sim)">
            <node unless="$(arg real)" {TF2} name="a" args="0 0 0 0 0 0 p a"/>
          </group>
          <node if="$(arg sim)" {TF2} name="b" args="0 0 0 0 0 0 p b"/>
          <node unless="$(arg sim)" {TF2} name="c" args="0 0 0 0 0 0 p c"/>
        </launch>""")
    transforms = by_name(tree)
    a, b, c = transforms["a"], transforms["b"], transforms["c"]
    assert a.condition.describe() == "if='$(arg sim)' and unless='$(arg real)'"
    assert a.unresolved_names == ()
    assert b.condition.excludes(c.condition)
    assert not a.condition.excludes(b.condition)


def test_conditional_arg_idiom_is_not_a_redeclaration(tmp_path: Path) -> None:
    xml = f"""
        <launch>
          <arg name="sim" default="false"/>
          <arg if="$(arg sim)" name="parent" value="sim_base"/>
          <arg unless="$(arg sim)" name="parent" value="real_base"/>
          <node {TF2} name="n" args="0 0 0 0 0 0 $(arg parent) laser"/>
        </launch>"""
    assert by_name(load(tmp_path, xml))["n"].parent == "real_base"
    assert by_name(load(tmp_path, xml, args={"sim": "true"}))["n"].parent == "sim_base"
    unknown = load(tmp_path, xml.replace('default="false"', ""))
    transform = by_name(unknown)["n"]
    assert transform.unresolved_names == ("parent",)
    assert "unresolved condition" in transform.unresolved_reasons[0]
    assert messages(unknown, "roslaunch_error") == []


def test_an_arg_declared_twice_is_a_roslaunch_error(tmp_path: Path) -> None:
    tree = load(tmp_path, """
        <launch>
          <arg name="x" default="1"/>
          <arg name="x" default="2"/>
        </launch>""")
    assert messages(tree, "roslaunch_error") == ["arg 'x' has already been declared"]


# --- namespaces ----------------------------------------------------------------------------


def test_group_and_node_namespaces(tmp_path: Path) -> None:
    tree = load(tmp_path, f"""
        <launch>
          <group ns="a">
            <group ns="b">
              <node {TF2} name="n1" args="0 0 0 0 0 0 p c1"/>
              <node ns="c" {TF2} name="n2" args="0 0 0 0 0 0 p c2"/>
              <node ns="/abs" {TF2} name="n3" args="0 0 0 0 0 0 p c3"/>
              <node ns="/" {TF2} name="n4" args="0 0 0 0 0 0 p c4"/>
            </group>
            <group ns="d//e"><node {TF2} name="n6" args="0 0 0 0 0 0 p c6"/></group>
          </group>
          <group ns="/r/"><node ns="s/" {TF2} name="n5" args="0 0 0 0 0 0 p c5"/></group>
          <node {TF2} name="n7" args="0 0 0 0 0 0 p c7"/>
        </launch>""")
    namespaces = {t.name: t.namespace for t in tree.transforms}
    assert namespaces == {"n1": "/a/b/", "n2": "/a/b/c/", "n3": "/abs/", "n4": "/",
                          "n6": "/a/d/e/", "n5": "/r/s/", "n7": "/"}


def test_root_namespace_from_the_command_line(tmp_path: Path) -> None:
    xml = f'<launch><node {TF2} name="n" args="0 0 0 0 0 0 p c"/></launch>'
    assert load(tmp_path, xml, args={"__ns": "robot1"}).transforms[0].namespace == "/robot1/"
    ros = load(tmp_path, xml, env={"ROS_NAMESPACE": "/r2"})
    assert ros.transforms[0].namespace == "/r2/"


def test_bad_namespaces_are_roslaunch_errors(tmp_path: Path) -> None:
    tree = load(tmp_path, f"""
        <launch>
          <group ns=""><node {TF2} name="a" args="0 0 0 0 0 0 p a"/></group>
          <group ns="~private"><node {TF2} name="b" args="0 0 0 0 0 0 p b"/></group>
          <node ns="~" {TF2} name="c" args="0 0 0 0 0 0 p c"/>
          <node {TF2} name="with/slash" args="0 0 0 0 0 0 p d"/>
        </launch>""")
    errors = messages(tree, "roslaunch_error")
    assert "<group> tag has an empty 'ns' attribute" in errors
    assert "cannot turn [~private] into a global name" in errors
    assert "cannot turn [~] into a global name" in errors
    assert "node name cannot contain a namespace: with/slash" in errors


def test_unresolved_namespace(tmp_path: Path) -> None:
    tree = load(tmp_path, f"""
        <launch>
          <group ns="$(arg robot)"><node {TF2} name="n" args="0 0 0 0 0 0 p c"/></group>
        </launch>""")
    transform = tree.transforms[0]
    assert transform.namespace == "/$(arg robot)/"
    assert transform.unresolved_names == ("namespace",)


def test_duplicate_node_names_are_a_roslaunch_error(tmp_path: Path) -> None:
    tree = load(tmp_path, f"""
        <launch>
          <node {TF2} name="same" args="0 0 0 0 0 0 p a"/>
          <group ns="/"><node {TF2} name="same" args="0 0 0 0 0 0 p b"/></group>
          <group ns="other"><node {TF2} name="same" args="0 0 0 0 0 0 p c"/></group>
          <node if="false" {TF2} name="same" args="0 0 0 0 0 0 p d"/>
        </launch>""")
    (duplicate,) = [d for d in tree.problems if d.rule == "roslaunch_error"]
    assert duplicate.message == "roslaunch file contains multiple nodes named [/same]"
    assert duplicate.line == 3
    assert [(r.line, r.column) for r in duplicate.related] == [(2, 3)]
    assert len(tree.transforms) == 3


@pytest.mark.parametrize("conditions, reported", [
    (('if="$(arg bswap)"', 'unless="$(arg bswap)"'), False),
    (('if="$(arg bswap)"', 'if="$(arg other)"'), True),
    (('', 'unless="$(arg bswap)"'), True),
])
def test_same_name_under_exclusive_conditions_is_no_duplicate(
        tmp_path: Path, conditions: tuple[str, str], reported: bool) -> None:
    # precision trial 3, fanuc_driver robot_state.launch: one node name, picked by
    # if/unless="$(arg use_bswap)", was "multiple nodes named [/joint_state]".
    first, second = conditions
    tree = load(tmp_path, f"""
        <launch>
          <arg name="bswap"/><arg name="other"/>
          <node {first} pkg="fanuc_driver" type="robot_state_bswap" name="joint_state"/>
          <node {second} pkg="fanuc_driver" type="robot_state" name="joint_state"/>
        </launch>""")
    duplicates = messages(tree, "roslaunch_error")
    assert duplicates == (["roslaunch file contains multiple nodes named [/joint_state]"]
                          if reported else [])


# --- includes ------------------------------------------------------------------------------


def test_include_passes_args_and_checks_them(tmp_path: Path) -> None:
    write(tmp_path / "inc" / "child.launch", f"""
        <launch>
          <arg name="parent"/>
          <arg name="child" default="child_default"/>
          <node {TF2} name="inc_$(arg child)" args="1 2 3 0 0 0 $(arg parent) $(arg child)"/>
        </launch>""")
    tree = load(tmp_path, """
        <launch>
          <arg name="top" default="top_frame"/>
          <include file="$(dirname)/inc/child.launch">
            <arg name="parent" value="$(arg top)"/>
          </include>
          <include file="inc/child.launch" ns="second">
            <arg name="parent" value="p2"/>
            <arg name="child" default="given"/>
          </include>
          <include file="inc/child.launch" ns="third">
            <arg name="parent" value="p3"/>
            <arg name="nobody" value="x"/>
          </include>
          <include file="inc/child.launch" ns="fourth"/>
        </launch>""")
    transforms = {(t.namespace, t.name): t for t in tree.transforms}
    first = transforms[("/", "inc_child_default")]
    assert (first.parent, first.child) == ("top_frame", "child_default")
    assert first.path.endswith("child.launch") and first.line == 4
    assert first.included_from is not None and first.included_from[1] == 3
    assert transforms[("/second/", "inc_given")].parent == "p2"
    errors = messages(tree, "roslaunch_error")
    assert any("unused args [nobody]" in m for m in errors)
    assert any("requires the 'parent' arg to be set" in m for m in errors)
    fourth = transforms[("/fourth/", "inc_child_default")]
    assert fourth.unresolved_names == ("parent",)


def test_included_file_does_not_see_the_parents_args(tmp_path: Path) -> None:
    write(tmp_path / "child.launch", f"""
        <launch><node {TF2} name="c" args="0 0 0 0 0 0 $(arg secret) x"/></launch>""")
    tree = load(tmp_path, """
        <launch>
          <arg name="secret" default="s"/>
          <include file="$(dirname)/child.launch"/>
        </launch>""")
    assert tree.transforms[0].unresolved_names == ("parent",)
    assert any("requires the 'secret' arg" in m for m in messages(tree, "roslaunch_error"))


def test_pass_all_args(tmp_path: Path) -> None:
    write(tmp_path / "child.launch", f"""
        <launch>
          <arg name="robot" default="child_default"/>
          <arg name="mode" value="child_mode"/>
          <node {TF2} name="pass_$(arg robot)" args="0 0 0 0 0 0 $(arg robot) $(arg mode)"/>
          <node {TF2} name="cli_$(arg robot)" args="0 0 0 0 0 0 $(arg robot) $(arg cli)"/>
        </launch>""")
    tree = load(tmp_path, """
        <launch>
          <arg name="robot" default="r1"/>
          <arg name="mode" default="parent_mode"/>
          <include file="$(dirname)/child.launch" pass_all_args="true"/>
          <include file="$(dirname)/child.launch" pass_all_args="true" ns="o">
            <arg name="robot" value="r2"/>
          </include>
        </launch>""", args={"cli": "from_cli"})
    transforms = {(t.namespace, t.name): t for t in tree.transforms}
    assert transforms[("/", "pass_r1")].child == "child_mode"
    assert transforms[("/o/", "pass_r2")].parent == "r2"
    assert transforms[("/", "cli_r1")].child == "from_cli"
    assert messages(tree, "roslaunch_error") == []


def test_include_cycle_is_reported_once_and_the_walk_goes_on(tmp_path: Path) -> None:
    write(tmp_path / "a.launch", f"""
        <launch>
          <node {TF2} name="in_a" args="0 0 0 0 0 0 p a"/>
          <include file="$(dirname)/b.launch"/>
        </launch>""")
    write(tmp_path / "b.launch", '<launch><include file="$(dirname)/a.launch"/></launch>')
    tree = load_tree(str(tmp_path / "a.launch"), LoadOptions())
    (cycle,) = messages(tree, "roslaunch_error")
    assert cycle.startswith("include cycle:") and cycle.count("a.launch") == 2
    assert [t.name for t in tree.transforms] == ["in_a"]


def test_missing_include_is_a_roslaunch_error(tmp_path: Path) -> None:
    tree = load(tmp_path, f"""
        <launch>
          <include file="$(dirname)/nowhere.launch"/>
          <include if="false" file="$(dirname)/skipped_so_not_checked.launch"/>
          <node {TF2} name="after" args="0 0 0 0 0 0 p a"/>
        </launch>""")
    (error,) = messages(tree, "roslaunch_error")
    assert "included file not found" in error and "nowhere.launch" in error
    assert [t.name for t in tree.transforms] == ["after"]


def test_relative_include_from_the_including_folder(tmp_path: Path) -> None:
    node = f'<node {TF2} name="x" args="0 0 0 0 0 0 a b"/>'
    write(tmp_path / "sub" / "x.launch", f"<launch>{node}</launch>")
    tree = load(tmp_path, '<launch><include file="sub/x.launch"/></launch>')
    assert [t.name for t in tree.transforms] == ["x"]


def test_include_depth_is_bounded(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(ros1, "MAX_INCLUDE_DEPTH", 3)
    for level in range(6):
        write(tmp_path / f"l{level}.launch", f"""
            <launch>
              <node {TF2} name="n{level}" args="0 0 0 0 0 0 p c{level}"/>
              <include file="$(dirname)/l{level + 1}.launch"/>
            </launch>""")
    tree = load_tree(str(tmp_path / "l0.launch"), LoadOptions())
    assert [t.name for t in tree.transforms] == ["n0", "n1", "n2"]
    assert any("not followed" in m for m in messages(tree, "unresolved"))


def test_nesting_is_bounded(tmp_path: Path) -> None:
    depth = ros1.MAX_NESTING + 20
    inner = f'<node {TF2} name="deep" args="0 0 0 0 0 0 p c"/>'
    tree = load(tmp_path, "<launch>" + "<group>" * depth + inner + "</group>" * depth + "</launch>")
    assert tree.transforms == ()
    assert any("nested deeper" in m for m in messages(tree, "unresolved"))


# --- unresolved values and locations -----------------------------------------------------


def test_unresolved_fields_reasons_and_condition(tmp_path: Path) -> None:
    tree = load(tmp_path, """
        <launch>
          <node if="$(arg use)" pkg="$(arg tf_pkg)" type="static_transform_publisher"
                name="$(arg name)" args="$(arg x) 0 0 0 0 0 base $(env CHILD)"/>
        </launch>""")
    (transform,) = tree.transforms
    assert transform.unresolved_names == ("name", "package", "translation", "child")
    assert [r.split(":")[0] for r in transform.unresolved_reasons] == [
        "$(arg name)", "$(arg x)", "$(env CHILD)", "$(arg tf_pkg)",
    ]
    assert transform.condition.describe() == "if='$(arg use)'"
    # 'use', declared nowhere, is also said (roslaunch refuses without use:=...).
    (info,) = [d for d in tree.problems
               if d.rule == "unresolved" and "requires the 'use' arg" not in d.message]
    assert "$(env CHILD)" in info.message and info.node == "$(arg name)"
    assert transform.parent == "base"


def test_other_packages_and_types_are_not_transforms(tmp_path: Path) -> None:
    tree = load(tmp_path, """
        <launch>
          <node pkg="tf2" type="static_transform_publisher" name="a" args="0 0 0 0 0 0 p a"/>
          <node pkg="tf" type="tf_echo" name="b" args="a b"/>
          <node pkg="$(arg p)" type="$(arg t)" name="c" args="0 0 0 0 0 0 p c"/>
          <node pkg="$(arg p)" type="static_transform_publisher" name="d" args="0 0 0 0 0 0 p d"/>
        </launch>""")
    assert [t.name for t in tree.transforms] == ["d"]


def test_location_is_the_line_and_column_of_the_node_element(tmp_path: Path) -> None:
    path = tmp_path / "loc.launch"
    path.write_text(
        "<launch>\n"
        "  <!-- launch-linter: comment -->\n"
        f"\t\t<node {TF2} name=\"a\"\n"
        '     args="0 0 0\n 0 0 0 p c"/>\n'
        f"  <group><node {TF2} name=\"b\" args=\"0 0 0 0 0 0 p d\"/></group>\n"
        "</launch>\n"
    )
    tree = load_tree(str(path), LoadOptions())
    assert [(t.name, t.line, t.column) for t in tree.transforms] == [("a", 3, 3), ("b", 6, 10)]
    assert tree.comments[0].text == " launch-linter: comment "


def test_files_not_launch_files(tmp_path: Path) -> None:
    robot = load(tmp_path, "<robot><link name='a'/></robot>")
    assert robot.status is FileStatus.PARSE_ERROR
    assert "no <launch> element" in messages(robot, "parse_error")[0]
    node = f"<node {TF2} name='n' args='0 0 0 0 0 0 a b'/>"
    nested = load(tmp_path, f"<robot><launch>{node}</launch></robot>")
    assert [t.name for t in nested.transforms] == ["n"]
    two = load(tmp_path, "<launch><group><launch/></group></launch>")
    assert messages(two, "parse_error") == ["more than one <launch> element"]


def test_launch_element_conditions(tmp_path: Path) -> None:
    node = f'<node {TF2} name="n" args="0 0 0 0 0 0 a b"/>'
    ignored = load(tmp_path, f'<launch if="false">{node}</launch>')
    assert [t.name for t in ignored.transforms] == ["n"]
    assert ignored.problems == ()
    substituted = load(tmp_path, '<launch if="$(arg x)"/>')
    assert messages(substituted, "roslaunch_error")


def test_unreadable_file(tmp_path: Path) -> None:
    tree = load_tree(str(tmp_path / "missing.launch"), LoadOptions())
    assert tree.status is FileStatus.UNREADABLE
    assert tree.problems[0].rule == "parse_error"


def test_an_unresolved_namespace_names_the_substitution_that_blocks_it() -> None:
    from launch_linter import lint_text

    result = lint_text(
        '<launch><arg name="robot"/><group ns="$(arg robot)">'
        '<node pkg="tf2_ros" type="static_transform_publisher" name="t" '
        'args="0 0 0 0 0 0 a b"/></group></launch>'
    )
    (transform,) = result.transforms
    assert transform.unresolved_names == ("namespace",)
    assert any("$(arg robot)" in reason for reason in transform.unresolved_reasons)
    (diagnostic,) = [d for d in result.diagnostics if d.rule == "unresolved"]
    assert "$(arg robot)" in diagnostic.message
