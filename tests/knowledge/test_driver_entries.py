"""The drivers block of the knowledge base (base drivers, LiDAR odometry, laser, camera and
joystick drivers): the edges each entry gives, as the rules read them, positive and
negative."""

from __future__ import annotations

from pathlib import Path

import pytest

from launch_linter.engine import LintOptions, lint_paths
from launch_linter.knowledge import KnowledgeError, bundled, parse
from launch_linter.model.diagnostic import Diagnostic, Severity
from launch_linter.rules._nodes import view_of

HEADER = ("from launch import LaunchDescription\n"
          "from launch_ros.actions import Node\n"
          "def generate_launch_description():\n"
          "    return LaunchDescription([\n")
EKF = ("        Node(package='robot_localization', executable='ekf_node', name='ekf',\n"
       "             parameters=[{'world_frame': 'odom', 'odom_frame': 'odom',\n"
       "                          'base_link_frame': 'base_footprint', 'odom0': 'odom'}]),\n")


def launch(tmp_path: Path, nodes: str) -> Path:
    path = tmp_path / "bringup.launch.py"
    path.write_text(HEADER + nodes + "    ])\n")
    return path


def findings(path: Path, rule: str) -> list[Diagnostic]:
    options = LintOptions(package_paths=(), select=frozenset({rule}))
    return [d for d in lint_paths([str(path)], options).diagnostics if d.rule == rule]


def edges(path: Path) -> tuple[set[tuple[str, str]], bool]:
    """The node edges of the file's tree, and whether the tree is closed."""
    tree = lint_paths([str(path)], LintOptions(package_paths=())).trees[0]
    view = view_of(tree, bundled())
    return {(e.parent, e.child) for e in view.edges}, view.open_because is None


BASE_DRIVERS = [
    ("kobuki_node", "kobuki_ros_node", "base_footprint"),
    ("create_driver", "create_driver", "base_footprint"),
]


@pytest.mark.parametrize(("package", "executable", "base"), BASE_DRIVERS)
def test_a_base_driver_odometry_tf_against_an_ekf_is_a_duplicate(
        tmp_path: Path, package: str, executable: str, base: str) -> None:
    path = launch(tmp_path, (
        f"        Node(package='{package}', executable='{executable}',\n"
        f"             parameters=[{{'base_frame': '{base}'}}]),\n" + EKF))
    found = findings(path, "duplicate_publisher")
    assert len(found) == 1 and found[0].severity is Severity.ERROR
    assert "'odom' -> 'base_footprint'" in found[0].message


@pytest.mark.parametrize(("package", "executable", "base"), BASE_DRIVERS)
def test_a_base_driver_with_publish_tf_off_leaves_the_edge_to_the_ekf(
        tmp_path: Path, package: str, executable: str, base: str) -> None:
    path = launch(tmp_path, (
        f"        Node(package='{package}', executable='{executable}',\n"
        f"             parameters=[{{'base_frame': '{base}', 'publish_tf': False}}]),\n"
        + EKF))
    assert findings(path, "duplicate_publisher") == []
    published, closed = edges(path)
    assert published == {("odom", "base_footprint")} and closed


def test_kobuki_ros_default_base_frame_is_base(tmp_path: Path) -> None:
    path = launch(tmp_path, "        Node(package='kobuki_node', executable='kobuki_ros_node'),\n")
    assert edges(path) == ({("odom", "base")}, True)


def test_kiss_icp_sends_its_odometry_frame_to_the_base_frame(tmp_path: Path) -> None:
    path = launch(tmp_path, (
        "        Node(package='kiss_icp', executable='kiss_icp_node',\n"
        "             parameters=[{'base_frame': 'base_footprint', 'lidar_odom_frame': 'odom',\n"
        "                          'publish_odom_tf': True, 'invert_odom_tf': False}]),\n"
        + EKF))
    assert edges(path)[0] == {("odom", "base_footprint")}
    assert len(findings(path, "duplicate_publisher")) == 1


def test_kiss_icp_inverted_sends_the_reverse_edge(tmp_path: Path) -> None:
    path = launch(tmp_path, (
        "        Node(package='kiss_icp', executable='kiss_icp_node',\n"
        "             parameters=[{'base_frame': 'base_link', 'publish_odom_tf': True,\n"
        "                          'invert_odom_tf': True}]),\n"))
    assert edges(path) == ({("base_link", "odom_lidar")}, True)


def test_kiss_icp_without_its_switches_or_base_frame_keeps_the_tree_open(
        tmp_path: Path) -> None:
    # publish_odom_tf has no static default; an empty base_frame means the cloud's frame.
    unswitched = launch(tmp_path, (
        "        Node(package='kiss_icp', executable='kiss_icp_node',\n"
        "             parameters=[{'base_frame': 'base_link'}]),\n"))
    assert edges(unswitched) == (set(), False)
    unnamed = launch(tmp_path, (
        "        Node(package='kiss_icp', executable='kiss_icp_node',\n"
        "             parameters=[{'publish_odom_tf': True, 'invert_odom_tf': False}]),\n"))
    assert edges(unnamed) == (set(), False)


LASERS = [
    ("sllidar_ros2", "sllidar_node"),
    ("rplidar_ros", "rplidar_composition"),
    ("ydlidar_ros2_driver", "ydlidar_ros2_driver_node"),
    ("ldlidar_stl_ros2", "ldlidar_stl_ros2_node"),
    ("velodyne_driver", "velodyne_driver_node"),
]


@pytest.mark.parametrize(("package", "executable"), LASERS)
def test_a_laser_driver_closes_the_tree_and_its_slashed_frame_is_reported(
        tmp_path: Path, package: str, executable: str) -> None:
    plain = launch(tmp_path, (
        f"        Node(package='{package}', executable='{executable}',\n"
        f"             parameters=[{{'frame_id': 'laser'}}]),\n"))
    assert edges(plain) == (set(), True)
    assert findings(plain, "frame_param_slash") == []
    slashed = launch(tmp_path, (
        f"        Node(package='{package}', executable='{executable}',\n"
        f"             parameters=[{{'frame_id': '/laser'}}]),\n"))
    found = findings(slashed, "frame_param_slash")
    assert len(found) == 1 and found[0].severity is Severity.WARNING


def test_urg_node2_strips_the_slash_of_its_frame(tmp_path: Path) -> None:
    path = launch(tmp_path, (
        "        Node(package='urg_node2', executable='urg_node2_node',\n"
        "             parameters=[{'frame_id': '/laser'}]),\n"))
    assert edges(path) == (set(), True)
    assert findings(path, "frame_param_slash") == []


@pytest.mark.parametrize(("package", "executable"), [
    ("teleop_twist_joy", "teleop_node"), ("joy", "joy_node"), ("joy", "game_controller_node"),
    ("joy_linux", "joy_linux_node"), ("usb_cam", "usb_cam_node_exe"),
    ("velodyne_laserscan", "velodyne_laserscan_node"),
])
def test_nodes_that_send_no_tf_close_the_tree(
        tmp_path: Path, package: str, executable: str) -> None:
    path = launch(tmp_path, f"        Node(package='{package}', executable='{executable}'),\n")
    assert edges(path) == (set(), True)


SICK = ("        Node(package='sick_scan_xd', executable='sick_generic_caller',\n"
        "             parameters=[{{'scanner_type': '{kind}', 'frame_id': 'laser',\n"
        "                          'publish_frame_id': 'world_lidar'{extra}}}]),\n")


@pytest.mark.parametrize(("kind", "extra", "expected"), [
    ("sick_tim_7xx", ", 'tf_publish_rate': 10.0", {("map", "laser")}),
    ("sick_multiscan", ", 'tf_publish_rate': 10.0", {("map", "world_lidar")}),
    ("sick_picoscan", ", 'tf_publish_rate': 10.0, 'tf_base_frame_id': 'base_link'",
     {("base_link", "world_lidar")}),
    ("sick_nav_350", ", 'tf_publish_rate': 10.0", {("map", "laser"), ("map", "nav")}),
    ("sick_tim_7xx", ", 'tf_publish_rate': 0.0", set()),
    ("sick_ldmrs", ", 'tf_publish_rate': 10.0", set()),
])
def test_sick_scan_xd_edges_follow_its_scanner_type(
        tmp_path: Path, kind: str, extra: str, expected: set[tuple[str, str]]) -> None:
    path = launch(tmp_path, SICK.format(kind=kind, extra=extra))
    assert edges(path) == (expected, True)


def test_sick_scan_xd_without_a_rate_or_a_type_leaves_the_tree_open(tmp_path: Path) -> None:
    # Drivers before 3.4.0 send no tf: the rate's code default is not assumed.
    unrated = launch(tmp_path, SICK.format(kind="sick_tim_7xx", extra=""))
    assert edges(unrated) == (set(), False)
    untyped = launch(tmp_path, (
        "        Node(package='sick_scan_xd', executable='sick_generic_caller',\n"
        "             parameters=[{'tf_publish_rate': 10.0}]),\n"))
    assert edges(untyped) == (set(), False)


def test_a_sick_scanner_and_a_static_transform_on_one_edge_is_a_duplicate(
        tmp_path: Path) -> None:
    path = launch(tmp_path, SICK.format(kind="sick_tim_5xx", extra=", 'tf_publish_rate': 10.0")
                  + "        Node(package='tf2_ros', executable='static_transform_publisher',\n"
                    "             arguments=['--frame-id', 'map', '--child-frame-id', 'laser',\n"
                    "                        '--x', '2']),\n")
    assert len(findings(path, "duplicate_publisher")) == 1


def test_a_text_condition_names_a_declared_parameter() -> None:
    entry = {"id": "device", "kind": "node", "ros": [2],
             "match": {"package": "p", "executables": ["e"]},
             "parameters": {"model": None},
             "publishes": [{"parent": "map", "child": "x", "when": ["!nope=a"],
                            "role": "sensor"}],
             "looks_up": [],
             "sources": [{"repository": "a/b", "package": "p", "file": "f", "ref": "r",
                          "commit": "0" * 40, "lines": "1"}]}
    with pytest.raises(KnowledgeError, match="nope"):
        parse({"format": 1, "entries": [entry]}, "user.json")
    entry["publishes"] = [{"parent": "map", "child": "x", "when": ["!model=a"],
                           "role": "sensor"}]
    assert parse({"format": 1, "entries": [entry]}, "user.json").entries[0].id == "device"


def test_ouster_sends_its_sensor_frames_unless_switched_off(tmp_path: Path) -> None:
    path = launch(tmp_path, (
        "        Node(package='ouster_ros', executable='os_driver',\n"
        "             parameters=[{'sensor_frame': 'lidar_base'}]),\n"))
    assert edges(path) == ({("lidar_base", "os_lidar"), ("lidar_base", "os_imu")}, True)
    off = launch(tmp_path, (
        "        Node(package='ouster_ros', executable='os_cloud',\n"
        "             parameters=[{'pub_static_tf': False}]),\n"))
    assert edges(off) == (set(), True)


def test_fast_lio_sends_its_fixed_frames(tmp_path: Path) -> None:
    path = launch(tmp_path, "        Node(package='fast_lio', executable='fastlio_mapping'),\n")
    assert edges(path) == ({("camera_init", "body")}, True)


def write_ros1(tmp_path: Path, body: str) -> Path:
    path = tmp_path / "bringup.launch"
    path.write_text(f"<launch>\n{body}</launch>\n")
    return path


def test_fake_localization_sends_only_with_a_ground_truth_nobody_reads(tmp_path: Path) -> None:
    # Its map -> odom waits for base_pose_ground_truth, a topic: not assumed, so a static
    # map -> odom beside it (rbx1's fake robot, no ground truth) is no finding.
    fake = "  <node pkg='fake_localization' type='fake_localization' name='fake'/>\n"
    static = "  <node pkg='tf' type='static_transform_publisher' name='s' " \
             "args='0 0 0 0 0 0 /map /odom 100'/>\n"
    path = write_ros1(tmp_path, fake + static)
    assert edges(path) == (set(), False)
    assert findings(path, "frame_authority") == []


@pytest.mark.parametrize("node", [
    "<node pkg='sick_scan' type='sick_generic_caller' name='lidar'/>",
    "<node pkg='laser_filters' type='scan_to_scan_filter_chain' name='filter'/>",
    "<node pkg='ldlidar_stl_ros' type='ldlidar_stl_ros_node' name='ld'/>",
    "<node pkg='uvc_camera' type='uvc_camera_node' name='camera'/>",
    "<node pkg='teleop_twist_keyboard' type='teleop_twist_keyboard.py' name='teleop'/>",
    "<node pkg='bluefox2' type='bluefox2_single_node' name='camera'/>",
    "<node pkg='nodelet' type='nodelet' name='camera' args='standalone bluefox2/SingleNodelet'/>",
])
def test_ros1_nodes_that_send_no_tf_close_the_tree(tmp_path: Path, node: str) -> None:
    assert edges(write_ros1(tmp_path, f"  {node}\n")) == (set(), True)


def test_ros2_depth_image_proc_and_laser_filters_close_the_tree(tmp_path: Path) -> None:
    path = launch(tmp_path, (
        "        Node(package='depth_image_proc', executable='point_cloud_xyz_node'),\n"
        "        Node(package='laser_filters', executable='scan_to_scan_filter_chain'),\n"))
    assert edges(path) == (set(), True)


def test_lio_sam_sends_odometry_to_the_base_and_its_lidar_link(tmp_path: Path) -> None:
    path = launch(tmp_path, (
        "        Node(package='lio_sam', executable='lio_sam_imuPreintegration',\n"
        "             parameters=[{'lidarFrame': 'velodyne'}]),\n"
        "        Node(package='lio_sam', executable='lio_sam_mapOptimization'),\n"
        "        Node(package='lio_sam', executable='lio_sam_imageProjection'),\n"))
    assert edges(path) == ({("odom", "base_link"), ("odom", "lidar_link")}, True)
    same = launch(tmp_path, (
        "        Node(package='lio_sam', executable='lio_sam_imuPreintegration',\n"
        "             parameters=[{'lidarFrame': 'base_link'}]),\n"))
    assert edges(same) == (set(), True)
