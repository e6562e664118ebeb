"""node_second_parent: a frame a node's edge gives a second parent (fault, then fixed)."""

from __future__ import annotations

from typing import Callable, List, Tuple

RULE = "node_second_parent"
Lint = Callable[..., List[Tuple[str, int]]]


def test_ekf_base_link_under_the_urdf_footprint(lint: Lint) -> None:
    urdf = ("&lt;robot name='r'&gt;&lt;joint name='base_joint' type='fixed'&gt;&lt;parent "
            "link='base_footprint'/&gt;&lt;child link='base_link'/&gt;&lt;/joint&gt;"
            "&lt;/robot&gt;")
    fault = (f'<launch><param name="robot_description" value="{urdf}"/>'
             '<node pkg="robot_state_publisher" type="robot_state_publisher" name="rsp"/>\n'
             '<node pkg="robot_localization" type="ekf_localization_node" name="ekf">'
             '<param name="odom0" value="odom"/></node></launch>')
    assert lint(fault, RULE) == [(RULE, 2)]
    fixed = fault.replace('name="ekf">', 'name="ekf"><param name="base_link_frame" '
                                         'value="base_footprint"/>')
    assert lint(fixed, RULE) == []


def test_a_static_map_to_base_beside_localization_and_odometry(lint: Lint) -> None:
    fault = ('<launch><node pkg="gmapping" type="slam_gmapping" name="gmapping"/>'
             '<node pkg="rf2o_laser_odometry" type="rf2o_laser_odometry_node" name="rf2o"/>\n'
             '<node pkg="tf2_ros" type="static_transform_publisher" name="m" '
             'args="0 0 0 0 0 0 map base_link"/></launch>')
    assert lint(fault, RULE) == [(RULE, 2)]
    fixed = fault.replace("map base_link", "base_link laser")
    assert lint(fixed, RULE) == []


def test_two_nodes_giving_one_frame_two_parents(lint: Lint) -> None:
    xml = ('<launch><node pkg="robot_localization" type="ekf_localization_node" name="a">'
           '<param name="odom0" value="odom"/></node>\n'
           '<node pkg="rf2o_laser_odometry" type="rf2o_laser_odometry_node" name="rf2o">'
           '<param name="odom_frame_id" value="odom_laser"/></node></launch>')
    assert lint(xml, RULE) == [(RULE, 2)]
