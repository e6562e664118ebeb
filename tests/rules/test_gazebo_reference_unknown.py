from __future__ import annotations

import time
from pathlib import Path

from _urdf import joint, link, lint_loaded, lint_urdf, robot

RULE = "gazebo_reference_unknown"
BODY = link("base_link") + link("imu_frame") + joint("imu_joint", "base_link", "imu_frame")
SENSOR = '<sensor name="imu" type="imu"><plugin name="p" filename="libimu.so"/></sensor>'


def test_a_reference_to_a_renamed_link_is_dropped() -> None:
    """wolfgang_robot#9: the IMU's <gazebo> still named the link's old name."""
    (found,) = lint_urdf(robot(BODY + f'\n<gazebo reference="L_IMU">{SENSOR}</gazebo>'), RULE)
    assert found.line == 3 and found.severity.value == "warning"
    assert '<gazebo reference="L_IMU">' in found.message


def test_a_close_name_is_offered() -> None:
    (found,) = lint_urdf(robot(BODY + f'\n<gazebo reference="imu_link">{SENSOR}</gazebo>'),
                         RULE)
    assert "(defined: 'imu_joint'" in found.message


def test_links_joints_and_the_robot_level_are_silent() -> None:
    for reference in ('reference="imu_frame"', 'reference="imu_joint"', ""):
        text = robot(BODY + f"\n<gazebo {reference}>{SENSOR}</gazebo>")
        assert lint_urdf(text, RULE) == (), reference


def test_a_link_under_an_undecided_condition_keeps_it_silent() -> None:
    text = robot(BODY + '<xacro:if value="$(env WITH_IMU)"><link name="imu2"/>'
                        '<joint name="j2" type="fixed"><parent link="base_link"/>'
                        '<child link="imu2"/></joint></xacro:if>\n'
                        f'<gazebo reference="imu2">{SENSOR}</gazebo>')
    assert lint_urdf(text, RULE) == ()


def test_an_undecided_reference_is_not_judged() -> None:
    text = robot(BODY + f'\n<xacro:if value="$(env SIM)"><gazebo reference="nowhere">'
                        f'{SENSOR}</gazebo></xacro:if>')
    assert lint_urdf(text, RULE) == ()


def test_an_unknown_reference_is_not_judged() -> None:
    text = robot(BODY + f'\n<gazebo reference="$(env IMU_LINK)">{SENSOR}</gazebo>')
    assert lint_urdf(text, RULE) == ()


def test_a_fragment_is_not_judged() -> None:
    """A sensor file whose joint hangs from a link another file defines: the reference
    may be to that file's links too."""
    text = robot(link("laser") + joint("laser_joint", "base_link", "laser")
                 + f'\n<gazebo reference="base_link">{SENSOR}</gazebo>')
    assert lint_urdf(text, RULE) == ()
    assert lint_urdf(robot(f'<gazebo reference="base_link">{SENSOR}</gazebo>'), RULE) == ()


def test_a_macro_reference_is_reported_where_it_is_written(tmp_path: Path) -> None:
    """kinova-movo#67's shape: a macro's <gazebo> naming a link the macro never makes."""
    macro = ('<xacro:macro name="cam" params="prefix">'
             '<link name="${prefix}_ir_frame"/>'
             '<joint name="${prefix}_j" type="fixed"><parent link="base_link"/>'
             '<child link="${prefix}_ir_frame"/></joint>'
             f'<gazebo reference="${{prefix}}_ir_link">{SENSOR}</gazebo>'
             '</xacro:macro>\n')
    text = robot(link("base_link") + macro + '<xacro:cam prefix="kinect"/>')
    (found,) = lint_loaded(tmp_path, text, RULE)
    assert found.line == 2 and found.related[0].line == 3
    assert "kinect_ir_link" in found.message and "'kinect_ir_frame'" in found.message


def test_many_references_are_read_in_linear_time() -> None:
    """Hostile: 20,000 <gazebo> elements naming no link, each one finding."""
    text = robot(BODY + "\n".join(f'<gazebo reference="l{i}"><mu1>1</mu1></gazebo>'
                                  for i in range(20_000)))
    start = time.process_time()
    found = lint_urdf(text, RULE)
    assert time.process_time() - start < 30.0
    assert len(found) == 20_000


def test_a_dropped_property_block_is_info() -> None:
    """A material or friction setting on no link does nothing, but loses no data or frame
    (kobuki_207's casters, rg2_simulation_2's fingers)."""
    (found,) = lint_urdf(robot(BODY + '\n<gazebo reference="caster"><mu1>0</mu1></gazebo>'),
                         RULE)
    assert found.severity.value == "info" and "do nothing" in found.message
