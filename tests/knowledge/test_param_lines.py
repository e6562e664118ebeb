"""Where each parameter value is written (NodeRecord.param_lines, ``where_set``): ROS 2
dictionary keys, XML/YAML ``<param>``, parameter file keys (PyYAML's marks), ROS 1
``<param>``/``<rosparam>``; the node's element where the value's own place is unknown."""

from __future__ import annotations

import sys
import time
from pathlib import Path

import pytest

from launch_linter.engine import LintOptions, lint_paths
from launch_linter.frontends import params
from launch_linter.model.robot import NodeRecord


def nodes(tmp_path: Path, files: dict[str, str], root: str) -> dict[str, NodeRecord]:
    for name, text in files.items():
        (tmp_path / name).write_text(text, encoding="utf-8")
    result = lint_paths([str(tmp_path / root)], LintOptions(package_paths=()))
    return {n.name or n.executable: n for tree in result.trees for n in tree.nodes}


def at(node: NodeRecord, name: str) -> tuple[str, int] | None:
    where = node.where_set(name)
    return None if where is None else (Path(where[0]).name, where[1])


PY = ("import os\n"                                                       # 1
      "from launch import LaunchDescription\n"                            # 2
      "from launch_ros.actions import Node\n"                             # 3
      "SHARED = {'use_sim_time': True}\n"                                 # 4
      "def generate_launch_description():\n"                              # 5
      "    extra = {}\n"                                                  # 6
      "    extra['publish_tf'] = False\n"                                 # 7
      "    here = os.path.dirname(__file__)\n"                            # 8
      "    return LaunchDescription([Node(\n"                             # 9
      "        package='robot_localization', executable='ekf_node',\n"    # 10
      "        name='ekf',\n"                                             # 11
      "        parameters=[{'use_sim_time': False,\n"                     # 12
      "                     'nested': {'frame': 'odom'}},\n"              # 13
      "                    os.path.join(here, 'ekf.yaml'),\n"             # 14
      "                    {**SHARED, 'two_d_mode': True},\n"             # 15
      "                    extra])])\n")                                  # 16
EKF_YAML = ("ekf:\n"
            "  ros__parameters:\n"
            "    map_frame: map\n"
            "    odom_frame: odom\n")


def test_ros2_python_dictionary_keys_and_parameter_file_keys(tmp_path: Path) -> None:
    ekf = nodes(tmp_path, {"ekf.yaml": EKF_YAML, "a.launch.py": PY}, "a.launch.py")["ekf"]
    assert at(ekf, "nested.frame") == ("a.launch.py", 13)
    assert at(ekf, "map_frame") == ("ekf.yaml", 3)
    assert at(ekf, "odom_frame") == ("ekf.yaml", 4)
    # The last setting wins, its place with it: SHARED's key, unpacked at line 15.
    assert ekf.given("use_sim_time") == "true"
    assert at(ekf, "use_sim_time") == ("a.launch.py", 4)
    assert at(ekf, "two_d_mode") == ("a.launch.py", 15)
    assert at(ekf, "publish_tf") == ("a.launch.py", 7)
    # Every ROS 2 parameter has a place, in the order of the parameters.
    assert [key for key, *_ in ekf.param_lines] == [key for key, _ in ekf.params]


def test_ros2_xml_and_yaml_params(tmp_path: Path) -> None:
    xml = ('<launch>\n'
           '  <node pkg="nav2_amcl" exec="amcl" name="amcl">\n'
           '    <param name="base_frame_id" value="base"/>\n'
           '    <param name="scan">\n'
           '      <param name="topic" value="/scan"/>\n'
           '    </param>\n'
           '  </node>\n'
           '</launch>\n')
    amcl = nodes(tmp_path, {"a.launch.xml": xml}, "a.launch.xml")["amcl"]
    assert at(amcl, "base_frame_id") == ("a.launch.xml", 3)
    assert at(amcl, "scan.topic") == ("a.launch.xml", 5)
    yaml_launch = ('launch:\n'
                   '- node:\n'
                   '    pkg: nav2_amcl\n'
                   '    exec: amcl\n'
                   '    name: amcl\n'
                   '    param:\n'
                   '    - name: base_frame_id\n'
                   '      value: base\n')
    amcl = nodes(tmp_path, {"b.launch.yaml": yaml_launch}, "b.launch.yaml")["amcl"]
    assert amcl.given("base_frame_id") == "base"
    assert at(amcl, "base_frame_id") is not None


def test_ros1_param_and_rosparam_text_and_file(tmp_path: Path) -> None:
    files = {
        "amcl.yaml": "# comment\nodom_frame_id: odom_a\nbase_frame_id: base_footprint\n",
        "a.launch": ('<launch>\n'
                     '<node pkg="amcl" type="amcl" name="amcl">\n'
                     '  <param name="base_frame_id" value="base"/>\n'
                     '  <rosparam file="$(dirname)/amcl.yaml" command="load"/>\n'
                     '  <rosparam>use_map_topic: true</rosparam>\n'
                     '</node>\n'
                     '</launch>\n'),
    }
    amcl = nodes(tmp_path, files, "a.launch")["amcl"]
    # The file's key overrides the <param> before it: its line, not the <param>'s.
    assert amcl.given("base_frame_id") == "base_footprint"
    assert at(amcl, "base_frame_id") == ("amcl.yaml", 3)
    assert at(amcl, "odom_frame_id") == ("amcl.yaml", 2)
    assert at(amcl, "use_map_topic") == ("a.launch", 5)


def test_without_pyyaml_a_flat_file_keeps_its_lines_and_others_are_unread(
        tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """The standalone linter's stdlib core: flat ``key: value`` files are read by line;
    a ROS 2 parameter file (nested) is unread, its values and places unknown."""
    monkeypatch.setitem(sys.modules, "yaml", None)
    monkeypatch.setattr(params, "_cache", {})
    document, why, places = params.parse_yaml_placed("a: 1\n\n  # c\nb: x\n")
    assert why is None and document == {"a": "1", "b": "x"}
    assert places == {("a",): (1, 1), ("b",): (4, 1)}
    ekf = nodes(tmp_path, {"ekf.yaml": EKF_YAML, "a.launch.py": PY}, "a.launch.py")["ekf"]
    assert ekf.given("map_frame") is None and ekf.unread
    assert at(ekf, "nested.frame") == ("a.launch.py", 13)


def test_a_key_that_is_not_text_and_an_alias_degrade_to_no_place() -> None:
    document, why, places = params.parse_yaml_placed(
        "base: &b {x: 1}\nother: *b\ntrue: 2\n")
    assert why is None and document["other"] == {"x": 1} and document[True] == 2
    assert places[("base", "x")] == (1, 11)
    # An alias reaches the same mapping by a second path: its keys are found there too.
    assert places[("other", "x")] == (1, 11)
    # A key PyYAML constructs as a boolean is written 'true', read back as 'True': no place.
    assert ("True",) not in places


def test_twenty_thousand_parameters_with_places_stay_linear(tmp_path: Path) -> None:
    """A dictionary and a parameter file of 20,000 keys each, every one a frame parameter
    a rule reads and reports at its place (where_set and given indexed once per node)."""
    count = 20_000
    entries = ", ".join(f"'s{i}': {{'sensor_frame': '/f{i}'}}" for i in range(count))
    sources = " ".join(f"s{i}" for i in range(count))
    launch = ("import os\nfrom launch import LaunchDescription\n"
              "from launch_ros.actions import Node\n"
              "def generate_launch_description():\n"
              "    return LaunchDescription([Node(package='nav2_costmap_2d',\n"
              "        executable='nav2_costmap_2d', name='costmap',\n"
              "        parameters=[os.path.join(os.path.dirname(__file__), 'c.yaml'),\n"
              f"                    {{'observation_sources': '{sources}', {entries}}}]),\n"
              "    ])\n")
    keys = "".join(f"    k{i}: {i}\n" for i in range(count))
    (tmp_path / "c.yaml").write_text(f"costmap:\n  ros__parameters:\n{keys}")
    (tmp_path / "c.launch.py").write_text(launch)
    started = time.process_time()
    result = lint_paths([str(tmp_path / "c.launch.py")], LintOptions(package_paths=()))
    spent = time.process_time() - started
    [costmap] = [n for tree in result.trees for n in tree.nodes]
    # A node keeps params.MAX_PARAMS of them (the file's, listed first).
    last = params.MAX_PARAMS - 1
    assert costmap.given(f"k{last}") == str(last)
    assert at(costmap, f"k{last}") == ("c.yaml", last + 3)
    assert len(costmap.param_lines) == len(costmap.params)
    assert spent < 30, spent
