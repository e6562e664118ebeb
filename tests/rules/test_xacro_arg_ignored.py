from __future__ import annotations

import time
from pathlib import Path

from _urdf import lint_loaded

from launch_linter import LintOptions, lint_paths

RULE = "xacro_arg_ignored"
XACRO = 'xmlns:xacro="http://www.ros.org/wiki/xacro"'


def described(body: str) -> str:
    return f'<robot name="r" {XACRO}>{body}<link name="$(arg tf_prefix)base_link"/></robot>'


DECLARED = '<xacro:arg name="tf_prefix" default=""/>'


def test_a_mapping_no_file_names_is_reported_with_the_declared_close_name(
        tmp_path: Path) -> None:
    (found,) = lint_loaded(tmp_path, described(DECLARED), RULE, "prefix:=ur3_")
    assert found.severity.value == "info" and found.line == 1
    assert "prefix:=" in found.message and "'tf_prefix'" in found.message


def test_a_mapping_declared_read_or_named_in_a_branch_not_taken_is_silent(
        tmp_path: Path) -> None:
    assert lint_loaded(tmp_path, described(DECLARED), RULE, "tf_prefix:=ur3_") == ()
    # Read without a declaration: xacro's $(arg) finds the command line's mapping.
    read_only = described('<link name="$(arg side)_wheel"/>')
    assert lint_loaded(tmp_path, read_only, RULE, "side:=left tf_prefix:=a") == ()
    # Named only under a condition the call does not take: another call may take it.
    branch = described(DECLARED + '<xacro:if value="false"><link name="$(arg sim)_x"/>'
                       '</xacro:if>')
    assert lint_loaded(tmp_path, branch, RULE, "sim:=true") == ()


def test_an_include_not_taken_is_read_and_one_not_known_leaves_it_unjudged(
        tmp_path: Path) -> None:
    (tmp_path / "control.xacro").write_text(
        f'<robot {XACRO}><link name="$(arg sim_mode)_c"/></robot>', encoding="utf-8")
    include = ('<xacro:arg name="use_control" default="false"/>'
               '<xacro:if value="$(arg use_control)">'
               '<xacro:include filename="control.xacro"/></xacro:if>')
    assert lint_loaded(tmp_path, described(DECLARED + include), RULE,
                       "use_control:=false sim_mode:=true") == ()
    unknown = described(DECLARED + '<xacro:include filename="${name}.xacro"/>')
    assert lint_loaded(tmp_path, unknown, RULE, "sim_mode:=true") == ()


def test_a_name_only_in_a_comment_is_not_read(tmp_path: Path) -> None:
    commented = described(DECLARED + '<!-- <link name="$(arg prefix)x"/> -->')
    (found,) = lint_loaded(tmp_path, commented, RULE, "prefix:=a")
    assert "'prefix'" in found.message


def test_a_ros2_command_is_reported_where_the_mapping_is_written(tmp_path: Path) -> None:
    (tmp_path / "robot.urdf.xacro").write_text(described(DECLARED), encoding="utf-8")
    launch = tmp_path / "robot.launch.py"
    launch.write_text(
        "import os\n"
        "from launch import LaunchDescription\n"
        "from launch.substitutions import Command\n"
        "from launch_ros.actions import Node\n\n\n"
        "def generate_launch_description():\n"
        "    path = os.path.join(os.path.dirname(__file__), 'robot.urdf.xacro')\n"
        "    description = Command(['xacro ', path,\n"
        "                           ' prefix:=', 'ur3_'])\n"
        "    return LaunchDescription([Node(package='robot_state_publisher',\n"
        "        executable='robot_state_publisher',\n"
        "        parameters=[{'robot_description': description}])])\n", encoding="utf-8")
    options = LintOptions(package_paths=(), select=frozenset({RULE}), ros_distro="humble")
    (found,) = lint_paths([str(launch)], options).diagnostics
    assert (found.line, found.column) == (10, 30)


def test_twenty_thousand_mappings_tags_and_includes_stay_linear(tmp_path: Path) -> None:
    """Each loop over the input is one pass: the mappings (the first 200 looked for),
    the <xacro:arg> tags, the comments and the include elements (whose files are read
    once each, at most 200) of a description."""
    count = 20_000
    tags = "".join(f'<xacro:arg name="a{i}" default=""/>' for i in range(count))
    comments = "<!-- x -->" * count
    text = described(DECLARED + tags + comments)
    mappings = " ".join(f"m{i}:=1" for i in range(count))
    started = time.process_time()
    found = lint_loaded(tmp_path, text, RULE, mappings)
    assert time.process_time() - started < 60
    assert len(found) == 200
    includes = "".join('<xacro:include filename="part.xacro"/>' for _ in range(count))
    (tmp_path / "part.xacro").write_text(f"<robot {XACRO}/>", encoding="utf-8")
    started = time.process_time()
    assert lint_loaded(tmp_path, described(DECLARED + includes), RULE, "tf_prefix:=a") == ()
    assert time.process_time() - started < 60
