"""What a new user sees when nothing is published (found on hector_quadrotor, whose
descriptions include a package that is not in the repository): ``transforms`` says it
found nothing and why instead of printing nothing, and ``graph``'s caption gives the
cause of each empty entry point in full, once, without repeating the description."""

from __future__ import annotations

from pathlib import Path

import pytest

from launch_linter.cli import main
from launch_linter.engine import LintOptions, lint_paths
from launch_linter.graph.model import build_graph

SPAWN = """<launch>
  <param name="robot_description" command="xacro $(dirname)/robot.urdf.xacro"/>
  <node pkg="robot_state_publisher" type="robot_state_publisher" name="rsp"/>
</launch>
"""

ROBOT = """<?xml version="1.0"?>
<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:include filename="$(find hector_sensors_description)/urdf/sonar_sensor.urdf.xacro"/>
  <link name="base_link"/>
  <xacro:sonar_sensor name="sonar" parent="base_link"/>
</robot>
"""


@pytest.fixture
def folder(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    (tmp_path / "spawn.launch").write_text(SPAWN)
    (tmp_path / "robot.urdf.xacro").write_text(ROBOT)
    monkeypatch.chdir(tmp_path)
    return tmp_path


def test_transforms_says_nothing_was_found_and_why(
    folder: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    assert main(["transforms", "spawn.launch"]) == 0
    out, err = capsys.readouterr()
    assert out == ""
    assert err == ("No transforms found in 1 file(s); 1 robot description(s) gave no joint "
                   "(`launch-linter check` says why).\n")


def test_transforms_says_nothing_more_when_something_is_listed(
    folder: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    (folder / "robot.urdf.xacro").write_text(
        '<robot name="r"><link name="a"/><link name="b"/>'
        '<joint name="j" type="fixed"><parent link="a"/><child link="b"/></joint></robot>\n')
    main(["transforms", "spawn.launch"])
    out, err = capsys.readouterr()
    assert "urdf fixed joint j a -> b" in out and err == ""


def test_the_caption_gives_the_cause_in_full_once(folder: Path) -> None:
    result = lint_paths(["spawn.launch"], LintOptions())
    (reason,) = [note for note in build_graph(result).notes if "gave no joint" in note]
    assert reason.endswith(
        "spawn.launch: robot_description at spawn.launch:2 gave no joint: robot.urdf.xacro:3: "
        "<xacro:include>: $(find hector_sensors_description): package not found under the "
        "package path")
    assert "robot description" not in reason and "unknown macro" not in reason
