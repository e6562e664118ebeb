from __future__ import annotations

from typing import Callable, List, Tuple

import pytest

from launch_linter.model import Diagnostic

Lint = Callable[..., List[Tuple[str, int]]]
LintDiagnostics = Callable[..., Tuple[Diagnostic, ...]]

RULE = "sensor_null"


def launch(name: str, args: str) -> str:
    return (
        f'<launch>\n<node pkg="tf2_ros" type="static_transform_publisher" name="{name}" '
        f'args="{args}"/>\n</launch>'
    )


@pytest.mark.parametrize(
    ("name", "args"),
    [
        # anchors.md (e): PhysFrame's sensor_null could never fire on its own.
        ("imu_tf", "0 0 0 0 0 0 base_link imu_link"),
        ("t", "0 0 0 0 0 0 base_link Velodyne"),
        ("kinect_frames", "0 0 0 0 0 0 1 camera_link camera_rgb"),
        ("radarRig_to_IMU", "0 0 0 0 0 0 radar bmi088"),
        ("t", "0 0 0 0 0 0 base_link velodyne2"),
    ],
)
def test_null_sensor_transform(lint: Lint, name: str, args: str) -> None:
    assert lint(launch(name, args), RULE) == [(RULE, 2)]


@pytest.mark.parametrize(
    ("name", "args"),
    [
        ("imu_tf", "0.05 0 0.1 0 0 0 base_link imu_link"),
        ("imu_tf", "0 0 0 1.5708 0 0 base_link imu_link"),
        ("map_tf", "0 0 0 0 0 0 map odom"),
        # Found in the corpus: "simulation" holds the letters "imu" but names no sensor.
        ("world_to_sim", "0 0 0 0 0 0 world_frame simulation/world_frame"),
        ("t", "0 0 0 0 0 0 base_link myimux"),
        # The sensor word only in the parent: the child is another frame of that device or
        # hangs under it (septentrio's imu -> aux1 antenna), not the sensor's mount.
        ("t", "0 0 0 0 0 0 openni_camera base"),
        ("tf_aux1", "0 0 0 0 0 0 imu aux1"),
        # An alias between two frames of one device.
        ("link_jasmin2", "0 0 0 0 0 0 velodyne_base_link horizontal_velodyne"),
        # A bare sensor shown in a world-fixed frame is not a mount.
        ("imu_in_map", "0 0 0 0 0 0 map imu"),
    ],
)
def test_passes(lint: Lint, name: str, args: str) -> None:
    assert lint(launch(name, args), RULE) == []


def test_message_names_the_sensor(lint_diagnostics: LintDiagnostics) -> None:
    (found,) = lint_diagnostics(launch("t", "0 0 0 0 0 0 base_link velodyne"), RULE)
    assert "velodyne" in found.message


def test_unresolved_displacement_is_silent(lint: Lint) -> None:
    xml = """<launch>
  <arg name="z"/>
  <node pkg="tf2_ros" type="static_transform_publisher" name="imu_tf"
        args="0 0 $(arg z) 0 0 0 base_link imu"/>
</launch>"""
    assert lint(xml, RULE) == []
    assert lint(xml, RULE, {"z": "0"}) == [(RULE, 3)]


def test_info_by_default_warning_in_the_study_profile() -> None:
    from launch_linter import LintOptions, lint_text
    from launch_linter.model import Severity

    text = launch("imu_tf", "0 0 0 0 0 0 base_link imu_link")
    default = lint_text(text, "t.launch", LintOptions(package_paths=())).diagnostics
    study = lint_text(text, "t.launch", LintOptions(package_paths=(), profile="study"))
    assert [d.severity for d in default if d.rule == RULE] == [Severity.INFO]
    assert [d.severity for d in study.diagnostics if d.rule == RULE] == [Severity.WARNING]


def test_study_profile_keeps_the_studys_check() -> None:
    from launch_linter import LintOptions, lint_text

    text = launch("t", "0 0 0 0 0 0 openni_camera base")
    study = lint_text(text, "t.launch", LintOptions(package_paths=(), profile="study"))
    assert [d.rule for d in study.diagnostics if d.rule == RULE] == [RULE]
