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
        ("t", "0 0 0 0 0 0 openni_camera base"),
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
