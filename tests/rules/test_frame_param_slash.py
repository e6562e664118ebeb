"""frame_param_slash: a frame parameter starting with '/' where the node hands it to tf2
(fault, then fixed)."""

from __future__ import annotations

from pathlib import Path

from launch_linter.engine import LintOptions, lint_paths

RULE = "frame_param_slash"


def run(tmp_path: Path, name: str, text: str) -> list[tuple[str, int]]:
    return [(rule, line) for rule, line, _ in levels(tmp_path, name, text)]


def levels(tmp_path: Path, name: str, text: str,
           distro: str | None = None) -> list[tuple[str, int, str]]:
    path = tmp_path / name
    path.write_text(text)
    options = LintOptions(package_paths=(), select=frozenset({RULE}), ros_distro=distro)
    return [(d.rule, d.line, d.severity.value)
            for d in lint_paths([str(path)], options).diagnostics]


def test_a_costmap_global_frame_with_a_slash_in_a_ros2_parameter_file(tmp_path: Path) -> None:
    (tmp_path / "nav.yaml").write_text(
        "bt_navigator:\n  ros__parameters:\n    global_frame: /map\n"
        "    robot_base_frame: base_link\n")
    launch = ("import os\nfrom launch import LaunchDescription\n"
              "from launch_ros.actions import Node\n"
              "def generate_launch_description():\n"
              "    here = os.path.dirname(__file__)\n"
              "    return LaunchDescription([\n"
              "        Node(package='nav2_bt_navigator', executable='bt_navigator',\n"
              "             name='bt_navigator',\n"
              "             parameters=[os.path.join(here, 'nav.yaml')])])\n")
    # At the parameter file's key (PyYAML's mark), the node's element as related.
    (tmp_path / "nav.launch.py").write_text(launch)
    options = LintOptions(package_paths=(), select=frozenset({RULE}))
    [found] = lint_paths([str(tmp_path / "nav.launch.py")], options).diagnostics
    assert (Path(found.path).name, found.line, found.column) == ("nav.yaml", 3, 5)
    assert [(Path(r.path).name, r.line) for r in found.related] == [("nav.launch.py", 7)]
    (tmp_path / "nav.yaml").write_text(
        "bt_navigator:\n  ros__parameters:\n    global_frame: map\n")
    assert run(tmp_path, "nav.launch.py", launch) == []


def test_ros1_nodes_on_tf_1_and_defaults_are_left_out(tmp_path: Path) -> None:
    """amcl strips the slash; gmapping looks frames up through tf 1, which strips it; a
    move_base without parameters keeps its own defaults."""
    ros1 = ('<launch><node pkg="amcl" type="amcl" name="amcl">'
            '<param name="global_frame_id" value="/map"/></node>'
            '<node pkg="gmapping" type="slam_gmapping" name="g">'
            '<param name="odom_frame" value="/odom"/></node>'
            '<node pkg="move_base" type="move_base" name="move_base"/></launch>')
    assert levels(tmp_path, "a.launch", ros1, "noetic") == []


MOVE_BASE = ('<launch>\n<node pkg="move_base" type="move_base" name="move_base">'
             '<rosparam>global_costmap:\n  global_frame: /map\n</rosparam></node>\n'
             '</launch>\n')


def test_a_melodic_costmap_hands_its_frames_to_tf2(tmp_path: Path) -> None:
    """navigation_tutorials#17: costmap_2d on tf2 from Melodic; Kinetic's resolved the
    slash with tf 1; with no target distribution the finding is a notice."""
    assert levels(tmp_path, "mb.launch", MOVE_BASE, "melodic") == [(RULE, 2, "warning")]
    assert levels(tmp_path, "mb.launch", MOVE_BASE, "kinetic") == []
    assert levels(tmp_path, "mb.launch", MOVE_BASE) == [(RULE, 2, "info")]
    fixed = MOVE_BASE.replace("/map", "map")
    assert levels(tmp_path, "mb.launch", fixed, "noetic") == []


def test_the_frame_a_map_server_stamps_on_its_map(tmp_path: Path) -> None:
    """teb_local_planner_tutorials#3: the costmaps look up the map's frame_id."""
    text = ('<launch>\n<node pkg="map_server" type="map_server" name="map_server" args="m.yaml">'
            '<param name="frame_id" value="/map"/></node>\n</launch>\n')
    assert levels(tmp_path, "m.launch", text, "melodic") == [(RULE, 2, "warning")]
    assert levels(tmp_path, "m.launch", text.replace("/map", "map"), "melodic") == []


def test_a_frame_prefix_that_is_a_slash(tmp_path: Path) -> None:
    """turtlebot3#1136: frame_prefix '"' + namespace + '/"' is '/' without a namespace, so
    robot_state_publisher publishes '/base_link'."""
    launch = ("from launch import LaunchDescription\n"
              "from launch.substitutions import LaunchConfiguration, PythonExpression\n"
              "from launch_ros.actions import Node\n"
              "def generate_launch_description():\n"
              "    ns = LaunchConfiguration('namespace', default='')\n"
              "    return LaunchDescription([\n"
              "        Node(package='robot_state_publisher', executable='robot_state_publisher',\n"
              "             parameters=[{'frame_prefix':\n"
              "                 PythonExpression(['\"', ns, '/\"'])}])])\n")
    # At the dictionary key that sets it, not at the Node( line.
    assert levels(tmp_path, "rsp.launch.py", launch) == [(RULE, 8, "warning")]
    fixed = launch.replace("['\"', ns, '/\"']", "['\"', ns, '/\" if \"', ns, '\" else \"\"']")
    assert levels(tmp_path, "rsp.launch.py", fixed) == []
    prefixed = launch.replace("default=''", "default='robot1'")
    assert levels(tmp_path, "rsp.launch.py", prefixed) == []


def test_the_finding_is_on_the_param_line_that_sets_the_frame(tmp_path: Path) -> None:
    # The <param> that writes the slash, not the node's element two lines above it.
    ros1 = ('<launch>\n<node pkg="map_server" type="map_server" name="m"\n'
            '      args="map.yaml">\n  <param name="frame_id" value="/eng2/7f"/>\n'
            '</node>\n</launch>\n')
    assert levels(tmp_path, "m.launch", ros1, "noetic") == [(RULE, 4, "warning")]
    # Set in a <rosparam>'s text: the <rosparam> element (here on the node's line).
    assert levels(tmp_path, "m.launch", MOVE_BASE, "noetic") == [(RULE, 2, "warning")]


SOURCES = ('<launch>\n<node pkg="move_base" type="move_base" name="move_base">\n'
           '<rosparam ns="global_costmap">observation_sources: scan bump\n'
           'scan: {{sensor_frame: {scan}, data_type: LaserScan}}\n'
           'bump: {{data_type: PointCloud2}}\n</rosparam>\n'
           '<param name="local_costmap/obstacle_layer/observation_sources" value="scan"/>\n'
           '<param name="local_costmap/obstacle_layer/scan/sensor_frame" value="{local}"/>\n'
           '</node>\n</launch>\n')


def test_a_costmap_observation_source_sensor_frame_is_a_frame_it_looks_up(
        tmp_path: Path) -> None:
    """Each source an obstacle layer lists (at the costmap's level, pre-Hydro, or in a
    layer's namespace) is a namespace whose sensor_frame the observations are
    transformed from in tf2 (costmap_2d observation_buffer.cpp, Melodic on)."""
    fault = SOURCES.format(scan="/base_laser_link", local="/base_laser_link")
    # At the <rosparam> that sets the first, the <param> that sets the second.
    assert levels(tmp_path, "s.launch", fault, "melodic") == [
        (RULE, 3, "warning"), (RULE, 8, "warning")]
    fixed = SOURCES.format(scan="base_laser_link", local="base_laser_link")
    assert levels(tmp_path, "s.launch", fixed, "melodic") == []
    # A frame under a name no observation_sources lists is not read by the costmap.
    unlisted = fixed.replace('value="scan"/>', 'value="other"/>').replace(
        'scan/sensor_frame" value="base_laser_link"', 'scan/sensor_frame" value="/x"')
    assert levels(tmp_path, "s.launch", unlisted, "melodic") == []
    # Kinetic's costmaps resolved frames with tf 1, which accepts the slash.
    assert levels(tmp_path, "s.launch", fault, "kinetic") == []


COB = ('<launch>\n<node pkg="cob_collision_velocity_filter" type="collision_velocity_filter"'
       ' name="collision_velocity_filter">\n<rosparam ns="anti_collision_costmap">'
       'global_frame: {frame}\nrobot_base_frame: base_footprint\n</rosparam>\n</node>\n'
       '</launch>\n')


def test_the_costmap_cob_collision_velocity_filter_runs(tmp_path: Path) -> None:
    """cob_collision_velocity_filter runs a Costmap2DROS 'anti_collision_costmap' on tf2
    from Melodic on (cob_control melodic_dev)."""
    assert levels(tmp_path, "c.launch", COB.format(frame="/base_link"), "melodic") == [
        (RULE, 3, "warning")]
    assert levels(tmp_path, "c.launch", COB.format(frame="base_link"), "melodic") == []
    assert levels(tmp_path, "c.launch", COB.format(frame="/base_link"), "kinetic") == []


def test_the_frame_a_depthimage_to_laserscan_nodelet_stamps_on_its_scans(
        tmp_path: Path) -> None:
    # turtlebot/turtlebot_simulator#78: costmap_2d (tf2 from Melodic) looks the scans'
    # frame up; the nodelet is known by the type its `load` arguments name.
    def launch(frame: str) -> str:
        return ('<launch>\n'
                '  <node pkg="nodelet" type="nodelet" name="m" args="manager"/>\n'
                '  <node pkg="nodelet" type="nodelet" name="d"\n'
                '        args="load depthimage_to_laserscan/DepthImageToLaserScanNodelet m">\n'
                f'    <param name="output_frame_id" value="{frame}"/>\n'
                '  </node>\n'
                '</launch>\n')
    assert levels(tmp_path, "a.launch", launch("/camera_depth_frame"), "melodic") == [
        (RULE, 5, "warning")]
    assert levels(tmp_path, "a.launch", launch("/camera_depth_frame"), "kinetic") == []
    assert levels(tmp_path, "a.launch", launch("camera_depth_frame"), "melodic") == []


def test_the_frame_a_ros2_depthimage_to_laserscan_stamps_on_its_scans(tmp_path: Path) -> None:
    launch = ('<launch>\n'
              '  <node pkg="depthimage_to_laserscan" exec="depthimage_to_laserscan_node">\n'
              '    <param name="output_frame" value="/camera_depth_frame"/>\n'
              '  </node>\n'
              '</launch>\n')
    # At the <param> that writes the value (ROS 2 XML <param> lines are kept).
    assert run(tmp_path, "a.launch.xml", launch) == [(RULE, 3)]
