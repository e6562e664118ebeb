from __future__ import annotations

import time
from pathlib import Path
from typing import Callable, List, Tuple

from _urdf import joint, link, lint_urdf, robot
from hypothesis import given, settings
from hypothesis import strategies as st

from launch_linter import LintOptions, lint_paths, lint_text
from launch_linter.model import Diagnostic, Location

Lint = Callable[..., List[Tuple[str, int]]]
LintDiagnostics = Callable[..., Tuple[Diagnostic, ...]]
LintTree = Callable[..., Tuple[Diagnostic, ...]]

RULE = "multiple_parents"


def node(name: str, parent: str, child: str, attrs: str = "") -> str:
    return (
        f'<node pkg="tf2_ros" type="static_transform_publisher" name="{name}" '
        f'args="0 0 0.1 0 0 0 {parent} {child}" {attrs}/>'
    )


def test_two_parents(lint_diagnostics: LintDiagnostics) -> None:
    xml = "\n".join([
        "<launch>",
        node("a", "base_link", "laser"),
        node("b", "base_footprint", "laser"),
        "</launch>",
    ])
    (found,) = lint_diagnostics(xml, RULE)
    assert found.line == 3 and found.related == (Location("test.launch", 2, 1),)
    assert found.message.startswith("frame 'laser' gets 2 parents")


def test_three_parents_once_each_later_node(lint_diagnostics: LintDiagnostics) -> None:
    xml = "\n".join([
        "<launch>",
        node("a", "base_link", "laser"),
        node("b", "base_footprint", "laser"),
        node("c", "odom", "laser"),
        "</launch>",
    ])
    found = lint_diagnostics(xml, RULE)
    assert [(d.line, len(d.related)) for d in found] == [(3, 1), (4, 2)]


def test_slashes_do_not_make_a_second_parent(lint: Lint) -> None:
    xml = "\n".join([
        "<launch>", node("a", "/base_link", "laser"), node("b", "base_link", "/laser"),
        "</launch>",
    ])
    assert lint(xml, RULE) == []


def test_a_chain_passes(lint: Lint) -> None:
    xml = "\n".join([
        "<launch>",
        node("a", "map", "odom"), node("b", "odom", "base_link"), node("c", "base_link", "laser"),
        "</launch>",
    ])
    assert lint(xml, RULE) == []


def test_conditional_presence_says_may(lint_diagnostics: LintDiagnostics) -> None:
    xml = "\n".join([
        "<launch>",
        '<arg name="sim"/>',
        node("a", "base_link", "laser"),
        node("b", "base_footprint", "laser", 'if="$(arg sim)"'),
        "</launch>",
    ])
    (found,) = lint_diagnostics(xml, RULE)
    assert "may get 2 parents" in found.message


def test_exclusive_conditions_pass(lint: Lint) -> None:
    xml = "\n".join([
        "<launch>",
        '<arg name="sim"/>',
        node("a", "base_link", "laser", 'unless="$(arg sim)"'),
        node("b", "base_footprint", "laser", 'if="$(arg sim)"'),
        "</launch>",
    ])
    assert lint(xml, RULE) == []
    assert lint(xml, RULE, {"sim": "false"}) == []


def test_across_includes(lint_tree: LintTree) -> None:
    driver = "<launch>\n" + node("laser_tf", "base_link", "laser") + "\n</launch>\n"
    robot = "\n".join([
        "<launch>",
        node("mount_tf", "base_footprint", "laser"),
        '<include file="$(dirname)/driver.launch"/>',
        "</launch>",
    ])
    (found,) = lint_tree({"driver.launch": driver, "robot.launch": robot}, "robot.launch", RULE)
    assert found.path.endswith("driver.launch") and found.line == 2
    assert found.related[0].path.endswith("robot.launch")
    assert "robot.launch:2" in found.message


def test_unresolved_parent_is_silent(lint: Lint) -> None:
    xml = "\n".join([
        "<launch>",
        '<arg name="p"/>',
        node("a", "base_link", "laser"),
        node("b", "$(arg p)", "laser"),
        "</launch>",
    ])
    assert lint(xml, RULE) == []
    assert lint(xml, RULE, {"p": "base_link"}) == []
    assert lint(xml, RULE, {"p": "odom"}) == [(RULE, 4)]


@settings(max_examples=60, deadline=None)
@given(st.lists(st.tuples(st.integers(0, 4), st.integers(0, 4)).filter(lambda e: e[0] != e[1]),
                max_size=8))
def test_one_report_per_later_transform_with_a_new_parent(edges: list[tuple[int, int]]) -> None:
    xml = "\n".join(
        ["<launch>", *(node(f"t{i}", f"f{p}", f"f{c}") for i, (p, c) in enumerate(edges)),
         "</launch>"]
    )
    options = LintOptions(package_paths=(), select=frozenset({RULE}))
    found = lint_text(xml, "test.launch", options).diagnostics
    expected = [
        i + 2 for i, (p, c) in enumerate(edges)
        if any(c2 == c and p2 != p for p2, c2 in edges[:i])
    ]
    assert [d.line for d in found] == expected


def test_urdf_joint_and_included_launch_file() -> None:
    from robot_ws import ws_lint

    (found,) = ws_lint("demo_bringup/launch/robot.launch", RULE)
    assert found.path.endswith("sensors.launch")
    assert "URDF joint 'laser_joint'" in found.message
    # The joint a macro made: at its call in the robot's file, then in the macro.
    assert found.related[0].path.endswith("robot.urdf.xacro")
    assert found.related[1].path.endswith("common.xacro")


def test_urdf_part_switched_off_by_an_arg() -> None:
    from robot_ws import ws_lint

    assert ws_lint("demo_bringup/launch/robot.launch", RULE, {"lidar": "false"}) == ()


def test_description_without_state_publisher_is_not_published() -> None:
    from robot_ws import ws_lint

    assert ws_lint("demo_description/launch/upload.launch", RULE) == ()
    (found,) = ws_lint("demo_description/launch/plain.launch", RULE)
    assert "URDF joint 'gps_joint'" in found.message


def test_a_frame_with_thousands_of_parents_gets_bounded_findings(
    lint_diagnostics: LintDiagnostics,
) -> None:
    count = 5_000
    xml = "\n".join(["<launch>", *(node(f"t{i}", f"p{i}", "shared") for i in range(count)),
                     "</launch>"])
    found = lint_diagnostics(xml, RULE)
    assert len(found) == count - 1
    last = found[-1]
    assert last.message.startswith(f"frame 'shared' gets {count} parents: 'p{count - 1}' here")
    assert f"and {count - 1 - 5} more;" in last.message and len(last.message) < 400
    assert len(last.related) == 10 and last.related[0].line == 2


def test_the_same_parent_many_times_is_one_parent(lint: Lint) -> None:
    xml = "\n".join(["<launch>", *(node(f"t{i}", "base", "laser") for i in range(3_000)),
                     node("other", "odom", "laser"), "</launch>"])
    assert lint(xml, RULE) == [(RULE, 3_002)]


def test_two_parent_joints_in_one_description_say_which_one_kdl_keeps() -> None:
    text = robot(link("a") + link("b") + link("c") + joint("z_first", "a", "c")
                 + joint("j3", "a", "b") + "\n" + joint("a_second", "b", "c"))
    (found,) = lint_urdf(text, "multiple_parents")
    assert "keeps one: 'c' under 'a' by joint 'z_first', the name that sorts last" \
        in found.message


def _robot_group(ns: str, parent: str) -> str:
    urdf = (f"&lt;robot name='{ns}'&gt;&lt;link name='{parent}'/&gt;&lt;link name='flange'/&gt;"
            f"&lt;joint name='{parent}-flange' type='fixed'&gt;&lt;parent link='{parent}'/&gt;"
            f"&lt;child link='flange'/&gt;&lt;/joint&gt;&lt;/robot&gt;")
    return (f'<group ns="{ns}"><param name="robot_description" value="{urdf}"/>'
            f'<node pkg="robot_state_publisher" type="robot_state_publisher" name="rsp"/>'
            f'</group>')


def test_two_robots_sharing_a_frame_name_are_left_to_robot_frame_collision() -> None:
    # precision trial 3, ros-industrial fanuc tests/roslaunch_test.xml: each robot variant
    # in its own namespace; 'flange' is under link_6 in one URDF and link_5 in the other.
    options = LintOptions(package_paths=(),
                          select=frozenset({RULE, "robot_frame_collision"}))
    xml = f"<launch>{_robot_group('r1', 'link_6')}\n{_robot_group('r2', 'link_5')}</launch>"
    found = lint_text(xml, "test.launch", options).diagnostics
    assert [d.rule for d in found] == ["robot_frame_collision"]
    # A static transform that gives 'flange' a third parent is still a second parent.
    with_static = xml.replace("</launch>", "\n" + node("t", "base_link", "flange") + "</launch>")
    found = lint_text(with_static, "test.launch", options).diagnostics
    assert [d.rule for d in found].count(RULE) == 1


def stp(name: str, args: str) -> str:
    return f'<node pkg="tf2_ros" type="static_transform_publisher" name="{name}" args="{args}"/>'


def test_parents_that_place_the_frame_at_one_pose_are_info(
        lint_diagnostics: LintDiagnostics) -> None:
    """precision trial 7 (leo rover): a static base_footprint -> lidar republishing the
    pose the robot's base_footprint -> base_link -> lidar gives: tf2 keeps one parent per
    frame, and either answers every lookup the same."""
    xml = "\n".join([
        "<launch>",
        stp("base", "0 0 0.1 1.5707963267948966 0 0 base_footprint base_link"),
        stp("lidar", "0.2 0 0.3 0 0 0 base_link lidar"),
        # (0.2, 0, 0.3) turned by the yaw of pi/2 is (0, 0.2, 0.3), then 0.1 up.
        stp("lidar_again", "0 0.2 0.4 1.5707963267948966 0 0 base_footprint lidar"),
        "</launch>",
    ])
    (found,) = lint_diagnostics(xml, RULE)
    assert found.severity.value == "info" and found.line == 4
    assert "same pose relative to 'base_footprint'" in found.message
    moved = xml.replace("0 0.2 0.4 1.5707963267948966", "0.2 0 0.4 1.5707963267948966")
    (wrong,) = lint_diagnostics(moved, RULE)
    assert wrong.severity.value == "error" and "same pose" not in wrong.message
    turned = xml.replace("0 0.2 0.4 1.5707963267948966 0 0 base_footprint",
                         "0 0.2 0.4 0 0 0 base_footprint")
    assert lint_diagnostics(turned, RULE)[0].severity.value == "error"


def test_a_way_up_through_a_frame_of_two_parents_is_not_composed(
        lint_diagnostics: LintDiagnostics) -> None:
    # base_link has two parents itself: which one tf2 keeps decides the pose: no proof.
    xml = "\n".join([
        "<launch>",
        stp("a", "0 0 0 0 0 0 base_footprint base_link"),
        stp("b", "0 0 0 0 0 0 odom base_link"),
        stp("c", "0 0 0.3 0 0 0 base_link lidar"),
        stp("d", "0 0 0.3 0 0 0 base_footprint lidar"),
        "</launch>",
    ])
    found = lint_diagnostics(xml, RULE)
    assert [d.severity.value for d in found] == ["error", "error"]


def test_a_long_chain_above_each_parent_is_followed_a_bounded_way(
        lint_diagnostics: LintDiagnostics) -> None:
    """Hostile: 20,000 frames in a chain above the two parents: each way up stops after
    MAX_DEPTH frames."""
    chain = [stp(f"c{i}", f"0 0 0 0 0 0 f{i + 1} f{i}") for i in range(20_000)]
    xml = "\n".join(["<launch>", *chain, stp("p", "0 0 1 0 0 0 f0 a"),
                     stp("q", "0 0 0 0 0 0 a b"), stp("x", "0 0 1 0 0 0 a lidar"),
                     stp("y", "0 0 1 0 0 0 b lidar"), "</launch>"])
    started = time.process_time()
    (found,) = lint_diagnostics(xml, RULE)
    assert time.process_time() - started < 60
    assert found.severity.value == "info"  # b is a at the same place: same pose


def test_joints_of_one_description_placing_a_link_at_one_pose_are_a_warning(
        tmp_path: Path) -> None:
    """staubli_experimental#37: tool0 under link_6 and under flange (itself at identity
    under link_6): tf agrees, but a URDF link has one parent joint; a static transform
    repeating a pose stays info (the test above)."""
    urdf = tmp_path / "robot.urdf"
    urdf.write_text("""<robot name="r">
  <link name="link_6"/><link name="flange"/><link name="tool0"/>
  <joint name="link_6-flange" type="fixed"><parent link="link_6"/><child link="flange"/>
    <origin xyz="0 0 0" rpy="0 0 0"/></joint>
  <joint name="joint_6-tool0" type="fixed"><parent link="link_6"/><child link="tool0"/>
    <origin xyz="0 0 0" rpy="0 0 0"/></joint>
  <joint name="flange-tool0" type="fixed"><parent link="flange"/><child link="tool0"/>
    <origin xyz="0 0 0" rpy="0 0 0"/></joint>
</robot>
""", encoding="utf-8")
    options = LintOptions(package_paths=(), select=frozenset({RULE}))
    (found,) = lint_paths([str(urdf)], options).diagnostics
    assert found.severity.value == "warning" and "same pose" in found.message
    moved = urdf.read_text(encoding="utf-8").replace(
        '<child link="tool0"/>\n    <origin xyz="0 0 0" rpy="0 0 0"/></joint>\n</robot>',
        '<child link="tool0"/>\n    <origin xyz="0 0 0.1" rpy="0 0 0"/></joint>\n</robot>')
    urdf.write_text(moved, encoding="utf-8")
    (wrong,) = lint_paths([str(urdf)], options).diagnostics
    assert wrong.severity.value == "error"
