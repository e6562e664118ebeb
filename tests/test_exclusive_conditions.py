"""Branches on one unknown value with exclusive tests are alternatives (issue 27)."""

from __future__ import annotations

from pathlib import Path

from hypothesis import given
from hypothesis import strategies as st

from launch_linter.engine import LintOptions, lint_paths
from launch_linter.model.equality import TRUTH, equality_test, exclusive, truth_test
from launch_linter.model.transform import Condition, ConditionLiteral


def literal(text: str, positive: bool = True) -> Condition:
    return Condition((ConditionLiteral(text, positive),))


def test_tests_read_from_condition_texts() -> None:
    assert equality_test("$(eval env('RUN_TYPE') == 'uav')") == ("env:RUN_TYPE", "uav", True)
    assert equality_test("$(eval optenv('RUN_TYPE') != \"uav\")") == ("env:RUN_TYPE", "uav",
                                                                      False)
    assert equality_test("$(eval arg('mode') == 'x')") == ("mode", "x", True)
    assert equality_test("$(eval mode == 'x')") == ("mode", "x", True)
    assert equality_test("LaunchConfigurationEquals('mode', 'sim')") == ("mode", "sim", True)
    assert equality_test("LaunchConfigurationNotEquals('mode', 'sim')") == ("mode", "sim",
                                                                            False)
    assert equality_test("$(eval '\\'$(var mode)\\' == \\'sim\\'')") == ("mode", "sim", True)
    assert equality_test("""PythonExpression(["'", mode, "' == 'x'"])""") == ("mode", "x",
                                                                              True)
    assert equality_test("xacro:${side == 'left'}") == ("side", "left", True)
    assert equality_test("xacro:${n == 2}") == ("n", "2.0", True)
    for undecided in ("$(eval arg('n') > 1)", "$(eval a == 'x' or b == 'y')",
                      "$(arg use_sim)", "$(eval a == b)", "LaunchConfiguration('x')"):
        assert equality_test(undecided) is None, undecided


def test_which_conditions_exclude_each_other() -> None:
    sim = literal("$(eval env('RUN_TYPE') == 'simulation')")
    uav = literal("$(eval env('RUN_TYPE') == 'uav')")
    assert sim.excludes(uav) and uav.excludes(sim)
    assert sim.excludes(literal("$(eval env('RUN_TYPE') != 'simulation')"))
    assert not sim.excludes(literal("$(eval env('RUN_TYPE') != 'uav')"))
    assert not sim.excludes(literal("$(eval env('OTHER') == 'uav')"))
    # unless of one test is its negation: "unless x == 'a'" and "if x == 'b'" may both hold.
    assert not literal("$(eval mode == 'a')", False).excludes(literal("$(eval mode == 'b')"))
    assert literal("$(eval mode == 'a')", False).excludes(literal("$(eval mode == 'a')"))


@given(st.text(max_size=80), st.text(max_size=80))
def test_reading_never_fails_and_exclusion_is_symmetric(first: str, second: str) -> None:
    a, b = equality_test(first), equality_test(second)
    if a is not None and b is not None:
        assert exclusive(a, b) == exclusive(b, a)
    assert literal(first).excludes(literal(second)) == literal(second).excludes(literal(first))


def test_alternative_groups_do_not_give_a_frame_two_parents(tmp_path: Path) -> None:
    node = '<node pkg="tf2_ros" type="static_transform_publisher" name="{}" args="{}"/>'
    (tmp_path / "a.launch").write_text(f"""<launch>
  <group if="$(eval env('RUN_TYPE') == 'simulation')">
    {node.format("a", "0 0 0 0 0 0 map odom")}</group>
  <group if="$(eval env('RUN_TYPE') == 'uav')">
    {node.format("b", "1 0 0 0 0 0 world odom")}</group>
  <group if="$(eval env('RUN_TYPE') != 'x')">
    {node.format("c", "0 0 0 0 0 0 m1 base")}</group>
  <group if="$(eval env('RUN_TYPE') != 'y')">
    {node.format("d", "0 0 0 0 0 0 m2 base")}</group>
</launch>""")
    result = lint_paths([str(tmp_path / "a.launch")], LintOptions())
    parents = [d.message for d in result.diagnostics if d.rule == "multiple_parents"]
    assert len(parents) == 1 and "'base'" in parents[0]


def test_xacro_alternatives_are_alternatives(tmp_path: Path) -> None:
    # The mount comes from an environment variable the linter is not given: both branches
    # are kept as conditional. (A name no property defines is a refusal, not an unknown.)
    (tmp_path / "r.urdf.xacro").write_text("""<robot name="r"
  xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:arg name="mount" default="top"/>
  <xacro:property name="mode" value="$(arg mount)"/>
  <link name="base"/><link name="top_mount"/><link name="side_mount"/><link name="lidar"/>
  <xacro:if value="${mode == 'top'}">
    <joint name="a" type="fixed"><parent link="top_mount"/><child link="lidar"/></joint>
  </xacro:if>
  <xacro:if value="${mode == 'side'}">
    <joint name="b" type="fixed"><parent link="side_mount"/><child link="lidar"/></joint>
  </xacro:if>
</robot>""")
    (tmp_path / "a.launch").write_text("""<launch>
  <param name="robot_description"
         command="xacro $(dirname)/r.urdf.xacro mount:=$(env LIDAR_MOUNT)"/>
  <node pkg="robot_state_publisher" type="robot_state_publisher" name="rsp"/>
</launch>""")
    result = lint_paths([str(tmp_path / "a.launch")], LintOptions())
    assert sorted(j.name for _, j in result.joints) == ["a", "b"]
    assert not [d for d in result.diagnostics if d.rule == "multiple_parents"]


def test_truth_tests_of_one_value_exclude_each_other() -> None:
    """IfCondition(x), UnlessCondition(x), IfCondition(PythonExpression(['not ', x])) and
    LaunchConfiguration(Not)Equals on x, related as truths of x (nav2's composed and
    separate nodes)."""
    assert truth_test("LaunchConfiguration('use_composition')") == (
        "use_composition", TRUTH, True)
    assert truth_test("PythonExpression(['not ', use_composition])") == (
        "use_composition", TRUTH, False)
    assert truth_test("$(eval not arg('sim'))") == ("sim", TRUTH, False)
    composed = literal("LaunchConfigAsBool('use_composition')")
    separate = literal("PythonExpression(['not ', use_composition])")
    assert composed.excludes(separate) and separate.excludes(composed)
    assert separate.excludes(literal("LaunchConfiguration('use_composition')"))
    assert not separate.excludes(literal("LaunchConfiguration('use_composition')", False))
    assert literal("$(var sim)").excludes(literal("$(var sim)", False))
    assert literal("$(var sim)").excludes(literal("LaunchConfigurationEquals('sim', 'false')"))
    assert not literal("$(var sim)").excludes(
        literal("LaunchConfigurationEquals('sim', 'true')"))
    assert literal("$(var sim)", False).excludes(
        literal("LaunchConfigurationEquals('sim', 'True')"))
    assert not literal("$(var sim)").excludes(
        literal("LaunchConfigurationNotEquals('sim', 'false')"))
    assert not literal("$(var sim)").excludes(literal("$(var other)", False))
    assert not literal("PythonExpression(['not ', a, ' and ', b])").excludes(literal("$(var a)"))


def test_one_program_under_two_unrelated_conditions_runs_twice(tmp_path: Path) -> None:
    """Two amcl under conditions on different arguments may both run: reported; under
    ``x`` and ``not x`` they are alternatives."""
    def launch(second: str) -> str:
        return ("from launch import LaunchDescription\n"
                "from launch.conditions import IfCondition\n"
                "from launch.substitutions import LaunchConfiguration, PythonExpression\n"
                "from launch_ros.actions import Node\n"
                "def generate_launch_description():\n"
                "    a = LaunchConfiguration('a')\n"
                "    return LaunchDescription([\n"
                "        Node(package='nav2_amcl', executable='amcl', condition=IfCondition(a)),\n"
                f"        Node(package='nav2_amcl', executable='amcl', condition={second}),\n"
                "    ])\n")
    path = tmp_path / "a.launch.py"
    options = LintOptions(package_paths=(), select=frozenset({"duplicate_publisher"}))
    path.write_text(launch("IfCondition(LaunchConfiguration('b'))"))
    assert len(lint_paths([str(path)], options).diagnostics) == 1
    path.write_text(launch("IfCondition(PythonExpression(['not ', a]))"))
    assert lint_paths([str(path)], options).diagnostics == ()


def test_a_launch_configuration_written_inside_the_expression_list(tmp_path: Path) -> None:
    """realsense-ros's rs_launch.py: ``PythonExpression([LaunchConfiguration('config_file'),
    " == ''"])`` and ``" != ''"`` choose one of two driver nodes; an undeclared
    ``config_file`` leaves both unresolved, and they are still alternatives."""
    assert equality_test("""PythonExpression([LaunchConfiguration('f'), " == ''"])""") == (
        "f", "", True)
    assert equality_test("""PythonExpression([LaunchConfiguration("f"), " != 'x'"])""") == (
        "f", "x", False)

    def launch(operator: str) -> str:
        return ("from launch import LaunchDescription\n"
                "from launch.conditions import IfCondition\n"
                "from launch.substitutions import LaunchConfiguration, PythonExpression\n"
                "from launch_ros.actions import Node\n"
                "def generate_launch_description():\n"
                "    return LaunchDescription([\n"
                "        Node(package='nav2_amcl', executable='amcl', condition=IfCondition(\n"
                "            PythonExpression([LaunchConfiguration('f'), \" == ''\"]))),\n"
                "        Node(package='nav2_amcl', executable='amcl', condition=IfCondition(\n"
                f"            PythonExpression([LaunchConfiguration('f'), \" {operator} ''\"]))),\n"
                "    ])\n")
    path = tmp_path / "a.launch.py"
    options = LintOptions(package_paths=(), select=frozenset({"duplicate_publisher"}))
    path.write_text(launch("!="))
    assert lint_paths([str(path)], options).diagnostics == ()
    path.write_text(launch("=="))
    assert len(lint_paths([str(path)], options).diagnostics) == 1
