"""Our xacro expander and URDF reader: features, unknowns and hostile input."""

from __future__ import annotations

from pathlib import Path

import pytest

from launch_linter import LintOptions, lint_paths
from launch_linter.frontends.robot.describe import RobotCache, xacro_command
from launch_linter.frontends.robot.urdf import joints_of
from launch_linter.frontends.robot.xacro import Expansion, expand
from launch_linter.model.robot import DescriptionKind, DescriptionSource, RobotJoint
from launch_linter.model.transform import Condition
from launch_linter.workspace.packages import PackageIndex

WS = Path(__file__).resolve().parent.parent / "fixtures" / "robot_ws"
HOSTILE = WS / "src" / "hostile" / "urdf"
HEAD = '<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">'


def run(tmp_path: Path, body: str, args: dict[str, str | None] | None = None
        ) -> Expansion:
    path = tmp_path / "r.xacro"
    path.write_text(HEAD + body + "</robot>", encoding="utf-8")
    return expand(str(path), args or {}, lambda _: None)


def joints(expansion: Expansion) -> list[RobotJoint]:
    assert expansion.root is not None
    source = DescriptionSource("x.launch", 1, 1, DescriptionKind.XACRO, "r.xacro")
    return joints_of(expansion.root, source, str, Condition())


def joint(parent: str, child: str, origin: str = "") -> str:
    return (f'<joint name="j" type="fixed"><parent link="{parent}"/><child link="{child}"/>'
            f'{origin}</joint>')


def test_unknown_arg_makes_the_frame_unresolved(tmp_path: Path) -> None:
    (found,) = joints(run(tmp_path, joint("$(arg p)base", "c")))
    assert found.parent is None and found.unresolved == ("parent",)
    assert "$(arg p)" in found.reasons[0]


def test_arg_given_with_an_unknown_value(tmp_path: Path) -> None:
    body = '<xacro:arg name="p" default="x_"/>' + joint("$(arg p)base", "c")
    (found,) = joints(run(tmp_path, body, {"p": None}))
    assert found.parent is None and "not known" in found.reasons[0]


def test_conditional_with_unknown_value_keeps_content_as_alternatives(tmp_path: Path) -> None:
    body = (f'<xacro:if value="$(arg a)">{joint("base_link", "x")}</xacro:if>'
            f'<xacro:unless value="$(arg a)">{joint("base_footprint", "x")}</xacro:unless>')
    first, second = joints(run(tmp_path, body, {"a": None}))
    assert not first.condition.always and first.condition.excludes(second.condition)


def test_escapes_and_python_are_not_run(tmp_path: Path) -> None:
    body = joint("a", "b", '<origin xyz="$${x} 0 0" rpy="${open(\'/etc/passwd\')} 0 0"/>')
    (found,) = joints(run(tmp_path, body))
    assert found.translation is None and found.rpy is None
    assert "open" in " ".join(found.reasons)


def test_circular_properties(tmp_path: Path) -> None:
    body = ('<xacro:property name="a" value="${b}"/><xacro:property name="b" value="${a}"/>'
            + joint("base", "c", '<origin xyz="${a} 0 0"/>'))
    (found,) = joints(run(tmp_path, body))
    assert found.translation is None and "circular" in found.reasons[0]


def test_unknown_macro_and_bad_parameters_are_problems(tmp_path: Path) -> None:
    body = ('<xacro:macro name="m" params="a"><link name="${a}"/></xacro:macro>'
            '<xacro:nope/><xacro:m b="1"/><xacro:m/>')
    messages = [p.message for p in run(tmp_path, body).problems]
    assert any("unknown macro 'nope'" in m for m in messages)
    assert any("invalid parameter 'b'" in m for m in messages)
    assert any("undefined parameters [a]" in m for m in messages)


@pytest.mark.parametrize("name, message", [
    ("recursive.xacro", "macros nested deeper"),
    ("cycle_a.xacro", "include cycle"),
    ("doubling.xacro", "longer than"),
    ("wide.xacro", "more than 100,000 elements"),
])
def test_hostile_descriptions_end_with_a_problem(name: str, message: str) -> None:
    expansion = expand(str(HOSTILE / name), {}, lambda _: None)
    assert expansion.root is None
    (problem,) = [p for p in expansion.problems if p.fatal]
    assert message in problem.message


def test_bombs_in_values_stay_unresolved() -> None:
    expansion = expand(str(HOSTILE / "bomb.xacro"), {}, lambda _: None)
    found = joints(expansion)
    assert [j.unresolved for j in found] == [("translation", "rotation"), ("child",)]


def test_hostile_launch_file_gives_diagnostics_not_a_crash() -> None:
    options = LintOptions(package_paths=(str(WS),), select=frozenset({"unresolved",
                                                                      "xacro_error"}))
    result = lint_paths([str(WS / "src" / "hostile" / "launch" / "hostile.launch")], options)
    text = "\n".join(d.message for d in result.diagnostics if d.rule == "unresolved")
    for expected in ("macros nested deeper", "include cycle", "longer than",
                     "not a xacro call", "URDF joint 'j'"):
        assert expected in text
    # missing.xacro is not in its package, which is found: xacro stops on it.
    missing, dunder = [d for d in result.diagnostics if d.rule == "xacro_error"]
    assert "no such file" in missing.message and missing.line == 7
    # bomb.xacro's ${__import__('os')...}: xacro's safe_eval refuses the name.
    assert "invalid name(s): __import__" in dunder.message


def test_variant_b_escape_keeps_literal_text() -> None:
    path = WS / "src" / "demo_description" / "urdf" / "features.urdf.xacro"
    found = joints(expand(str(path), {"variant": "b"}, lambda _: None))
    (last,) = [j for j in found if j.name == "variant_b_joint"]
    assert last.translation is None and "${not evaluated}" in last.reasons[0]


@pytest.mark.parametrize("command, file, args", [
    ("/opt/ros/noetic/share/xacro/xacro --inorder robot.xacro a:=1", "robot.xacro",
     (("a", "1"),)),
    ("python /opt/xacro/xacro.py robot.xacro", "robot.xacro", ()),
    ("rosrun xacro xacro robot.xacro b:=x -o out.urdf", "robot.xacro", (("b", "x"),)),
    ("xacro robot.xacro", "robot.xacro", ()),
])
def test_xacro_commands(command: str, file: str, args: object) -> None:
    parsed = xacro_command([(w, True) for w in command.split()])
    assert parsed == (file, args, None, False)


def test_an_unresolved_word_after_the_file_may_give_more_args() -> None:
    words = [("xacro", True), ("robot.xacro", True), ("a:=1", True), ("$(var extra)", False)]
    assert xacro_command(words) == ("robot.xacro", (("a", "1"),), None, True)


def test_not_xacro() -> None:
    assert xacro_command([("cat", True), ("robot.urdf", True)]) is None


def test_one_expansion_per_file_and_args() -> None:
    cache = RobotCache()
    index = PackageIndex([str(WS)])
    path = str(WS / "src" / "demo_description" / "urdf" / "robot.urdf.xacro")
    first = cache.expansion(path, (), index, {})
    assert cache.expansion(path, (), index, {}) is first
    assert cache.expansion(path, (("use_lidar", "false"),), index, {}) is not first
    assert len(cache) == 2


def test_an_expansion_is_reused_for_args_and_variables_it_never_reads(tmp_path: Path) -> None:
    path = tmp_path / "r.xacro"
    path.write_text('<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">'
                    '<xacro:arg name="a" default="x"/><link name="$(arg a)$(optenv V)"/>'
                    '</robot>')
    cache = RobotCache()
    index = PackageIndex([str(tmp_path)])
    first = cache.expansion(str(path), (("unused", "1"),), index, {"W": "1"})
    assert cache.expansion(str(path), (("unused", "2"),), index, {"W": "2"}) is first
    assert cache.expansion(str(path), (("a", "x"),), index, {}) is not first
    assert cache.expansion(str(path), (), index, {"V": "1"}) is not first
    assert len(cache) == 3


def test_quoted_defaults_call_and_namespaced_includes(tmp_path: Path) -> None:
    (tmp_path / "parts.xacro").write_text("""<robot xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:macro name="mount" params="parent child xyz:='0.1 0 0.2' prefix:=''">
    <link name="${prefix}${child}"/>
    <joint name="${prefix}${child}_joint" type="fixed">
      <origin xyz="${xyz}"/><parent link="${parent}"/><child link="${prefix}${child}"/>
    </joint>
  </xacro:macro>
</robot>""")
    (tmp_path / "robot.xacro").write_text("""<robot name="r"
  xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:include filename="parts.xacro" ns="parts"/>
  <xacro:property name="which" value="parts.mount"/>
  <link name="base"/>
  <xacro:parts.mount parent="base" child="lidar"/>
  <xacro:call macro="${which}" parent="base" child="imu" xyz="1 2 3"/>
</robot>""")
    expansion = expand(str(tmp_path / "robot.xacro"), {}, lambda _: None)
    assert [p.message for p in expansion.problems] == []
    assert expansion.root is not None
    joints = {j.attrib["name"]: j for j in expansion.root.children if j.tag == "joint"}
    origins = {name: [c.attrib["xyz"] for c in j.children if c.tag == "origin"]
               for name, j in joints.items()}
    assert origins == {"lidar_joint": ["0.1 0 0.2"], "imu_joint": ["1 2 3"]}


def test_an_unprefixed_insert_block_leaves_the_origin_unknown(tmp_path: Path) -> None:
    """xacro before 1.14 inserted <insert_block> written without the prefix, later
    versions keep it as a literal element: the joint's origin depends on the version
    (mastering_ros's xtion macro, written for Indigo)."""
    macro = ('<xacro:macro name="m" params="*o">{}</xacro:macro>'
             '<xacro:m><origin rpy="1 0 0"/></xacro:m>')
    legacy = macro.format(joint("a", "b", '<insert_block name="o"/>'))
    (found,) = joints(run(tmp_path, legacy))
    assert found.rpy is None and found.unresolved == ("translation", "rotation")
    assert "xacro before 1.14" in found.reasons[0]
    source = DescriptionSource("x.launch", 1, 1, DescriptionKind.XACRO, "r.xacro")
    noetic = run(tmp_path, legacy).root
    assert noetic is not None
    (dropped,) = joints_of(noetic, source, str, Condition(), distro_known=True)
    assert dropped.rpy == (0.0, 0.0, 0.0) and dropped.unresolved == ()
    prefixed = macro.format(joint("a", "b", '<xacro:insert_block name="o"/>'))
    (inserted,) = joints(run(tmp_path, prefixed))
    assert inserted.rpy == (1.0, 0.0, 0.0) and inserted.unresolved == ()
