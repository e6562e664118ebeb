from __future__ import annotations

from robot_ws import ws_lint

RULE = "conflicting_transform"


def test_two_files_publish_one_mount_with_different_values() -> None:
    (found,) = ws_lint("demo_bringup/launch/cameras.launch", RULE)
    assert found.path.endswith("camera_driver.launch") and found.line == 2
    assert found.related[0].path.endswith("cameras.launch")
    assert "'base_link' -> 'rear_camera'" in found.message


def test_urdf_joint_and_ros2_static_transform_disagree() -> None:
    (found,) = ws_lint("demo_ros2/launch/bringup.launch.py", RULE)
    assert "URDF joint 'sonar_joint'" in found.message
    assert found.related[0].path.endswith("robot.urdf.xacro")


def test_the_urdf_part_switched_off_by_an_arg_is_not_compared() -> None:
    assert ws_lint("demo_ros2/launch/bringup.launch.py", RULE, {"lidar": "true"}) == ()


def test_same_values_in_two_sources_are_no_conflict(lint_tree) -> None:  # type: ignore[no-untyped-def]
    node = ('<node pkg="tf2_ros" type="static_transform_publisher" name="{}" '
            'args="0.1 0 0 0 0 0 base_link laser"/>')
    files = {"a.launch": f'<launch>{node.format("a")}<include file="$(dirname)/b.launch"/>'
                         '</launch>',
             "b.launch": f'<launch>{node.format("b")}</launch>'}
    assert lint_tree(files, "a.launch", RULE) == ()


def test_within_one_file_it_is_dup_sig(lint) -> None:  # type: ignore[no-untyped-def]
    xml = ('<launch><node pkg="tf2_ros" type="static_transform_publisher" name="a" '
           'args="0.1 0 0 0 0 0 base_link laser"/><node pkg="tf2_ros" '
           'type="static_transform_publisher" name="b" args="0.2 0 0 0 0 0 base_link laser"/>'
           '</launch>')
    assert lint(xml, RULE) == []


def test_a_static_transform_that_freezes_a_movable_joint(lint) -> None:  # type: ignore[no-untyped-def]
    urdf = ("&lt;robot name='r'&gt;&lt;joint name='arm' type='revolute'&gt;&lt;parent "
            "link='base_link'/&gt;&lt;child link='arm_link'/&gt;&lt;/joint&gt;&lt;/robot&gt;")
    xml = (f'<launch><param name="robot_description" value="{urdf}"/>'
           '<node pkg="robot_state_publisher" type="robot_state_publisher" name="rsp"/>'
           '<node pkg="joint_state_publisher" type="joint_state_publisher" name="jsp"/>\n'
           '<node pkg="tf2_ros" type="static_transform_publisher" name="a" '
           'args="0 0 0 0 0 0 base_link arm_link"/></launch>')
    assert lint(xml, RULE) == [(RULE, 2)]


def test_a_movable_joint_without_joint_states_is_not_published(lint) -> None:  # type: ignore[no-untyped-def]
    """robot_state_publisher sends a movable joint only from /joint_states: with nothing
    publishing them, the static transform is the wheel's only publisher."""
    urdf = ("&lt;robot name='r'&gt;&lt;joint name='wheel' type='continuous'&gt;&lt;parent "
            "link='base_link'/&gt;&lt;child link='wheel_link'/&gt;&lt;/joint&gt;&lt;/robot&gt;")
    xml = (f'<launch><param name="robot_description" value="{urdf}"/>'
           '<node pkg="robot_state_publisher" type="robot_state_publisher" name="rsp"/>\n'
           '<node pkg="tf2_ros" type="static_transform_publisher" name="a" '
           'args="0 0 0 0 0 0 base_link wheel_link"/></launch>')
    assert lint(xml, RULE) == []


def test_thousands_of_one_transform_in_one_file_and_one_other(lint_tree) -> None:  # type: ignore[no-untyped-def]
    node = ('<node pkg="tf2_ros" type="static_transform_publisher" name="{}" '
            'args="0.{} 0 0 0 0 0 base_link laser"/>')
    many = "".join(node.format(f"a{i}", i + 1) for i in range(3_000))
    files = {"a.launch": f'<launch>{many}<include file="$(dirname)/b.launch"/></launch>',
             "b.launch": f'<launch>{node.format("b", 1)}</launch>'}
    (found,) = lint_tree(files, "a.launch", RULE)
    # The first of a.launch with other values than b.launch's (0.1) is the one named.
    assert found.path.endswith("b.launch") and "static transform 'a1'" in found.message
