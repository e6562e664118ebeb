"""The language server's state without the protocol: which entry points read a file,
unsaved texts, configuration as ``check`` reads it, hover text."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest

from launch_linter.resolve.xml_safe import read_launch_bytes, unsaved_texts
from launch_linter.server.session import Session

FIXTURE = Path(__file__).resolve().parent.parent / "fixtures" / "robot_ws"


@pytest.fixture
def workspace(tmp_path: Path) -> Path:
    shutil.copytree(FIXTURE, tmp_path / "ws")
    return (tmp_path / "ws").resolve()


def test_unsaved_texts_are_read_inside_the_block_only(tmp_path: Path) -> None:
    path = tmp_path / "a.launch"
    path.write_text("<launch/>")
    with unsaved_texts({str(path): b"<launch><!-- edited --></launch>"}):
        assert read_launch_bytes(str(path)) == b"<launch><!-- edited --></launch>"
    assert read_launch_bytes(str(path)) == b"<launch/>"


def test_entry_points_that_include_or_load_a_file_are_known(workspace: Path) -> None:
    session = Session([str(workspace)])
    session.index()
    robot = str(workspace / "src/demo_bringup/launch/robot.launch")
    sensors = workspace / "src/demo_bringup/launch/sensors.launch"
    assert robot in session.roots_reading(str(sensors))
    xacro = str(workspace / "src/demo_description/urdf/sensors.xacro")
    readers = session.roots_reading(xacro)
    assert robot in readers and xacro not in readers


def test_configuration_is_read_as_check_reads_it(workspace: Path) -> None:
    sensors = workspace / "src/demo_bringup/launch/sensors.launch"
    session = Session([str(workspace)])
    session.index()
    session.update(str(sensors), sensors.read_text())
    assert "multiple_parents" in {d.rule for d in session.diagnostics(str(sensors))}
    (workspace / ".launch-linter.toml").write_text('ignore = ["multiple_parents"]\n')
    session.forget_configuration()
    session.update(str(sensors), sensors.read_text())
    assert "multiple_parents" not in {d.rule for d in session.diagnostics(str(sensors))}


def test_hover_is_none_off_a_frame_and_walks_a_cycle_once(tmp_path: Path) -> None:
    launch = tmp_path / "cycle.launch"
    text = ('<launch>\n'
            '  <node pkg="tf2_ros" type="static_transform_publisher" name="ab"'
            ' args="0 0 1 0 0 0 a b"/>\n'
            '  <node pkg="tf2_ros" type="static_transform_publisher" name="ba"'
            ' args="0 0 1 0 0 0 b a"/>\n'
            '</launch>\n')
    launch.write_text(text)
    session = Session([str(tmp_path)])
    session.index()
    session.update(str(launch), text)
    line = text.splitlines()[1]
    shown = session.hover(str(launch), 1, line.index(" a b") + 1)
    assert shown is not None and "`a` → `b` → `a` (a cycle)" in shown
    assert "parent `b` from static_transform_publisher 'ba' (tf2_ros)" in shown
    assert session.hover(str(launch), 0, 2) is None
