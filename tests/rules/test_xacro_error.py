from __future__ import annotations

import time
from pathlib import Path

from _urdf import link, lint_loaded, lint_urdf, robot

from launch_linter import LintOptions, lint_text

RULE = "xacro_error"


WHEEL = '<xacro:macro name="wheel" params="side *origin"><link name="${side}"/>' \
        '<xacro:insert_block name="origin"/></xacro:macro>'


def test_an_undefined_macro(tmp_path: Path) -> None:
    (found,) = lint_loaded(tmp_path, robot(link("a") + "\n<xacro:wheeel/>"), RULE)
    assert found.severity.value == "error" and found.line == 3
    assert "unknown macro 'wheeel'" in found.message


def test_in_a_file_linted_on_its_own_it_is_info() -> None:
    (found,) = lint_urdf(robot(link("a") + "\n<xacro:wheeel/>"), RULE)
    assert found.severity.value == "info" and "xacro stops here" in found.message


def test_a_missing_parameter(tmp_path: Path) -> None:
    (found,) = lint_loaded(tmp_path, robot(WHEEL + '<xacro:wheel><origin/></xacro:wheel>'),
                           RULE)
    assert "undefined parameters [side]" in found.message and found.severity.value == "error"


def test_quoted_defaults_are_read_as_xacro_reads_them(tmp_path: Path) -> None:
    macro = ('<xacro:macro name="m" params="name xyz:=\'0 0 0\'"><link name="${name}"/>'
             '</xacro:macro>')
    assert lint_urdf(robot(macro + '<xacro:m name="a"/>'), RULE) == ()
    (found,) = lint_loaded(tmp_path, robot(macro + '<xacro:m xyz="1 0 0"/>'), RULE)
    assert "undefined parameters [name]" in found.message


def test_a_missing_block(tmp_path: Path) -> None:
    (found,) = lint_loaded(tmp_path, robot(WHEEL + '<xacro:wheel side="l"/>'), RULE)
    assert "not enough blocks" in found.message


def test_an_undeclared_arg(tmp_path: Path) -> None:
    (found,) = lint_loaded(tmp_path, robot('<link name="$(arg name)"/>'), RULE)
    assert "$(arg name)" in found.message and found.severity.value == "error"


def test_an_arg_the_call_gives_or_declares() -> None:
    assert lint_urdf(robot('<link name="$(arg name)"/>'), RULE, args={"name": "a"}) == ()
    assert lint_urdf(robot('<xacro:arg name="name" default="a"/><link name="$(arg name)"/>'),
                     RULE) == ()


def test_a_correct_call() -> None:
    assert lint_urdf(robot(WHEEL + '<xacro:wheel side="l"><origin/></xacro:wheel>'), RULE) == ()


def test_after_an_include_not_read_nothing_is_proven() -> None:
    text = robot('<xacro:include filename="$(find nowhere)/m.xacro"/><xacro:wheel/>')
    assert lint_urdf(text, RULE) == ()
    # The include not read is the cause; the macro it may define is not another one.
    (include,) = lint_urdf(text, "unresolved")
    assert "$(find nowhere)" in include.message


def test_unresolved_words_of_the_xacro_call_may_give_the_arg(tmp_path: Path) -> None:
    text = robot('<link name="$(arg name)"/>')
    (found,) = lint_loaded(tmp_path, text, RULE)
    assert found.severity.value == "error"
    assert "robot_state_publisher publishes nothing" in found.message
    assert lint_loaded(tmp_path, text, RULE, "$(arg more)") == ()


def test_under_an_undecided_condition_it_is_info(tmp_path: Path) -> None:
    text = robot('<xacro:arg name="x" default="true"/><xacro:if value="$(arg x)">'
                 '<xacro:nothing/></xacro:if>')
    (found,) = lint_loaded(tmp_path, text, RULE, "x:=$(arg y)")
    assert found.severity.value == "info"
    (found,) = lint_loaded(tmp_path, text, RULE, "x:=true")
    assert found.severity.value == "error"


def test_a_description_only_a_spawner_reads_is_expanded_for_refusals(tmp_path: Path) -> None:
    # roslaunch runs the xacro command when it loads the file, publisher or not.
    (found,) = lint_loaded(tmp_path, robot(link("a") + "\n<xacro:wheeel/>"), RULE,
                           publisher=False)
    assert found.severity.value == "error" and found.line == 3
    assert "the launch stops before any node starts" in found.message


def test_without_a_publisher_a_correct_description_says_nothing(tmp_path: Path) -> None:
    text = robot(WHEEL + '<xacro:wheel side="l"><origin/></xacro:wheel>' + link("x"))
    assert lint_loaded(tmp_path, text, RULE, publisher=False) == ()
    # Nor do the structure rules: nothing publishes the description.
    assert lint_loaded(tmp_path, robot(link("a") + link("b")), "urdf_root",
                       publisher=False) == ()


def test_a_macro_parameter_is_evaluated_at_the_call(tmp_path: Path) -> None:
    # xacro evaluates a call's parameters at once (eval_text in handle_macro_call): an
    # undeclared arg there stops it, whether or not the body uses the parameter.
    macro = '<xacro:macro name="m" params="name"><link name="x"/></xacro:macro>'
    (found,) = lint_loaded(tmp_path, robot(macro + '\n<xacro:m name="$(arg nope)"/>'), RULE)
    assert found.line == 3 and "$(arg nope)" in found.message
    declared = '<xacro:arg name="nope" default="a"/>'
    assert lint_loaded(tmp_path, robot(declared + macro + '<xacro:m name="$(arg nope)"/>'),
                       RULE) == ()


def test_a_property_name_that_is_no_python_identifier(tmp_path: Path) -> None:
    # xacro's is_valid_name refuses '' and keywords; a plain name is fine.
    (found,) = lint_loaded(tmp_path, robot(link("a") + '\n<xacro:property name="" value="1"/>'),
                           RULE)
    assert found.severity.value == "error" and found.line == 3
    assert "property names must be valid Python identifiers: ''" in found.message
    assert lint_loaded(tmp_path, robot(link("a") + '<xacro:property name="gap" value="1"/>'),
                       RULE) == ()


def test_a_name_no_property_defines(tmp_path: Path) -> None:
    # depthai-ros #96: properties set only under a false xacro:if, read unconditionally.
    text = robot('<xacro:if value="${1 == 2}"><xacro:property name="imu_x" value="1"/>'
                 '</xacro:if><link name="imu${imu_x}"/>')
    (found,) = lint_loaded(tmp_path, text, RULE)
    assert found.severity.value == "error" and "name 'imu_x' is not defined" in found.message
    # xacro is in order: a property defined after its use is not defined at the use.
    assert lint_loaded(tmp_path, robot('<link name="l${x}"/><xacro:property name="x" '
                                       'value="1"/>'), RULE) != ()


def test_xacro_symbols_and_defined_properties_are_no_refusal() -> None:
    for expression in ("pi", "radians(90)", "math.pi", "python.abs(-1)", "sorted([2, 1])[0]",
                       "xacro.arg('a')", "load_yaml('x.yaml')", "cbrt(8)", "fma(1, 2, 3)"):
        assert lint_urdf(robot(f'<link name="l${{{expression}}}"/>'), RULE) == (), expression
    assert lint_urdf(robot('<xacro:property name="x" value="1"/><link name="l${x}"/>'),
                     RULE) == ()


def test_a_name_that_may_come_from_what_was_not_followed_is_unknown(tmp_path: Path) -> None:
    not_read = robot('<xacro:include filename="$(find nowhere)/p.xacro"/><link name="l${x}"/>')
    assert lint_loaded(tmp_path, not_read, RULE) == ()
    undecided = robot('<xacro:arg name="a" default="true"/><xacro:if value="$(arg a)">'
                      '<xacro:property name="x" value="1"/></xacro:if><link name="l${y}"/>')
    assert lint_loaded(tmp_path, undecided, RULE, "a:=$(arg b)") == ()
    (found,) = lint_loaded(tmp_path, undecided, RULE, "a:=true")
    assert "name 'y' is not defined" in found.message
    # A legacy (pre-Noetic) xacro's symbols are not listed: unknown there.
    options = LintOptions(package_paths=(), select=frozenset({RULE}), ros_distro="kinetic")
    text = robot('<link name="l${x}"/>')
    assert lint_text(text, "robot.urdf.xacro", options).diagnostics == ()
    assert lint_urdf(text, RULE) != ()


def test_unprefixed_tags_may_define_names_for_a_legacy_xacro() -> None:
    # hsr_description, autolabor_pro1: <property>/<macro> without the prefix, read by
    # xacro before Noetic; Noetic's xacro leaves them and stops at the first ${x}.
    text = robot('<property name="x" value="1"/><link name="l${x}"/>')
    assert lint_urdf(text, RULE) == ()
    options = LintOptions(package_paths=(), select=frozenset({RULE}), ros_distro="noetic")
    (found,) = lint_text(text, "robot.urdf.xacro", options).diagnostics
    assert "name 'x' is not defined" in found.message


def test_an_expression_with_an_extra_closing_bracket(tmp_path: Path) -> None:
    """kuka-lwr#47: an inertia macro's ``${mass * (...) / 12)}``; xacro compiles each
    expression it evaluates and stops on the SyntaxError."""
    macro = ('<xacro:macro name="inertia" params="mass">\n'
             '<inertia ixx="${mass * (1 + 2) / 12)}"/></xacro:macro>')
    text = robot('<link name="a"><inertial>' + macro + '<xacro:inertia mass="2"/>'
                 "</inertial></link>")
    (found,) = lint_loaded(tmp_path, text, RULE)
    assert "')' closes no bracket" in found.message and found.severity.value == "error"
    assert found.line == 3  # the <inertia> in the macro
    fixed = text.replace("/ 12)}", "/ 12}")
    assert lint_loaded(tmp_path, fixed, RULE) == ()


def test_an_expression_never_evaluated_is_not_refused(tmp_path: Path) -> None:
    # xacro evaluates a macro's body only when it is called.
    text = robot(link("a") + '<xacro:macro name="m" params=""><link name="${(1}"/>'
                 "</xacro:macro>")
    assert lint_loaded(tmp_path, text, RULE) == ()


def test_a_call_not_matching_a_macro_defined_after_an_include_not_read(tmp_path: Path) -> None:
    """jackal#90: the mount macro's file includes a package not found, then defines the
    macro; a call without its parameter and block is xacro's stop whatever that include
    held (nothing there can redefine a macro defined after it)."""
    unread = '<xacro:include filename="$(find nowhere)/m.xacro"/>\n'
    (found,) = lint_loaded(tmp_path, robot(unread + WHEEL + '\n<xacro:wheel/>'), RULE)
    assert found.line == 4 and found.severity.value == "error"
    assert "not enough blocks" in found.message
    (extra,) = lint_loaded(tmp_path, robot(
        unread + WHEEL + '\n<xacro:wheel side="l" size="2"><origin/></xacro:wheel>'), RULE)
    assert "invalid parameter 'size'" in extra.message
    assert lint_loaded(tmp_path, robot(
        unread + WHEEL + '\n<xacro:wheel side="l"><origin/></xacro:wheel>'), RULE) == ()


def test_a_macro_defined_before_an_include_not_read_may_be_redefined_there(
        tmp_path: Path) -> None:
    # The include may define another 'wheel' macro, with other parameters.
    text = robot(WHEEL + '\n<xacro:include filename="$(find nowhere)/m.xacro"/>\n'
                 '<xacro:wheel/>')
    assert lint_loaded(tmp_path, text, RULE) == ()
    # An arg the include may declare stays unproven too.
    assert lint_loaded(tmp_path, robot(
        '<xacro:include filename="$(find nowhere)/m.xacro"/>\n<link name="$(arg n)"/>'),
        RULE) == ()


def test_twenty_thousand_calls_after_an_include_not_read(tmp_path: Path) -> None:
    """Hostile: each refusal looks back at the problems since its macro's definition, at
    most the 1,000 kept: 20,000 refused calls stay linear."""
    calls = "\n".join(f'<xacro:wheel side="s{i}"/>' for i in range(20_000))
    text = robot('<xacro:include filename="$(find nowhere)/m.xacro"/>\n' + WHEEL + calls)
    started = time.process_time()
    found = lint_loaded(tmp_path, text, RULE)
    assert time.process_time() - started < 60
    assert found and all("not enough blocks" in d.message for d in found)
