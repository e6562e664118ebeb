"""A diagnostic about text reached through an include names the include, once, in every
format: ROS 1 XML and ROS 2 XML, YAML and Python alike (text: ``(included from
FILE:LINE)``; JSON: ``included_from``; SARIF: a related location "included from here")."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from launch_linter.cli import main

PACKAGE_XML = """<?xml version="1.0"?>
<package format="3">
  <name>demo</name><version>0.0.0</version><description>d</description>
  <maintainer email="a@b.c">a</maintainer><license>MIT</license>
  <buildtool_depend>ament_cmake</buildtool_depend>
  <export><build_type>ament_cmake</build_type></export>
</package>
"""

ROS1 = {
    "part.launch": """<launch>
  <arg name="model"/>
  <node pkg="tf" type="static_transform_publisher" name="t_$(arg model)"
        args="0 0 0 0 0 0 a $(env HOST_FRAME) 100"/>
</launch>
""",
    "bringup.launch": """<launch>
  <include file="$(dirname)/part.launch"><arg name="model" value="burger"/></include>
  <include file="$(dirname)/part.launch"><arg name="model" value="waffle"/></include>
</launch>
""",
}

ROS2_XML = {
    "part.launch.xml": """<launch>
  <arg name="model"/>
  <node pkg="tf2_ros" exec="static_transform_publisher" name="t_$(var model)"
        args="--frame-id a --child-frame-id $(env HOST_FRAME)"/>
</launch>
""",
    "bringup.launch.xml": """<launch>
  <include file="$(dirname)/part.launch.xml"><arg name="model" value="burger"/></include>
  <include file="$(dirname)/part.launch.xml"><arg name="model" value="waffle"/></include>
</launch>
""",
}

ROS2_YAML = {
    "part.launch.yaml": """launch:
- arg:
    name: model
- node:
    pkg: tf2_ros
    exec: static_transform_publisher
    name: "t_$(var model)"
    args: "--frame-id a --child-frame-id $(env HOST_FRAME)"
""",
    "bringup.launch.yaml": """launch:
- include:
    file: "$(dirname)/part.launch.yaml"
    arg:
    - {name: model, value: burger}
- include:
    file: "$(dirname)/part.launch.yaml"
    arg:
    - {name: model, value: waffle}
""",
}

ROS2_PYTHON = {
    "part.launch.py": """import os

from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='tf2_ros', executable='static_transform_publisher',
             arguments=['--frame-id', 'a', '--child-frame-id', os.environ['HOST_FRAME']]),
    ])
""",
    "bringup.launch.py": """import os

from launch import LaunchDescription
from launch.actions import IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource


def generate_launch_description():
    here = os.path.dirname(__file__)
    part = PythonLaunchDescriptionSource(os.path.join(here, 'part.launch.py'))
    return LaunchDescription([
        IncludeLaunchDescription(part, launch_arguments={'model': 'burger'}.items()),
        IncludeLaunchDescription(part, launch_arguments={'model': 'waffle'}.items()),
    ])
""",
}

CASES = [
    pytest.param(ROS1, "bringup.launch", 2, 3, id="ros1-xml"),
    pytest.param(ROS2_XML, "bringup.launch.xml", 2, 3, id="ros2-xml"),
    pytest.param(ROS2_YAML, "bringup.launch.yaml", 2, 3, id="ros2-yaml"),
    pytest.param(ROS2_PYTHON, "bringup.launch.py", 12, 9, id="ros2-python"),
]


def _project(root: Path, files: dict[str, str]) -> None:
    (root / "pkg").mkdir()
    (root / "pkg" / "package.xml").write_text(PACKAGE_XML)
    for name, text in files.items():
        (root / "pkg" / name).write_text(text)


def _run(capsys: pytest.CaptureFixture[str], *argv: str) -> str:
    capsys.readouterr()
    main(["check", *argv, "--exit-zero", "--no-cache"])
    return capsys.readouterr().out


@pytest.mark.parametrize(("files", "root", "line", "column"), CASES)
def test_text_names_the_including_file_once(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch,
    files: dict[str, str], root: str, line: int, column: int,
) -> None:
    _project(tmp_path, files)
    monkeypatch.chdir(tmp_path)
    out = _run(capsys, f"pkg/{root}")
    through = [text for text in out.splitlines() if "HOST_FRAME" in text]
    # Included twice with other arguments: the cause once, with the first include.
    assert len(through) == 1, out
    assert through[0].endswith(f" (included from pkg/{root}:{line}) [unresolved]")
    assert through[0].count("included from") == 1


@pytest.mark.parametrize(("files", "root", "line", "column"), CASES)
def test_json_and_sarif_name_the_include(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch,
    files: dict[str, str], root: str, line: int, column: int,
) -> None:
    _project(tmp_path, files)
    monkeypatch.chdir(tmp_path / "pkg")
    document = json.loads(_run(capsys, root, "--format", "json"))
    (found,) = [d for d in document["diagnostics"] if "HOST_FRAME" in d["message"]]
    site = {"path": root, "line": line, "column": column}
    assert found["included_from"] == site
    assert found["related"][-1] == site
    sarif = json.loads(_run(capsys, root, "--format", "sarif"))
    (result,) = [r for r in sarif["runs"][0]["results"] if "HOST_FRAME" in r["message"]["text"]]
    (related,) = result["relatedLocations"]
    assert related["message"]["text"] == "included from here"
    assert related["physicalLocation"]["artifactLocation"]["uri"] == root
    assert related["physicalLocation"]["region"]["startLine"] == line


def test_text_of_the_file_linted_itself_names_no_include(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    _project(tmp_path, ROS2_PYTHON)
    monkeypatch.chdir(tmp_path / "pkg")
    document = json.loads(_run(capsys, "part.launch.py", "--format", "json"))
    (found,) = document["diagnostics"]
    assert found["included_from"] is None and "included from" not in found["message"]


SPAWN = """<launch>
  <arg name="model" default="base"/>
  <param name="robot_description" command="xacro $(dirname)/$(arg model).urdf.xacro"/>
  <node pkg="robot_state_publisher" type="robot_state_publisher" name="rsp"/>
</launch>
"""

VARIANT = """<?xml version="1.0"?>
<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:include filename="$(find missing_sensors)/urdf/sonar.urdf.xacro"/>
  <link name="base_link"/>
  <xacro:sonar_sensor parent="base_link"/>
</robot>
"""

WITH_CAMERA = """<launch>
  <include file="$(dirname)/spawn.launch"><arg name="model" value="camera"/></include>
</launch>
"""


def test_a_description_an_include_gives_names_the_include_once_per_variant(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    """A multi-robot ROS 1 stack: spawn.launch is linted alone (its default model) and
    included for another model; a description whose sensor include is not read names
    that include, not the macro it would have defined."""
    _project(tmp_path, {"spawn.launch": SPAWN, "base.urdf.xacro": VARIANT,
                        "camera.urdf.xacro": VARIANT, "with_camera.launch": WITH_CAMERA,
                        "also_camera.launch": WITH_CAMERA})
    monkeypatch.chdir(tmp_path / "pkg")
    lines = [line for line in _run(capsys, ".").splitlines() if "spawn.launch:3:" in line]
    assert all("unknown macro" not in line for line in lines), lines
    base = [line for line in lines if "base.urdf.xacro:3:" in line]
    camera = [line for line in lines if "camera.urdf.xacro:3:" in line]
    assert len(base) == 1 and "included from" not in base[0]
    # Included by two roots: once, naming the first include.
    assert len(camera) == 1, lines
    assert camera[0].endswith("(included from also_camera.launch:2) [unresolved]")
