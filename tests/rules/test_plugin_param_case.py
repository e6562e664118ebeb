from __future__ import annotations

import time
from pathlib import Path

from _urdf import link, lint_loaded, lint_urdf, robot

from launch_linter.knowledge import bundled

RULE = "plugin_param_case"


def drive(params: str, filename: str = "libgazebo_ros_diff_drive.so") -> str:
    return robot(link("base_footprint") + f'\n<gazebo>\n<plugin name="d" filename="{filename}">'
                 f'<robotNamespace>/</robotNamespace>\n{params}\n</plugin>\n</gazebo>')


def test_a_parameter_spelt_with_other_capitals_is_ignored() -> None:
    """jnmouse_description#9: <publishTF> for gazebo_ros_diff_drive's publishTf."""
    (found,) = lint_urdf(drive("<publishTF>false</publishTF>"), RULE)
    assert found.line == 5 and found.severity.value == "warning"
    assert "reads <publishTf>, not <publishTF>" in found.message and "(true)" in found.message
    assert lint_urdf(drive("<publishTf>false</publishTf>"), RULE) == ()


def test_unknown_plugins_and_unlisted_parameters_are_not_judged() -> None:
    assert lint_urdf(drive("<publishTF>false</publishTF>", "libmy_drive.so"), RULE) == ()
    assert lint_urdf(drive("<wheelTorque>5</wheelTorque>"), RULE) == ()


def test_a_description_a_launch_file_loads_is_reported_once(tmp_path: Path) -> None:
    (found,) = lint_loaded(tmp_path, drive("<OdometryFrame>odom</OdometryFrame>"), RULE)
    assert "reads <odometryFrame>, not <OdometryFrame>" in found.message


def test_the_odometry_transform_needs_publish_tf_too() -> None:
    """gazebo_ros_diff_drive (ROS 1) sends odom -> base only with publishTf and
    publishOdomTF both true (noetic-devel f9e1a46, lines 118-123, 272, 453)."""
    entry = bundled().plugin("gazebo_plugin", "libgazebo_ros_diff_drive.so", 1)
    assert entry is not None and entry.default("publishTf") is True
    (edge,) = entry.publishes
    assert edge.when == ("publishTf", "publishOdomTF")


def test_twenty_thousand_parameters_of_one_plugin_in_linear_time() -> None:
    params = "".join(f"<publishTF>{i % 2}</publishTF>" for i in range(20_000))
    start = time.process_time()
    found = lint_urdf(drive(params), RULE)
    assert time.process_time() - start < 30.0
    assert len(found) == 1  # one place, one finding
