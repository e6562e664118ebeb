"""file_never_launched: refusals of a ROS 2 package's launch file that nothing runs are info.

The shape of navigation2's ``nav2_costmap_2d/test/simple_driving_test.xml``: a ROS 1
rostest file left in an ament package, neither installed nor included."""

from __future__ import annotations

import time
from pathlib import Path

import pytest

from launch_linter.engine import LintOptions, lint_paths
from launch_linter.frontends.xml_dialect import ros1_sign

RULES = frozenset({"file_never_launched", "ros2_schema", "roslaunch_error"})
MANIFEST = """<package format="3"><name>drive</name>
<buildtool_depend>ament_cmake</buildtool_depend>
<export><build_type>ament_cmake</build_type></export></package>
"""
INSTALLS_LAUNCH = ("project(drive)\n"
                   "install(DIRECTORY launch DESTINATION share/${PROJECT_NAME})\n")
ROSTEST = """<launch>
  <param name="/use_sim_time" value="true"/>
  <node name="map_server" pkg="map_server" type="map_server"/>
  <test test-name="drive_test" pkg="drive" type="tester"/>
</launch>
"""
ROS2_MISSPELT = '<launch>\n  <node pkg="drive" exec="driver" namespce="a"/>\n</launch>\n'


def package(tmp_path: Path, cmake: str = INSTALLS_LAUNCH) -> Path:
    (tmp_path / "package.xml").write_text(MANIFEST)
    (tmp_path / "CMakeLists.txt").write_text(cmake)
    for folder in ("launch", "test"):
        (tmp_path / folder).mkdir(exist_ok=True)
    return tmp_path


def levels(path: Path) -> list[tuple[str, int, str]]:
    package_root = next(p for p in path.parents if (p / "package.xml").exists())
    options = LintOptions(package_paths=(str(package_root),), select=RULES)
    found = lint_paths([str(path)], options).diagnostics
    return sorted({(d.rule, d.line, d.severity.value) for d in found})


def test_a_rostest_file_left_in_an_ament_package_is_info(tmp_path: Path) -> None:
    root = package(tmp_path) / "test" / "drive_test.xml"
    root.write_text(ROSTEST)
    found = levels(root)
    assert ("file_never_launched", 1, "info") in found
    assert {level for _, _, level in found} == {"info"}
    assert {rule for rule, _, _ in found} == RULES


def test_a_rostest_file_the_package_installs_keeps_its_errors(tmp_path: Path) -> None:
    root = package(tmp_path, INSTALLS_LAUNCH + "install(DIRECTORY test DESTINATION share/"
                   "${PROJECT_NAME})\n") / "test" / "drive_test.xml"
    root.write_text(ROSTEST)
    found = levels(root)
    assert "file_never_launched" not in {rule for rule, _, _ in found}
    assert {level for _, _, level in found} == {"error"}


def test_a_rostest_file_another_launch_file_names_keeps_its_errors(tmp_path: Path) -> None:
    root = package(tmp_path) / "test" / "drive_test.xml"
    root.write_text(ROSTEST)
    (tmp_path / "launch" / "all.launch.xml").write_text(
        '<launch><include file="$(find-pkg-share drive)/test/drive_test.xml"/></launch>')
    assert {level for _, _, level in levels(root)} == {"error"}


def test_a_file_a_cmake_command_names_keeps_its_errors(tmp_path: Path) -> None:
    """add_launch_test(test/scratch.launch.xml) runs it as a test: not a leftover; a CMake
    comment naming it (navigation2's TODO) runs nothing."""
    root = package(tmp_path) / "test" / "scratch.launch.xml"
    root.write_text(ROS2_MISSPELT)
    (tmp_path / "test" / "CMakeLists.txt").write_text(
        "# TODO: run scratch.launch.xml one day\n")
    assert levels(root) == [("file_never_launched", 1, "info"), ("ros2_schema", 2, "info")]
    (tmp_path / "test" / "CMakeLists.txt").write_text(
        "add_launch_test(scratch.launch.xml TIMEOUT 60)\n")
    assert levels(root) == [("ros2_schema", 2, "error")]
    (tmp_path / "test" / "CMakeLists.txt").unlink()
    (tmp_path / "CMakeLists.txt").write_text(
        INSTALLS_LAUNCH + "add_launch_test(test/scratch.launch.xml)\n")
    assert levels(root) == [("ros2_schema", 2, "error")]


def test_a_ros2_file_never_installed_is_info(tmp_path: Path) -> None:
    """Install rules read completely, none installs test/: ros2 launch cannot find it."""
    root = package(tmp_path) / "test" / "scratch.launch.xml"
    root.write_text(ROS2_MISSPELT)
    assert levels(root) == [("file_never_launched", 1, "info"), ("ros2_schema", 2, "info")]


def test_a_ros2_file_installed_keeps_its_error(tmp_path: Path) -> None:
    root = package(tmp_path) / "launch" / "drive.launch.xml"
    root.write_text(ROS2_MISSPELT)
    assert levels(root) == [("ros2_schema", 2, "error")]


def test_a_ros2_file_whose_install_is_unknown_keeps_its_error(tmp_path: Path) -> None:
    """add_subdirectory may install more: not proven absent, and no ROS 1 sign."""
    root = package(tmp_path, INSTALLS_LAUNCH + "add_subdirectory(test)\n") / "test" / \
        "scratch.launch.xml"
    root.write_text(ROS2_MISSPELT)
    assert levels(root) == [("ros2_schema", 2, "error")]


def test_a_rostest_file_whose_install_is_unknown_is_info(tmp_path: Path) -> None:
    root = package(tmp_path, INSTALLS_LAUNCH + "add_subdirectory(test)\n") / "test" / \
        "drive_test.xml"
    root.write_text(ROSTEST)
    assert {level for _, _, level in levels(root)} == {"info"}


def test_a_ros1_sign_in_a_comment_is_not_one(tmp_path: Path) -> None:
    root = package(tmp_path, INSTALLS_LAUNCH + "add_subdirectory(test)\n") / "test" / \
        "scratch.launch.xml"
    root.write_text('<!-- was <test test-name="x"/> in ROS 1 -->\n' + ROS2_MISSPELT)
    assert levels(root) == [("ros2_schema", 3, "error")]


def test_twenty_thousand_refusals_in_a_file_nothing_runs(tmp_path: Path) -> None:
    root = package(tmp_path) / "test" / "drive_test.xml"
    root.write_text("<launch>\n" + '<rosparam param="p"/>\n' * 10_000
                    + '<node pkg="a" type="b"/>\n' * 10_000 + "</launch>\n")
    started = time.process_time()
    found = levels(root)
    assert time.process_time() - started < 60
    assert ("file_never_launched", 1, "info") in found
    assert {level for _, _, level in found} == {"info"}


def test_ros1_signs_read_in_linear_time() -> None:
    """Unclosed ``<node`` tags and comment openers: each scan stops at the next ``<``."""
    started = time.process_time()
    assert ros1_sign(b"<launch>" + b"<node pkg='a' " * 20_000 + b"<!--" * 20_000) is None
    assert ros1_sign(b"<node a='b' " * 20_000 + b"type='x'>") == "<node type=>"
    assert time.process_time() - started < 60


def test_twenty_thousand_cmake_commands_read_once(tmp_path: Path) -> None:
    root = package(tmp_path) / "test" / "scratch.launch.xml"
    root.write_text(ROS2_MISSPELT)
    (tmp_path / "test" / "CMakeLists.txt").write_text(
        "# scratch.launch.xml\n" + "set(a b c d)\n" * 20_000)
    started = time.process_time()
    assert levels(root) == [("file_never_launched", 1, "info"), ("ros2_schema", 2, "info")]
    assert time.process_time() - started < 60


def test_a_package_without_its_build_file_proves_nothing_uninstalled(tmp_path: Path) -> None:
    """A partial copy (package.xml and the launch folder, no CMakeLists.txt or setup.py):
    its install rules were never read, so its refusals stay errors (autoware_universe
    #10072's trimmed package)."""
    (tmp_path / "package.xml").write_text(MANIFEST)
    (tmp_path / "launch").mkdir()
    root = tmp_path / "launch" / "drive.launch.xml"
    root.write_text(ROS2_MISSPELT)
    found = levels(root)
    assert "file_never_launched" not in {rule for rule, _, _ in found}
    assert "error" in {level for _, _, level in found}
    (tmp_path / "CMakeLists.txt").write_text("project(drive)\n")
    assert ("file_never_launched", 1, "info") in levels(root)


def test_an_installed_ros1_file_named_as_a_kept_copy_is_info(tmp_path: Path) -> None:
    # gazebo_worlds' old_small_warehouse.launch.xml beside small_warehouse.launch.py.
    root = package(tmp_path) / "launch" / "old_drive.launch.xml"
    root.write_text(ROSTEST)
    (tmp_path / "launch" / "drive.launch.py").write_text("def generate_launch_description(): ...\n")
    found = levels(root)
    assert ("file_never_launched", 1, "info") in found
    assert {level for _, _, level in found} == {"info"}


def test_an_installed_half_ported_ros1_file_keeps_its_errors(tmp_path: Path) -> None:
    # Orbbec's multi_astra.launch.xml: installed, half-ported, not marked as a copy.
    root = package(tmp_path) / "launch" / "multi_drive.launch.xml"
    root.write_text(ROSTEST)
    assert {level for _, _, level in levels(root)} == {"error"}


@pytest.mark.parametrize(("name", "marked"), [
    ("old_small_warehouse.launch.xml", True), ("control.launch_ORIG.py", True),
    ("robot-backup.launch.xml", True), ("Copy of robot.launch", True),
    ("bold.launch", False), ("older.launch", False), ("holder.launch.xml", False),
])
def test_names_that_mark_a_kept_copy(name: str, marked: bool) -> None:
    from launch_linter.frontends.launchable import marked_as_copy

    assert marked_as_copy(name) is marked
