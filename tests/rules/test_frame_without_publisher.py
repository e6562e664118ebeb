"""frame_without_publisher: a frame a node looks up that nothing publishes; only in a
closed tree, else one info naming the node that opens it."""

from __future__ import annotations

import time
from pathlib import Path

from launch_linter import LintOptions, lint_paths, lint_text
from launch_linter.model.diagnostic import Severity
from launch_linter.rules.frame_without_publisher import WHOLE_ROBOT_LEVEL

RULE = "frame_without_publisher"
STATIC = ('<node pkg="tf2_ros" type="static_transform_publisher" name="base" '
          'args="0 0 0 0 0 0 odom base_footprint"/>')


def found(xml: str) -> list[tuple[int, Severity, str]]:
    result = lint_text(xml, "a.launch", LintOptions(package_paths=(), select=frozenset({RULE})))
    return [(d.line, d.severity, d.message) for d in result.diagnostics]


def test_a_base_frame_nothing_publishes_in_a_closed_tree() -> None:
    xml = f'<launch>{STATIC}\n<node pkg="gmapping" type="slam_gmapping" name="g"/></launch>'
    ((line, severity, message),) = found(xml)
    assert (line, severity) == (2, Severity.INFO) and "'base_link'" in message
    fixed = xml.replace('name="g"/>', 'name="g"><param name="base_frame" '
                                      'value="base_footprint"/></node>')
    assert found(fixed) == []


def test_an_unknown_node_opens_the_tree_once() -> None:
    xml = (f'<launch>{STATIC}\n<node pkg="gmapping" type="slam_gmapping" name="g"/>'
           '<node pkg="amcl" type="amcl" name="a"/>'
           '<node pkg="my_driver" type="driver" name="d"/></launch>')
    ((_, severity, message),) = found(xml)
    assert severity == Severity.INFO and "my_driver/driver" in message
    assert "'base_link'" in message


def test_a_costmap_sensor_frame_nothing_publishes_is_reported_at_its_param() -> None:
    """A costmap observation source's sensor_frame is a frame move_base looks up; the
    finding is on the <param> that names it."""
    laser = ('<node pkg="tf2_ros" type="static_transform_publisher" name="laser" '
             'args="0 0 0 0 0 0 base_link base_laser_link"/>')
    xml = ('<launch>' + laser + '\n<node pkg="tf2_ros" type="static_transform_publisher" '
           'name="b" args="0 0 0 0 0 0 map odom"/><node pkg="tf2_ros" '
           'type="static_transform_publisher" name="c" args="0 0 0 0 0 0 odom base_link"/>\n'
           '<node pkg="move_base" type="move_base" name="move_base">\n'
           '<param name="global_costmap/observation_sources" value="scan"/>\n'
           '<param name="global_costmap/scan/sensor_frame" value="base_laser"/>\n'
           '</node></launch>')
    ((line, severity, message),) = found(xml)
    assert (line, severity) == (5, Severity.INFO) and "'base_laser'" in message
    assert found(xml.replace('value="base_laser"', 'value="base_laser_link"')) == []


# A whole robot: its description published by robot_state_publisher (read completely),
# its odometry (an EKF sending odom -> base_footprint) and its localization (amcl).
WHOLE_URDF = """<robot name="r">
  <link name="base_footprint"/><link name="base_link"/><link name="wheel"/>
  <joint name="base_joint" type="fixed">
    <parent link="base_footprint"/><child link="base_link"/>
  </joint>
  <joint name="wheel_joint" type="continuous">
    <parent link="base_link"/><child link="wheel"/>
  </joint>
</robot>
"""
WHOLE = """<launch>
  <param name="robot_description" textfile="$(dirname)/r.urdf"/>
  <node pkg="robot_state_publisher" type="robot_state_publisher" name="rsp"/>
  <node pkg="joint_state_publisher" type="joint_state_publisher" name="jsp"/>
  <node pkg="robot_localization" type="ekf_localization_node" name="ekf">
    <param name="world_frame" value="odom"/><param name="odom0" value="wheel_odom"/>
    <param name="base_link_frame" value="base_footprint"/>
  </node>
  <node pkg="amcl" type="amcl" name="amcl"/>
  <node pkg="move_base" type="move_base" name="move_base">
    <param name="local_costmap/global_frame" value="odom"/>
    <param name="local_costmap/robot_base_frame" value="{base}"/>
  </node>
</launch>
"""


def whole(tmp_path: Path, launch: str, urdf: str = WHOLE_URDF
          ) -> list[tuple[int, Severity, str]]:
    (tmp_path / "r.urdf").write_text(urdf)
    (tmp_path / "a.launch").write_text(launch)
    options = LintOptions(package_paths=(), select=frozenset({RULE}))
    result = lint_paths([str(tmp_path / "a.launch")], options)
    return [(d.line, d.severity, d.message) for d in result.diagnostics]


def test_a_frame_the_whole_robot_lacks_is_found_at_the_whole_robot_level(
        tmp_path: Path) -> None:
    ((line, severity, message),) = whole(tmp_path, WHOLE.format(base="base"))
    assert (line, severity) == (12, WHOLE_ROBOT_LEVEL) and "'base'" in message
    assert "brings up the whole robot" in message and "robot_localization" in message
    assert whole(tmp_path, WHOLE.format(base="base_link")) == []


def test_a_tree_without_the_robot_description_or_odometry_stays_at_info(
        tmp_path: Path) -> None:
    """A navigation launch beside a bringup started on its own: the robot's publishers
    are elsewhere, so the frame may be theirs."""
    launch = WHOLE.format(base="base")
    cases = {
        "robot_state_publisher": launch.replace(
            '<node pkg="robot_state_publisher" type="robot_state_publisher" name="rsp"/>',
            ""),
        "odometry": launch.replace('type="ekf_localization_node"', 'type="navsat_transform_node"'),
    }
    for why, reduced in cases.items():
        found = whole(tmp_path, reduced)
        assert {s for _, s, _ in found} == {Severity.INFO}, why
        assert any("'base'" in message and "whole robot" not in message
                   and why in message for _, _, message in found), why
    unread = launch.replace('textfile="$(dirname)/r.urdf"',
                            'textfile="$(find absent_pkg)/r.urdf"')
    found = whole(tmp_path, unread)
    assert {s for _, s, _ in found} == {Severity.INFO}
    assert all("not read completely" in message for _, _, message in found)


def test_a_global_frame_needs_a_localization_in_the_tree(tmp_path: Path) -> None:
    launch = WHOLE.format(base="base_link").replace(
        '<param name="local_costmap/global_frame" value="odom"/>',
        '<param name="local_costmap/global_frame" value="odom"/>'
        '<param name="global_costmap/global_frame" value="world"/>')
    ((_, severity, message),) = whole(tmp_path, launch)
    assert "'world'" in message and "amcl/amcl" in message and "whole robot" in message
    alone = launch.replace('<node pkg="amcl" type="amcl" name="amcl"/>', "")
    ((_, severity, message),) = whole(tmp_path, alone)
    assert severity == Severity.INFO and "nothing in this tree localizes" in message


def test_a_urdf_frame_dropped_for_want_of_joint_states_stays_at_info(
        tmp_path: Path) -> None:
    """robot_state_publisher sends a movable joint only from /joint_states, which a
    driver started on its own may publish: the frame is not misnamed."""
    launch = WHOLE.format(base="wheel")
    assert whole(tmp_path, launch) == []
    without = launch.replace(
        '<node pkg="joint_state_publisher" type="joint_state_publisher" name="jsp"/>', "")
    ((_, severity, message),) = whole(tmp_path, without)
    assert severity == Severity.INFO and "/joint_states" in message


def test_a_sensor_drivers_default_frame_stays_at_info_unless_the_driver_runs(
        tmp_path: Path) -> None:
    """camera_link is the RealSense driver's default frame: a camera launch started on its
    own gives it. When the tree starts the driver under another frame, nothing will."""
    launch = WHOLE.format(base="camera_link")
    ((_, severity, message),) = whole(tmp_path, launch)
    assert severity == Severity.INFO and "realsense2_camera" in message
    assert "whole robot" not in message
    driver = ('<node pkg="realsense2_camera" type="realsense2_camera_node" name="cam">'
              '<param name="base_frame_id" value="front_camera_link"/></node>\n</launch>')
    messages = [m for _, _, m in whole(tmp_path, launch.replace("</launch>", driver))]
    assert any("'camera_link'" in m and "whole robot" in m for m in messages), messages
    # Connected to the robot, the driver's own frame is published.
    connected = launch.replace("</launch>", driver).replace(
        'value="camera_link"', 'value="front_camera_link"')
    assert [m for _, _, m in whole(tmp_path, connected) if "front_camera_link" in m] == []


def test_twenty_thousand_conditional_publishers_and_lookups_stay_linear(
        tmp_path: Path) -> None:
    """20,000 robot_state_publishers and 20,000 move_base nodes, each under a test of its
    own: which publisher runs with which node is found by the node's tests, not by
    scanning every publisher for every lookup (4 * 10^8 comparisons, a minute)."""
    count = 20_000
    args = "".join(f'<arg name="r{i}"/><arg name="m{i}"/>' for i in range(count))
    nodes = "".join(
        f'<node pkg="robot_state_publisher" type="robot_state_publisher" name="rsp{i}" '
        f'if="$(arg {"m" if i % 2 else "r"}{i})"/>'
        f'<node pkg="move_base" type="move_base" name="mb{i}" if="$(arg m{i})">'
        f'<param name="local_costmap/robot_base_frame" value="base"/></node>'
        for i in range(count))
    launch = WHOLE.format(base="base").replace(
        '<node pkg="robot_state_publisher" type="robot_state_publisher" name="rsp"/>',
        args + nodes)
    started = time.process_time()
    found = whole(tmp_path, launch)
    assert time.process_time() - started < 60
    assert len(found) == count + 1
    # The odd move_base nodes run with a robot_state_publisher of their own test.
    assert sum("brings up the whole robot" in m for _, _, m in found) == count // 2
