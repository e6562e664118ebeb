from __future__ import annotations

from typing import Callable, List, Tuple

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
