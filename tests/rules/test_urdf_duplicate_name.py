from __future__ import annotations

from _urdf import joint, link, lint_urdf, robot

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
