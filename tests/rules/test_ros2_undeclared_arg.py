from __future__ import annotations

from pathlib import Path

import pytest

from launch_linter import LintOptions, lint_paths

RULE = "ros2_undeclared_arg"

PY_HEAD = """from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, IncludeLaunchDescription, OpaqueFunction
from launch.actions import SetLaunchConfiguration, GroupAction
from launch.conditions import IfCondition, LaunchConfigurationEquals
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node, SetParameter
"""
AMENT_PACKAGE = """<package format="3"><name>pkg</name>
  <export><build_type>ament_cmake</build_type></export>
</package>
"""


def _lint(tmp_path: Path, files: dict[str, str], root: str,
          options: LintOptions | None = None) -> list[tuple[str, int, str, str]]:
    for name, text in files.items():
        path = tmp_path / name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text, encoding="utf-8")
    result = lint_paths([str(tmp_path / root)], options or LintOptions(package_paths=()))
    return [(Path(d.path).name, d.line, d.severity.value, d.message)
            for d in result.diagnostics if d.rule == RULE]
SET_PARAMETER = """    return LaunchDescription([
        SetParameter(name='q', value=LaunchConfiguration('a')),
    ])
"""


def _py(body: str) -> str:
    return PY_HEAD + "\n\ndef generate_launch_description():\n" + body


def test_python_parameter_read_never_declared_is_an_error(tmp_path: Path) -> None:
    text = _py("""    use_sim_time = LaunchConfiguration('use_sim_time')
    return LaunchDescription([
        Node(package='foo', executable='bar', parameters=[{'use_sim_time': use_sim_time}]),
    ])
""")
    ((name, line, level, message),) = _lint(tmp_path, {"a.launch.py": text}, "a.launch.py")
    # At the LaunchConfiguration that names it (where a default or the right name is
    # written), not at the Node that performs it: launch's error names no place.
    assert (name, line, level) == ("a.launch.py", 11, "error")
    assert "launch configuration 'use_sim_time' does not exist" in message
    assert "a.launch.py" in message


def test_python_declared_or_defaulted_is_silent(tmp_path: Path) -> None:
    text = _py("""    return LaunchDescription([
        DeclareLaunchArgument('use_sim_time', default_value='false'),
        DeclareLaunchArgument('required'),
        Node(package='foo', executable='bar', name=LaunchConfiguration('required'),
             parameters=[{'use_sim_time': LaunchConfiguration('use_sim_time'),
                          'other': LaunchConfiguration('other', default='1')}],
             condition=LaunchConfigurationEquals('mode', 'fast')),
    ])
""")
    assert _lint(tmp_path, {"a.launch.py": text}, "a.launch.py") == []


def test_python_declaration_not_added_to_the_description_declares_nothing(
    tmp_path: Path
) -> None:
    text = _py("""    declared = DeclareLaunchArgument('rate', default_value='10')
    return LaunchDescription([
        Node(package='foo', executable='bar', remappings=[('in', LaunchConfiguration('rate'))]),
    ])
""")
    ((_, _, level, _),) = _lint(tmp_path, {"a.launch.py": text}, "a.launch.py")
    assert level == "error"


def test_set_launch_configuration_and_group_configurations_set_it(tmp_path: Path) -> None:
    text = _py("""    return LaunchDescription([
        SetLaunchConfiguration('a', '1'),
        GroupAction([SetParameter(name='p', value=LaunchConfiguration('b'))],
                    launch_configurations={'b': '2'}),
        SetParameter(name='q', value=LaunchConfiguration('a')),
    ])
""")
    assert _lint(tmp_path, {"a.launch.py": text}, "a.launch.py") == []


def test_unmodelled_action_reads_count(tmp_path: Path) -> None:
    text = _py(SET_PARAMETER)
    assert [level for _, _, level, _ in _lint(tmp_path, {"a.launch.py": text},
                                               "a.launch.py")] == ["error"]


def test_command_line_argument_sets_it(tmp_path: Path) -> None:
    text = _py(SET_PARAMETER)
    options = LintOptions(package_paths=(), args={"a": "1"})
    assert _lint(tmp_path, {"a.launch.py": text}, "a.launch.py", options) == []


def test_misspelling_suggests_the_declared_name(tmp_path: Path) -> None:
    text = """<launch>
  <arg name="use_sim_time" default="false"/>
  <node pkg="foo" exec="bar"><param name="use_sim_time" value="$(var use_sim_tme)"/></node>
</launch>
"""
    ((_, line, level, message),) = _lint(tmp_path, {"a.launch.xml": text}, "a.launch.xml")
    assert (line, level) == (3, "error")
    assert "did you mean 'use_sim_time'" in message


def test_xml_remap_and_unmodelled_tag_read_it(tmp_path: Path) -> None:
    text = """<launch>
  <node pkg="foo" exec="bar"><remap from="a" to="$(var topic)"/></node>
  <set_parameter name="x" value="$(var value)"/>
  <node pkg="foo" exec="baz" name="$(var defaulted 'n')"/>
</launch>
"""
    found = _lint(tmp_path, {"a.launch.xml": text}, "a.launch.xml")
    assert [(line, level) for _, line, level, _ in found] == [(2, "error"), (3, "error")]


def test_yaml_read(tmp_path: Path) -> None:
    pytest.importorskip("yaml")
    text = """launch:
- node:
    pkg: foo
    exec: bar
    name: $(var name)
"""
    ((_, line, level, _),) = _lint(tmp_path, {"a.launch.yaml": text}, "a.launch.yaml")
    assert (line, level) == (2, "error")


def test_includer_passes_it(tmp_path: Path) -> None:
    inner = """<launch>
  <node pkg="foo" exec="bar" name="$(var robot)"/>
</launch>
"""
    outer = """<launch>
  <include file="$(dirname)/inner.launch.xml"><arg name="robot" value="r1"/></include>
</launch>
"""
    files = {"pkg/package.xml": AMENT_PACKAGE,
             "pkg/launch/inner.launch.xml": inner, "pkg/launch/outer.launch.xml": outer}
    assert _lint(tmp_path, files, "pkg/launch/outer.launch.xml") == []
    # Linted on its own, the included file is only an info: its includer may pass it.
    ((_, _, level, message),) = _lint(tmp_path, files, "pkg/launch/inner.launch.xml")
    assert level == "info"
    assert "outer.launch.xml" in message


def test_includer_that_does_not_pass_it_is_an_error_at_the_read(tmp_path: Path) -> None:
    inner = """<launch>
  <node pkg="foo" exec="bar" name="$(var robot)"/>
</launch>
"""
    outer = """<launch>
  <include file="$(dirname)/inner.launch.xml"/>
</launch>
"""
    files = {"package.xml": AMENT_PACKAGE, "inner.launch.xml": inner,
             "outer.launch.xml": outer}
    ((name, line, level, message),) = _lint(tmp_path, files, "outer.launch.xml")
    assert (name, line, level) == ("inner.launch.xml", 2, "error")
    assert "ros2 launch of " in message and "outer.launch.xml" in message


def test_declared_by_the_includer_is_seen_inside(tmp_path: Path) -> None:
    inner = '<launch><node pkg="foo" exec="bar" name="$(var robot)"/></launch>\n'
    outer = """<launch>
  <arg name="robot" default="r1"/>
  <include file="$(dirname)/inner.launch.xml"/>
</launch>
"""
    files = {"package.xml": AMENT_PACKAGE, "inner.launch.xml": inner,
             "outer.launch.xml": outer}
    assert _lint(tmp_path, files, "outer.launch.xml") == []
    files["outer.launch.xml"] = outer.replace('<arg name="robot" default="r1"/>', "")
    assert [level for *_, level, _ in _lint(tmp_path, files, "outer.launch.xml")] == ["error"]


def test_unfollowed_include_makes_it_an_info(tmp_path: Path) -> None:
    text = """<launch>
  <include file="$(find-pkg-share elsewhere)/launch/common.launch.xml"/>
  <node pkg="foo" exec="bar" name="$(var robot)"/>
</launch>
"""
    ((_, _, level, message),) = _lint(tmp_path, {"a.launch.xml": text}, "a.launch.xml")
    assert level == "info"
    assert "does not follow" in message


def test_unknown_launch_arguments_make_it_an_info(tmp_path: Path) -> None:
    inner = '<launch><node pkg="foo" exec="bar" name="$(var robot)"/></launch>\n'
    outer = _py("""    return LaunchDescription([IncludeLaunchDescription(
        PythonLaunchDescriptionSource('inner.launch.xml'),
        launch_arguments=make_arguments().items())])
""")
    files = {"inner.launch.xml": inner, "outer.launch.py": outer}
    levels = [level for _, _, level, _ in _lint(tmp_path, files, "outer.launch.py")]
    assert levels == ["info"]


def test_read_under_an_undecided_condition_is_an_info(tmp_path: Path) -> None:
    text = """<launch>
  <arg name="gui" default="true"/>
  <arg name="mode"/>
  <group if="$(var mode)">
    <node pkg="foo" exec="bar" name="$(var robot)"/>
  </group>
</launch>
"""
    ((_, line, level, _),) = _lint(tmp_path, {"a.launch.xml": text}, "a.launch.xml")
    assert (line, level) == (5, "info")


def test_false_condition_skips_the_read(tmp_path: Path) -> None:
    text = """<launch>
  <arg name="gui" default="false"/>
  <node if="$(var gui)" pkg="foo" exec="bar" name="$(var robot)"/>
</launch>
"""
    assert _lint(tmp_path, {"a.launch.xml": text}, "a.launch.xml") == []


def test_opaque_function_perform_and_get(tmp_path: Path) -> None:
    text = _py("""    return LaunchDescription([OpaqueFunction(function=setup)])


def setup(context):
    robot = LaunchConfiguration('robot').perform(context)
    mode = context.launch_configurations.get('mode', 'x')
    return [Node(package='foo', executable='bar', name=robot + mode)]
""")
    ((_, _, level, message),) = _lint(tmp_path, {"a.launch.py": text}, "a.launch.py")
    assert level == "error"
    assert "'robot'" in message


def test_ros1_arg_substitution_in_ros2_xml(tmp_path: Path) -> None:
    text = '<launch><node pkg="foo" exec="bar" name="$(arg robot)"/></launch>\n'
    (tmp_path / "a.launch.xml").write_text(text, encoding="utf-8")
    result = lint_paths([str(tmp_path / "a.launch.xml")], LintOptions(package_paths=()))
    messages = [d.message for d in result.diagnostics if d.rule == "roslaunch_error"]
    assert any("$(arg)" in m and "$(var NAME)" in m for m in messages)


def test_study_profile_is_silent(tmp_path: Path) -> None:
    text = '<launch><node pkg="foo" exec="bar" name="$(var robot)"/></launch>\n'
    options = LintOptions(package_paths=(), profile="study")
    assert _lint(tmp_path, {"a.launch.xml": text}, "a.launch.xml", options) == []


def test_include_passing_its_own_read_does_not_declare_it(tmp_path: Path) -> None:
    # leggedrobotics/elevation_mapping_cupy#108: the declaration was left out of the
    # description, and the include passing the value reads it before setting it.
    inner = '<launch><node pkg="foo" exec="bar" name="$(var use_sim_time)"/></launch>\n'
    outer = _py("""    declared = DeclareLaunchArgument('use_sim_time', default_value='true')
    return LaunchDescription([IncludeLaunchDescription(
        PythonLaunchDescriptionSource('inner.launch.xml'),
        launch_arguments={'use_sim_time': LaunchConfiguration('use_sim_time')}.items())])
""")
    files = {"inner.launch.xml": inner, "outer.launch.py": outer}
    ((name, line, level, _),) = _lint(tmp_path, files, "outer.launch.py")
    assert (name, line, level) == ("outer.launch.py", 14, "error")


def test_one_python_launch_configuration_read_by_several_actions_is_one_finding(
        tmp_path: Path) -> None:
    text = _py("""    prefix = LaunchConfiguration('prefix')
    return LaunchDescription([
        DeclareLaunchArgument('gui'),
        Node(package='foo', executable='a', name=prefix,
             condition=IfCondition(LaunchConfiguration('gui'))),
        Node(package='foo', executable='b', parameters=[{'frame': prefix}]),
    ])
""")
    # One place: reported once, and for sure, since the second Node always runs.
    assert [(name, line, level) for name, line, level, _ in
            _lint(tmp_path, {"a.launch.py": text}, "a.launch.py")] == [
        ("a.launch.py", 11, "error")]


def test_only_what_was_not_followed_before_the_read_makes_it_an_info(tmp_path: Path) -> None:
    text = """<launch>
  <node pkg="foo" exec="bar" name="$(var robot)"/>
  <include file="$(find-pkg-share elsewhere)/launch/common.launch.xml"/>
</launch>
"""
    assert [level for *_, level, _ in _lint(tmp_path, {"a.launch.xml": text},
                                             "a.launch.xml")] == ["error"]


def test_reads_at_one_place_are_one_finding(tmp_path: Path) -> None:
    text = """<launch>
  <node pkg="foo" exec="bar" name="$(var a)" namespace="$(var b)"/>
</launch>
"""
    ((_, _, _, message),) = _lint(tmp_path, {"a.launch.xml": text}, "a.launch.xml")
    assert "configurations 'a', 'b' are" in message or "configurations 'b', 'a' are" in message


def test_an_xml_read_is_reported_at_the_element_that_writes_it(tmp_path: Path) -> None:
    text = """<launch>
  <node pkg="foo" exec="bar" name="n">
    <param name="frame" value="$(var prefix)base"/>
  </node>
  <node pkg="foo" exec="baz" name="$(var robot)"/>
</launch>
"""
    assert sorted(line for _, line, _, _ in _lint(tmp_path, {"a.launch.xml": text},
                                                   "a.launch.xml")) == [3, 5]
