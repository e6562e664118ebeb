from __future__ import annotations

import time

from _urdf import joint, link, lint_urdf, robot

RULE = "urdf_plugin_outside_gazebo"
PLUGIN = ('<plugin name="jsp" filename="libgazebo_ros_joint_state_publisher.so">'
          '<jointName>wheel_joint</jointName></plugin>')
BODY = link("base_link") + link("wheel") + joint("wheel_joint", "base_link", "wheel",
                                                 "continuous")


def test_a_plugin_straight_under_robot_is_never_loaded() -> None:
    """steer_bot#4: the joint state plugin written after the </gazebo> it belonged in."""
    (found,) = lint_urdf(robot(BODY + "\n" + PLUGIN), RULE)
    assert found.line == 3 and found.severity.value == "warning"
    assert "'libgazebo_ros_joint_state_publisher.so'" in found.message
    assert lint_urdf(robot(BODY + "\n<gazebo>" + PLUGIN + "</gazebo>"), RULE) == ()


def test_a_sensor_straight_under_robot_too() -> None:
    (found,) = lint_urdf(robot(BODY + '\n<sensor name="lidar" type="ray"/>'), RULE)
    assert "<sensor> 'lidar'" in found.message
    inside = robot(BODY + '\n<gazebo reference="base_link"><sensor name="lidar" '
                          'type="ray"/></gazebo>')
    assert lint_urdf(inside, RULE) == ()


def test_urdfs_own_sensor_element_is_not_a_gazebo_sensor() -> None:
    """samples9, Fengming-Zhang/catkin_ws kejia.urdf: the wiki's urdf/XML/sensor form,
    fixed to its <parent link>, describes the laser; it was never meant for Gazebo."""
    urdf_sensor = ('\n<sensor name="big_laser" update_rate="40"><parent link="base_link"/>'
                   '<origin xyz="0 0.35 0.38" rpy="0 0 0"/><ray><horizontal samples="100" '
                   'resolution="1" min_angle="-1.57" max_angle="1.57"/></ray></sensor>')
    assert lint_urdf(robot(BODY + urdf_sensor), RULE) == ()
    gazebo_sensor = ('\n<sensor name="big_laser" type="ray"><update_rate>40</update_rate>'
                     '<ray><scan><horizontal><samples>100</samples></horizontal></scan>'
                     '</ray></sensor>')
    (found,) = lint_urdf(robot(BODY + gazebo_sensor), RULE)
    assert "<sensor> 'big_laser'" in found.message


def test_a_macro_plugin_is_reported_once_where_it_is_written() -> None:
    macro = f'<xacro:macro name="drive" params="n">{PLUGIN}</xacro:macro>\n'
    (found,) = lint_urdf(robot(BODY + macro + '<xacro:drive n="1"/>\n<xacro:drive n="2"/>'),
                         RULE)
    assert found.line == 2 and found.related[0].line == 3


def test_an_undecided_condition_is_not_judged() -> None:
    text = robot(BODY + '<xacro:arg name="sim" default="true"/>'
                        f'<xacro:if value="$(arg sim)">{PLUGIN}</xacro:if>')
    assert len(lint_urdf(text, RULE)) == 1  # decided by the default
    # The environment is not known: the plugin may not be there at all.
    assert lint_urdf(text.replace("$(arg sim)", "$(env SIM)"), RULE) == ()


def test_many_plugins_outside_are_read_in_linear_time() -> None:
    """Hostile: 20,000 <plugin> elements under <robot>, each one finding."""
    text = robot(BODY + "\n".join(
        f'<plugin name="p{i}" filename="libp{i}.so"/>' for i in range(20_000)))
    start = time.process_time()
    found = lint_urdf(text, RULE)
    assert time.process_time() - start < 30.0
    assert len(found) == 20_000
