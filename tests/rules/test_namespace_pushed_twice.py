"""namespace_pushed_twice: a ROS 2 node under a namespace pushed twice (error when its tf
is provably apart from the tree's, else info)."""

from __future__ import annotations

import time
from pathlib import Path

from launch_linter.engine import LintOptions, lint_paths

RULE = "namespace_pushed_twice"

STATIC = ("Node(package='tf2_ros', executable='static_transform_publisher',\n"
          "     arguments=['--frame-id', 'base_link', '--child-frame-id', 'laser'],\n"
          "     remappings=[('/tf', 'tf'), ('/tf_static', 'tf_static')]),\n")
INNER = ("from launch import LaunchDescription\n"
         "from launch.actions import GroupAction\n"
         "from launch.substitutions import LaunchConfiguration\n"
         "from launch_ros.actions import Node, PushRosNamespace\n"
         "def generate_launch_description():\n"
         "    return LaunchDescription([GroupAction([\n"
         "        PushRosNamespace(LaunchConfiguration('namespace')),\n"
         "        Node(package='slam_toolbox', executable='async_slam_toolbox_node',\n"
         "             name='slam_toolbox', remappings={remaps}),\n"
         "    ])])\n")
ROOT = ("import os\n"
        "from launch import LaunchDescription\n"
        "from launch.actions import GroupAction, IncludeLaunchDescription\n"
        "from launch.launch_description_sources import PythonLaunchDescriptionSource\n"
        "from launch_ros.actions import Node, PushRosNamespace\n"
        "def generate_launch_description():\n"
        "    inner = os.path.join(os.path.dirname(__file__), 'inner.launch.py')\n"
        "    include = IncludeLaunchDescription(PythonLaunchDescriptionSource(inner),\n"
        "        launch_arguments={{'namespace': 'robot1'}}.items())\n"
        "    return LaunchDescription([{body}])\n")
GROUPED = "GroupAction([PushRosNamespace('robot1'),\n" + STATIC + "include])"
APART = "GroupAction([PushRosNamespace('robot1'),\n" + STATIC + "]), include"


def run(tmp_path: Path, body: str, remaps: str = "[('/tf', 'tf')]"
        ) -> list[tuple[str, int, str]]:
    (tmp_path / "inner.launch.py").write_text(INNER.format(remaps=remaps))
    path = tmp_path / "root.launch.py"
    path.write_text(ROOT.format(body=body))
    options = LintOptions(package_paths=(), select=frozenset({RULE}))
    return [(Path(d.path).name, d.line, d.severity.value)
            for d in lint_paths([str(path)], options).diagnostics]


def test_a_namespace_pushed_by_the_includer_and_the_included_file(tmp_path: Path) -> None:
    assert run(tmp_path, GROUPED) == [("inner.launch.py", 7, "error")]


def test_pushed_once_is_silent(tmp_path: Path) -> None:
    assert run(tmp_path, APART) == []


def test_with_tf_not_remapped_the_tree_is_shared_so_info(tmp_path: Path) -> None:
    assert run(tmp_path, GROUPED, remaps="[]") == [("inner.launch.py", 7, "info")]


def test_a_node_namespace_repeating_the_pushed_one(tmp_path: Path) -> None:
    body = ("GroupAction([PushRosNamespace('robot1'),\n"
            "Node(package='p', executable='e', name='n', namespace='robot1')])")
    assert run(tmp_path, body) == [("root.launch.py", 11, "info")]
    other = body.replace("namespace='robot1'", "namespace='arm'")
    assert run(tmp_path, other) == []


def test_many_pushes_stay_fast(tmp_path: Path) -> None:
    # 20,000 nested pushes of distinct names: none doubled, every one looked at.
    pushes = ", ".join(f"PushRosNamespace('n{i}')" for i in range(20_000))
    start = time.process_time()
    assert run(tmp_path, f"GroupAction([{pushes}])") == []
    assert time.process_time() - start < 60


def test_xml_remappings_are_read_for_the_tf_topic(tmp_path: Path) -> None:
    (tmp_path / "inner.launch.xml").write_text(
        '<launch>\n  <arg name="namespace" default=""/>\n  <group>\n'
        '    <push-ros-namespace namespace="$(var namespace)"/>\n'
        '    <node pkg="slam_toolbox" exec="async_slam_toolbox_node" name="slam">\n'
        '      <remap from="/tf" to="tf"/>\n    </node>\n  </group>\n</launch>\n')
    root = tmp_path / "root.launch.xml"
    root.write_text(
        '<launch>\n  <group>\n    <push-ros-namespace namespace="robot1"/>\n'
        '    <node pkg="tf2_ros" exec="static_transform_publisher"\n'
        '          args="--frame-id base_link --child-frame-id laser">\n'
        '      <remap from="/tf" to="tf"/>\n    </node>\n'
        '    <include file="$(dirname)/inner.launch.xml">\n'
        '      <arg name="namespace" value="robot1"/>\n    </include>\n'
        '  </group>\n</launch>\n')
    options = LintOptions(package_paths=(), select=frozenset({RULE}))
    found = [(Path(d.path).name, d.line, d.severity.value)
             for d in lint_paths([str(root)], options).diagnostics]
    assert found == [("inner.launch.xml", 4, "error")]
