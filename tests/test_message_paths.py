"""A message that quotes a path shows it as the report shows file paths: relative to the
current folder when under it, absolute otherwise (``model.paths.shown_path``). A tree
whose messages quote paths of every kind (an include not found or not followed, a
parameter file, an include's unused arguments, xacro includes missing or broken, a
description file partly unresolved, a URDF without links; ROS 1 and ROS 2) is linted
from a package folder and from above the tree: no message holds an absolute path under
the current folder."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from launch_linter.cli import main
from launch_linter.model.paths import shown_in_text

CATKIN = """<?xml version="1.0"?>
<package format="2"><name>pkg</name><version>0.0.0</version><description>d</description>
<maintainer email="a@b.c">a</maintainer><license>MIT</license>
<buildtool_depend>catkin</buildtool_depend></package>
"""

AMENT = """<?xml version="1.0"?>
<package format="3"><name>pkg2</name><version>0.0.0</version><description>d</description>
<maintainer email="a@b.c">a</maintainer><license>MIT</license>
<buildtool_depend>ament_cmake</buildtool_depend>
<export><build_type>ament_cmake</build_type></export></package>
"""

FILES = {
    "pkg/package.xml": CATKIN,
    "pkg/launch/root.launch": """<launch>
  <include file="$(find pkg)/launch/missing.launch"/>
  <include file="$(find pkg)/launch/part.launch"><arg name="unused" value="1"/></include>
  <rosparam file="$(find pkg)/config/none.yaml" command="load"/>
  <param name="robot_description" command="xacro $(find pkg)/urdf/r.urdf.xacro"/>
  <node pkg="robot_state_publisher" type="robot_state_publisher" name="rsp"/>
</launch>
""",
    "pkg/launch/part.launch": "<launch></launch>\n",
    "pkg/launch/var.launch": """<launch>
  <arg name="model"/>
  <include file="$(find pkg)/launch/$(arg model).launch"/>
  <param name="robot_description" command="xacro $(find pkg)/urdf/$(arg model).urdf.xacro"/>
  <node pkg="robot_state_publisher" type="robot_state_publisher" name="rsp"/>
</launch>
""",
    "pkg/launch/empty.launch": """<launch>
  <param name="robot_description" textfile="$(find pkg)/urdf/empty.urdf"/>
  <node pkg="robot_state_publisher" type="robot_state_publisher" name="rsp"/>
</launch>
""",
    "pkg/urdf/r.urdf.xacro": """<?xml version="1.0"?>
<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:include filename="$(find pkg)/urdf/nothere.xacro"/>
  <xacro:include filename="$(find pkg)/urdf/broken.xacro"/>
  <link name="base_link"/>
</robot>
""",
    "pkg/urdf/broken.xacro": "<robot>\n<link name=\"x\">\n</robot>\n",
    "pkg/urdf/empty.urdf": '<?xml version="1.0"?>\n<robot name="e"></robot>\n',
    "pkg2/package.xml": AMENT,
    "pkg2/launch/bringup.launch.py": """import os

from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import Command, LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    share = get_package_share_directory('pkg2')
    model = LaunchConfiguration('model', default='m')
    return LaunchDescription([
        IncludeLaunchDescription(PythonLaunchDescriptionSource(
            os.path.join(share, 'launch', 'missing.launch.py'))),
        IncludeLaunchDescription(PythonLaunchDescriptionSource(
            [share, '/launch/', LaunchConfiguration('other'), '.launch.py'])),
        Node(package='robot_state_publisher', executable='robot_state_publisher',
             parameters=[{'robot_description': Command(
                 ['xacro ', share, '/urdf/', LaunchConfiguration('other'), '.xacro'])}]),
        Node(package='robot_state_publisher', executable='robot_state_publisher', name='b',
             parameters=[{'robot_description': Command(
                 ['xacro ', share, '/urdf/', model, '.xacro'])}]),
    ])
""",
}


@pytest.fixture
def tree(tmp_path: Path) -> Path:
    root = tmp_path / "ws" / "src"
    for name, text in FILES.items():
        (root / name).parent.mkdir(parents=True, exist_ok=True)
        (root / name).write_text(text)
    return root


def _messages(capsys: pytest.CaptureFixture[str], *paths: str) -> list[str]:
    capsys.readouterr()
    main(["check", *paths, "--format", "json", "--exit-zero", "--no-cache"])
    return [d["message"] for d in json.loads(capsys.readouterr().out)["diagnostics"]]


@pytest.mark.parametrize("where", ["ws/src/pkg", "ws/src/pkg2", "ws/src", "ws", "."])
def test_no_message_quotes_the_current_folder_absolute(
    tree: Path, tmp_path: Path, capsys: pytest.CaptureFixture[str],
    monkeypatch: pytest.MonkeyPatch, where: str,
) -> None:
    monkeypatch.chdir(tmp_path / where)
    messages = _messages(capsys, str(tree))
    quoting = [m for m in messages if any(word in m for word in (
        "not found", "not followed", "does not exist", "unused args", "cannot read",
        "not well-formed", "defines no link", "is not resolved"))]
    assert len(quoting) >= 10, messages  # every kind above was reported
    # Under the current folder every path is relative; from a package folder, the other
    # package's files are outside it and stay absolute.
    absolute = [m for m in messages if str(tmp_path / where) + "/" in m]
    assert not absolute, "\n".join(absolute)


def test_the_quoted_paths_are_relative_to_the_current_folder(
    tree: Path, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.chdir(tree / "pkg")
    text = "\n".join(_messages(capsys, "."))
    for quoted in ("included file not found: launch/missing.launch",
                   "for include of [launch/part.launch]",
                   "file does not exist [config/none.yaml]",
                   "included file urdf/nothere.xacro not found",
                   "'urdf/empty.urdf' defines no link",
                   "include file 'launch/$(arg model).launch' not followed",
                   "the description file 'urdf/$(arg model).urdf.xacro' is not resolved"):
        assert quoted in text
    # An included file that is not well-formed is reported at its own file and line (the
    # <link> left open on line 2), the path as the diagnostic's, relative like the rest.
    main(["check", ".", "--format", "json", "--exit-zero", "--no-cache"])
    places = {(d["path"], d["line"]) for d in json.loads(capsys.readouterr().out)[
        "diagnostics"] if "not well-formed XML" in d["message"]}
    assert ("urdf/broken.xacro", 2) in places


def test_a_description_that_cannot_be_read_is_named_once(
    tree: Path, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.chdir(tree / "pkg2")
    (found,) = [m for m in _messages(capsys, ".") if "m.xacro" in m]
    # Not in its package, which is found: xacro stops on it (xacro_error).
    assert found == ("xacro stops here (no such file urdf/m.xacro): the xacro command fails, "
                     "so robot_description is not set and robot_state_publisher publishes "
                     "nothing")


def test_outside_the_current_folder_paths_stay_absolute(
    tree: Path, tmp_path: Path, capsys: pytest.CaptureFixture[str],
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    elsewhere = tmp_path / "elsewhere"
    elsewhere.mkdir()
    monkeypatch.chdir(elsewhere)
    text = "\n".join(_messages(capsys, str(tree / "pkg")))
    assert f"included file not found: {tree / 'pkg' / 'launch' / 'missing.launch'}" in text


def test_shown_in_text_keeps_the_unresolved_rest_as_written(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.chdir(tmp_path)
    written = f"{tmp_path}/pkg/launch/$(arg a/b).launch"
    assert shown_in_text(written, len(f"{tmp_path}/pkg/launch/")) == "pkg/launch/$(arg a/b).launch"
    assert shown_in_text("$(find x)/a.launch", 0) == "$(find x)/a.launch"
    assert shown_in_text("/elsewhere/$(arg a)", len("/elsewhere/")) == "/elsewhere/$(arg a)"


def test_a_configuration_error_names_the_file_as_paths_are_shown(
    tree: Path, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    (tree / "pkg" / "pyproject.toml").write_text("[tool.launch-linter]\nbogus = 1\n")
    monkeypatch.chdir(tree / "pkg")
    assert main(["check", "."]) == 2
    assert capsys.readouterr().err.startswith(
        "launch-linter: error: pyproject.toml: unknown key(s) 'bogus'")
    monkeypatch.chdir(tree / "pkg" / "launch")  # the file is above: absolute
    assert main(["check", "."]) == 2
    assert f"error: {tree / 'pkg' / 'pyproject.toml'}: unknown" in capsys.readouterr().err


def test_an_unparsable_description_is_named_once(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    """navigation2_tutorials: ``robot description X.urdf:4: X.urdf:4: not well-formed``."""
    (tmp_path / "robot.urdf").write_text('\n\n\n<?xml version="1.0"?>\n<robot name="r"/>\n')
    (tmp_path / "rsp.launch").write_text(
        '<launch>\n  <param name="robot_description" textfile="$(dirname)/robot.urdf"/>\n'
        '  <node pkg="robot_state_publisher" type="robot_state_publisher" name="rsp"/>\n'
        '</launch>\n')
    monkeypatch.chdir(tmp_path)
    (found,) = [m for m in _messages(capsys, "rsp.launch") if "well-formed" in m]
    assert found.startswith("robot description robot.urdf:4: not well-formed XML: ")
