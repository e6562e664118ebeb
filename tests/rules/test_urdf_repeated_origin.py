from __future__ import annotations

from _urdf import joint, link, lint_urdf, robot

RULE = "urdf_repeated_origin"
BOX = '<geometry><box size="1 1 1"/></geometry>'


def test_a_second_origin_in_a_visual() -> None:
    text = robot('<link name="a"><visual><origin rpy="1.57 0 0"/>\n<origin/>' + BOX
                 + "</visual></link>")
    (found,) = lint_urdf(text, RULE)
    assert found.line == 3 and "<visual> of link 'a'" in found.message
    assert found.severity.value == "info"
    assert lint_urdf(text.replace("\n<origin/>", ""), RULE) == ()


def test_collisions_inertials_and_joints() -> None:
    text = robot('<link name="a"><collision><origin/><origin/>' + BOX + "</collision>"
                 '<inertial><origin/><origin/><mass value="1"/></inertial></link>'
                 + link("b") + joint("j", "a", "b").replace("<parent", "<origin/><origin/><parent"))
    owners = sorted(d.node or "" for d in lint_urdf(text, RULE))
    assert owners == ["<collision> of link 'a'", "<inertial> of link 'a'", "joint 'j'"]


def test_two_visuals_each_with_one_origin_are_fine() -> None:
    # A link may have several <visual>s (urdfdom's visual_array), each with its origin.
    visual = "<visual><origin/>" + BOX + "</visual>"
    assert lint_urdf(robot(f'<link name="a">{visual}{visual}</link>'), RULE) == ()


def test_a_macro_called_twice_is_reported_once_where_it_is_written() -> None:
    """urdf_tutorial#22: the wheel macro's visual has two origins."""
    macro = ('<xacro:macro name="wheel" params="side"><link name="${side}_wheel"><visual>'
             '<origin rpy="1.57 0 0"/>\n<origin/>' + BOX + "</visual></link></xacro:macro>\n")
    text = robot(macro + '<xacro:wheel side="l"/>\n<xacro:wheel side="r"/>')
    (found,) = lint_urdf(text, RULE)
    assert found.line == 3 and found.related[0].line == 4  # the origin; the first call
