"""Node parameters read statically: ROS 1 <param>/<rosparam> (text, files, beside the
node), ROS 2 dictionaries and parameter files, controllers in controller-manager files."""

from __future__ import annotations

from pathlib import Path

import pytest
import yaml
from hypothesis import given
from hypothesis import strategies as st

from launch_linter.engine import LintOptions, lint_paths
from launch_linter.frontends.params import flat_yaml, ros2_file_params, scalar_text
from launch_linter.knowledge import bundled
from launch_linter.model.robot import UNKNOWN_VALUE, NodeRecord
from launch_linter.rules._nodes import view_of


def nodes(tmp_path: Path, files: dict[str, str], root: str) -> list[NodeRecord]:
    for name, text in files.items():
        (tmp_path / name).write_text(text, encoding="utf-8")
    result = lint_paths([str(tmp_path / root)], LintOptions(package_paths=()))
    return [n for tree in result.trees for n in tree.nodes]


def test_ros1_params_rosparam_text_files_and_names_beside_the_node(tmp_path: Path) -> None:
    files = {
        "amcl.yaml": "odom_frame_id: odom_a\nbase_frame_id: base_footprint\n",
        "a.launch": (
            '<launch><param name="amcl/global_frame_id" value="world"/>'
            '<rosparam file="$(dirname)/amcl.yaml" command="load" ns="amcl"/>'
            '<node pkg="amcl" type="amcl" name="amcl"><param name="tf_broadcast" value="true"/>'
            '<rosparam>use_map_topic: true</rosparam></node>'
            '<node pkg="move_base" type="move_base" name="move_base">'
            '<rosparam file="$(dirname)/amcl.yaml" command="load" ns="local_costmap"/></node>'
            '</launch>'),
    }
    found = {n.package: n for n in nodes(tmp_path, files, "a.launch")}
    amcl = found["amcl"]
    assert amcl.given("tf_broadcast") == "true"
    assert amcl.given("use_map_topic") == "true"
    assert amcl.given("global_frame_id") == "world"
    assert amcl.given("odom_frame_id") == "odom_a"
    assert found["move_base"].given("local_costmap/odom_frame_id") == "odom_a"
    assert amcl.unread == ()


def test_ros1_a_parameter_file_loaded_with_subst_value_is_substituted(tmp_path: Path) -> None:
    """roslaunch resolves $(arg ...) in a <rosparam> file's text when subst_value is true
    (robotont_navigation's costmap_common.yaml: robot_base_frame: $(arg prefix)base_footprint);
    without it the text stays as written; under an unresolved subst_value it is unknown."""
    files = {
        "costmap.yaml": "robot_base_frame: $(arg prefix)base_footprint\n",
        "a.launch": (
            '<launch><arg name="prefix" default="r1/"/><arg name="s"/>'
            '<node pkg="move_base" type="move_base" name="a">'
            '<rosparam file="$(dirname)/costmap.yaml" subst_value="true" ns="local_costmap"/>'
            '</node><node pkg="move_base" type="move_base" name="b">'
            '<rosparam file="$(dirname)/costmap.yaml" ns="local_costmap"/></node>'
            '<node pkg="move_base" type="move_base" name="c">'
            '<rosparam file="$(dirname)/costmap.yaml" subst_value="$(arg s)" '
            'ns="local_costmap"/></node></launch>'),
    }
    a, b, c = nodes(tmp_path, files, "a.launch")
    assert a.given("local_costmap/robot_base_frame") == "r1/base_footprint"
    assert b.given("local_costmap/robot_base_frame") == "$(arg prefix)base_footprint"
    assert c.given("local_costmap/robot_base_frame") == UNKNOWN_VALUE


def test_ros1_an_unresolved_parameter_file_leaves_the_node_unread(tmp_path: Path) -> None:
    files = {"a.launch": ('<launch><arg name="f"/><node pkg="amcl" type="amcl" name="amcl">'
                          '<rosparam file="$(arg f)" command="load"/></node></launch>')}
    (amcl,) = nodes(tmp_path, files, "a.launch")
    assert amcl.unread


def test_ros2_dictionaries_and_parameter_files_by_node_key(tmp_path: Path) -> None:
    files = {
        "ekf.yaml": ("/**:\n  ros__parameters:\n    use_sim_time: true\n"
                     "ekf_filter_node:\n  ros__parameters:\n    world_frame: map\n"
                     "other:\n  ros__parameters:\n    world_frame: odom\n"),
        "a.launch.py": (
            "import os\nfrom launch import LaunchDescription\nfrom launch_ros.actions import Node\n"
            "def generate_launch_description():\n"
            "    here = os.path.dirname(__file__)\n"
            "    return LaunchDescription([Node(package='robot_localization', "
            "executable='ekf_node', name='ekf_filter_node', "
            "parameters=[os.path.join(here, 'ekf.yaml'), {'publish_tf': False}])])\n"),
    }
    (ekf,) = nodes(tmp_path, files, "a.launch.py")
    assert ekf.given("world_frame") == "map"
    assert ekf.given("use_sim_time") == "true"
    assert ekf.given("publish_tf") == "false"
    assert ekf.unread == ()


@pytest.mark.parametrize("key, node, applies", [
    ("/**", "/ns/amcl", True),
    ("/**/amcl", "/amcl", True),
    ("/**/amcl", "/a/b/amcl", True),
    ("/*/amcl", "/ns/amcl", True),
    ("/*/amcl", "/amcl", False),
    ("amcl", "/amcl", True),
    ("/ns/amcl", "/ns/amcl", True),
    # rclcpp adds a leading '/' to a bare key: it names the node at the root only.
    ("amcl", "/ns/amcl", False),
    ("ns/amcl", "/ns/amcl", True),
    ("amcl_node", "/amcl", False),
])
def test_a_parameter_file_key_applies_as_rclcpp_matches_it(key: str, node: str,
                                                           applies: bool) -> None:
    namespace, name = node.rsplit("/", 1)
    document = {key: {"ros__parameters": {"x": 1}}}
    assert (ros2_file_params(document, name, namespace or "/") == [("x", "1")]) is applies


_NAMES = st.lists(st.from_regex(r"[A-Za-z_][A-Za-z0-9_]{0,8}", fullmatch=True),
                  min_size=1, max_size=4)


@given(_NAMES, _NAMES)
def test_a_full_key_names_one_node_and_a_double_star_reaches_every_namespace(
        names: list[str], other: list[str]) -> None:
    namespace, name = "/" + "/".join(names[:-1]), names[-1]
    document = {"/".join(names): {"ros__parameters": {"x": 1}}}
    assert ros2_file_params(document, name, namespace) == [("x", "1")]
    anywhere = {"/**/" + name: {"ros__parameters": {"x": 1}}}
    assert ros2_file_params(anywhere, name, "/" + "/".join(other)) == [("x", "1")]
    if other != names[:-1]:
        assert ros2_file_params(document, name, "/" + "/".join(other)) == []


def test_a_key_naming_another_node_leaves_the_node_at_its_defaults(tmp_path: Path) -> None:
    # husky/husky#244: the file's key is imu_filter_node, the node is named imu_filter:
    # the file is read, gives it nothing, and the filter's defaults hold (publish_tf true).
    files = {
        "imu.yaml": "imu_filter_node:\n  ros__parameters:\n    publish_tf: false\n",
        "a.launch.py": (
            "import os\nfrom launch import LaunchDescription\nfrom launch_ros.actions import Node\n"
            "def generate_launch_description():\n"
            "    here = os.path.dirname(__file__)\n"
            "    return LaunchDescription([Node(package='imu_filter_madgwick', "
            "executable='imu_filter_madgwick_node', name='imu_filter', "
            "parameters=[os.path.join(here, 'imu.yaml')])])\n"),
    }
    (imu,) = nodes(tmp_path, files, "a.launch.py")
    assert imu.params == () and imu.unread == ()
    entry = bundled().node("imu_filter_madgwick", "imu_filter_madgwick_node", 2)
    assert entry is not None and entry.default("publish_tf") is True


def test_ros2_controllers_of_a_controller_manager_file(tmp_path: Path) -> None:
    files = {
        "controllers.yaml": (
            "controller_manager:\n  ros__parameters:\n    diff_cont:\n"
            "      type: diff_drive_controller/DiffDriveController\n"
            "diff_cont:\n  ros__parameters:\n    enable_odom_tf: false\n"),
        "a.launch.xml": ('<launch><node pkg="controller_manager" exec="ros2_control_node" '
                         'name="controller_manager">'
                         '<param from="$(dirname)/controllers.yaml"/></node></launch>'),
    }
    found = nodes(tmp_path, files, "a.launch.xml")
    (controller,) = [n for n in found if n.kind == "controller"]
    assert controller.plugin == "diff_drive_controller/DiffDriveController"
    assert controller.given("enable_odom_tf") == "false"


# Keys that YAML 1.1 reads as booleans or nulls ("no", "on", "null") are not parameter
# names: left out.
@given(st.dictionaries(st.from_regex(r"[a-z_][a-z0-9_]{0,8}", fullmatch=True).filter(
                           lambda key: isinstance(yaml.safe_load(key), str)),
                       st.from_regex(r"[a-z_/][a-z0-9_/]{0,10}", fullmatch=True),
                       max_size=8))
def test_flat_yaml_reads_flat_text_as_pyyaml_does(pairs: dict[str, str]) -> None:
    text = "".join(f"{key}: {value}  # note\n" for key, value in pairs.items())
    expected = {k: scalar_text(v) for k, v in (yaml.safe_load(text) or {}).items()}
    assert flat_yaml(text) == expected


def test_nested_yaml_is_not_flat() -> None:
    assert flat_yaml("a:\n  b: 1\n") is None
    assert flat_yaml("a: [1, 2]\n") is None
    assert flat_yaml("a: &x 1\n") is None


CONTROLLERS_YAML = (
    "controller_manager:\n  ros__parameters:\n    update_rate: 50\n"
    "    diff_drive_base_controller:\n"
    "      type: diff_drive_controller/DiffDriveController\n"
    "diff_drive_base_controller:\n  ros__parameters:\n    odom_frame_id: odom\n"
    "    base_frame_id: base_footprint\n    enable_odom_tf: true\n")


def test_ros2_controller_manager_without_a_name_reads_its_default_section(
        tmp_path: Path) -> None:
    found = nodes(tmp_path, {
        "controllers.yaml": CONTROLLERS_YAML,
        "a.launch.py": (
            "from launch import LaunchDescription\n"
            "from launch_ros.actions import Node\n"
            "import os\n"
            "def generate_launch_description():\n"
            "    f = os.path.join(os.path.dirname(__file__), 'controllers.yaml')\n"
            "    return LaunchDescription([Node(package='controller_manager', "
            "executable='ros2_control_node', parameters=[f])])\n")}, "a.launch.py")
    (controller,) = [n for n in found if n.kind == "controller"]
    assert controller.name == "diff_drive_base_controller"
    assert controller.given("base_frame_id") == "base_footprint"


def test_ros2_spawner_param_file_gives_the_controller_and_its_parameters(
        tmp_path: Path) -> None:
    """jazzy's ``spawner NAME --param-file FILE``: the type and parameters from the file;
    given twice (manager and spawner) it is still one controller."""
    launch = (
        "from launch import LaunchDescription\n"
        "from launch_ros.actions import Node\n"
        "import os\n"
        "def generate_launch_description():\n"
        "    f = os.path.join(os.path.dirname(__file__), 'controllers.yaml')\n"
        "    return LaunchDescription([\n"
        "        Node(package='controller_manager', executable='ros2_control_node'{}),\n"
        "        Node(package='controller_manager', executable='spawner',\n"
        "             arguments=['diff_drive_base_controller', '--param-file', f,\n"
        "                        '-c', '/controller_manager']),\n"
        "    ])\n")
    found = nodes(tmp_path, {"controllers.yaml": CONTROLLERS_YAML,
                             "a.launch.py": launch.format("")}, "a.launch.py")
    (controller,) = [n for n in found if n.kind == "controller"]
    assert controller.plugin == "diff_drive_controller/DiffDriveController"
    assert controller.given("enable_odom_tf") == "true"
    assert controller.line == 8
    (tmp_path / "a.launch.py").write_text(launch.format(", parameters=[f]"))
    result = lint_paths([str(tmp_path / "a.launch.py")], LintOptions(package_paths=()))
    (tree,) = result.trees
    assert [n.kind for n in tree.nodes].count("controller") == 2
    edges = view_of(tree, bundled()).edges
    assert [(e.parent, e.child) for e in edges] == [("odom", "base_footprint")]


def test_nav2_servers_run_their_costmap_nodes_with_their_sections(tmp_path: Path) -> None:
    found = nodes(tmp_path, {
        "nav2.yaml": (
            "controller_server:\n  ros__parameters:\n    odom_topic: odom\n"
            "local_costmap:\n  local_costmap:\n    ros__parameters:\n"
            "      global_frame: odom\n      robot_base_frame: base_footprint\n"
            "global_costmap:\n  global_costmap:\n    ros__parameters:\n"
            "      global_frame: /map\n"),
        "a.launch.xml": (
            '<launch><node pkg="nav2_controller" exec="controller_server" '
            'name="controller_server"><param from="$(dirname)/nav2.yaml"/></node>\n'
            '<node pkg="nav2_planner" exec="planner_server" name="planner_server">'
            '<param from="$(dirname)/nav2.yaml"/></node></launch>')}, "a.launch.xml")
    costmaps = {n.name: n for n in found if n.plugin == "nav2_costmap_2d::Costmap2DROS"}
    assert costmaps["local_costmap"].namespace == "/local_costmap"
    assert costmaps["local_costmap"].given("robot_base_frame") == "base_footprint"
    assert costmaps["global_costmap"].given("global_frame") == "/map"
    options = LintOptions(package_paths=(), select=frozenset({"frame_param_slash"}))
    found_slash = lint_paths([str(tmp_path / "a.launch.xml")], options).diagnostics
    assert [d.line for d in found_slash] == [2]
