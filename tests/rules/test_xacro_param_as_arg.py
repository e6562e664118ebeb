from __future__ import annotations

import time
from pathlib import Path

from _urdf import link, lint_loaded, lint_urdf, robot
from hypothesis import given, settings
from hypothesis import strategies as st

from launch_linter.frontends.robot.xacro_macros import params_read_as_args

RULE = "xacro_param_as_arg"


def camera(use: str, params: str = "name parent") -> str:
    return (f'<xacro:macro name="camera" params="{params}">\n'
            '<link name="${name}_link"/>\n'
            '<joint name="${name}_joint" type="fixed">\n'
            f'<parent link="{use}"/>\n'
            '<child link="${name}_link"/>\n'
            '</joint>\n'
            '</xacro:macro>\n')


CALL = link("base_link") + '<xacro:camera name="front" parent="base_link"/>'


def test_a_parameter_read_as_an_arg_is_a_warning_at_its_line() -> None:
    (found,) = lint_urdf(robot(camera("$(arg parent)") + CALL), RULE)
    assert found.severity.value == "warning" and found.line == 5
    assert "macro 'camera'" in found.message and "${parent}" in found.message


def test_read_with_the_parameter_or_an_arg_that_is_no_parameter_it_is_silent() -> None:
    assert lint_urdf(robot(camera("${parent}") + CALL), RULE) == ()
    declared = '<xacro:arg name="base" default="base_link"/>'
    assert lint_urdf(robot(declared + camera("$(arg base)") + CALL), RULE) == ()
    # A property named like an arg, at the top or in the body, is no parameter.
    named = ('<xacro:arg name="base" default="base_link"/>'
             '<xacro:property name="base" value="$(arg base)"/>')
    assert lint_urdf(robot(named + camera("$(arg base)") + CALL), RULE) == ()
    inner = camera("$(arg base)").replace(
        '<link name="${name}_link"/>', '<xacro:property name="base" value="b"/>')
    assert lint_urdf(robot(declared + inner + CALL), RULE) == ()


def test_judged_true_one_call_given_the_parameter_and_another_the_arg() -> None:
    """zitongbai/ur_project_ros2's ur_robotiq_rs macro (xacro_param_as_arg_judged.jsonl):
    the arm gets ${sim_gazebo}, the gripper $(arg sim_gazebo)."""
    macro = ('<xacro:arg name="sim_gazebo" default="true"/>\n'
             '<xacro:macro name="part" params="sim_gazebo"><link name="p${sim_gazebo}"/>'
             '</xacro:macro>\n'
             '<xacro:macro name="arm_and_gripper" params="sim_gazebo:=false">\n'
             '<xacro:part sim_gazebo="${sim_gazebo}"/>\n'
             '<xacro:part\n sim_gazebo="$(arg sim_gazebo)"/>\n'
             '</xacro:macro>\n'
             '<xacro:arm_and_gripper sim_gazebo="$(arg sim_gazebo)"/>')
    (found,) = lint_urdf(robot(macro), RULE)
    assert found.line == 7 and found.severity.value == "warning"


def test_an_arg_of_that_name_declared_still_leaves_the_parameter_ignored() -> None:
    declared = '<xacro:arg name="parent" default="base_link"/>'
    (found,) = lint_urdf(robot(declared + camera("$(arg parent)") + CALL), RULE)
    assert found.severity.value == "warning"


def test_an_arg_the_body_declares_from_the_parameter_is_still_the_first_calls() -> None:
    macro = ('<xacro:macro name="m" params="side">\n<xacro:arg name="side" default="${side}"/>\n'
             '<link name="$(arg side)_wheel"/>\n</xacro:macro>\n'
             '<xacro:m side="left"/><xacro:m side="right"/>')
    (found,) = lint_urdf(robot(macro), RULE)
    assert found.line == 4
    # xacro would make left_wheel twice: the second call's 'right' is ignored.
    (twice,) = lint_urdf(robot(macro), "urdf_duplicate_name")
    assert "left_wheel" in twice.message


def test_every_default_form_counts_and_block_parameters_do_not() -> None:
    for params in ("name parent:=base_link", "name parent:=^", "name parent:=^|base_link",
                   "name parent:='base_link'", "name parent=base_link"):
        (found,) = lint_urdf(robot(camera("$(arg parent)", params) + CALL), RULE)
        assert found.line == 5, params
    blocks = ('<xacro:macro name="m" params="*origin"><link name="$(arg origin)"/>'
              '<xacro:insert_block name="origin"/></xacro:macro>')
    assert lint_urdf(robot('<xacro:arg name="origin" default="a"/>' + blocks), RULE) == ()


def test_a_macro_never_called_and_a_text_and_an_escape() -> None:
    macro = ('<xacro:macro name="plugin" params="ns">\n<gazebo>\n<plugin name="p" '
             'filename="x.so">\n<topicName>\n$(arg ns)/scan</topicName>\n'
             '<frameName>$$(arg ns)</frameName>\n</plugin>\n</gazebo>\n</xacro:macro>')
    (found,) = lint_urdf(robot(link("a") + macro), RULE)
    assert found.line == 6  # the text's line, not its element's


def test_inside_an_expression_and_an_arg_named_by_an_expression() -> None:
    macro = ('<xacro:macro name="m" params="gazebo name">\n'
             '<xacro:if value="${\'$(arg gazebo)\' == \'true\'}"><link name="g"/></xacro:if>\n'
             '<link name="$(arg ${name}_frame)"/>\n</xacro:macro>')
    (found,) = lint_urdf(robot(link("a") + macro), RULE)
    assert found.line == 3 and "$(arg gazebo)" in found.message


def test_an_unprefixed_macro_of_a_legacy_xacro() -> None:
    text = robot('<macro name="m" params="side">\n<link name="$(arg side)"/>\n</macro>')
    assert params_read_as_args(text.encode(), False) == {}
    (uses,) = params_read_as_args(text.encode(), True).values()
    assert [(use.macro, use.name, use.line) for use in uses] == [("m", "side", 3)]


def test_an_attribute_on_a_later_line_of_its_element() -> None:
    call = ('<xacro:macro name="m" params="a b">\n<xacro:other\n x="${a}"\n'
            ' y="$(arg b)"/>\n</xacro:macro>')
    (found,) = lint_urdf(robot(link("a") + call), RULE)
    assert found.line == 5


def test_nested_macros_see_the_outer_parameters() -> None:
    nested = ('<xacro:macro name="outer" params="prefix">\n'
              '<xacro:macro name="inner" params="side">\n'
              '<link name="$(arg prefix)_$(arg side)"/>\n'
              '</xacro:macro>\n'
              '<xacro:inner side="l"/>\n'
              '</xacro:macro>\n')
    inner, outer = sorted(lint_urdf(robot(nested), RULE), key=lambda d: d.message)
    assert outer.line == inner.line == 4
    assert "macro 'outer'" in outer.message and "$(arg prefix)" in outer.message
    assert "macro 'inner'" in inner.message and "$(arg side)" in inner.message
    # Outside the macros the same names are no parameters.
    assert lint_urdf(robot('<xacro:arg name="prefix" default="p"/>'
                           '<link name="$(arg prefix)"/>'), RULE) == ()


def test_a_default_of_the_outermost_macro_is_read_where_it_is_called() -> None:
    macro = ('<xacro:arg name="prefix" default="p"/>'
             '<xacro:macro name="m" params="prefix:=$(arg prefix)">'
             '<link name="${prefix}_l"/></xacro:macro><xacro:m/>')
    assert lint_urdf(robot(macro), RULE) == ()


def test_a_macro_of_an_included_file(tmp_path: Path) -> None:
    (tmp_path / "camera.xacro").write_text(robot(camera("$(arg parent)")), encoding="utf-8")
    (tmp_path / "robot.urdf.xacro").write_text(
        robot('<xacro:include filename="camera.xacro"/>' + CALL), encoding="utf-8")
    from launch_linter import LintOptions, lint_paths

    options = LintOptions(package_paths=(), select=frozenset({RULE}))
    (found,) = lint_paths([str(tmp_path / "robot.urdf.xacro")], options).diagnostics
    assert found.path.endswith("camera.xacro") and found.line == 5


def test_an_error_where_xacro_provably_stops(tmp_path: Path) -> None:
    text = robot(camera("$(arg parent)") + CALL)
    (found,) = lint_loaded(tmp_path, text, RULE)
    assert found.severity.value == "error" and found.line == 5
    # xacro_error leaves that refusal to this rule: one finding.
    assert lint_loaded(tmp_path, text, "xacro_error") == ()
    # Given by the xacro call, or not called: the parameter is ignored, xacro goes on.
    assert lint_loaded(tmp_path, text, RULE, "parent:=x")[0].severity.value == "warning"
    uncalled = robot(camera("$(arg parent)") + link("base_link"))
    assert lint_loaded(tmp_path, uncalled, RULE)[0].severity.value == "warning"


def test_under_an_undecided_branch_it_stays_a_warning(tmp_path: Path) -> None:
    text = robot('<xacro:arg name="cam" default="true"/>' + camera("$(arg parent)")
                 + link("base_link") + '<xacro:if value="$(arg cam)">'
                 '<xacro:camera name="front" parent="base_link"/></xacro:if>')
    (found,) = lint_loaded(tmp_path, text, RULE, "cam:=$(arg y)")
    assert found.severity.value == "warning"
    (found,) = lint_loaded(tmp_path, text, RULE, "cam:=true")
    assert found.severity.value == "error"


def test_many_macros_and_parameters_stay_linear() -> None:
    """20,000 macros of 20,000 parameters in all, each read as an arg, and one macro of
    20,000 parameters read in one element: the scan stays linear (bounded by MAX_USES)."""
    count = 20_000
    macros = "".join(f'<xacro:macro name="m{i}" params="p{i}"><link name="$(arg p{i})"/>'
                     f'</xacro:macro>' for i in range(count))
    params = " ".join(f"q{i}" for i in range(count))
    uses = "".join(f' a{i}="$(arg q{i})"' for i in range(count))
    wide = f'<xacro:macro name="w" params="{params}"><xacro:x{uses}/></xacro:macro>'
    started = time.process_time()
    found = lint_urdf(robot(macros + wide), RULE)
    assert time.process_time() - started < 30
    assert found
    data = robot(wide).encode()
    started = time.process_time()
    (uses_found,) = params_read_as_args(data, False).values()
    assert time.process_time() - started < 10 and len(uses_found) == 1000
    # 20,000 macros inside one of 20,000 parameters: the outer scope is not copied.
    inner = "".join(f'<xacro:macro name="i{i}" params="r{i}"><link name="$(arg none)"/>'
                    f'</xacro:macro>' for i in range(count))
    nested = robot(f'<xacro:macro name="w" params="{params} none_of_these">{inner}'
                   f'<link name="$(arg q1)"/></xacro:macro>').encode()
    started = time.process_time()
    (uses_found,) = params_read_as_args(nested, False).values()
    assert time.process_time() - started < 10 and [u.name for u in uses_found] == ["q1"]


@settings(max_examples=60, deadline=None, database=None)
@given(names=st.lists(st.from_regex(r"[a-z][a-z0-9_]{0,6}", fullmatch=True), min_size=1,
                      max_size=5, unique=True),
       used=st.lists(st.integers(0, 7), max_size=6), space=st.sampled_from(["", " ", "\n "]))
def test_found_exactly_for_the_parameters_each_at_its_line(
        names: list[str], used: list[int], space: str) -> None:
    """Each ``$(arg X)`` (X a parameter or not) on a line of its own: found when X is a
    parameter, at that line."""
    args = [names[i] if i < len(names) else f"other{i}" for i in used]
    lines = "".join(f'\n<e{k}{space} v="$(arg {name})"/>' for k, name in enumerate(args))
    text = robot(f'<xacro:macro name="m" params="{" ".join(names)}">{lines}\n</xacro:macro>')
    found = params_read_as_args(text.encode(), False)
    uses = [use for group in found.values() for use in group]
    start = 2  # the macro's line
    expected = [(name, start + k + 1 + (k + 1) * space.count("\n"))
                for k, name in enumerate(args) if name in names]
    assert [(use.name, use.line) for use in uses] == expected
