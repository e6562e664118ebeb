"""``__file__`` in a Python launch file names where the file is installed
(``share/<pkg>/launch/``), so paths made from it are mapped back through the install
layout to their source files."""

from __future__ import annotations

from pathlib import Path

import pytest

from launch_linter import LintOptions, lint_paths

PACKAGE = ('<package format="3"><name>p</name><version>0.0.0</version><description>d'
           '</description><maintainer email="a@b.c">a</maintainer><license>MIT</license>'
           '<buildtool_depend>ament_cmake</buildtool_depend></package>')
CMAKE = """cmake_minimum_required(VERSION 3.8)
project(p)
install(DIRECTORY bringup/launch description/urdf DESTINATION share/${PROJECT_NAME})
"""
URDF = ('<robot name="r"><link name="base_link"/><link name="laser"/><joint name="j" '
        'type="fixed"><parent link="base_link"/><child link="laser"/></joint></robot>')
HEAD = """import os
from pathlib import Path
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
"""


@pytest.mark.parametrize("body", [
    "    urdf = os.path.join(os.path.dirname(__file__), '..', 'urdf', 'r.urdf')\n"
    "    text = open(urdf).read()\n",
    "    text = (Path(__file__).parent.parent / 'urdf' / 'r.urdf').read_text()\n",
    "    text = open(str(Path(__file__).resolve().parent.parent / 'urdf' / 'r.urdf')).read()\n",
])
def test_a_path_from_file_is_read_through_the_install_layout(tmp_path: Path,
                                                             body: str) -> None:
    package = tmp_path / "src" / "p"
    (package / "bringup" / "launch").mkdir(parents=True)
    (package / "description" / "urdf").mkdir(parents=True)
    (package / "package.xml").write_text(PACKAGE, encoding="utf-8")
    (package / "CMakeLists.txt").write_text(CMAKE, encoding="utf-8")
    (package / "description" / "urdf" / "r.urdf").write_text(URDF, encoding="utf-8")
    launch = package / "bringup" / "launch" / "a.launch.py"
    launch.write_text(HEAD + body + "    return LaunchDescription([Node(package="
                      "'robot_state_publisher', executable='robot_state_publisher', "
                      "parameters=[{'robot_description': text}])])\n", encoding="utf-8")
    result = lint_paths([str(launch)], LintOptions())
    (tree,) = result.trees
    assert [(j.parent, j.child) for j in tree.joints] == [("base_link", "laser")]
    assert not [d for d in result.diagnostics if d.severity.value in ("error", "warning")]


def test_without_install_rules_file_is_where_the_file_is(tmp_path: Path) -> None:
    package = tmp_path / "p"
    (package / "launch").mkdir(parents=True)
    (package / "urdf").mkdir()
    (package / "package.xml").write_text(PACKAGE, encoding="utf-8")
    (package / "urdf" / "r.urdf").write_text(URDF, encoding="utf-8")
    launch = package / "launch" / "a.launch.py"
    launch.write_text(HEAD + "    text = (Path(__file__).parent.parent / 'urdf' / 'r.urdf')"
                      ".read_text()\n    return LaunchDescription([Node(package="
                      "'robot_state_publisher', executable='robot_state_publisher', "
                      "parameters=[{'robot_description': text}])])\n", encoding="utf-8")
    (tree,) = lint_paths([str(launch)], LintOptions()).trees
    assert [j.child for j in tree.joints] == ["laser"]
