"""``.urdf``/``.xacro`` files as inputs of their own: found in folders, read with their
default args and ``--arg`` values, parts left to their includer, one finding per place
when a launch file loads the same description."""

from __future__ import annotations

from pathlib import Path

from launch_linter import LintOptions, lint_paths
from launch_linter.workspace.discovery import discover

XACRO = 'xmlns:xacro="http://www.ros.org/wiki/xacro"'
TWO_ROOTS = f'<robot name="r" {XACRO}>\n<link name="a"/>\n<link name="b"/>\n</robot>\n'


def _lint(paths: list[Path], rule: str, args: dict[str, str] | None = None):  # type: ignore[no-untyped-def]
    options = LintOptions(args=args or {}, package_paths=(), select=frozenset({rule}))
    return lint_paths([str(p) for p in paths], options).diagnostics


def test_descriptions_are_found_in_folders_but_not_semantic_ones(tmp_path: Path) -> None:
    for name in ("robot.urdf.xacro", "arm.urdf", "arm.srdf.xacro", "notes.txt"):
        (tmp_path / name).write_text("<robot/>", encoding="utf-8")
    found = sorted(Path(f.path).name for f in discover([str(tmp_path)]))
    assert found == ["arm.urdf", "robot.urdf.xacro"]


def test_loaded_and_on_its_own_is_one_finding_at_the_launch_files_level(tmp_path: Path) -> None:
    (tmp_path / "robot.urdf.xacro").write_text(TWO_ROOTS, encoding="utf-8")
    (tmp_path / "robot.launch").write_text(
        '<launch><param name="robot_description" command="xacro $(dirname)/robot.urdf.xacro"/>'
        '<node pkg="robot_state_publisher" type="robot_state_publisher" name="rsp"/></launch>',
        encoding="utf-8")
    (found,) = _lint([tmp_path], "urdf_root")
    assert found.severity.value == "error" and found.line == 3
    (alone,) = _lint([tmp_path / "robot.urdf.xacro"], "urdf_root")
    assert alone.severity.value == "warning"


def test_a_part_its_package_includes_is_left_to_the_includer(tmp_path: Path) -> None:
    (tmp_path / "package.xml").write_text("<package><name>p</name></package>", encoding="utf-8")
    (tmp_path / "urdf").mkdir()
    (tmp_path / "urdf" / "robot.urdf.xacro").write_text(
        f'<robot name="r" {XACRO}><link name="base"/>'
        '<xacro:include filename="$(find p)/urdf/sensor.xacro"/></robot>', encoding="utf-8")
    sensor = ('<robot name="s"><link name="laser"/><joint name="j" type="fixed">'
              '<parent link="base"/><child link="laser"/></joint></robot>')
    (tmp_path / "urdf" / "sensor.xacro").write_text(sensor, encoding="utf-8")
    assert _lint([tmp_path / "urdf" / "sensor.xacro"], "urdf_missing_link") == ()
    (tmp_path / "urdf" / "lonely.xacro").write_text(sensor, encoding="utf-8")
    assert len(_lint([tmp_path / "urdf" / "lonely.xacro"], "urdf_missing_link")) == 1


def test_arg_values_reach_a_description_on_its_own(tmp_path: Path) -> None:
    path = tmp_path / "robot.urdf.xacro"
    path.write_text(f'<robot name="r" {XACRO}><xacro:arg name="second" default="false"/>'
                    '<link name="a"/><xacro:if value="$(arg second)"><link name="b"/>'
                    '</xacro:if></robot>', encoding="utf-8")
    assert _lint([path], "urdf_root") == ()
    assert len(_lint([path], "urdf_root", {"second": "true"})) == 1


def test_a_urdf_is_read_as_it_is(tmp_path: Path) -> None:
    path = tmp_path / "robot.urdf"
    path.write_text('<robot name="r"><link name="${prefix}a"/><link name="${prefix}b"/>'
                    '<joint name="j" type="fixed"><parent link="${prefix}a"/>'
                    '<child link="${prefix}b"/></joint></robot>', encoding="utf-8")
    assert _lint([path], "urdf_missing_link") == () and _lint([path], "urdf_root") == ()


def test_a_description_that_is_not_well_formed_is_a_parse_error(tmp_path: Path) -> None:
    path = tmp_path / "robot.urdf"
    path.write_text('<robot name="r"><link name="a">\n</robot>', encoding="utf-8")
    (found,) = _lint([path], "parse_error")
    assert "not well-formed" in found.message
