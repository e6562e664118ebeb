"""frame_param_slash: a ROS 2 node's frame parameter starting with '/' (fault, then fixed)."""

from __future__ import annotations

from pathlib import Path

from launch_linter.engine import LintOptions, lint_paths

RULE = "frame_param_slash"


def run(tmp_path: Path, name: str, text: str) -> list[tuple[str, int]]:
    path = tmp_path / name
    path.write_text(text)
    options = LintOptions(package_paths=(), select=frozenset({RULE}))
    return [(d.rule, d.line) for d in lint_paths([str(path)], options).diagnostics]


def test_a_costmap_global_frame_with_a_slash_in_a_ros2_parameter_file(tmp_path: Path) -> None:
    (tmp_path / "nav.yaml").write_text(
        "bt_navigator:\n  ros__parameters:\n    global_frame: /map\n"
        "    robot_base_frame: base_link\n")
    launch = ("import os\nfrom launch import LaunchDescription\n"
              "from launch_ros.actions import Node\n"
              "def generate_launch_description():\n"
              "    here = os.path.dirname(__file__)\n"
              "    return LaunchDescription([\n"
              "        Node(package='nav2_bt_navigator', executable='bt_navigator',\n"
              "             name='bt_navigator',\n"
              "             parameters=[os.path.join(here, 'nav.yaml')])])\n")
    assert run(tmp_path, "nav.launch.py", launch) == [(RULE, 7)]
    (tmp_path / "nav.yaml").write_text(
        "bt_navigator:\n  ros__parameters:\n    global_frame: map\n")
    assert run(tmp_path, "nav.launch.py", launch) == []


def test_ros1_nodes_and_defaults_are_left_out(tmp_path: Path) -> None:
    ros1 = ('<launch><node pkg="amcl" type="amcl" name="amcl">'
            '<param name="global_frame_id" value="/map"/></node>'
            '<node pkg="gmapping" type="slam_gmapping" name="g">'
            '<param name="odom_frame" value="/odom"/></node></launch>')
    assert run(tmp_path, "a.launch", ros1) == []
