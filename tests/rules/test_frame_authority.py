from __future__ import annotations

from typing import Callable, List, Tuple

from robot_ws import ws_lint

RULE = "frame_authority"
Lint = Callable[..., List[Tuple[str, int]]]
MAP_ODOM = ('<node pkg="tf2_ros" type="static_transform_publisher" name="t" '
            'args="0 0 0 0 0 0 map odom"/>')


def test_static_map_odom_in_an_included_file_and_odom_base_beside_ekf() -> None:
    found = ws_lint("demo_bringup/launch/navigation.launch", RULE)
    assert sorted((d.path.rsplit("/", 1)[-1], d.node) for d in found) == [
        ("fake_map.launch", "map_odom"), ("navigation.launch", "odom_base")]
    assert all("REP 105" in d.message for d in found)


def test_exclusive_alternatives_are_not_compared() -> None:
    assert ws_lint("demo_bringup/launch/alternatives.launch", RULE) == ()


def test_ros2_alternatives_decided_by_args() -> None:
    assert ws_lint("demo_ros2/launch/bringup.launch.py", RULE) == ()
    assert ws_lint("demo_ros2/launch/bringup.launch.py", RULE, {"sim": "false"}) == ()


def test_publish_tf_false_is_no_authority(lint: Lint) -> None:
    xml = (f'<launch><node pkg="amcl" type="amcl" name="amcl"><param name="tf_broadcast" '
           f'value="false"/></node>{MAP_ODOM}</launch>')
    assert lint(xml, RULE) == []


def test_robot_localization_map_world_frame(lint: Lint) -> None:
    xml = (f'<launch><node pkg="robot_localization" type="ekf_localization_node" name="ekf">'
           f'<param name="world_frame" value="map"/><param name="odom0" value="odom"/></node>\n'
           f'{MAP_ODOM}</launch>')
    assert lint(xml, RULE) == [(RULE, 2)]


def test_odometry_filter_does_not_own_map_odom(lint: Lint) -> None:
    xml = (f'<launch><node pkg="robot_localization" type="ekf_localization_node" name="ekf"/>'
           f'{MAP_ODOM}</launch>')
    assert lint(xml, RULE) == []


def test_ros2_amcl(lint: Lint) -> None:
    xml = ('<launch><node pkg="nav2_amcl" exec="amcl" name="amcl"/>\n'
           '<node pkg="tf2_ros" exec="static_transform_publisher" '
           'args="--frame-id map --child-frame-id odom"/></launch>')
    assert lint(xml, RULE) == [(RULE, 2)]


def test_hector_with_odom_frame_set_to_the_base_publishes_another_edge(lint: Lint) -> None:
    xml = ('<launch><arg name="odom_frame" default="base_link"/>'
           '<node pkg="hector_mapping" type="hector_mapping" name="hector">'
           '<param name="odom_frame" value="$(arg odom_frame)"/></node>\n'
           f'{MAP_ODOM}</launch>')
    assert lint(xml, RULE) == []
    assert lint(xml, RULE, {"odom_frame": "odom"}) == [(RULE, 2)]


def test_unknown_frame_parameter_leaves_the_node_out(lint: Lint) -> None:
    xml = ('<launch><arg name="f"/><node pkg="slam_toolbox" type="sync_slam_toolbox_node" '
           'name="slam"><param name="odom_frame" value="$(arg f)"/></node>\n'
           f'{MAP_ODOM}</launch>')
    assert lint(xml, RULE) == []


def test_switch_set_beside_the_node_by_its_private_name(lint: Lint) -> None:
    xml = ('<launch><node pkg="hector_mapping" type="hector_mapping" name="hector_mapping"/>'
           '<arg name="off" default="true"/><group if="$(arg off)">'
           '<param name="hector_mapping/pub_map_odom_transform" value="false"/></group>\n'
           f'{MAP_ODOM}</launch>')
    assert lint(xml, RULE) == []
    assert lint(xml, RULE, {"off": "false"}) == [(RULE, 2)]


def test_filter_without_world_frame_in_the_launch_file_is_left_out(lint: Lint) -> None:
    # ndt_gnss_localizer's "global_odom" EKF: world_frame comes from a YAML (map in a
    # dual-EKF setup), so the static odom -> base_link placeholder is what it needs.
    xml = ('<launch><rosparam command="load" file="/nonexistent/ekf.yaml"/>'
           '<node pkg="robot_localization" type="ekf_localization_node" name="ekf"/>\n'
           '<node pkg="tf2_ros" type="static_transform_publisher" name="t" '
           'args="0 0 0 0 0 0 odom base_link"/></launch>')
    assert lint(xml, RULE) == []


def test_filter_with_world_frame_odom_owns_odom_base(lint: Lint) -> None:
    xml = ('<launch><node pkg="robot_localization" type="ekf_localization_node" name="ekf">'
           '<param name="world_frame" value="odom"/><param name="imu0" value="imu"/></node>\n'
           '<node pkg="tf2_ros" type="static_transform_publisher" name="t" '
           'args="0 0 0 0 0 0 odom base_link"/></launch>')
    assert lint(xml, RULE) == [(RULE, 2)]
