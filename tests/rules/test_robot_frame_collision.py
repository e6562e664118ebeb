"""robot_frame_collision: one robot file included per robot without frame prefixes."""

from __future__ import annotations

from pathlib import Path

from launch_linter.engine import LintOptions, lint_paths

RULE = "robot_frame_collision"
ROBOT = ('<launch>\n<param name="robot_description" value="&lt;robot name=\'r\'&gt;'
         '&lt;joint name=\'j\' type=\'fixed\'&gt;&lt;parent link=\'base_link\'/&gt;'
         '&lt;child link=\'laser\'/&gt;&lt;/joint&gt;&lt;/robot&gt;"/>\n'
         '<node pkg="robot_state_publisher" type="robot_state_publisher" name="rsp"/>\n'
         '</launch>\n')


def run(tmp_path: Path, fleet: str) -> list[tuple[str, str, int]]:
    (tmp_path / "robot.launch").write_text(ROBOT)
    (tmp_path / "fleet.launch").write_text(fleet)
    options = LintOptions(package_paths=(), select=frozenset({RULE}))
    result = lint_paths([str(tmp_path / "fleet.launch")], options)
    return [(d.rule, Path(d.path).name, d.line) for d in result.diagnostics]


def test_two_namespaced_robots_without_a_prefix(tmp_path: Path) -> None:
    fault = ('<launch><group ns="r1"><include file="$(dirname)/robot.launch"/></group>'
             '<group ns="r2"><include file="$(dirname)/robot.launch"/></group></launch>')
    # At the second robot's publisher (line 3), where the prefix is missing.
    assert run(tmp_path, fault) == [(RULE, "robot.launch", 3)]
    fixed = fault.replace('<group ns="r1">', '<group ns="r1"><param name="tf_prefix" '
                                             'value="r1"/>')
    assert run(tmp_path, fixed) == []


def test_the_finding_names_the_description_beside_its_publisher(tmp_path: Path) -> None:
    fault = ('<launch><group ns="r1"><include file="$(dirname)/robot.launch"/></group>'
             '<group ns="r2"><include file="$(dirname)/robot.launch"/></group></launch>')
    (tmp_path / "robot.launch").write_text(ROBOT)
    (tmp_path / "fleet.launch").write_text(fault)
    options = LintOptions(package_paths=(), select=frozenset({RULE}))
    (found,) = lint_paths([str(tmp_path / "fleet.launch")], options).diagnostics
    assert found.severity.name == "ERROR"
    assert [(Path(r.path).name, r.line) for r in found.related] == [("robot.launch", 2)]


def test_a_description_read_by_no_one_publisher_stays_at_its_param(tmp_path: Path) -> None:
    """Two publishers in the namespace the description is set in: which one reads it is
    not one answer, so the finding stays at the description."""
    robot = ROBOT.replace('name="rsp"/>', 'name="rsp"/>\n<node pkg="robot_state_publisher" '
                                          'type="robot_state_publisher" name="rsp2"/>')
    (tmp_path / "robot.launch").write_text(robot)
    fleet = ('<launch><group ns="r1"><include file="$(dirname)/robot.launch"/></group>'
             '<group ns="r2"><include file="$(dirname)/robot.launch"/></group></launch>')
    (tmp_path / "fleet.launch").write_text(fleet)
    options = LintOptions(package_paths=(), select=frozenset({RULE}))
    found = lint_paths([str(tmp_path / "fleet.launch")], options).diagnostics
    assert [(Path(d.path).name, d.line) for d in found] == [("robot.launch", 2)]


def test_one_robot_is_silent(tmp_path: Path) -> None:
    assert run(tmp_path, '<launch><include file="$(dirname)/robot.launch"/></launch>') == []


def test_a_ros2_frame_prefix_given_to_ros1_publishers_is_no_prefix(tmp_path: Path) -> None:
    """ROS 1 robot_state_publisher reads tf_prefix, not frame_prefix
    (ros/robot_state_publisher#192): the robots' frames still collide."""
    robot = ROBOT.replace('name="rsp"/>', 'name="rsp"><param name="frame_prefix" '
                                          'value="$(arg p)"/></node>')
    (tmp_path / "robot.launch").write_text(robot.replace("<launch>\n", '<launch>\n<arg name="p"/>'))
    fleet = ('<launch><group ns="r1"><include file="$(dirname)/robot.launch">'
             '<arg name="p" value="r1"/></include></group>'
             '<group ns="r2"><include file="$(dirname)/robot.launch">'
             '<arg name="p" value="r2"/></include></group></launch>')
    (tmp_path / "fleet.launch").write_text(fleet)
    options = LintOptions(package_paths=(), select=frozenset({RULE}))
    found = lint_paths([str(tmp_path / "fleet.launch")], options).diagnostics
    assert [(d.rule, Path(d.path).name) for d in found] == [(RULE, "robot.launch")]
    (tmp_path / "robot.launch").write_text(
        robot.replace("<launch>\n", '<launch>\n<arg name="p"/>').replace("frame_prefix",
                                                                         "tf_prefix"))
    assert lint_paths([str(tmp_path / "fleet.launch")], options).diagnostics == ()


def test_a_tree_roslaunch_refuses_runs_no_robot(tmp_path: Path) -> None:
    """husky's multi_husky_playpen.launch passes ``multimaster`` to a spawn file that no
    longer declares it: roslaunch refuses the tree, so no two robots run."""
    fleet = ('<launch><group ns="r1"><include file="$(dirname)/robot.launch"/></group>'
             '<group ns="r2"><include file="$(dirname)/robot.launch">{}</include></group>'
             '</launch>')
    assert run(tmp_path, fleet.format("")) == [(RULE, "robot.launch", 3)]
    assert run(tmp_path, fleet.format('<arg name="multimaster" value="true"/>')) == []


def _package(tmp_path: Path, cmake: str) -> Path:
    (tmp_path / "package.xml").write_text("<package format='2'><name>cell</name></package>")
    (tmp_path / "CMakeLists.txt").write_text(cmake)
    (tmp_path / "tests").mkdir()
    return tmp_path / "tests" / "fleet.launch"


def test_a_parse_check_aggregate_is_not_one_system(tmp_path: Path) -> None:
    """abb's tests/roslaunch_test_*.xml: one group per launch file, only parsed by
    roslaunch_add_file_check and never installed."""
    (tmp_path / "robot.launch").write_text(ROBOT)
    fleet = ('<launch><group ns="a"><include file="$(dirname)/../robot.launch"/></group>'
             '<group ns="b"><include file="$(dirname)/../robot.launch"/></group></launch>')
    options = LintOptions(package_paths=(), select=frozenset({RULE}))
    checked = ("roslaunch_add_file_check(tests/fleet.launch USE_TEST_DEPENDENCIES)\n"
               "install(DIRECTORY launch urdf DESTINATION ${CATKIN_PACKAGE_SHARE_DESTINATION})\n")
    root = _package(tmp_path, checked)
    root.write_text(fleet)
    assert lint_paths([str(root)], options).diagnostics == ()
    for cmake in ("roslaunch_add_file_check(launch)\n",
                  checked.replace("launch urdf", "launch tests urdf")):
        (tmp_path / "CMakeLists.txt").write_text(cmake)
        found = lint_paths([str(root)], options).diagnostics
        assert [(d.rule, Path(d.path).name) for d in found] == [(RULE, "robot.launch")]


def test_a_literal_foreach_in_install_is_read(tmp_path: Path) -> None:
    """abb_experimental's support packages install ``DIRECTORY ${dir}/`` inside
    ``foreach(dir config launch meshes urdf)``: tests/ is not among them, so the checked
    aggregate is still only parsed; with tests among the items it is installed."""
    (tmp_path / "robot.launch").write_text(ROBOT)
    fleet = ('<launch><group ns="a"><include file="$(dirname)/../robot.launch"/></group>'
             '<group ns="b"><include file="$(dirname)/../robot.launch"/></group></launch>')
    options = LintOptions(package_paths=(), select=frozenset({RULE}))
    checked = ("roslaunch_add_file_check(tests/fleet.launch)\n"
               "foreach(dir config launch meshes urdf)\n"
               "  install(DIRECTORY ${dir}/ DESTINATION share/${dir})\n"
               "endforeach()\n")
    root = _package(tmp_path, checked)
    root.write_text(fleet)
    assert lint_paths([str(root)], options).diagnostics == ()
    for cmake in (checked.replace("meshes urdf", "meshes tests urdf"),
                  checked.replace("config launch meshes urdf", "IN LISTS folders")):
        (tmp_path / "CMakeLists.txt").write_text(cmake)
        found = lint_paths([str(root)], options).diagnostics
        assert [(d.rule, Path(d.path).name) for d in found] == [(RULE, "robot.launch")]


PLUGIN_ROBOT = """<robot name="tb3">
  <link name="base_footprint"/><link name="base_link"/>
  <joint name="j" type="fixed"><parent link="base_footprint"/><child link="base_link"/></joint>
  <gazebo><plugin name="drive" filename="libgazebo_ros_diff_drive.so">
    <odometryFrame>odom</odometryFrame><robotBaseFrame>base_footprint</robotBaseFrame>
    <publishOdomTF>true</publishOdomTF>
  </plugin></gazebo>
</robot>
"""
SIM_ROBOT = """  <group ns="{ns}">
    {group_prefix}
    <param name="robot_description" textfile="$(dirname)/tb3.urdf"/>
    <node pkg="robot_state_publisher" type="robot_state_publisher" name="rsp">
      {node_prefix}
    </node>
    <node pkg="gazebo_ros" type="spawn_model" name="spawn" args="-urdf -model {ns}
      -param robot_description"/>
  </group>
"""


def _simulation(tmp_path: Path, where: str) -> list[tuple[str, str, int]]:
    (tmp_path / "tb3.urdf").write_text(PLUGIN_ROBOT)
    robots = []
    for ns in ("tb3_0", "tb3_1"):
        prefix = f'<param name="tf_prefix" value="{ns}"/>'
        robots.append(SIM_ROBOT.format(ns=ns, group_prefix=prefix if where == "group" else "",
                                       node_prefix=prefix if where == "node" else ""))
    (tmp_path / "sim.launch").write_text("<launch>\n" + "".join(robots) + "</launch>\n")
    options = LintOptions(package_paths=(), select=frozenset({RULE}))
    found = lint_paths([str(tmp_path / "sim.launch")], options).diagnostics
    return [(d.rule, Path(d.path).name, d.line) for d in found]


def test_gazebo_plugins_find_tf_prefix_from_the_robot_namespace(tmp_path: Path) -> None:
    """turtlebot3_simulations c75c07e: a tf_prefix private to robot_state_publisher is not
    the one the diff-drive plugin finds from the robot's namespace (spawn_model's), so
    both robots' plugins send odom -> base_footprint; set in the group, it prefixes both."""
    assert _simulation(tmp_path, "node") == [(RULE, "tb3.urdf", 4)]
    assert _simulation(tmp_path, "group") == []


def test_frame_prefix_before_robot_state_publisher_2_5_is_no_prefix(tmp_path: Path) -> None:
    """frame_prefix arrived in robot_state_publisher 2.5.0 (ros/robot_state_publisher#159):
    on dashing or eloquent two namespaced publishers with it still collide."""
    (tmp_path / "r.urdf").write_text(
        "<robot name='r'><link name='base_link'/><link name='laser'/><joint name='j' "
        "type='fixed'><parent link='base_link'/><child link='laser'/></joint></robot>")
    robots = "".join(
        f"Node(package='robot_state_publisher', executable='robot_state_publisher', "
        f"namespace='{ns}', parameters=[{{'robot_description': open('{tmp_path}/r.urdf')"
        f".read(), 'frame_prefix': '{ns}/'}}]),\n" for ns in ("r1", "r2"))
    (tmp_path / "fleet.launch.py").write_text(
        "from launch import LaunchDescription\nfrom launch_ros.actions import Node\n\n"
        f"def generate_launch_description():\n    return LaunchDescription([\n{robots}])\n")
    for distro, expected in (("humble", 0), ("eloquent", 1)):
        options = LintOptions(package_paths=(), select=frozenset({RULE}), ros_distro=distro)
        found = lint_paths([str(tmp_path / "fleet.launch.py")], options).diagnostics
        assert len(found) == expected, distro


def test_the_closest_tf_prefix_is_the_one_searchparam_finds() -> None:
    from launch_linter.frontends.robot.describe import searched_tf_prefix
    from launch_linter.model.robot import UNKNOWN_VALUE

    set_in = [("/", "world"), ("/tb3_0/", "tb3_0"), ("/tb3_0/arm/", "arm")]
    assert searched_tf_prefix("/tb3_0", set_in) == "tb3_0"
    assert searched_tf_prefix("/tb3_0/arm", set_in) == "arm"
    assert searched_tf_prefix("/tb3_1", set_in) == "world"
    assert searched_tf_prefix("/tb3_10", set_in[1:]) == ""
    assert searched_tf_prefix("/tb3_1", [(None, "x")]) == UNKNOWN_VALUE


def _mir_like(tmp_path: Path, namespaces: tuple[str, ...], prefixed: bool) -> int:
    """One robot launch file giving its description (frames ``<ns>/...`` when
    ``prefixed``) to robot_state_publisher and to joint_state_publisher, included once per
    namespace (awdguyi/ros2_ws_test's mir_description.launch.py)."""
    link = "${ns}/" if prefixed else ""
    (tmp_path / "r.urdf.xacro").write_text(
        "<robot name='r' xmlns:xacro='http://www.ros.org/wiki/xacro'>"
        "<xacro:arg name='ns' default='x'/><xacro:property name='ns' value='$(arg ns)'/>"
        f"<link name='{link}base_link'/><link name='{link}laser'/><joint name='j' "
        f"type='fixed'><parent link='{link}base_link'/><child link='{link}laser'/></joint>"
        "</robot>")
    (tmp_path / "robot.launch.py").write_text(
        "from launch import LaunchDescription\nfrom launch.actions import DeclareLaunchArgument"
        "\nfrom launch.substitutions import Command, LaunchConfiguration\n"
        "from launch_ros.actions import Node\n\n"
        "def generate_launch_description():\n"
        "    ns = LaunchConfiguration('namespace')\n"
        f"    description = Command(['xacro ', '{tmp_path}/r.urdf.xacro', ' ns:=', ns])\n"
        "    return LaunchDescription([\n"
        "        DeclareLaunchArgument('namespace', default_value='x'),\n"
        "        Node(package='robot_state_publisher', executable='robot_state_publisher',\n"
        "             namespace=ns, parameters=[{'robot_description': description}]),\n"
        "        Node(package='joint_state_publisher', executable='joint_state_publisher',\n"
        "             namespace=ns, parameters=[{'robot_description': description}]),\n"
        "    ])\n")
    includes = "".join(
        "        IncludeLaunchDescription(PythonLaunchDescriptionSource("
        f"'{tmp_path}/robot.launch.py'), launch_arguments={{'namespace': '{ns}'}}.items()),\n"
        for ns in namespaces)
    (tmp_path / "fleet.launch.py").write_text(
        "from launch import LaunchDescription\nfrom launch.actions import "
        "IncludeLaunchDescription\nfrom launch.launch_description_sources import "
        "PythonLaunchDescriptionSource\n\n"
        f"def generate_launch_description():\n    return LaunchDescription([\n{includes}"
        "    ])\n")
    options = LintOptions(package_paths=(), select=frozenset({RULE}))
    return len(lint_paths([str(tmp_path / "fleet.launch.py")], options).diagnostics)


def test_a_description_given_to_joint_state_publisher_publishes_no_frames(
        tmp_path: Path) -> None:
    """joint_state_publisher reads robot_description to list the joints and publishes
    /joint_states, never tf: its copy of each robot's description is no second robot."""
    assert _mir_like(tmp_path, ("mir0", "mir1"), prefixed=True) == 0
    assert _mir_like(tmp_path, ("mir0",), prefixed=True) == 0
    # Two robots whose frames are not prefixed still collide, joint_state_publisher or not.
    assert _mir_like(tmp_path, ("mir0", "mir1"), prefixed=False) == 1
