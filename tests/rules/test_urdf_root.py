from __future__ import annotations

from pathlib import Path

from _urdf import joint, link, lint_loaded, lint_urdf, robot

RULE = "urdf_root"


def test_two_root_links_quote_urdfdom() -> None:
    (found,) = lint_urdf(robot(link("base_link") + "\n" + link("gripper")), RULE)
    assert found.severity.value == "warning" and found.line == 3
    assert "Two root links found: [base_link] and [gripper]" in found.message
    assert found.related[0].line == 2


def test_urdfdom_names_the_roots_in_its_own_order() -> None:
    (found,) = lint_urdf(robot(link("z_base") + link("a_tool")), RULE)
    assert "[a_tool] and [z_base]" in found.message


def test_a_tree_has_one_root() -> None:
    text = robot(link("a") + link("b") + link("c") + joint("j1", "a", "b") + joint("j2", "b", "c"))
    assert lint_urdf(text, RULE) == ()


def test_no_root_when_the_joints_form_a_loop() -> None:
    (found,) = lint_urdf(robot(link("a") + link("b") + joint("j1", "a", "b")
                               + joint("j2", "b", "a")), RULE)
    assert "No root link found" in found.message


def test_a_joint_to_an_undefined_link_is_no_loop() -> None:
    """A fragment joining its only link to a base it does not define (smrr_description's
    camera.urdf): urdfdom stops on the missing parent link, not for want of a root, and
    urdf_missing_link reports that; a real loop beside it is still one."""
    fragment = robot(link("camera_link") + joint("camera_joint", "base_link", "camera_link"))
    assert lint_urdf(fragment, RULE) == ()
    assert [f.rule for f in lint_urdf(fragment, "urdf_missing_link")] == ["urdf_missing_link"]
    looped = robot(link("a") + link("b") + joint("j1", "a", "b") + joint("j2", "b", "a"))
    assert len(lint_urdf(looped, RULE)) == 1


def test_a_link_under_an_undecided_condition_is_no_certain_root(tmp_path: Path) -> None:
    text = robot('<xacro:arg name="gripper" default="true"/>' + link("base_link")
                 + '<xacro:if value="$(arg gripper)">' + link("gripper") + "</xacro:if>")
    assert lint_loaded(tmp_path, text, RULE, "gripper:=$(arg g)") == ()
    assert len(lint_loaded(tmp_path, text, RULE, "gripper:=true")) == 1
    assert lint_loaded(tmp_path, text, RULE, "gripper:=false") == ()


def test_an_expansion_not_followed_is_not_judged() -> None:
    text = robot(link("base_link") + '<xacro:include filename="missing.xacro"/>'
                 + link("arm_link"))
    assert lint_urdf(text, RULE) == ()


def test_loaded_by_a_launch_file_it_is_an_error(tmp_path: Path) -> None:
    (found,) = lint_loaded(tmp_path, robot(link("a") + link("b")), RULE)
    assert "robot_state_publisher stops at start-up" in found.message
    assert found.severity.value == "error"
    assert found.path.endswith("robot.urdf.xacro")


def test_without_a_publisher_a_loaded_description_is_not_read(tmp_path: Path) -> None:
    assert lint_loaded(tmp_path, robot(link("a") + link("b")), RULE, publisher=False) == ()


def test_a_wrapper_macro_that_does_not_forward_the_parent(tmp_path: Path) -> None:
    """The pattern of franka_ros issue 374 (written here, not copied): an arm macro joins
    its first link to ``connected_to`` only when that is given, and the wrapper that the
    cell calls with ``parent=`` does not pass it on, so the arm floats as a second root."""
    text = robot(
        '<xacro:macro name="arm" params="arm_id connected_to:=\'\'">'
        '<link name="${arm_id}_link0"/><link name="${arm_id}_link1"/>'
        '<joint name="${arm_id}_joint1" type="revolute"><parent link="${arm_id}_link0"/>'
        '<child link="${arm_id}_link1"/></joint>'
        '<xacro:unless value="${not connected_to}">'
        '<joint name="${arm_id}_joint_${connected_to}" type="fixed">'
        '<parent link="${connected_to}"/><child link="${arm_id}_link0"/></joint>'
        '</xacro:unless></xacro:macro>'
        '<xacro:macro name="robot" params="arm_id parent">'
        '<xacro:arm arm_id="${arm_id}"/></xacro:macro>'
        '<link name="world"/>\n<xacro:robot arm_id="panda_1" parent="world"/>')
    (found,) = lint_loaded(tmp_path, text, RULE)
    assert "Two root links found: [panda_1_link0] and [world]" in found.message
    fixed = text.replace('<xacro:arm arm_id="${arm_id}"/>',
                         '<xacro:arm arm_id="${arm_id}" connected_to="${parent}"/>')
    assert lint_loaded(tmp_path, fixed, RULE) == ()


def test_a_link_without_a_name_is_a_root_of_its_own() -> None:
    """urdfdom reads ``<link nmae="foo"/>`` as a link named '' ("No name given for the
    link.") and refuses two roots, [] and the robot's (ms-iot/ROSOnWindows#50)."""
    (found,) = lint_urdf(robot(link("camera_frame") + '\n<link nmae="foo"/>'), RULE)
    assert found.line == 3 and "Two root links found: [] and [camera_frame]" in found.message
    assert "without a name" in found.message and found.related[0].line == 2


def test_a_named_link_attached_to_the_tree_is_no_root_even_beside_an_unresolved_name(
        tmp_path: Path) -> None:
    text = robot(link("a") + link("b") + joint("j", "a", "b"))
    assert lint_urdf(text, RULE) == ()
    unknown = robot(link("a") + '<link name="${undefined_name}"/>')
    assert lint_loaded(tmp_path, unknown, RULE) == ()
