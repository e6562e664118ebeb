"""A robot chosen by an environment variable: each file that could fill the name is read
as an alternative robot, under ``env('X') == 'value'``, and said once as info."""

from __future__ import annotations

from pathlib import Path

from launch_linter import LintOptions, lint_paths

PACKAGE = ('<package format="3"><name>desc</name><version>0.0.0</version><description>d'
           '</description><maintainer email="a@b.c">a</maintainer><license>MIT</license>'
           '<buildtool_depend>ament_cmake</buildtool_depend></package>')
LAUNCH = """import os
from launch import LaunchDescription
from launch.substitutions import Command
from launch_ros.actions import Node
from ament_index_python.packages import get_package_share_directory


def generate_launch_description():
    model = os.environ['ROBOT_MODEL']
    urdf = os.path.join(get_package_share_directory('desc'), 'urdf', 'bot_' + model + '.urdf')
    return LaunchDescription([
        Node(package='robot_state_publisher', executable='robot_state_publisher',
             parameters=[{'robot_description': Command(['xacro ', urdf])}]),
    ])
"""


def urdf(child: str, parent: str = "base_link") -> str:
    return (f'<robot name="r"><link name="{parent}"/><link name="{child}"/>'
            f'<joint name="j" type="fixed"><parent link="{parent}"/><child link="{child}"/>'
            '</joint></robot>')


def workspace(tmp_path: Path, models: dict[str, str]) -> Path:
    package = tmp_path / "src" / "desc"
    (package / "urdf").mkdir(parents=True)
    (package / "launch").mkdir()
    (package / "package.xml").write_text(PACKAGE, encoding="utf-8")
    for name, text in models.items():
        (package / "urdf" / name).write_text(text, encoding="utf-8")
    launch = package / "launch" / "bot.launch.py"
    launch.write_text(LAUNCH, encoding="utf-8")
    return launch


def test_each_candidate_is_read_as_an_alternative_robot(tmp_path: Path) -> None:
    # Both publish 'laser' from different parents: alternatives, so no two parents.
    launch = workspace(tmp_path, {"bot_small.urdf": urdf("laser"),
                                  "bot_big.urdf": urdf("laser", "base_footprint"),
                                  "other.urdf": urdf("x")})
    result = lint_paths([str(launch)], LintOptions())
    (tree,) = result.trees
    assert sorted((j.parent, j.child) for j in tree.joints) == [
        ("base_footprint", "laser"), ("base_link", "laser")]
    first, second = tree.joints
    assert first.condition.excludes(second.condition)
    said = [d for d in result.diagnostics if "alternative robot" in d.message]
    assert len(said) == 1 and said[0].severity.value == "info"
    assert "(big, small)" in said[0].message and "ROBOT_MODEL" in said[0].message
    assert not [d for d in result.diagnostics if d.severity.value in ("error", "warning")]


def test_given_the_variable_only_that_robot_is_read(tmp_path: Path) -> None:
    launch = workspace(tmp_path, {"bot_small.urdf": urdf("a"), "bot_big.urdf": urdf("b")})
    result = lint_paths([str(launch)], LintOptions(env={"ROBOT_MODEL": "big"}))
    assert [j.child for j in result.trees[0].joints] == ["b"]


def test_too_many_or_no_candidates_leave_it_unread(tmp_path: Path) -> None:
    many = {f"bot_m{i}.urdf": urdf(f"c{i}") for i in range(9)}
    for models, said in ((many, "9 files (more than 8)"), ({"x.urdf": urdf("a")}, "no file")):
        launch = workspace(tmp_path / str(len(models)), models)
        result = lint_paths([str(launch)], LintOptions())
        assert not result.trees[0].joints
        assert [d for d in result.diagnostics if said in d.message]


def test_ros1_env_in_a_xacro_command(tmp_path: Path) -> None:
    package = tmp_path / "src" / "bot"
    (package / "urdf").mkdir(parents=True)
    (package / "launch").mkdir()
    (package / "package.xml").write_text(PACKAGE.replace("desc", "bot").replace(
        "ament_cmake", "catkin"), encoding="utf-8")
    for name in ("small", "big"):
        (package / "urdf" / f"bot_{name}.urdf.xacro").write_text(urdf(f"l_{name}"),
                                                                   encoding="utf-8")
    launch = package / "launch" / "a.launch"
    launch.write_text(
        '<launch><param name="robot_description" command="$(find xacro)/xacro '
        '$(find bot)/urdf/bot_$(env BOT_MODEL).urdf.xacro"/>\n'
        '<node pkg="robot_state_publisher" type="robot_state_publisher" name="rsp"/>'
        "</launch>", encoding="utf-8")
    result = lint_paths([str(launch)], LintOptions())
    assert sorted(j.child for j in result.trees[0].joints) == ["l_big", "l_small"]
