"""ros2_param_file_unmatched: a ROS 2 parameter file whose node keys reach no node it is
given to (rclcpp's key matching: a leading `/` added, `/*` one name, `/**` any)."""

from __future__ import annotations

import json
import time
from pathlib import Path

import pytest

from launch_linter.engine import LintOptions, lint_paths

RULE = "ros2_param_file_unmatched"


def run(tmp_path: Path, launch: str, params: str, name: str = "a.launch.py"
        ) -> list[tuple[str, int, str]]:
    (tmp_path / "params.yaml").write_text(params)
    path = tmp_path / name
    path.write_text(launch)
    options = LintOptions(package_paths=(), select=frozenset({RULE}))
    return [(Path(d.path).name, d.line, d.severity.value)
            for d in lint_paths([str(path)], options).diagnostics]


PY = ("import os\n"
      "from launch import LaunchDescription\n"
      "from launch_ros.actions import Node, PushRosNamespace\n"
      "from launch.actions import GroupAction\n"
      "def generate_launch_description():\n"
      "    f = os.path.join(os.path.dirname(__file__), 'params.yaml')\n"
      "    return LaunchDescription([{nodes}])\n")
NODE = "Node(package='p', executable='e', parameters=[f]{extra})"
KEYED = "{key}:\n  ros__parameters:\n    base_frame: base_link\n"


def test_a_key_naming_another_node_is_reported_at_the_key(tmp_path: Path) -> None:
    launch = PY.format(nodes=NODE.format(extra=", name='driver'"))
    assert run(tmp_path, launch, KEYED.format(key="driver_node")) == [
        ("params.yaml", 1, "error")]
    # Nested: at the innermost key; info, since a namespace given may make it match.
    nested = "# x\nother:\n  driver_node:\n    ros__parameters:\n      a: 1\n"
    assert run(tmp_path, launch, nested) == [("params.yaml", 3, "info")]


def test_keys_that_match_as_rclcpp_matches_them_are_silent(tmp_path: Path) -> None:
    launch = PY.format(nodes=NODE.format(extra=", name='driver', namespace='robot'"))
    # Another name: an error whatever the namespace; a key of the node's own name or with
    # a namespace part misses only with these launch arguments (a namespace may change).
    for key, level in (("driver_node", "error"), ("/robot/driver_x", "info"),
                       ("driver", "info"), ("/*/*/driver", "info")):
        assert run(tmp_path, launch, KEYED.format(key=key)) == [("params.yaml", 1, level)]
    for key in ("/**", "/robot/driver", "robot/driver", "/*/driver", "/**/driver", "/robot/*"):
        assert run(tmp_path, launch, KEYED.format(key=key)) == [], key
    nested = "robot:\n  driver:\n    ros__parameters:\n      a: 1\n"
    assert run(tmp_path, launch, nested) == []


def test_a_name_from_a_launch_argument_is_info(tmp_path: Path) -> None:
    launch = PY.replace("def generate_launch_description():",
                        "from launch.substitutions import LaunchConfiguration as C\n"
                        "from launch.actions import DeclareLaunchArgument as D\n"
                        "def generate_launch_description():").format(
        nodes="D('n', default_value='driver'), " + NODE.format(extra=", name=C('n')"))
    assert run(tmp_path, launch, KEYED.format(key="driver_node")) == [
        ("params.yaml", 1, "info")]


def test_a_file_shared_by_nodes_is_reported_only_when_it_reaches_none(tmp_path: Path) -> None:
    shared = KEYED.format(key="left") + KEYED.format(key="right")
    two = ", ".join(NODE.format(extra=f", name='{n}'") for n in ("left", "right"))
    assert run(tmp_path, PY.format(nodes=two), shared) == []
    # A third node given the same file takes nothing from it, but the file was written
    # for the others (teleop_twist_joy's launch gives joy_node the teleop node's file).
    three = two + ", " + NODE.format(extra=", name='middle'")
    assert run(tmp_path, PY.format(nodes=three), shared) == []
    # Reaching none of the nodes it is given to: each node reported.
    apart = ", ".join(NODE.format(extra=f", name='{n}'") for n in ("up", "down"))
    assert run(tmp_path, PY.format(nodes=apart), shared) == [
        ("params.yaml", 1, "error"), ("params.yaml", 1, "error")]
    # A node of unknown name given the file may take it: silent.
    unknown = apart + ", " + NODE.format(extra="")
    assert run(tmp_path, PY.format(nodes=unknown), shared) == []


def test_pushed_namespace_is_part_of_the_name(tmp_path: Path) -> None:
    pushed = ("GroupAction([PushRosNamespace('robot'), "
              + NODE.format(extra=", name='driver'") + "])")
    assert run(tmp_path, PY.format(nodes=pushed), KEYED.format(key="driver")) == [
        ("params.yaml", 1, "info")]
    assert run(tmp_path, PY.format(nodes=pushed), KEYED.format(key="driver_node")) == [
        ("params.yaml", 1, "error")]
    assert run(tmp_path, PY.format(nodes=pushed), KEYED.format(key="robot/driver")) == []


def test_unknown_names_and_remappings_and_many_node_processes_are_silent(
        tmp_path: Path) -> None:
    other = KEYED.format(key="someone_else")
    for extra in ("",  # the executable's own name: not known
                  ", name='driver', arguments=['--ros-args', '-r', '__node:=someone_else']",
                  ", name='driver', ros_arguments=['-r', '__ns:=/x']",
                  ", name='driver', arguments=ARGS",
                  ", name=NAME"):
        assert run(tmp_path, PY.format(nodes=NODE.format(extra=extra)), other) == [], extra
    for package, executable in (("controller_manager", "ros2_control_node"),
                                ("rclcpp_components", "component_container"),
                                ("nav2_controller", "controller_server")):
        node = (f"Node(package='{package}', executable='{executable}', name='x', "
                "parameters=[f])")
        assert run(tmp_path, PY.format(nodes=node), other) == [], package
    # A file without ros__parameters, or one not read, says nothing here.
    launch = PY.format(nodes=NODE.format(extra=", name='driver'"))
    assert run(tmp_path, launch, "driver_node:\n  a: 1\n") == []
    assert run(tmp_path, launch, "[unclosed\n") == []


def test_xml_param_from_and_composable_nodes(tmp_path: Path) -> None:
    xml = ('<launch>\n  <node pkg="p" exec="e" name="driver">\n'
           '    <param from="$(dirname)/params.yaml"/>\n  </node>\n</launch>\n')
    assert run(tmp_path, xml, KEYED.format(key="driver_node"), "a.launch.xml") == [
        ("params.yaml", 1, "error")]
    assert run(tmp_path, xml.replace('name="driver"', 'name="driver" ros_args="-r __node:=q"'),
               KEYED.format(key="driver_node"), "a.launch.xml") == []
    yaml = ("launch:\n- node:\n    pkg: p\n    exec: e\n    name: driver\n    param:\n"
            "    - from: $(dirname)/params.yaml\n")
    assert run(tmp_path, yaml, KEYED.format(key="driver_node"), "a.launch.yaml") == [
        ("params.yaml", 1, "error")]
    assert run(tmp_path, yaml, KEYED.format(key="driver"), "a.launch.yaml") == []
    composable = ("ComposableNodeContainer(name='c', namespace='', package='rclcpp_components',"
                  " executable='component_container', composable_node_descriptions=["
                  "ComposableNode(package='p', plugin='p::P', name='{name}', "
                  "parameters=[f])])")
    py = PY.replace("Node, PushRosNamespace",
                    "Node, PushRosNamespace, ComposableNodeContainer\n"
                    "from launch_ros.descriptions import ComposableNode")
    assert run(tmp_path, py.format(nodes=composable.format(name="driver")),
               KEYED.format(key="driver_node")) == [("params.yaml", 1, "error")]
    assert run(tmp_path, py.format(nodes=composable.format(name="driver_node")),
               KEYED.format(key="driver_node")) == []


def test_hostile_file_of_20000_node_keys(tmp_path: Path) -> None:
    # 20,000 node keys, one section shared through an alias (small enough to be read).
    keys = "n: &s {ros__parameters: {a: 1}}\n" + "".join(f"n{i}: *s\n" for i in range(20000))
    launch = PY.format(nodes=NODE.format(extra=", name='driver'"))
    start = time.process_time()
    found = run(tmp_path, launch, keys)
    assert time.process_time() - start < 20
    # Bounded: the sections kept (MAX_PARAMS) are judged, one finding.
    assert len(found) == 1 and found[0][0] == "params.yaml"


def test_a_parameter_file_is_walked_once_per_node(tmp_path: Path,
                                                   monkeypatch: pytest.MonkeyPatch) -> None:
    """The node's parameters and the keys that miss it come from one walk of the file's
    sections (they were two walks, each matching every key's pattern)."""
    from launch_linter.frontends import params

    walks: list[object] = []
    walk = params._ros2_sections_keyed

    def counted(document: object) -> list[tuple[str, dict[object, object], tuple[str, ...]]]:
        walks.append(document)
        return walk(document)

    monkeypatch.setattr(params, "_ros2_sections_keyed", counted)
    launch = PY.format(nodes=NODE.format(extra=", name='driver'"))
    assert run(tmp_path, launch, KEYED.format(key="driver_node")) == [
        ("params.yaml", 1, "error")]
    assert len(walks) == 1
    walks.clear()
    assert run(tmp_path, launch, KEYED.format(key="driver")) == []
    assert len(walks) == 1


def test_a_partial_wildcard_repeats_the_character_before_it(tmp_path: Path) -> None:
    # rclcpp turns only `/*` into a name wildcard; `/driver*` is a std::regex: `/drive`
    # and any number of `r`, so it reaches `driver` and `driverr`, never `driver_x`.
    for name, found in (("driver", []), ("driverr", []),
                        ("driver_x", [("params.yaml", 1, "error")])):
        launch = PY.format(nodes=NODE.format(extra=f", name='{name}'"))
        assert run(tmp_path, launch, KEYED.format(key="/driver*")) == found, name


UNNAMED = "Node(package='{package}', executable='{executable}', parameters=[f]{extra})"


def test_a_node_without_a_name_is_checked_under_its_programs_names(tmp_path: Path) -> None:
    launch = PY.format(nodes=UNNAMED.format(package="lio_sam",
                                            executable="lio_sam_imuPreintegration", extra=""))
    # The program runs two nodes; a key naming either reaches it.
    assert run(tmp_path, launch, KEYED.format(key="/lio_sam*")) == [("params.yaml", 1, "error")]
    for key in ("lio_sam_transformFusion", "/lio_sam_imu_preintegration", "/**", "/*"):
        assert run(tmp_path, launch, KEYED.format(key=key)) == [], key


def test_plugin_nodes_under_the_programs_node(tmp_path: Path) -> None:
    # mavros_node's plugins are nodes named after themselves under /NS/mavros.
    launch = PY.format(nodes=UNNAMED.format(package="mavros", executable="mavros_node",
                                            extra=", namespace='mavros'"))
    for key in ("/mavros/**/conn", "/mavros/mavros", "/mavros/mavros/conn", "/mavros/**"):
        assert run(tmp_path, launch, KEYED.format(key=key)) == [], key
    # The ROS 1 keys: /mavros names a node in the root namespace; info, as a namespace
    # given may make it match.
    for key in ("/mavros", "/mavros/conn"):
        assert run(tmp_path, launch, KEYED.format(key=key)) == [("params.yaml", 1, "info")]


def test_a_program_whose_names_are_unknown_is_not_checked(tmp_path: Path) -> None:
    launch = PY.format(nodes=UNNAMED.format(package="p", executable="e", extra=""))
    assert run(tmp_path, launch, KEYED.format(key="/anything")) == []
    # A random name: no key can name it, but it is never proven.
    launch = PY.format(nodes=UNNAMED.format(package="tf2_ros",
                                            executable="static_transform_publisher",
                                            extra=""))
    assert run(tmp_path, launch, KEYED.format(key="static_transform_publisher")) == []
    assert run(tmp_path, launch, KEYED.format(key="other")) == [("params.yaml", 1, "info")]


def test_many_keys_against_a_programs_names_stay_bounded(tmp_path: Path) -> None:
    launch = PY.format(nodes=UNNAMED.format(package="mavros", executable="mavros_node",
                                            extra=""))
    params = "n: &s {ros__parameters: {a: 1}}\n" + "".join(f"k{i}x*: *s\n"
                                                            for i in range(20_000))
    start = time.process_time()
    assert [level for _, _, level in run(tmp_path, launch, params)] == ["info"]
    assert time.process_time() - start < 30


def test_a_users_node_names_entry_makes_its_program_checked(tmp_path: Path) -> None:
    from launch_linter.knowledge import bundled
    from launch_linter.workspace.config import load_knowledge_file

    names = {"id": "node_names_my_driver", "kind": "node_names", "ros": [2],
             "match": {"package": "p", "executables": ["e"]}, "names": ["my_driver"],
             "sources": [{"repository": "me/p", "package": "p", "file": "src/e.cpp",
                          "ref": "main", "commit": "0" * 40, "lines": "12"}]}
    # The user's entry for tf2_ros's program replaces the bundled one of its id.
    fixed = {**names, "id": "node_names_tf2_ros_static_transform_publisher",
             "match": {"package": "tf2_ros", "executables": ["static_transform_publisher"]},
             "names": ["static_transform_publisher"]}
    knowledge = tmp_path / "knowledge.json"
    knowledge.write_text(json.dumps({"format": 2, "entries": [names, fixed]}))
    base = bundled().extended(load_knowledge_file(str(knowledge)))
    (tmp_path / "params.yaml").write_text(KEYED.format(key="/other"))

    def findings(package: str, executable: str, with_user: bool) -> list[tuple[int, str]]:
        path = tmp_path / "a.launch.py"
        path.write_text(PY.format(nodes=UNNAMED.format(package=package,
                                                       executable=executable, extra="")))
        options = LintOptions(package_paths=(), select=frozenset({RULE}),
                              knowledge=base if with_user else None)
        return [(d.line, d.severity.value)
                for d in lint_paths([str(path)], options).diagnostics]

    assert findings("p", "e", False) == []
    assert findings("p", "e", True) == [(1, "error")]
    assert findings("tf2_ros", "static_transform_publisher", False) == [(1, "info")]
    assert findings("tf2_ros", "static_transform_publisher", True) == [(1, "error")]
    assert base.node_names("lio_sam", "lio_sam_imuPreintegration") == (
        "lio_sam_imu_preintegration", "lio_sam_transformFusion")
