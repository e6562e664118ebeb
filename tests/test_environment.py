"""Packages from a sourced environment and a built workspace (issue 27), in ROS's order."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

from launch_linter.engine import LintOptions, lint_paths
from launch_linter.workspace.environment import built_beside, environment_places
from launch_linter.workspace.packages import PackageIndex

AMENT = ('<?xml version="1.0"?><package format="3"><name>{name}</name>'
         "<export><build_type>ament_cmake</build_type></export></package>")


def write(path: Path, text: str) -> Path:
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text)
    return path


def installed(prefix: Path, name: str, files: dict[str, str], indexed: bool = True) -> Path:
    share = prefix / "share" / name
    write(share / "package.xml", AMENT.format(name=name))
    if indexed:
        write(prefix / "share" / "ament_index" / "resource_index" / "packages" / name, "")
    for relative, text in files.items():
        write(share / relative, text)
    return share


def tf_launch(child: str) -> str:
    return (f'<launch><node pkg="tf2_ros" exec="static_transform_publisher" '
            f'args="--frame-id a --child-frame-id {child}"/></launch>')


def test_the_order_of_the_environment_variables() -> None:
    places = environment_places({
        "CMAKE_PREFIX_PATH": "/c", "ROS_PACKAGE_PATH": f"/r1{os.pathsep}/r2",
        "AMENT_PREFIX_PATH": f"/overlay{os.pathsep}/opt/ros/jazzy{os.pathsep}/overlay",
    })
    assert places == (("prefix", "/overlay"), ("prefix", "/opt/ros/jazzy"),
                      ("source", "/r1"), ("source", "/r2"), ("prefix", "/c"))
    assert environment_places({}) == ()


def test_an_overlay_wins_over_its_underlay_and_sources_over_both(tmp_path: Path) -> None:
    overlay, underlay = tmp_path / "overlay", tmp_path / "underlay"
    installed(overlay, "shared", {})
    installed(underlay, "shared", {})
    installed(underlay, "only_under", {}, indexed=False)  # a catkin install: no index
    write(tmp_path / "src" / "shared" / "package.xml", AMENT.format(name="shared"))
    places = environment_places({"AMENT_PREFIX_PATH": f"{overlay}{os.pathsep}{underlay}"})
    index = PackageIndex([], places)
    assert index.find("shared") == str(overlay / "share" / "shared")
    assert index.find("only_under") == str(underlay / "share" / "only_under")
    with_sources = PackageIndex([str(tmp_path / "src")], places)
    assert with_sources.find("shared") == str(tmp_path / "src" / "shared")


def test_installed_files_are_read_not_linted(tmp_path: Path) -> None:
    prefix = tmp_path / "opt"
    installed(prefix, "sensors", {"launch/lidar.launch.xml": tf_launch("lidar")})
    ws = tmp_path / "ws"
    write(ws / "src" / "bot" / "package.xml", AMENT.format(name="bot"))
    top = write(ws / "src" / "bot" / "launch" / "bot.launch.xml",
                '<launch><include file="$(find-pkg-share sensors)/launch/lidar.launch.xml"/>'
                '</launch>')
    without = lint_paths([str(ws)], LintOptions())
    assert [t.child for t in without.transforms] == []
    assert any("package 'sensors' not found" in d.message for d in without.diagnostics)
    options = LintOptions(environment=environment_places({"AMENT_PREFIX_PATH": str(prefix)}))
    result = lint_paths([str(ws)], options)
    assert [f.path for f in result.files] == [str(top)]
    assert [t.child for t in result.transforms] == ["lidar"]


def test_a_missing_file_of_an_installed_package_is_absent(tmp_path: Path) -> None:
    prefix = tmp_path / "opt"
    installed(prefix, "sensors", {})
    write(tmp_path / "ws" / "src" / "bot" / "package.xml", AMENT.format(name="bot"))
    top = write(tmp_path / "ws" / "src" / "bot" / "launch" / "bot.launch.xml",
                '<launch><include file="$(find-pkg-share sensors)/launch/gone.launch.xml"/>'
                '</launch>')
    options = LintOptions(environment=environment_places({"AMENT_PREFIX_PATH": str(prefix)}))
    errors = [d.message for d in lint_paths([str(top)], options).diagnostics
              if d.rule == "roslaunch_error"]
    assert errors == [f"included file not found: "
                      f"{prefix}/share/sensors/launch/gone.launch.xml"]


def test_the_workspace_install_folder_beside_src(tmp_path: Path) -> None:
    ws = tmp_path / "ws"
    installed(ws / "install" / "sensors", "sensors",
              {"launch/lidar.launch.xml": tf_launch("lidar")})  # colcon isolated layout
    write(ws / "src" / "bot" / "package.xml", AMENT.format(name="bot"))
    write(ws / "src" / "bot" / "launch" / "bot.launch.xml",
          '<launch><include file="$(find-pkg-share sensors)/launch/lidar.launch.xml"/>'
          '</launch>')
    assert built_beside([str(ws / "src")]) == (("prefix", str(ws / "install")),)
    result = lint_paths([str(ws / "src")], LintOptions())
    assert [t.child for t in result.transforms] == ["lidar"]
    assert len(result.files) == 1


def test_ros_package_path_is_crawled_like_sources(tmp_path: Path) -> None:
    write(tmp_path / "share" / "amcl" / "package.xml",
          "<package><name>amcl</name></package>")
    write(tmp_path / "share" / "amcl" / "examples" / "a.launch",
          '<launch><node pkg="tf" type="static_transform_publisher" name="t" '
          'args="0 0 0 0 0 0 map odom 100"/></launch>')
    write(tmp_path / "ws" / "src" / "bot" / "package.xml", "<package><name>bot</name></package>")
    top = write(tmp_path / "ws" / "src" / "bot" / "a.launch",
                '<launch><include file="$(find amcl)/examples/a.launch"/></launch>')
    options = LintOptions(environment=environment_places(
        {"ROS_PACKAGE_PATH": str(tmp_path / "share")}))
    assert [t.child for t in lint_paths([str(top)], options).transforms] == ["odom"]


def test_check_reads_a_sourced_shell(tmp_path: Path) -> None:
    prefix = tmp_path / "opt"
    installed(prefix, "sensors", {"launch/lidar.launch.xml": tf_launch("lidar")})
    write(tmp_path / "ws" / "src" / "bot" / "package.xml", AMENT.format(name="bot"))
    top = write(tmp_path / "ws" / "src" / "bot" / "launch" / "bot.launch.xml",
                '<launch><include file="$(find-pkg-share sensors)/launch/lidar.launch.xml"/>'
                '</launch>')
    env = {k: v for k, v in os.environ.items()
           if k not in ("AMENT_PREFIX_PATH", "ROS_PACKAGE_PATH", "CMAKE_PREFIX_PATH")}
    command = [sys.executable, "-m", "launch_linter", "check", str(top), "--format", "json",
               "--exit-zero"]
    before = json.loads(subprocess.run(command, env=env, capture_output=True, text=True,
                                       check=True).stdout)
    env["AMENT_PREFIX_PATH"] = str(prefix)
    after = json.loads(subprocess.run(command, env=env, capture_output=True, text=True,
                                      check=True).stdout)
    assert any("not found" in d["message"] for d in before["diagnostics"])
    assert not any("not found" in d["message"] for d in after["diagnostics"])


def test_a_hostile_environment_is_bounded() -> None:
    many = os.pathsep.join(f"/p{i}" for i in range(20_000))
    places = environment_places({"AMENT_PREFIX_PATH": many, "ROS_PACKAGE_PATH": many})
    assert len(places) == 2 * 256
