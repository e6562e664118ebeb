"""xacro up to Melodic (and ROS 2 Dashing/Eloquent) also reads xacro tags written without
the ``xacro:`` prefix; Noetic's and later ROS 2 xacro do not (ros/xacro melodic-devel
e2ba976, noetic-devel 7045754). The linter reads them so for a distribution it is told."""

from __future__ import annotations

from pathlib import Path

import pytest

from launch_linter import LintOptions, lint_paths

XACRO = 'xmlns:xacro="http://www.ros.org/wiki/xacro"'
PARTS = (f'<robot name="parts" {XACRO}>\n<macro name="wheel" params="side">'
         '<link name="${side}_wheel"/></macro>\n</robot>\n')


def _lint(tmp_path: Path, body: str, distro: str | None, rule: str) -> list[str]:
    (tmp_path / "parts.xacro").write_text(PARTS, encoding="utf-8")
    (tmp_path / "robot.urdf.xacro").write_text(
        f'<robot name="r" {XACRO}>\n{body}\n</robot>\n', encoding="utf-8")
    (tmp_path / "view.launch").write_text(
        '<launch><param name="robot_description" '
        'command="xacro $(dirname)/robot.urdf.xacro"/>'
        '<node pkg="robot_state_publisher" type="robot_state_publisher" name="rsp"/></launch>',
        encoding="utf-8")
    options = LintOptions(package_paths=(), ros_distro=distro, select=frozenset({rule}))
    result = lint_paths([str(tmp_path / "view.launch")], options)
    return [d.severity.value for d in result.diagnostics]


@pytest.mark.parametrize("distro", ["kinetic", "melodic"])
def test_unprefixed_include_and_call_are_read_by_a_legacy_xacro(tmp_path: Path,
                                                                distro: str) -> None:
    body = '<include filename="parts.xacro"/>\n<wheel side="left"/>'
    assert _lint(tmp_path, body, distro, "urdf_empty_robot") == []


@pytest.mark.parametrize("distro", ["noetic", "humble", None])
def test_noetic_ros2_and_an_unknown_distro_read_them_as_plain_elements(
        tmp_path: Path, distro: str | None) -> None:
    body = '<include filename="parts.xacro"/>\n<wheel side="left"/>'
    assert _lint(tmp_path, body, distro, "urdf_empty_robot") == ["error"]


def test_an_include_with_children_is_gazebos_not_xacros(tmp_path: Path) -> None:
    # <include><uri>model://x</uri></include> is an SDF include even for a legacy xacro.
    body = '<link name="a"/>\n<include><uri>model://parts.xacro</uri></include>'
    assert _lint(tmp_path, body, "melodic", "xacro_error") == []
    assert _lint(tmp_path, body, "melodic", "urdf_empty_robot") == []


def test_a_legacy_xacro_takes_an_element_named_like_a_macro_for_a_call(
        tmp_path: Path) -> None:
    # As xacro's handle_macro_call does: <wheel/> without its parameter fails there.
    body = '<include filename="parts.xacro"/>\n<link name="a"/>\n<wheel/>'
    assert _lint(tmp_path, body, "melodic", "xacro_error") == ["error"]
    assert _lint(tmp_path, body, "noetic", "xacro_error") == []


@pytest.mark.parametrize(("distro", "expected"), [("kinetic", []), ("noetic", ["info"])])
def test_an_unprefixed_insert_block_inserts_the_block_for_a_legacy_xacro(
        tmp_path: Path, distro: str, expected: list[str]) -> None:
    """mastering_ros's Indigo xtion macro inserts its optical origin unprefixed: a legacy
    xacro inserts it (no unused block), Noetic's drops it."""
    body = ('<xacro:macro name="cam" params="*optical">'
            '<joint name="j" type="fixed"><parent link="a"/><child link="b"/>'
            '<insert_block name="optical"/></joint></xacro:macro>'
            '<link name="a"/><link name="b"/>'
            '<xacro:cam><origin rpy="-1.57 0 -1.57"/></xacro:cam>')
    assert _lint(tmp_path, body, distro, "xacro_unused_block") == expected
