"""Which front-end reads a file: by suffix for Python and YAML, by content for XML."""

from __future__ import annotations

from pathlib import Path

import pytest

from launch_linter import LintOptions, lint_paths, lint_text
from launch_linter.frontends.dispatch import front_end

ROS1_NODE = '<node pkg="tf" type="static_transform_publisher" name="t" args="0 0 0 0 0 0 a b 100"/>'


@pytest.mark.parametrize(("path", "text", "expected"), [
    ("a.launch.py", "", "ros2"),
    ("a.launch.yaml", "", "ros2"),
    ("a.launch.yml", "", "ros2"),
    ("a.launch", f"<launch>{ROS1_NODE}</launch>", "ros1"),
    ("a.launch.xml", f"<launch>{ROS1_NODE}</launch>", "ros1"),
    ("a.launch", '<launch><node pkg="tf2_ros" exec="x"/></launch>', "ros2"),
    ("a.xml", '<launch><let name="a" value="b"/></launch>', "ros2"),
    ("a.launch", '<launch><arg name="a" default="$(var b)"/></launch>', "ros2"),
    ("a.launch", '<launch><push-ros-namespace namespace="r"/></launch>', "ros2"),
    ("a.launch", '<launch><push_ros_namespace namespace="r"/></launch>', "ros2"),
    ("a.launch", '<launch><include file="$(dirname)/b.launch.py"/></launch>', "ros2"),
    ("a.launch", '<launch><include file="$(find pkg)/b.launch"/></launch>', "ros1"),
    ("a.launch", "<launch><!-- <let name='a' value='b'/> --></launch>", "ros1"),
    ("a.launch", '<launch><node pkg="x" type="y" exec_name="z"/></launch>', "ros1"),
    ("a.launch", '<launch><executable cmd="ls"/></launch>', "ros2"),
    ("a.launch", '<launch><set_env name="A" value="1"/></launch>', "ros2"),
    ("a.launch", '<launch><set_parameter name="a" value="1"/></launch>', "ros2"),
    ("a.launch", '<launch><timer period="1"><log message="x"/></timer></launch>', "ros2"),
    # A ROS 1 slip for <remap from= to=> (Robin-Wujw/nao_navigation), not a ROS 2 sign.
    ("a.launch", '<launch><node pkg="a" type="b"><param from="a" to="b"/></node></launch>',
     "ros1"),
    ("a.launch", '<launch><node pkg="a" name="n" ros_args="--log-level debug"/></launch>',
     "ros2"),
    ("a.launch", '<launch><arg name="a" default="$(find-exec ls)"/></launch>', "ros2"),
    ("a.launch", '<launch><executables/><logger/><letter/></launch>', "ros1"),
    ("a.launch", '<launch><arg name="a" default="$(eval 1 and 2)"/></launch>', "ros1"),
])


def test_front_end(path: str, text: str, expected: str) -> None:
    assert front_end(path, text.encode()) == expected


def test_ros2_only_tags_are_the_schema_actions_roslaunch_lacks() -> None:
    from launch_linter.frontends.ros2_schema import ACTIONS
    from launch_linter.frontends.xml_dialect import ROS2_ONLY_TAGS

    roslaunch_tags = {"arg", "group", "include", "node"}
    assert set(ROS2_ONLY_TAGS) == (set(ACTIONS) - roslaunch_tags) | {"composable_node"}


def test_executable_alone_makes_ros2_and_its_mistakes_are_reported() -> None:
    xml = '<launch><executable cmd="ls" nam="x"/></launch>'
    result = lint_text(xml, "example.launch", LintOptions(package_paths=()))
    assert [d.rule for d in result.diagnostics] == ["ros2_schema"]


def test_lint_text_reads_ros2_xml_even_with_a_ros1_suffix() -> None:
    xml = ('<launch><node pkg="tf2_ros" exec="static_transform_publisher" name="t" '
           'args="0 0 0 0 0 0 base_link laser"/></launch>')
    result = lint_text(xml, "example.launch", LintOptions(package_paths=()))
    (transform,) = result.transforms
    assert (transform.ros_version, transform.parent, transform.child) == (2, "base_link", "laser")
    assert [d.rule for d in result.diagnostics] == ["ros2_positional_args"]


def test_lint_text_reads_python_and_yaml_by_suffix() -> None:
    python = (
        "from launch import LaunchDescription\n"
        "from launch_ros.actions import Node\n"
        "def generate_launch_description():\n"
        "    return LaunchDescription([Node(package='tf2_ros', "
        "executable='static_transform_publisher', arguments=['--frame-id', 'a', "
        "'--child-frame-id', 'b'])])\n"
    )
    yaml = ("launch:\n- node: {pkg: tf2_ros, exec: static_transform_publisher, "
            "args: '--frame-id a --child-frame-id b'}\n")
    for text, path in ((python, "x.launch.py"), (yaml, "x.launch.yaml")):
        result = lint_text(text, path, LintOptions(package_paths=()))
        assert [(t.parent, t.child) for t in result.transforms] == [("a", "b")]
        assert result.files[0].status.value == "ok"


def test_a_python_script_named_launch_is_read_as_python(tmp_path: Path) -> None:
    """nav2's waypoint_follower/test_case_py.launch is a Python script (#! python3):
    ros2 launch reads what its XML front-end refuses as Python, and no XML starts with
    #!; it was a false 'not well-formed XML' parse_error."""
    python = (
        "#!/usr/bin/env python3\n"
        "from launch import LaunchDescription\n"
        "from launch_ros.actions import Node\n"
        "def generate_launch_description():\n"
        "    return LaunchDescription([Node(package='tf2_ros', "
        "executable='static_transform_publisher', arguments=['--frame-id', 'a', "
        "'--child-frame-id', 'b'])])\n"
    )
    script = tmp_path / "test_case_py.launch"
    script.write_text(python)
    result = lint_paths([str(script)], LintOptions(package_paths=()))
    assert [(t.parent, t.child, t.ros_version) for t in result.transforms] == [("a", "b", 2)]
    assert [d.rule for d in result.diagnostics] == []
    assert front_end("a.launch", python.encode()) == "ros2"
    # Anything else that is no XML stays a parse error, as roslaunch and launch say.
    shell = tmp_path / "run.launch"
    shell.write_text("#!/bin/sh\nroslaunch x y.launch\n")
    assert front_end(str(shell), shell.read_bytes()) == "ros1"
    assert [d.rule for d in lint_paths([str(shell)], LintOptions(package_paths=())
                                       ).diagnostics] == ["parse_error"]
