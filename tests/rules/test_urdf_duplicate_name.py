from __future__ import annotations

from pathlib import Path

from _urdf import joint, link, lint_urdf, robot

from launch_linter import LintOptions, lint_paths

RULE = "urdf_duplicate_name"


def test_a_link_defined_twice() -> None:
    (found,) = lint_urdf(robot(link("a") + "\n" + link("a")), RULE)
    assert "link 'a' is not unique." in found.message and found.line == 3
    assert "already defined at line 2" in found.message


def test_a_joint_defined_twice() -> None:
    text = robot(link("a") + link("b") + joint("j", "a", "b") + "\n" + joint("j", "a", "b"))
    (found,) = lint_urdf(text, RULE)
    assert "joint 'j' is not unique." in found.message


def test_a_link_and_a_joint_may_share_a_name() -> None:
    assert lint_urdf(robot(link("a") + link("b") + joint("b", "a", "b")), RULE) == ()


def test_a_macro_instantiated_twice_with_one_prefix() -> None:
    text = robot('<xacro:macro name="arm" params="prefix">\n'
                 '<link name="${prefix}link"/></xacro:macro>\n'
                 '<xacro:arm prefix="left_"/>\n<xacro:arm prefix="left_"/>')
    # Each instance is shown at its call: the second call, pointing at the first.
    (found,) = lint_urdf(text, RULE)
    assert "already defined at line" in found.message and found.node == "left_link"
    assert found.line == found.related[0].line + 1
    assert lint_urdf(text.replace('"left_"/>\n<xacro:arm prefix="left_"',
                                  '"left_"/>\n<xacro:arm prefix="right_"'), RULE) == ()


def test_exclusive_branches_are_not_compared() -> None:
    text = robot('<xacro:arg name="x" default="true"/>'
                 '<xacro:if value="$(arg x)">' + link("a") + "</xacro:if>"
                 '<xacro:unless value="$(arg x)">' + link("a") + "</xacro:unless>")
    assert lint_urdf(text, RULE, args={"x": "true"}) == ()


MATERIAL = '<material name="blue"><color rgba="0 0 1 1"/></material>'


def test_a_top_level_material_defined_twice_even_alike() -> None:
    # urdfdom's parseURDF refuses a second top-level material of a name, whatever it holds.
    (found,) = lint_urdf(robot(link("a") + MATERIAL + "\n" + MATERIAL), RULE)
    assert "material 'blue' is not unique." in found.message and found.line == 3
    assert found.related[0].line == 2


def test_materials_inside_visuals_are_not_compared() -> None:
    visual = f'<visual><geometry><box size="1 1 1"/></geometry>{MATERIAL}</visual>'
    text = robot(MATERIAL + f'<link name="a">{visual}</link><link name="b">{visual}</link>'
                 + joint("j", "a", "b"))
    assert lint_urdf(text, RULE) == ()


def test_two_materials_without_a_name() -> None:
    # urdfdom keeps a nameless top-level material as '' and refuses the second one.
    (found,) = lint_urdf(robot(link("a") + "<material/>\n<material/>"), RULE)
    assert "material '' is not unique." in found.message


def test_a_material_in_a_macro_called_twice() -> None:
    """motoman#314: each call of the arm macro makes its top-level material again."""
    text = robot('<xacro:macro name="arm" params="prefix">\n' + MATERIAL
                 + '<link name="${prefix}link"/></xacro:macro>\n'
                 '<xacro:arm prefix="left_"/>\n<xacro:arm prefix="right_"/>')
    (found,) = lint_urdf(text, RULE)
    assert found.line == 5 and found.node == "blue"
    assert [r.line for r in found.related] == [4, 3]  # the first call, the definition
    assert "each call of the macro makes the material written at line 3" in found.message


def test_a_file_included_twice(tmp_path: Path) -> None:
    """gazebo_ros_l515#7: a materials file included by a part and by its includer."""
    (tmp_path / "materials.xacro").write_text(robot(MATERIAL), encoding="utf-8")
    (tmp_path / "part.xacro").write_text(robot('<xacro:include filename="materials.xacro"/>'),
                                         encoding="utf-8")
    top = tmp_path / "robot.urdf.xacro"
    top.write_text(robot('<xacro:include filename="part.xacro"/>\n' + link("a") + "\n"
                         '<xacro:include filename="materials.xacro"/>'), encoding="utf-8")
    options = LintOptions(package_paths=(), select=frozenset({RULE}))
    (found,) = lint_paths([str(top)], options).diagnostics
    assert found.path.endswith("robot.urdf.xacro") and found.line == 4
    assert "is made again by this include" in found.message
    first, definition = found.related
    assert first.path.endswith("part.xacro") and first.line == 2
    assert definition.path.endswith("materials.xacro") and definition.line == 2
    top.write_text(robot('<xacro:include filename="part.xacro"/>\n' + link("a")),
                   encoding="utf-8")
    assert lint_paths([str(top)], options).diagnostics == ()
