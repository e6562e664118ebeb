"""duplicate_publisher: an edge a node publishes and another source publishes too. The
cases are small copies of faults users reported (each with its fixed version)."""

from __future__ import annotations

from pathlib import Path
from typing import Callable, List, Tuple

from launch_linter.engine import LintOptions, lint_paths
from launch_linter.rules import duplicate_publisher

RULE = "duplicate_publisher"
Lint = Callable[..., List[Tuple[str, int]]]


def test_amcl_and_a_map_frame_ekf_both_publish_map_odom(lint: Lint) -> None:
    fault = ('<launch><node pkg="amcl" type="amcl" name="amcl"/>\n'
             '<node pkg="robot_localization" type="ekf_localization_node" name="ekf_map">'
             '<param name="world_frame" value="map"/><param name="imu0" value="imu"/>'
             '</node></launch>')
    assert lint(fault, RULE) == [(RULE, 2)]
    fixed = fault.replace('name="amcl"/>', 'name="amcl"><param name="tf_broadcast" '
                                           'value="false"/></node>')
    assert lint(fixed, RULE) == []


def test_an_odometry_ekf_beside_diff_drive_controller(tmp_path: Path) -> None:
    """ROS 2: the controller's YAML keeps enable_odom_tf on while an EKF publishes
    odom -> base_link too."""
    (tmp_path / "controllers.yaml").write_text(
        "controller_manager:\n  ros__parameters:\n    diff_cont:\n"
        "      type: diff_drive_controller/DiffDriveController\n"
        "diff_cont:\n  ros__parameters:\n    base_frame_id: base_link\n")
    launch = tmp_path / "bringup.launch.xml"
    launch.write_text(
        '<launch>\n<node pkg="controller_manager" exec="ros2_control_node" '
        'name="controller_manager"><param from="$(dirname)/controllers.yaml"/></node>\n'
        '<node pkg="robot_localization" exec="ekf_node" name="ekf_filter_node">'
        '<param name="world_frame" value="odom"/><param name="odom0" value="odom"/></node>\n'
        '</launch>\n')
    options = LintOptions(package_paths=(), select=frozenset({RULE}))
    found = lint_paths([str(launch)], options).diagnostics
    assert [(d.rule, d.line) for d in found] == [(RULE, 3)]
    (tmp_path / "controllers.yaml").write_text(
        "controller_manager:\n  ros__parameters:\n    diff_cont:\n"
        "      type: diff_drive_controller/DiffDriveController\n"
        "diff_cont:\n  ros__parameters:\n    enable_odom_tf: false\n")
    assert lint_paths([str(launch)], options).diagnostics == ()


def test_a_camera_driver_publishing_the_urdf_camera_joints(lint: Lint) -> None:
    urdf = ("&lt;robot name='r'&gt;&lt;joint name='cam' type='fixed'&gt;&lt;parent "
            "link='camera_link'/&gt;&lt;child link='camera_depth_frame'/&gt;&lt;/joint&gt;"
            "&lt;/robot&gt;")
    fault = (f'<launch><param name="robot_description" value="{urdf}"/>'
             '<node pkg="robot_state_publisher" type="robot_state_publisher" name="rsp"/>\n'
             '<node pkg="realsense2_camera" type="realsense2_camera_node" name="camera"/>'
             '</launch>')
    assert lint(fault, RULE) == [(RULE, 2)]
    fixed = fault.replace('name="camera"/>', 'name="camera"><param name="publish_tf" '
                                             'value="false"/></node>')
    assert lint(fixed, RULE) == []


def test_exclusive_conditions_and_unknown_parameters_are_silent(lint: Lint) -> None:
    xml = ('<launch><arg name="sim" default="true"/>'
           '<node if="$(arg sim)" pkg="amcl" type="amcl" name="amcl"/>\n'
           '<node unless="$(arg sim)" pkg="robot_localization" type="ekf_localization_node" '
           'name="ekf_map"><param name="world_frame" value="map"/></node>'
           '<arg name="f" default="$(env NOPE)"/>'
           '<node pkg="slam_toolbox" type="async_slam_toolbox_node" name="slam">'
           '<param name="odom_frame" value="$(arg f)"/></node></launch>')
    assert lint(xml, RULE) == []


def _run(launch: Path) -> list[tuple[str, str]]:
    options = LintOptions(package_paths=(), select=frozenset({RULE}))
    return [(d.severity.value, d.message) for d in lint_paths([str(launch)], options).diagnostics]


def test_proven_when_every_parameter_source_was_read(tmp_path: Path) -> None:
    """Both nodes known and every parameter source read: the finding says so and is at
    the rule's level."""
    (tmp_path / "ekf.yaml").write_text("world_frame: map\nodom0: odom\n")
    launch = tmp_path / "nav.launch"
    launch.write_text('<launch><node pkg="amcl" type="amcl" name="amcl"/>\n'
                      '<node pkg="robot_localization" type="ekf_localization_node" '
                      'name="ekf_map"><rosparam command="load" file="$(dirname)/ekf.yaml"/>'
                      '</node></launch>\n')
    [(level, message)] = _run(launch)
    assert message.endswith("(both publishers known and their parameters read)")
    assert level == duplicate_publisher.SEVERITY.value


def test_not_proven_when_a_parameter_file_was_not_read(tmp_path: Path) -> None:
    """amcl's parameter file is missing: tf_broadcast may be set there, so the finding is
    info and names the file and the parameter left at its default."""
    launch = tmp_path / "nav.launch"
    launch.write_text('<launch><node pkg="amcl" type="amcl" name="amcl">'
                      '<rosparam command="load" file="$(dirname)/missing.yaml"/></node>\n'
                      '<node pkg="robot_localization" type="ekf_localization_node" '
                      'name="ekf_map"><param name="world_frame" value="map"/>'
                      '<param name="odom0" value="odom"/></node></launch>\n')
    [(level, message)] = _run(launch)
    assert level == "info"
    assert "not proven: amcl/amcl" in message
    assert "'tf_broadcast'" in message and "missing.yaml" in message


def test_a_filter_given_no_input_publishes_nothing(lint: Lint) -> None:
    """robot_localization sends no transform before its first measurement: two filters
    whose (read) parameters name no input topic are not two publishers."""
    xml = ('<launch><node pkg="robot_localization" type="ekf_localization_node" name="a"/>\n'
           '<node pkg="robot_localization" type="ekf_localization_node" name="b"/></launch>')
    assert lint(xml, RULE) == []
    fed = xml.replace('name="b"/>', 'name="b"><param name="odom0" value="odom"/></node>')
    assert lint(fed, RULE) == []
    both = fed.replace('name="a"/>', 'name="a"><param name="imu0" value="imu"/></node>')
    assert lint(both, RULE) == [(RULE, 2)]


def test_a_parse_check_aggregate_is_not_one_running_system(tmp_path: Path) -> None:
    """seed_r7's tests/roslaunch_test_navigation.xml includes the mapping and the
    localization bringups side by side only for roslaunch_add_file_check to parse them."""
    (tmp_path / "package.xml").write_text("<package format='2'><name>nav</name></package>")
    (tmp_path / "tests").mkdir()
    root = tmp_path / "tests" / "check.launch"
    root.write_text('<launch><node pkg="amcl" type="amcl" name="amcl"/>\n'
                    '<node pkg="gmapping" type="slam_gmapping" name="gmapping"/></launch>\n')
    options = LintOptions(package_paths=(), select=frozenset({RULE}))
    (tmp_path / "CMakeLists.txt").write_text("roslaunch_add_file_check(tests/check.launch)\n")
    assert lint_paths([str(root)], options).diagnostics == ()
    (tmp_path / "CMakeLists.txt").write_text("roslaunch_add_file_check(launch)\n")
    assert [d.line for d in lint_paths([str(root)], options).diagnostics] == [2]
