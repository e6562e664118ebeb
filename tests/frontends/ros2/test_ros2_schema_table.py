"""The ROS 2 action schema: where each entry comes from, and what launch refuses."""

from __future__ import annotations

import re
import subprocess
from pathlib import Path

import pytest
from ros2_helpers import Load, rules

from launch_linter.frontends.ros2_schema import ACTIONS, LAUNCH, LAUNCH_ROS, VERSIONS
from launch_linter.model.launch import FileStatus

# Where every entry was read: (repository, file). The versions are the Humble, Iron, Jazzy
# and Rolling branches of both repositories (VERSIONS).
SOURCES = {
    "append_env": (LAUNCH, "launch/launch/actions/append_environment_variable.py"),
    "arg": (LAUNCH, "launch/launch/actions/declare_launch_argument.py"),
    "executable": (LAUNCH, "launch/launch/actions/execute_process.py"),
    "group": (LAUNCH, "launch/launch/actions/group_action.py"),
    "include": (LAUNCH, "launch/launch/actions/include_launch_description.py"),
    "log": (LAUNCH, "launch/launch/actions/log_info.py"),
    "reset_env": (LAUNCH, "launch/launch/actions/reset_environment.py"),
    "reset": (LAUNCH, "launch/launch/actions/reset_launch_configurations.py"),
    "set_env": (LAUNCH, "launch/launch/actions/set_environment_variable.py"),
    "let": (LAUNCH, "launch/launch/actions/set_launch_configuration.py"),
    "shutdown": (LAUNCH, "launch/launch/actions/shutdown_action.py"),
    "timer": (LAUNCH, "launch/launch/actions/timer_action.py"),
    "unset_env": (LAUNCH, "launch/launch/actions/unset_environment_variable.py"),
    "node": (LAUNCH_ROS, "launch_ros/launch_ros/actions/node.py"),
    "node_container": (LAUNCH_ROS, "launch_ros/launch_ros/actions/composable_node_container.py"),
    "load_composable_node": (LAUNCH_ROS, "launch_ros/launch_ros/actions/load_composable_nodes.py"),
    "push_ros_namespace": (LAUNCH_ROS, "launch_ros/launch_ros/actions/push_ros_namespace.py"),
    "push-ros-namespace": (LAUNCH_ROS, "launch_ros/launch_ros/actions/push_ros_namespace.py"),
    "ros_timer": (LAUNCH_ROS, "launch_ros/launch_ros/actions/ros_timer.py"),
    "set_parameter": (LAUNCH_ROS, "launch_ros/launch_ros/actions/set_parameter.py"),
    "set_parameters_from_file": (
        LAUNCH_ROS, "launch_ros/launch_ros/actions/set_parameters_from_file.py"),
    "set_remap": (LAUNCH_ROS, "launch_ros/launch_ros/actions/set_remap.py"),
    "set_ros_log_dir": (LAUNCH_ROS, "launch_ros/launch_ros/actions/set_ros_log_dir.py"),
    "set_use_sim_time": (LAUNCH_ROS, "launch_ros/launch_ros/actions/set_use_sim_time.py"),
}


def test_every_entry_names_its_source() -> None:
    assert "humble" in VERSIONS and "rolling" in VERSIONS
    assert set(ACTIONS) == set(SOURCES)
    for tag, spec in ACTIONS.items():
        assert (spec.repo, spec.source) == SOURCES[tag], tag
        assert {"if", "unless"} <= spec.attributes, tag  # launch.Action.parse


MIRRORS = {LAUNCH: Path("/work/.mirror/ros2+launch/repo"),
           LAUNCH_ROS: Path("/work/.mirror/ros2+launch_ros/repo")}


def _show(repo: str, branch: str, path: str) -> str:
    done = subprocess.run(["git", "-C", str(MIRRORS[repo]), "show", f"{branch}:{path}"],
                          capture_output=True, text=True, check=False)
    return done.stdout


@pytest.mark.skipif(not all(p.is_dir() for p in MIRRORS.values()),
                    reason="needs git checkouts of ros2/launch and ros2/launch_ros")
@pytest.mark.parametrize("branch", ["humble", "iron", "jazzy", "rolling"])
def test_table_reads_what_the_sources_read(branch: str) -> None:
    """Every name a ``parse`` method reads with ``get_attr`` is in the table (as an
    attribute or a nested tag), and every exposed tag is an entry."""
    for tag, spec in ACTIONS.items():
        text = _show(spec.repo, branch, spec.source)
        if not text:  # set_ros_log_dir is newer than Humble
            continue
        assert f"expose_action('{tag}')" in text, (branch, tag)
        read = set(re.findall(r"get_attr\(\s*'([^']+)'", text))
        known = set(spec.attributes) | {name for name, _ in spec.nested}
        for _, nested in spec.nested:
            known |= nested.attributes | {name for name, _ in nested.nested}
        known |= {"if", "unless", "type", "value", "name", "from", "to", "allow_substs"}
        assert read <= known | {"cmd"}, (branch, tag, read - known)


NODE = '<node pkg="tf2_ros" exec="static_transform_publisher" name="tf" {extra}' \
       ' args="--frame-id a --child-frame-id b"{body}'


def _xml(extra: str = "", body: str = "/>") -> str:
    return f"<launch>\n  {NODE.format(extra=extra, body=body)}\n</launch>\n"


@pytest.mark.parametrize("extra", [
    'namespce="x"', 'ns="x"', 'type="static_transform_publisher"', 'output="screen" respawn="true"'
    ' launch-prefix="gdb" ros_args="--log-level debug" exec_name="n"',
])
def test_node_attributes(load: Load, extra: str) -> None:
    tree = load({"a.launch.xml": _xml(extra)}, "a.launch.xml")
    refused = "output" not in extra
    assert (("ros2_schema", 2) in rules(tree)) is refused
    assert (tree.status is FileStatus.PARSE_ERROR) is refused
    assert (len(tree.transforms) == 0) is refused


def test_nested_tags_and_their_attributes(load: Load) -> None:
    body = '>\n<remap from="a" to="b"/><param name="p"><param name="q" value="1"/></param>' \
           '<param from="x.yaml" allow_substs="true"/><env name="A" value="1"/></node>'
    assert "ros2_schema" not in [r for r, _ in rules(load({"a.launch.xml": _xml("", body)},
                                                           "a.launch.xml"))]
    for bad in ('<remapp from="a" to="b"/>', '<remap from="a" too="b"/>',
                '<param name="p" vale="1"/>', '<param name="p"><param nam="q"/></param>',
                '<rosparam command="load" file="x"/>'):
        tree = load({"b.launch.xml": _xml("", f">\n{bad}</node>")}, "b.launch.xml")
        assert ("ros2_schema", 3) in rules(tree), bad


def test_unknown_tags(load: Load) -> None:
    text = "<launch>\n<set-env name='A' value='1'/>\n<gz_server world='w'/>\n" \
           "<node_container pkg='rclcpp_components' exec='component_container' name='c'>" \
           "<composable_node pkg='p' plugin='q' name='n' namespce='x'/></node_container>\n" \
           "</launch>\n"
    found = rules(load({"a.launch.xml": text}, "a.launch.xml"))
    assert ("ros2_schema", 2) in found
    assert ("unresolved", 3) in found and ("ros2_schema", 3) not in found
    assert ("ros2_schema", 4) in found


def test_groups_hold_actions_and_sep_attributes(load: Load) -> None:
    text = "<launch>\n<group scoped='true' forwarding='false'><keep name='a' value='1'/>" \
           "<timer period='1'><let name='x' value='y'/></timer></group>\n" \
           "<executable cmd='ls -l' cmd-sep=' ' cwd='/'><env name='A' value='1'/></executable>\n" \
           "<group><remap from='a' to='b'/></group>\n</launch>\n"
    found = rules(load({"a.launch.xml": text}, "a.launch.xml"))
    assert [line for rule, line in found if rule == "ros2_schema"] == [4]


def test_yaml_keys(load: Load) -> None:
    good = "launch:\n- group:\n    scoped: false\n    children:\n    - arg: {name: a}\n" \
           "- group:\n  - let: {name: b, value: c}\n"
    assert "ros2_schema" not in [r for r, _ in rules(load({"a.launch.yaml": good},
                                                          "a.launch.yaml"))]
    bad = "launch:\n- node:\n    pkg: tf2_ros\n    exec: static_transform_publisher\n" \
          "    ns: robot\n    args: '--frame-id a --child-frame-id b'\n" \
          "    remap:\n    - {from: a, to: b, extra: c}\n- arg:\n    name: x\n    deflt:\n"
    tree = load({"b.launch.yaml": bad}, "b.launch.yaml")
    schema = [line for rule, line in rules(tree) if rule == "ros2_schema"]
    assert schema == [2, 8, 9]
    assert tree.transforms == ()


def test_refused_include_is_not_followed(load: Load) -> None:
    inner = _xml('namespce="x"')
    outer = "<launch>\n<include file='$(dirname)/inner.launch.xml'/>\n" \
            "<node pkg='tf2_ros' exec='static_transform_publisher' name='o'" \
            " args='--frame-id c --child-frame-id d'/>\n</launch>\n"
    tree = load({"inner.launch.xml": inner, "outer.launch.xml": outer}, "outer.launch.xml")
    assert [t.name for t in tree.transforms] == ["o"]
    assert any(d.rule == "ros2_schema" and d.path == "inner.launch.xml"
               for d in tree.problems)


@pytest.mark.parametrize(("body", "line"), [
    ("<log/>", 2), ("<set_parameter name='a'/>", 2),
    ("<timer><let name='a' value='b'/></timer>", 2),
    ("<node pkg='p' exec='e'><remap from='a'/></node>", 2),
    ("<arg name='a'><choice/></arg>", 2),
    ("<load_composable_node target='c'><composable_node pkg='p' plugin='q'/>"
     "</load_composable_node>", 2),
])
def test_missing_required_attributes(load: Load, body: str, line: int) -> None:
    # <let> makes the file ROS 2 for the dispatcher.
    tree = load({"a.launch.xml": f"<launch>\n{body}\n<let name='z' value='1'/>\n</launch>\n"},
                "a.launch.xml")
    assert ("ros2_schema", line) in rules(tree)
    assert any("is missing the required" in d.message for d in tree.problems)


def test_required_attributes_the_reader_reports_are_not_doubled(load: Load) -> None:
    tree = load({"a.launch.xml": "<launch>\n<let name='a'/>\n<include file='x.xml'>"
                                 "<arg name='b'/></include>\n</launch>\n"}, "a.launch.xml")
    assert "ros2_schema" not in [rule for rule, _ in rules(tree)]
