from __future__ import annotations

from pathlib import Path
from typing import Callable, List, Tuple

from conftest import run_rule
from launch_linter.frontends.ros1_unused_args import unused_args
from launch_linter.resolve.xml_safe import parse_xml

RULE = "ros1_unused_arg"
Lint = Callable[..., List[Tuple[str, int]]]


def found(xml: str) -> list[tuple[int, str, tuple[int, ...]]]:
    return [(d.line, d.severity.value, tuple(r.line for r in d.related))
            for d in run_rule(xml, RULE)]


def test_an_argument_an_include_gets_another_value_for_is_a_warning(tmp_path: Path) -> None:
    (tmp_path / "driver.launch").write_text(
        '<launch><arg name="frame_id_base"/><param name="f" value="$(arg frame_id_base)"/>'
        '</launch>', encoding="utf-8")
    xml = ('<launch>\n<arg name="ns" default="cam"/>\n'
           '<arg name="frame_id_base" default="$(arg ns)"/>\n'
           f'<include file="{tmp_path}/driver.launch">\n'
           '<arg name="frame_id_base" value="$(arg ns)"/>\n</include>\n</launch>')
    assert found(xml) == [(3, "warning", (5,))]
    fixed = xml.replace('value="$(arg ns)"/>\n</include>', 'value="$(arg frame_id_base)"/>\n'
                        '</include>')
    assert found(fixed) == []


def test_a_frame_parameter_of_its_name_written_out_is_a_warning() -> None:
    xml = ('<launch>\n<arg name="odom_frame" default="odom"/>\n'
           '<node pkg="p" type="t" name="n">\n'
           '<param name="odom_frame" value="odom"/>\n</node>\n</launch>')
    assert found(xml) == [(2, "warning", (4,))]
    assert found(xml.replace('value="odom"', 'value="base_frame"')) == [(2, "warning", (4,))]


def test_a_frame_tied_to_another_argument_is_info() -> None:
    xml = ('<launch>\n<arg name="odom_frame" default="odom"/>\n<arg name="base_frame"/>\n'
           '<node pkg="p" type="t" name="n">\n'
           '<param name="odom_frame" value="$(arg base_frame)"/>\n</node>\n</launch>')
    assert found(xml) == [(2, "info", ())]


def test_an_argument_nothing_names_is_info() -> None:
    assert found('<launch>\n<arg name="delay" default="100"/>\n</launch>') == [
        (2, "info", ())]


def test_every_kind_of_read_counts_whatever_the_condition() -> None:
    reads = [
        '<node pkg="p" type="t" name="n" if="$(arg x)"/>',
        '<group if="false"><param name="a" value="$(arg  x )"/></group>',
        '<param name="a" value="$(eval x + 1)"/>',
        '<param name="a" value="$(eval arg(\'x\') == 1)"/>',
        '<rosparam subst_value="true">a: $(arg x)</rosparam>',
        '<arg name="y" default="$(arg x)/y"/><param name="b" value="$(arg y)"/>',
    ]
    for read in reads:
        assert found(f'<launch><arg name="x" default="1"/>{read}</launch>') == [], read


def test_files_that_hand_arguments_on_unseen_are_not_judged() -> None:
    for hands_on in ('<include file="other.launch" pass_all_args="true"/>',
                     '<rosparam file="p.yaml" subst_value="true"/>'):
        root = parse_xml(f'<launch><arg name="x" default="1"/>{hands_on}</launch>'.encode(),
                         collect=("launch",)).collected[0]
        assert unused_args(root) == [], hands_on


def test_value_arguments_and_group_arguments_are_not_the_interface() -> None:
    xml = ('<launch><arg name="c" value="1"/>'
           '<group if="true"><arg name="g" default="1"/></group></launch>')
    assert found(xml) == []


def test_an_unclosed_read_is_no_read() -> None:
    xml = ('<launch>\n<arg name="frame" default="a"/>\n'
           '<param name="frame" value="$(arg frame"/>\n</launch>')
    assert [level for _, level, _ in found(xml)] == ["warning"]


def test_another_setting_the_file_fixes_is_info() -> None:
    xml = ('<launch>\n<arg name="headless" default="false"/>\n'
           '<param name="headless" value="true"/>\n</launch>')
    assert found(xml) == [(2, "info", ())]


def test_twenty_thousand_arguments_take_linear_time() -> None:
    args = "".join(f'<arg name="a{i}" default="1"/>' for i in range(20_000))
    reads = "".join(f'<param name="p{i}" value="$(arg a{i})"/>' for i in range(0, 20_000, 2))
    root = parse_xml(f"<launch>{args}{reads}</launch>".encode(),
                     collect=("launch",)).collected[0]
    assert len(unused_args(root)) == 10_000


def test_an_eval_spaced_otherwise_is_still_read() -> None:
    assert found('<launch><arg name="x" default="1"/>'
                 '<param name="a" value="$( eval x + 1)"/></launch>') == []


def test_a_frame_missed_where_the_others_are_handed_on_by_name_is_a_warning() -> None:
    """zed-ros-wrapper#248 and #392: imu_frame declared beside the camera frames, each of
    which the node gets as <param name="X" value="$(arg X)"/>; imu_frame never."""
    xml = ('<launch>\n<arg name="left_camera_frame" default="zed_left"/>\n'
           '<arg name="imu_frame" default="imu_link"/>\n'
           '<node pkg="zed_wrapper" type="zed_wrapper_node" name="zed">\n'
           '<param name="left_camera_frame" value="$(arg left_camera_frame)"/>\n'
           '</node>\n</launch>')
    assert found(xml) == [(3, "warning", (5,))]
    fixed = xml.replace("</node>", '<param name="imu_frame" value="$(arg imu_frame)"/>\n'
                                   "</node>")
    assert found(fixed) == []
    # An include's argument handed on by its name is the same convention.
    include = xml.replace('<node pkg="zed_wrapper" type="zed_wrapper_node" name="zed">',
                          '<include file="$(dirname)/driver.launch">').replace(
        '<param name="left_camera_frame"', '<arg name="left_camera_frame"').replace(
        "</node>", "</include>")
    assert found(include) == [(3, "warning", (5,))]


def test_no_sibling_handed_on_by_name_or_no_frame_stays_info() -> None:
    # The other frame is given a value of its own, not the argument of its name.
    xml = ('<launch>\n<arg name="left_camera_frame" default="zed_left"/>\n'
           '<arg name="imu_frame" default="imu_link"/>\n<node pkg="p" type="t" name="n">\n'
           '<param name="left_camera_frame" value="$(arg left_camera_frame)_x"/>\n'
           '</node>\n</launch>')
    assert found(xml) == [(3, "info", ())]
    # Not a frame (a rate, a tolerance): a dead setting, info (a convention finding).
    given = xml.replace("_x\"", '"')
    for other in ("imu_rate", "frame_tolerance"):
        assert found(given.replace("imu_frame", other)) == [(3, "info", ())]


def test_twenty_thousand_frame_arguments_beside_forwarded_ones_take_linear_time() -> None:
    import time

    args = "".join(f'<arg name="f{i}_frame" default="x"/>' for i in range(20_000))
    given = "".join(f'<param name="f{i}_frame" value="$(arg f{i}_frame)"/>'
                    for i in range(0, 20_000, 2))
    root = parse_xml(f"<launch>{args}{given}</launch>".encode(),
                     collect=("launch",)).collected[0]
    started = time.process_time()
    unread = unused_args(root)
    assert time.process_time() - started < 60
    assert len(unread) == 10_000 and all(arg.frame_forgotten for arg in unread)


def test_an_eval_written_with_a_character_reference_is_still_read() -> None:
    # The bytes never spell "eval": the walk (made for the unread frame argument) must
    # still read the values, which it skips only in a file that cannot hold an $(eval).
    xml = ('<launch><arg name="x" default="1"/><arg name="base_frame" default="base"/>'
           '<param name="a" value="$(&#101;val x + 1)"/></launch>')
    assert found(xml) == [(1, "info", ())]
    assert len(found(xml.replace("&#101;val", "xval"))) == 2


def test_an_argument_declared_in_any_case_counts_and_other_tags_do_not() -> None:
    # The declaration scan lowercases only three-letter tags: <ARG>, <Arg> are arguments;
    # <args>, <env>, <ar> and a two-letter tag are not.
    xml = ('<launch><ARG name="upper" default="1"/><Arg name="mixed"/>'
           '<args name="plural"/><env name="e" value="v"/><ar name="short"/>'
           '<İg name="dotted"/></launch>').encode()
    root = parse_xml(xml, collect=("launch",)).collected[0]
    assert [arg.name for arg in unused_args(root, xml)] == ["upper", "mixed"]
