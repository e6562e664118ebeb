from __future__ import annotations

from typing import Callable, List, Tuple

from robot_ws import ws_lint

RULE = "optical_frame_rotation"
Lint = Callable[..., List[Tuple[str, int]]]


def static(args: str) -> str:
    return (f'<launch><node pkg="tf2_ros" type="static_transform_publisher" name="t" '
            f'args="{args}"/></launch>')


def test_urdf_optical_joint_without_rotation_is_found_and_the_rotated_one_is_not() -> None:
    found = ws_lint("demo_bringup/launch/robot.launch", RULE)
    assert [(d.path.rsplit("/", 1)[-1], d.line, d.node) for d in found] == [
        ("robot.urdf.xacro", 39, "bad_optical_joint")]


def test_launch_optical_frame_with_rep103_rotation_is_fine() -> None:
    assert ws_lint("demo_bringup/launch/cameras.launch", RULE) == ()


def test_null_rotation(lint: Lint) -> None:
    assert lint(static("0 0 0 0 0 0 camera_link camera_optical"), RULE) == [(RULE, 1)]


def test_rep103_quaternion_either_sign(lint: Lint) -> None:
    assert lint(static("0 0 0 -0.5 0.5 -0.5 0.5 camera_link camera_optical_frame"), RULE) == []
    assert lint(static("0 0 0 0.5 -0.5 0.5 -0.5 camera_link camera_optical_frame"), RULE) == []


def test_optical_parent_is_not_a_body_frame(lint: Lint) -> None:
    xml = static("0.05 0 0 0 0 0 camera_color_optical_frame camera_depth_optical_frame")
    assert lint(xml, RULE) == []


def test_other_names_are_not_optical(lint: Lint) -> None:
    assert lint(static("0 0 0 0 0 0 camera_link camera_optics"), RULE) == []


def test_calibrated_pose_from_another_frame_is_not_checked(lint: Lint) -> None:
    assert lint(static("0.1 0 1 0.3 0.2 0.1 base head_kinect_rgb_optical_frame"), RULE) == []
    assert lint(static("0 0 0.1 0 0 0 left_hand left_hand_camera_depth_optical_frame"),
                RULE) == []


def test_stream_word_after_the_body_stem(lint: Lint) -> None:
    assert lint(static("0 0 0 0 0 0 camera_link camera_color_optical_frame"), RULE) == [
        (RULE, 1)]
