"""ROS 2 launch XML: arguments, scoping, namespaces, conditions, includes, components."""

from __future__ import annotations

import pytest
from ros2_helpers import FIXTURES, Load, by_name, rules

from launch_linter.model.launch import FileStatus

TF = 'pkg="tf2_ros" exec="static_transform_publisher"'


def launch(body: str) -> str:
    return f"<launch>\n{body}\n</launch>\n"


def test_a_node_with_flags(load: Load) -> None:
    tree = load({"a.launch.xml": launch(
        f'  <node {TF} name="laser_tf" namespace="robot"\n'
        '        args="--x 0.1 --yaw 1.57 --frame-id base_link --child-frame-id laser"/>'
    )}, "a.launch.xml")
    (transform,) = tree.transforms
    assert (transform.path, transform.line, transform.column) == ("a.launch.xml", 2, 3)
    assert (transform.name, transform.namespace) == ("laser_tf", "/robot")
    assert (transform.parent, transform.child) == ("base_link", "laser")
    assert transform.translation == (0.1, 0.0, 0.0)
    assert (transform.ros_version, transform.launch_format) == (2, "ros2-xml")
    assert transform.tokens == (
        "--x", "0.1", "--yaw", "1.57", "--frame-id", "base_link", "--child-frame-id", "laser",
    )
    assert tree.problems == () and tree.status is FileStatus.OK


def test_other_nodes_are_not_transforms(load: Load) -> None:
    tree = load({"a.launch.xml": launch(
        '  <node pkg="demo_nodes_cpp" exec="talker"/>\n'
        '  <node pkg="tf2_ros" exec="buffer_server"/>'
    )}, "a.launch.xml")
    assert tree.transforms == ()


def test_arg_default_let_and_command_line(load: Load) -> None:
    files = {"a.launch.xml": launch(
        '  <arg name="parent" default="base_link"/>\n'
        '  <let name="child" value="$(var parent)_laser"/>\n'
        f'  <node {TF} name="t" args="--frame-id $(var parent) --child-frame-id $(var child)"/>'
    )}
    (transform,) = load(files, "a.launch.xml").transforms
    assert (transform.parent, transform.child) == ("base_link", "base_link_laser")
    (transform,) = load(files, "a.launch.xml", args={"parent": "body"}).transforms
    assert (transform.parent, transform.child) == ("body", "body_laser")


def test_an_unset_argument_is_unresolved_with_its_reason(load: Load) -> None:
    tree = load({"a.launch.xml": launch(
        '  <arg name="child"/>\n'
        f'  <node {TF} name="t" args="--frame-id base --child-frame-id $(var child)"/>'
    )}, "a.launch.xml")
    (transform,) = tree.transforms
    assert transform.unresolved_names == ("child",) and transform.parent == "base"
    assert rules(tree) == [("unresolved", 3)]
    assert "$(var child)" in tree.problems[0].message


def test_a_group_scopes_configurations_and_the_namespace(load: Load) -> None:
    tree = load({"a.launch.xml": launch(
        '  <let name="child" value="outer"/>\n'
        '  <group>\n'
        '    <push-ros-namespace namespace="r1"/>\n'
        '    <let name="child" value="inner"/>\n'
        f'    <node {TF} name="a" args="--frame-id base --child-frame-id $(var child)"/>\n'
        '  </group>\n'
        f'  <node {TF} name="b" args="--frame-id base --child-frame-id $(var child)"/>'
    )}, "a.launch.xml")
    nodes = by_name(tree)
    assert (nodes["a"].namespace, nodes["a"].child) == ("/r1", "inner")
    assert (nodes["b"].namespace, nodes["b"].child) == ("/", "outer")


def test_an_unscoped_group_leaks(load: Load) -> None:
    tree = load({"a.launch.xml": launch(
        '  <group scoped="false"><push_ros_namespace namespace="r1"/>'
        '<let name="c" value="x"/></group>\n'
        f'  <node {TF} name="b" namespace="sub" args="--frame-id base --child-frame-id $(var c)"/>'
    )}, "a.launch.xml")
    (transform,) = tree.transforms
    assert (transform.namespace, transform.child) == ("/r1/sub", "x")


def test_an_absolute_node_namespace_ignores_the_pushed_one(load: Load) -> None:
    tree = load({"a.launch.xml": launch(
        '  <push-ros-namespace namespace="r1"/>\n'
        f'  <node {TF} name="b" namespace="/top" args="--frame-id a --child-frame-id b"/>'
    )}, "a.launch.xml")
    assert tree.transforms[0].namespace == "/top"


def test_conditions(load: Load) -> None:
    tree = load({"a.launch.xml": launch(
        '  <arg name="lidar" default="false"/>\n'
        f'  <node {TF} name="off" if="$(var lidar)" args="--frame-id a --child-frame-id b"/>\n'
        f'  <node {TF} name="on" unless="$(var lidar)" args="--frame-id a --child-frame-id c"/>\n'
        f'  <node {TF} name="x" if="$(var camera)" args="--frame-id a --child-frame-id d"/>\n'
        f'  <node {TF} name="y" unless="$(var camera)" args="--frame-id a --child-frame-id e"/>'
    )}, "a.launch.xml")
    nodes = by_name(tree)
    assert set(nodes) == {"on", "x", "y"}
    assert nodes["on"].condition.always
    assert nodes["x"].condition.excludes(nodes["y"].condition)
    assert nodes["x"].condition.describe() == "if='$(var camera)'"


def test_an_invalid_condition_is_a_launch_error(load: Load) -> None:
    tree = load({"a.launch.xml": launch(
        f'  <node {TF} name="t" if="yes" args="--frame-id a --child-frame-id b"/>'
    )}, "a.launch.xml")
    assert rules(tree) == [("roslaunch_error", 2)]
    assert not tree.transforms[0].condition.always


def test_a_value_set_under_an_unknown_condition_is_unknown_after_it(load: Load) -> None:
    tree = load({"a.launch.xml": launch(
        '  <let name="c" value="one"/>\n'
        '  <group if="$(var flag)" scoped="false"><let name="c" value="two"/></group>\n'
        f'  <node {TF} name="t" args="--frame-id a --child-frame-id $(var c)"/>'
    )}, "a.launch.xml")
    assert tree.transforms[0].unresolved_names == ("child",)


def test_a_value_set_in_a_conditional_scoped_group_is_known_inside(load: Load) -> None:
    tree = load({"a.launch.xml": launch(
        '  <group if="$(var flag)"><let name="c" value="two"/>\n'
        f'    <node {TF} name="t" args="--frame-id a --child-frame-id $(var c)"/></group>'
    )}, "a.launch.xml")
    (transform,) = tree.transforms
    assert transform.child == "two" and not transform.condition.always


def test_include_passes_arguments_and_leaks_them_back(load: Load) -> None:
    tree = load({
        "a.launch.xml": launch(
            '  <include file="sub/b.launch.xml"><arg name="frame" value="imu"/></include>\n'
            f'  <node {TF} name="after" args="--frame-id base --child-frame-id $(var set_in_b)"/>'
        ),
        "sub/b.launch.xml": launch(
            '  <arg name="frame"/>\n'
            '  <let name="set_in_b" value="gps"/>\n'
            f'  <node {TF} name="inside" args="--frame-id base --child-frame-id $(var frame)"/>'
        ),
    }, "a.launch.xml")
    nodes = by_name(tree)
    assert nodes["inside"].child == "imu"
    assert nodes["inside"].path == "sub/b.launch.xml"
    assert nodes["inside"].included_from == ("a.launch.xml", 2)
    assert nodes["after"].child == "gps"
    assert tree.files == ("a.launch.xml", "sub/b.launch.xml")


def test_include_through_find_pkg_share(load: Load) -> None:
    package = '<package format="3"><name>robot</name></package>'
    tree = load({
        "ws/robot/package.xml": package,
        "ws/robot/launch/tf.launch.xml": launch(
            f'  <node {TF} name="t" args="--frame-id a --child-frame-id b"/>'
        ),
        "a.launch.xml": launch(
            '  <include file="$(find-pkg-share robot)/launch/tf.launch.xml"/>\n'
            '  <include file="$(find-pkg-share missing)/launch/x.launch.xml"/>'
        ),
    }, "a.launch.xml", packages=("ws",))
    assert [t.name for t in tree.transforms] == ["t"]
    assert rules(tree) == [("unresolved", 3)]


def test_a_required_argument_an_include_does_not_pass(load: Load) -> None:
    tree = load({
        "a.launch.xml": launch('  <let name="frame" value="x"/>\n  <include file="b.launch.xml"/>'),
        "b.launch.xml": launch('  <arg name="frame"/>'),
    }, "a.launch.xml")
    assert rules(tree) == [("roslaunch_error", 3)]
    assert "missing required argument" in tree.problems[0].message


def test_the_command_line_does_not_satisfy_an_included_required_argument(load: Load) -> None:
    # launch/actions/include_launch_description.py (ros2/launch, dashing 2e12986 to rolling
    # 02595ba): execute() compares the declared arguments only with the include's own
    # launch_arguments, never with context.launch_configurations, where `ros2 launch`
    # put the command line's values: the include still raises.
    tree = load({
        "a.launch.xml": launch('  <let name="robot" value="r"/>\n  <include file="b.launch.xml"/>'),
        "b.launch.xml": launch('  <arg name="frame"/>'),
    }, "a.launch.xml", args={"frame": "x"})
    assert rules(tree) == [("roslaunch_error", 3)]


def test_the_command_line_value_reaches_an_included_file(load: Load) -> None:
    # DeclareLaunchArgument keeps a value already set (the command line's) over its default.
    tree = load({
        "a.launch.xml": launch('  <let name="robot" value="r"/>\n  <include file="b.launch.xml"/>'),
        "b.launch.xml": launch(
            '  <arg name="frame" default="d"/>\n'
            f'  <node {TF} name="t" args="--frame-id $(var frame) --child-frame-id c"/>'),
    }, "a.launch.xml", args={"frame": "x"})
    assert rules(tree) == []
    assert by_name(tree)["t"].parent == "x"


def test_include_cycles_and_missing_files(load: Load) -> None:
    tree = load({
        "a.launch.xml": launch(
            '  <include file="b.launch.yaml"/>\n  <include file="no.launch.xml"/>'
        ),
        "b.launch.yaml": "launch:\n- include:\n    file: a.launch.xml\n",
    }, "a.launch.xml")
    messages = [d.message for d in tree.problems]
    assert any("include cycle" in m for m in messages)
    assert any("included file not found" in m for m in messages)


def test_composable_node(load: Load) -> None:
    tree = load({"a.launch.xml": launch(
        '  <node_container pkg="rclcpp_components" exec="component_container" name="c" '
        'namespace="">\n'
        '    <composable_node pkg="tf2_ros" plugin="tf2_ros::StaticTransformBroadcasterNode"\n'
        '                     name="tool_tf">\n'
        '      <param name="translation">\n'
        '        <param name="z" value="0.2"/>\n'
        '      </param>\n'
        '      <param name="frame_id" value="flange"/>\n'
        '      <param name="child_frame_id" value="tool"/>\n'
        '    </composable_node>\n'
        '  </node_container>'
    )}, "a.launch.xml")
    (transform,) = tree.transforms
    assert (transform.name, transform.line) == ("tool_tf", 3)
    assert (transform.parent, transform.child, transform.translation) == (
        "flange", "tool", (0.0, 0.0, 0.2),
    )
    assert transform.executable == "tf2_ros::StaticTransformBroadcasterNode"
    assert transform.arg_issues == ()


def test_composable_node_parameters_from_a_file(load: Load) -> None:
    tree = load({"a.launch.xml": launch(
        '  <load_composable_node target="/c">\n'
        '    <composable_node pkg="tf2_ros" plugin="tf2_ros::StaticTransformBroadcasterNode"'
        ' name="t">\n'
        '      <param from="$(dirname)/tf.yaml"/>\n'
        '    </composable_node>\n'
        '  </load_composable_node>'
    )}, "a.launch.xml")
    (transform,) = tree.transforms
    assert transform.name == "t"  # launch_ros requires it (ComposableNode.parse)
    assert set(transform.unresolved) == {"translation", "rotation", "parent", "child"}
    assert transform.arg_issues == ()


def test_ros1_type_in_ros2_xml(load: Load) -> None:
    tree = load({"a.launch.xml": launch(
        '  <let name="x" value="1"/>\n'
        '  <node pkg="tf" type="static_transform_publisher" name="t" args="0 0 0 0 0 0 a b 100"/>'
    )}, "a.launch.xml")
    assert rules(tree) == [("ros2_schema", 3), ("roslaunch_error", 3)]
    assert "'type' 'exec'" in tree.problems[1].message


def test_parse_errors(load: Load) -> None:
    tree = load({"a.launch.xml": "<launch><let name='x' value='1'>\n</launch>"}, "a.launch.xml")
    assert tree.status is FileStatus.PARSE_ERROR and rules(tree)[0][0] == "parse_error"
    tree = load({"a.launch.xml": '<launch><node exec="x" args="$(var a"/></launch>'},
                "a.launch.xml")
    assert rules(tree) == [("roslaunch_error", 1)]


def test_comments_and_element_lines_for_suppressions(load: Load) -> None:
    tree = load({"a.launch.xml": launch(
        '  <!-- launch-linter: disable=ros2_positional_args -->\n'
        f'  <node {TF} name="t" args="0 0 0 0 0 0 a b"/>'
    )}, "a.launch.xml")
    assert [(c.line, c.text.strip()) for c in tree.comments] == [
        (2, "launch-linter: disable=ros2_positional_args"),
    ]
    assert ("a.launch.xml", 3) in tree.element_lines


def test_the_fixture_tree_in_every_format(load: Load) -> None:
    from launch_linter.frontends.dispatch import load_tree
    from launch_linter.frontends.ros1 import LoadOptions
    from launch_linter.workspace.packages import PackageIndex

    root = FIXTURES / "robot_description" / "launch" / "robot.launch.xml"
    options = LoadOptions(packages=PackageIndex([str(FIXTURES)]),
                          display_path=lambda p: p.rsplit("/", 1)[-1])
    tree = load_tree(str(root), options)
    found = {(t.path, t.name): (t.namespace, t.parent, t.child) for t in tree.transforms}
    assert found == {
        ("robot.launch.xml", "footprint_tf"): ("/", "base_footprint", "base_link"),
        ("robot.launch.xml", "lidar_tf"): ("/sensors", "base_link", "lidar"),
        ("sensors.launch.yaml", "imu_tf"): ("/", "base_link", "imu_link"),
        ("sensors.launch.yaml", "camera_tf"): ("/", "base_link", "camera_link"),
        ("arm.launch.py", "shoulder_tf"): ("/", "base_link", "arm_base"),
        ("arm.launch.py", "elbow_tf"): ("/", "base_link", "arm_upper"),
        ("arm.launch.py", "gripper_tf"): ("/", "arm_upper", "flange"),
        ("arm.launch.py", "tool_tf"): ("/", "flange", "tool"),
    }
    assert {t.launch_format for t in tree.transforms} == {"ros2-xml", "ros2-yaml", "ros2-python"}
    assert tree.problems == ()


def test_set_env_and_forwarding(load: Load) -> None:
    tree = load({"a.launch.xml": launch(
        '  <set_env name="ROBOT" value="r2"/>\n'
        '  <let name="parent" value="base"/>\n'
        '  <group forwarding="false">\n'
        f'    <node {TF} name="a" args="--frame-id $(var parent) --child-frame-id $(env ROBOT)"/>\n'
        '  </group>\n'
        '  <unset_env name="ROBOT"/>\n'
        f'  <node {TF} name="b" args="--frame-id $(var parent) --child-frame-id $(env ROBOT x)"/>'
    )}, "a.launch.xml", env={"ROBOT": "r1"})
    nodes = by_name(tree)
    assert (nodes["a"].child, nodes["a"].unresolved_names) == ("r2", ("parent",))
    assert (nodes["b"].parent, nodes["b"].child) == ("base", "x")


def test_run_time_substitutions_are_unresolved_not_errors(load: Load) -> None:
    tree = load({"a.launch.xml": launch(
        '  <node pkg="tf2_ros" exec="static_transform_publisher" name="t"'
        ' args="--frame-id $(param base_frame) --child-frame-id laser"'
        ' cwd="$(launch_log_dir)" output="$(log_dir)"/>'
    )}, "a.launch.xml")
    assert [rule for rule, _ in rules(tree)] == ["unresolved"]
    (transform,) = tree.transforms
    assert "parent" in transform.unresolved and transform.child == "laser"


def test_executable_ros2_run_is_a_node(load: Load) -> None:
    tree = load({"a.launch.xml": launch(
        '  <push-ros-namespace namespace="r"/>\n'
        '  <executable cmd="ros2 run tf2_ros static_transform_publisher --frame-id base'
        ' --child-frame-id cam" output="screen"/>\n'
        '  <executable cmd="ls -l"/>'
    )}, "a.launch.xml")
    (transform,) = tree.transforms
    assert (transform.package, transform.executable) == ("tf2_ros", "static_transform_publisher")
    assert (transform.namespace, transform.parent, transform.child) == ("/", "base", "cam")
    assert transform.line == 3


@pytest.mark.parametrize(("executable", "expected"), [
    ('cmd="$(find-exec ros2) run tf2_ros static_transform_publisher --frame-id a'
     ' --child-frame-id b"', [("a", "b")]),
    ('cmd="ros2 run tf2_ros static_transform_publisher --frame-id a --child-frame-id b"'
     ' shell="true"', [("a", "b")]),
    ('cmd="ros2 run tf2_ros static_transform_publisher --frame-id $HOME'
     ' --child-frame-id b" shell="true"', []),
])
def test_executable_ros2_run_forms(load: Load, executable: str,
                                   expected: list[tuple[str, str]]) -> None:
    tree = load({"a.launch.xml": launch(f"  <executable {executable}/>")}, "a.launch.xml")
    assert [(t.parent, t.child) for t in tree.transforms] == expected


def test_a_refused_substitution_is_reported_where_it_is_written(load: Load) -> None:
    # launch's parser instantiates each substitution while it parses the file
    # (launch/frontend/expose.py, instantiate_substitution: 'Unknown substitution'), so the
    # fault is the attribute's, not the node's; each place that writes it is named once.
    tree = load({"a.launch.xml": launch(
        '  <arg name="params" default="p.yaml"/>\n'
        '  <node pkg="demo" exec="talker" name="t">\n'
        '    <param from="$(arg params)"/>\n'
        '    <param name="a" value="$(var params x y)"/>\n'
        '  </node>\n'
        '  <node pkg="demo" exec="listener" name="l">\n'
        '    <param from="$(arg params)"/>\n'
        '  </node>')}, "a.launch.xml")
    assert rules(tree) == [("roslaunch_error", 4), ("roslaunch_error", 5),
                           ("roslaunch_error", 8)]
    assert "'$(var)' takes 1 to 2 argument(s), not 3" in tree.problems[1].message


def test_a_substitution_launch_knows_is_not_reported(load: Load) -> None:
    tree = load({"a.launch.xml": launch(
        '  <arg name="params" default="p.yaml"/>\n'
        '  <node pkg="demo" exec="talker" name="t">\n'
        '    <param from="$(var params)"/>\n'
        '  </node>')}, "a.launch.xml")
    assert rules(tree) == []


def test_a_refused_substitution_in_yaml_is_reported_at_its_entry(load: Load) -> None:
    tree = load({"a.launch.yaml": (
        "launch:\n"
        "- node:\n"
        "    pkg: demo\n"
        "    exec: talker\n"
        "    param:\n"
        "    - from: $(arg params)\n")}, "a.launch.yaml")
    assert rules(tree) == [("roslaunch_error", 6)]
