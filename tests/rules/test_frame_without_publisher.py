"""frame_without_publisher: a frame a node looks up that nothing publishes; only in a
closed tree, else one info naming the node that opens it."""

from __future__ import annotations

from launch_linter import LintOptions, lint_text
from launch_linter.model.diagnostic import Severity

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
