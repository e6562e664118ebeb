"""ros2_param_file_missing: a ROS 2 node's parameter file whose path is empty (an included
file's argument left at its empty default) or provably absent; launch_ros leaves it out."""

from __future__ import annotations

import time
from pathlib import Path

from launch_linter.engine import LintOptions, lint_paths

RULE = "ros2_param_file_missing"

INCLUDED = ("from launch import LaunchDescription\n"
            "from launch.actions import DeclareLaunchArgument\n"
            "from launch.substitutions import LaunchConfiguration\n"
            "from launch_ros.actions import Node\n"
            "def generate_launch_description():\n"
            "    return LaunchDescription([\n"
            "        DeclareLaunchArgument('links_path', default_value=''),\n"
            "        Node(package='p', executable='e',\n"
            "             parameters=[LaunchConfiguration('links_path')]),\n"
            "    ])\n")
ROOT = ("import os\n"
        "from launch import LaunchDescription\n"
        "from launch.actions import IncludeLaunchDescription\n"
        "from launch.launch_description_sources import PythonLaunchDescriptionSource\n"
        "def generate_launch_description():\n"
        "    here = os.path.dirname(__file__)\n"
        "    return LaunchDescription([\n"
        "        IncludeLaunchDescription(\n"
        "            PythonLaunchDescriptionSource(os.path.join(here, 'inner.launch.py')),\n"
        "            launch_arguments={given}.items()),\n"
        "    ])\n")


def run(tmp_path: Path, root: str, inner: str = INCLUDED, rule: str = RULE
        ) -> list[tuple[str, int, str]]:
    (tmp_path / "inner.launch.py").write_text(inner)
    (tmp_path / "links.yaml").write_text("/**:\n  ros__parameters:\n    a: 1\n")
    path = tmp_path / "root.launch.py"
    path.write_text(root)
    options = LintOptions(package_paths=(), select=frozenset({rule}))
    return [(Path(d.path).name, d.line, d.severity.value)
            for d in lint_paths([str(path)], options).diagnostics]


def test_an_included_argument_left_empty_is_an_error_at_the_substitution(tmp_path: Path
                                                                         ) -> None:
    assert run(tmp_path, ROOT.format(given="{}")) == [("inner.launch.py", 9, "error")]


def test_the_argument_given_a_file_is_silent(tmp_path: Path) -> None:
    given = "{'links_path': os.path.join(here, 'links.yaml')}"
    assert run(tmp_path, ROOT.format(given=given)) == []


def test_the_root_files_own_empty_argument_is_left_to_the_command_line(tmp_path: Path
                                                                       ) -> None:
    # Linted as the root, the argument is one whoever runs the file gives: unresolved.
    (tmp_path / "links.yaml").write_text("a: 1\n")
    root = tmp_path / "inner.launch.py"
    root.write_text(INCLUDED)
    for rule, expected in ((RULE, []), ("unresolved", [("inner.launch.py", 9, "info")])):
        options = LintOptions(package_paths=(), select=frozenset({rule}))
        found = [(Path(d.path).name, d.line, d.severity.value)
                 for d in lint_paths([str(root)], options).diagnostics]
        assert found == expected


def test_an_absent_file_under_the_linted_tree_is_an_error(tmp_path: Path) -> None:
    inner = INCLUDED.replace("LaunchConfiguration('links_path')",
                             "os.path.join(os.path.dirname(__file__), 'gone.yaml')")
    inner = "import os\n" + inner
    assert run(tmp_path, ROOT.format(given="{}"), inner) == [("inner.launch.py", 9, "error")]
    present = inner.replace("gone.yaml", "links.yaml")
    assert run(tmp_path, ROOT.format(given="{}"), present) == []


def test_a_file_outside_every_known_place_is_not_judged(tmp_path: Path) -> None:
    inner = INCLUDED.replace("LaunchConfiguration('links_path')", "'/nowhere/known/x.yaml'")
    assert run(tmp_path, ROOT.format(given="{}"), inner) == []


def test_many_empty_defaults_stay_fast(tmp_path: Path) -> None:
    # 20,000 declarations in four groups (a list holds at most 10,000 items).
    groups = "".join(
        "        GroupAction([" + "".join(
            f"DeclareLaunchArgument('a{g}_{i}', default_value=''), " for i in range(5_000))
        + "]),\n" for g in range(4))
    inner = INCLUDED.replace("from launch.actions import DeclareLaunchArgument",
                             "from launch.actions import DeclareLaunchArgument, GroupAction")
    inner = inner.replace("    return LaunchDescription([\n",
                          "    return LaunchDescription([\n" + groups)
    start = time.process_time()
    found = run(tmp_path, ROOT.format(given="{}"), inner)
    assert found == [("inner.launch.py", 13, "error")]
    assert time.process_time() - start < 30


def test_an_absent_file_given_by_an_argument_default_is_reported_at_the_configuration(
        tmp_path: Path) -> None:
    # The wrong text is the argument's default; the node reads it where it names the
    # LaunchConfiguration (the node related), as for an empty path.
    inner = ("import os\n"
             "from launch import LaunchDescription\n"
             "from launch.actions import DeclareLaunchArgument\n"
             "from launch.substitutions import LaunchConfiguration\n"
             "from launch_ros.actions import Node\n"
             "def generate_launch_description():\n"
             "    return LaunchDescription([\n"
             "        DeclareLaunchArgument('links_path', default_value=os.path.join(\n"
             "            os.path.dirname(__file__), 'gone.yaml')),\n"
             "        Node(package='p', executable='e',\n"
             "             parameters=[\n"
             "                 LaunchConfiguration('links_path')]),\n"
             "    ])\n")
    (tmp_path / "inner.launch.py").write_text(inner)
    options = LintOptions(package_paths=(), select=frozenset({RULE}))
    (found,) = lint_paths([str(tmp_path / "inner.launch.py")], options).diagnostics
    assert (found.line, found.severity.value) == (12, "error")
    assert [r.line for r in found.related] == [10]


def test_a_configuration_shared_by_two_nodes_is_reported_at_each_node(tmp_path: Path
                                                                      ) -> None:
    inner = ("import os\n"
             "from launch import LaunchDescription\n"
             "from launch.actions import DeclareLaunchArgument\n"
             "from launch.substitutions import LaunchConfiguration\n"
             "from launch_ros.actions import Node\n"
             "def generate_launch_description():\n"
             "    params = LaunchConfiguration('links_path')\n"
             "    return LaunchDescription([\n"
             "        DeclareLaunchArgument('links_path', default_value=os.path.join(\n"
             "            os.path.dirname(__file__), 'gone.yaml')),\n"
             "        Node(package='p', executable='a', parameters=[params]),\n"
             "        Node(package='p', executable='b', parameters=[params]),\n"
             "    ])\n")
    (tmp_path / "inner.launch.py").write_text(inner)
    options = LintOptions(package_paths=(), select=frozenset({RULE}))
    found = lint_paths([str(tmp_path / "inner.launch.py")], options).diagnostics
    assert [d.line for d in found] == [11, 12]
