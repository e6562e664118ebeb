from __future__ import annotations

from pathlib import Path
from typing import Callable, List, Tuple

from _urdf import lint_loaded

from conftest import run_rule

RULE = "camera_streams_one_frame"
Lint = Callable[..., List[Tuple[str, int]]]


def zed(left: str | None, right: str | None, package: str = "zed_cpu_ros") -> str:
    params = "".join(f'\n<param name="{name}" value="{value}"/>'
                     for name, value in (("left_frame_id", left), ("right_frame_id", right))
                     if value is not None)
    return (f'<launch>\n<node pkg="{package}" type="{package}" name="zed">{params}\n'
            f'</node>\n</launch>')


def found(xml: str) -> list[tuple[int, str, tuple[int, ...]]]:
    return [(d.line, d.severity.value, tuple(r.line for r in d.related))
            for d in run_rule(xml, RULE)]


def test_a_known_stereo_pair_given_one_frame_is_found_at_the_repeating_parameter() -> None:
    assert found(zed("left_frame", "left_frame")) == [(4, "warning", (2, 3))]


def test_one_stream_given_the_other_default_frame() -> None:
    # zed_cpu_ros's left camera defaults to left_camera (src/zed_cpu_ros.cpp).
    assert found(zed(None, "left_camera")) == [(3, "warning", (2,))]


def test_two_frames_and_the_defaults_are_silent() -> None:
    assert found(zed("left_frame", "right_frame")) == []
    assert found(zed(None, None)) == []
    assert found(zed("/left_frame", "right_frame")) == []


def test_a_leading_slash_is_the_same_frame() -> None:
    assert [line for line, _, _ in found(zed("/left_frame", "left_frame"))] == [4]


def test_an_unknown_node_with_left_and_right_frames_alike_is_info() -> None:
    assert found(zed("cam", "cam", package="my_stereo")) == [(4, "info", (2, 3))]
    assert found(zed("cam_l", "cam_r", package="my_stereo")) == []


def test_left_inside_another_word_is_no_pair() -> None:
    xml = ('<launch><node pkg="p" type="t" name="n">'
           '<param name="leftover_frame" value="a"/><param name="rightover_frame" value="a"/>'
           '</node></launch>')
    assert found(xml) == []


def test_an_unresolved_value_is_not_compared() -> None:
    xml = ('<launch>\n<node pkg="zed_cpu_ros" type="zed_cpu_ros" name="z">'
           '<param name="left_frame_id" value="$(env NOPE_X)"/>'
           '<param name="right_frame_id" value="$(env NOPE_X)"/></node></launch>')
    assert found(xml) == []


def camera_sensor(link: str, frame: str | None, pose: str | None = None) -> str:
    name = f"<frame_name>{frame}</frame_name>" if frame else ""
    placed = f"<pose>{pose}</pose>" if pose else ""
    return (f'<gazebo reference="{link}"><sensor name="s_{link}_{pose}" '
            f'type="camera">{placed}<plugin name="p" filename="libgazebo_ros_camera.so">'
            f'{name}</plugin></sensor></gazebo>')


def simulated(tmp_path: Path, sensors: list[str]) -> list[tuple[str, str]]:
    links = "".join(f'<link name="{n}"/>' for n in ("base_link", "left", "right"))
    joints = "".join(
        f'<joint name="j_{n}" type="fixed"><parent link="base_link"/><child link="{n}"/>'
        f'<origin xyz="0 {y} 0"/></joint>' for n, y in (("left", 0.06), ("right", -0.06)))
    text = f'<robot name="r">{links}{joints}\n' + "\n".join(sensors) + "\n</robot>"
    found = lint_loaded(tmp_path, text, RULE)
    return [(d.path.rsplit("/", 1)[-1], d.severity.value) for d in found]


def test_two_simulated_cameras_on_two_links_with_one_frame_are_info(tmp_path: Path) -> None:
    assert simulated(tmp_path, [camera_sensor("left", "stereo_optical"),
                                camera_sensor("right", "stereo_optical")]) == [
        ("robot.urdf.xacro", "info")]


def test_two_simulated_cameras_with_their_own_frames_are_silent(tmp_path: Path) -> None:
    assert simulated(tmp_path, [camera_sensor("left", "left_optical"),
                                camera_sensor("right", "right_optical")]) == []


def test_two_sensors_rendering_from_one_place_may_share_a_frame(tmp_path: Path) -> None:
    assert simulated(tmp_path, [camera_sensor("left", "rgbd_optical"),
                                camera_sensor("left", "rgbd_optical")]) == []
    # ROS 1's camera plugins stamp 'world' without a frameName (gazebo_ros_camera_utils).
    assert simulated(tmp_path, [camera_sensor("left", None, "0 0.06 0 0 0 0"),
                                camera_sensor("left", None, "0 -0.06 0 0 0 0")]) == [
        ("robot.urdf.xacro", "info")]


def test_two_camera_drivers_given_one_frame_are_info() -> None:
    xml = ('<launch>\n<node pkg="zed_cpu_ros" type="zed_cpu_ros" name="a">'
           '<param name="left_frame_id" value="l"/><param name="right_frame_id" value="r"/>'
           '</node>\n<node pkg="zed_cpu_ros" type="zed_cpu_ros" name="b">'
           '<param name="left_frame_id" value="l"/><param name="right_frame_id" value="r2"/>'
           '</node>\n</launch>')
    assert found(xml) == [(3, "info", (3, 2))]
    alternatives = xml.replace('name="a">', 'name="a" if="$(arg x)">').replace(
        'name="b">', 'name="b" unless="$(arg x)">').replace("<launch>", '<launch><arg name="x"/>')
    assert found(alternatives) == []


def test_twenty_thousand_left_and_right_frame_parameters_take_linear_time() -> None:
    params = "".join(f'<param name="left_{i}_frame" value="f{i}"/>'
                     f'<param name="right_{i}_frame" value="f{i}"/>' for i in range(20_000))
    xml = f'<launch><node pkg="p" type="t" name="n">{params}</node></launch>'
    assert len(run_rule(xml, RULE)) == 20_000
