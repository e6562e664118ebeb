"""node_executable_missing when the package's source is in the linted workspace: that
checkout shadows the installed release, so the release facts of the knowledge base do
not decide (robot_state_publisher's own source copied into a workspace, its `<test>`
files running `state_publisher`)."""

from __future__ import annotations

import os
import time
from pathlib import Path

import pytest

from launch_linter import __version__
from launch_linter.commands.options import NO_CACHE_VARIABLE
from launch_linter.engine import LintOptions, lint_paths
from launch_linter.results_cache import ResultsCache

RULE = "node_executable_missing"
MANIFEST = "<package><name>{name}</name><buildtool_depend>catkin</buildtool_depend></package>\n"
RSP_CMAKE = """project(robot_state_publisher)
find_package(catkin REQUIRED)
add_executable(robot_state_publisher src/joint_state_listener.cpp)
add_executable(state_publisher src/joint_state_listener.cpp)
"""
NODE = '<node name="rsp{i}" pkg="{package}" type="state_publisher"/>'


def package(root: Path, name: str, cmake: str = "project(x)\n") -> Path:
    folder = root / name
    (folder / "launch").mkdir(parents=True, exist_ok=True)
    (folder / "package.xml").write_text(MANIFEST.format(name=name))
    (folder / "CMakeLists.txt").write_text(cmake)
    return folder


def lint(launch: Path, roots: tuple[str, ...] | None, distro: str | None,
         environment: tuple[tuple[str, str], ...] = ()) -> list[tuple[int, str]]:
    options = LintOptions(package_paths=roots, select=frozenset({RULE}), ros_distro=distro,
                          environment=environment)
    return [(d.line, d.severity.value) for d in lint_paths([str(launch)], options).diagnostics]


def launch_file(folder: Path, package_name: str = "robot_state_publisher",
                count: int = 1) -> Path:
    path = folder / "launch" / "view.launch"
    path.write_text("<launch>\n" + "\n".join(
        NODE.format(i=i, package=package_name) for i in range(count)) + "\n</launch>\n")
    return path


def test_a_source_copy_in_the_workspace_silences_the_release_fact(tmp_path: Path) -> None:
    src = tmp_path / "ws" / "src"
    rsp = package(src, "robot_state_publisher", RSP_CMAKE)
    own = launch_file(rsp)
    other = launch_file(package(src, "my_robot"))
    for distro in ("noetic", None):
        assert lint(own, None, distro) == []  # the workspace found from the file
        assert lint(other, None, distro) == []
        assert lint(other, (str(src),), distro) == []


def test_without_the_source_the_release_fact_still_reports(tmp_path: Path) -> None:
    src = tmp_path / "ws" / "src"
    other = launch_file(package(src, "my_robot"))
    assert lint(other, None, "noetic") == [(2, "error")]
    assert lint(other, (str(src),), None) == [(2, "info")]
    # Installed (a prefix's share folder), not source: the release decides.
    share = tmp_path / "opt" / "ros" / "noetic" / "share" / "robot_state_publisher"
    share.mkdir(parents=True)
    (share / "package.xml").write_text(MANIFEST.format(name="robot_state_publisher"))
    prefix = (("prefix", str(tmp_path / "opt" / "ros" / "noetic")),)
    assert lint(other, (str(src),), "noetic", prefix) == [(2, "error")]


def test_a_source_copy_outside_the_linted_roots_does_not_count(tmp_path: Path) -> None:
    src = tmp_path / "ws" / "src"
    other = launch_file(package(src, "my_robot"))
    package(tmp_path / "elsewhere", "robot_state_publisher", RSP_CMAKE)
    assert lint(other, (str(src),), "noetic") == [(2, "error")]


def test_twenty_thousand_nodes_of_twenty_thousand_packages(tmp_path: Path) -> None:
    # Each package name is asked once; an unknown package costs no crawl.
    src = tmp_path / "ws" / "src"
    folder = package(src, "my_robot")
    path = folder / "launch" / "many.launch"
    path.write_text("<launch>\n" + "\n".join(
        NODE.format(i=i, package=f"p{i}" if i % 2 else "robot_state_publisher")
        for i in range(20_000)) + "\n</launch>\n")
    started = time.process_time()
    assert len(lint(path, (str(src),), "noetic")) == 10_000
    package(src, "robot_state_publisher", RSP_CMAKE)
    assert lint(path, (str(src),), "noetic") == []
    assert time.process_time() - started < 60


ROS2_MANIFEST = """<package format="3"><name>robot_state_publisher</name>
<export><build_type>ament_cmake</build_type></export></package>
"""
ROS2_LAUNCH = """from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='robot_state_publisher', executable='{executable}'),
    ])
"""


def test_a_ros2_source_copy_is_judged_by_its_own_install_rules(tmp_path: Path) -> None:
    # The release fact gives way; the package's CMakeLists.txt, read completely, decides.
    rsp = tmp_path / "ws" / "src" / "robot_state_publisher"
    (rsp / "launch").mkdir(parents=True)
    (rsp / "package.xml").write_text(ROS2_MANIFEST)
    (rsp / "CMakeLists.txt").write_text(
        "project(robot_state_publisher)\nadd_executable(robot_state_publisher src/a.cpp)\n"
        "install(TARGETS robot_state_publisher DESTINATION lib/${PROJECT_NAME})\n")
    path = rsp / "launch" / "rsp.launch.py"
    path.write_text(ROS2_LAUNCH.format(executable="state_publisher"))
    options = LintOptions(select=frozenset({RULE}), ros_distro="humble")
    found = lint_paths([str(path)], options).diagnostics
    assert [(d.line, d.severity.value) for d in found] == [(7, "error")]
    assert "installs no executable 'state_publisher' into lib/" in found[0].message
    (rsp / "CMakeLists.txt").write_text(
        "project(robot_state_publisher)\nadd_executable(state_publisher src/a.cpp)\n"
        "install(TARGETS state_publisher DESTINATION lib/${PROJECT_NAME})\n")
    assert lint(path, None, "humble") == []


def test_a_source_copy_added_later_relints_through_the_results_cache(
        tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    # The tree depends on the package crawl that found (or did not find) the source.
    monkeypatch.delenv(NO_CACHE_VARIABLE, raising=False)
    monkeypatch.chdir(tmp_path)
    src = tmp_path / "ws" / "src"
    launch_file(package(src, "my_robot"))
    options = LintOptions(select=frozenset({RULE}), ros_distro="noetic")

    def cached() -> tuple[list[int], list[str]]:
        cache = ResultsCache.open(str(tmp_path / "cache"), __version__, options)
        assert cache is not None
        found = lint_paths(["ws"], options, keep_trees=False, cache=cache).diagnostics
        cache.save()
        return [d.line for d in found], [os.path.basename(p) for p in cache.missed]

    assert cached() == ([2], ["view.launch"])
    assert cached() == ([2], [])
    package(src, "robot_state_publisher", RSP_CMAKE)
    assert cached() == ([], ["view.launch"])
