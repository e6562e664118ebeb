from __future__ import annotations

from _urdf import joint, link, lint_urdf, robot

RULE = "urdf_missing_link"


def test_a_child_link_not_defined() -> None:
    (found,) = lint_urdf(robot(link("a") + "\n" + joint("j", "a", "b")), RULE)
    assert "child link [b] of joint [j] not found" in found.message and found.line == 3


def test_a_parent_link_not_defined_names_the_close_ones() -> None:
    (found,) = lint_urdf(robot(link("base_link") + link("b") + joint("j", "base", "b")), RULE)
    assert "parent link [base] of joint [j] not found" in found.message
    assert "(defined: 'base_link')" in found.message and found.related


def test_a_prefix_the_links_did_not_get() -> None:
    text = robot('<xacro:macro name="arm" params="prefix">'
                 '<link name="${prefix}base"/><link name="tool"/>'
                 '<joint name="${prefix}j" type="fixed"><parent link="${prefix}base"/>'
                 '<child link="${prefix}tool"/></joint></xacro:macro>'
                 '<xacro:arm prefix="r_"/>')
    (found,) = lint_urdf(text, RULE)
    assert "'r_tool'" in found.message and "'tool'" in found.message


def test_all_links_defined() -> None:
    assert lint_urdf(robot(link("a") + link("b") + joint("j", "a", "b")), RULE) == ()


def test_a_link_name_not_known_makes_nothing_provable() -> None:
    text = robot(link("a") + '<link name="$(env X)"/>' + joint("j", "a", "b"))
    assert lint_urdf(text, RULE) == ()
