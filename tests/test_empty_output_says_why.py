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


ARM_VARIANT = """<?xml version="1.0"?>
<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:arg name="arm" default="gen3"/>
  <xacro:include filename="$(find kortex_description)/arms/$(arg arm)/macro.xacro"/>
  <xacro:include filename="$(find kortex_description)/grippers/macro.xacro"/>
  <link name="world"/>
  <joint name="tool_frame_joint" type="fixed">
    <parent link="${last_arm_link}"/><child link="tool_frame"/>
  </joint>
  <link name="tool_frame"/>
</robot>
"""


def test_a_description_says_each_cause_once_and_not_its_consequences(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """A xacro-heavy arm (ros2_kortex): the package its includes need is not found; that
    is said once, not once per include, and the joint whose parent the arm macro would
    have defined is not another cause."""
    (tmp_path / "spawn.launch").write_text(SPAWN)
    (tmp_path / "robot.urdf.xacro").write_text(ARM_VARIANT)
    monkeypatch.chdir(tmp_path)
    result = lint_paths(["spawn.launch"], LintOptions())
    messages = [d.message for d in result.diagnostics if d.rule == "unresolved"]
    assert len(messages) == 1, messages
    assert "$(find kortex_description)" in messages[0]
