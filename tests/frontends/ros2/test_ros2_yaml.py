"""ROS 2 launch YAML: the same actions as XML, with line numbers."""

from __future__ import annotations

import sys

import pytest
from ros2_helpers import Load, by_name, rules

from launch_linter.frontends.ros2_yaml import read_yaml
from launch_linter.model.launch import FileStatus

SENSORS = """\
launch:
# sensors of the base
- arg:
    name: parent
    default: base_link
- let:
    name: lidar
    value: velodyne
- node:
    pkg: tf2_ros
    exec: static_transform_publisher
    name: lidar_tf
    namespace: sensors
    args: "--z 0.4 --frame-id $(var parent) --child-frame-id $(var lidar)"
- group:
    if: $(var use_imu)
    children:
    - push_ros_namespace:
        namespace: imu
    - node:
        pkg: tf2_ros
        exec: static_transform_publisher
        name: imu_tf
        args: "0 0 0.1 0 0 0 $(var parent) imu_link"
"""


def test_nodes_arguments_groups_and_lines(load: Load) -> None:
    tree = load({"s.launch.yaml": SENSORS}, "s.launch.yaml")
    nodes = by_name(tree)
    lidar, imu = nodes["lidar_tf"], nodes["imu_tf"]
    assert (lidar.line, lidar.column, lidar.namespace) == (9, 3, "/sensors")
    assert (lidar.parent, lidar.child, lidar.translation) == ("base_link", "velodyne",
                                                               (0.0, 0.0, 0.4))
    assert (imu.line, imu.namespace, imu.parent, imu.child) == (20, "/imu", "base_link",
                                                                 "imu_link")
    assert imu.condition.describe() == "if='$(var use_imu)'"
    assert [i.kind for i in imu.arg_issues] == ["positional"]
    assert {t.launch_format for t in tree.transforms} == {"ros2-yaml"}
    # Comments feed only suppression directives: a file without one keeps none.
    assert tree.comments == ()
    marked = load({"s.launch.yaml": SENSORS.replace("sensors of", "launch-linter: sensors of")},
                  "s.launch.yaml")
    assert [(c.line, c.text.strip()) for c in marked.comments] == [
        (2, "launch-linter: sensors of the base")
    ]
    assert ("s.launch.yaml", 9) in marked.element_lines


def test_a_group_given_as_a_list_and_include_arguments(load: Load) -> None:
    tree = load({
        "a.launch.yaml": (
            "launch:\n"
            "- group:\n"
            "  - include:\n"
            "      file: $(dirname)/b.launch.xml\n"
            "      arg:\n"
            "      - name: frame\n"
            "        value: gps\n"
        ),
        "b.launch.xml": (
            '<launch><arg name="frame"/><node pkg="tf2_ros" exec="static_transform_publisher" '
            'name="gps_tf" args="--frame-id base --child-frame-id $(var frame)"/></launch>'
        ),
    }, "a.launch.yaml")
    (transform,) = tree.transforms
    assert (transform.name, transform.child, transform.launch_format) == ("gps_tf", "gps",
                                                                          "ros2-xml")
    assert transform.included_from == ("a.launch.yaml", 3)


def test_composable_node_in_yaml(load: Load) -> None:
    tree = load({"a.launch.yaml": (
        "launch:\n"
        "- node_container:\n"
        "    pkg: rclcpp_components\n"
        "    exec: component_container\n"
        "    name: c\n"
        "    namespace: ''\n"
        "    composable_node:\n"
        "    - pkg: tf2_ros\n"
        "      plugin: tf2_ros::StaticTransformBroadcasterNode\n"
        "      name: t\n"
        "      param:\n"
        "      - name: child_frame_id\n"
        "        value: laser\n"
    )}, "a.launch.yaml")
    (transform,) = tree.transforms
    assert (transform.line, transform.parent_written, transform.child) == (8, "/frame", "laser")
    assert [i.kind for i in transform.arg_issues] == ["default_frames"]


@pytest.mark.parametrize(("text", "line"), [
    ("launch:\n- node: [\n", 3),
    ("launch:\n  node: {}\n", 2),
    ("not_launch:\n- node: {}\n", 1),
    ("launch:\n- node: {}\n  arg: {}\n", 2),
])
def test_malformed_files_are_parse_errors(load: Load, text: str, line: int) -> None:
    tree = load({"a.launch.yaml": text}, "a.launch.yaml")
    assert tree.status is FileStatus.PARSE_ERROR
    assert rules(tree) == [("parse_error", line)]


def test_aliases_cannot_multiply_work() -> None:
    lines = ["launch:", "- group: &g0", "  - let: {name: a, value: b}"]
    lines += [f"- group: &g{i}\n  - group: *g{i - 1}\n  - group: *g{i - 1}" for i in range(1, 30)]
    read = read_yaml("/x/a.launch.yaml", "\n".join(lines).encode())
    assert read.actions is None
    assert "too large" in read.problems[0].message


def test_without_pyyaml(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setitem(sys.modules, "yaml", None)
    read = read_yaml("/x/a.launch.yaml", b"launch: []\n")
    assert read.actions is None
    assert "needs PyYAML" in read.problems[0].message
