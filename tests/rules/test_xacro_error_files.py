"""xacro_error for what a launch file's xacro call is given: a file that is provably not
there, and (legacy processing order) an include whose file name needs a property."""

from __future__ import annotations

import time
from pathlib import Path

from _urdf import link, lint_loaded, robot

from launch_linter import LintOptions, lint_paths
from launch_linter.model.diagnostic import Diagnostic

RULE = "xacro_error"
RSP = '<node pkg="robot_state_publisher" type="robot_state_publisher" name="rsp"/>'
PACKAGE_XML = ('<package format="2"><name>{}</name><version>1.0.0</version>'
               '<description>d</description><maintainer email="a@b.c">a</maintainer>'
               '<license>BSD</license><buildtool_depend>catkin</buildtool_depend></package>')


def _launch(folder: Path, command: str, rule: str = RULE, distro: str | None = None,
            roots: tuple[str, ...] = ()) -> tuple[Diagnostic, ...]:
    folder.mkdir(parents=True, exist_ok=True)
    launch = folder / "robot.launch"
    launch.write_text(f'<launch>\n<param name="robot_description" command="{command}"/>\n'
                      f'{RSP}</launch>', encoding="utf-8")
    options = LintOptions(package_paths=roots, select=frozenset({rule}), ros_distro=distro)
    return lint_paths([str(launch)], options).diagnostics


def test_a_xacro_file_missing_beside_the_launch_file(tmp_path: Path) -> None:
    (found,) = _launch(tmp_path, "xacro $(dirname)/robots/robot.urdf.xacro")
    assert found.severity.value == "error" and found.line == 2
    assert "no such file" in found.message and "robot.urdf.xacro" in found.message


def test_a_xacro_file_missing_in_a_ros1_package_found(tmp_path: Path) -> None:
    package = tmp_path / "src" / "demo_description"
    (package / "urdf").mkdir(parents=True)
    (package / "package.xml").write_text(PACKAGE_XML.format("demo_description"))
    (package / "urdf" / "robot.urdf.xacro").write_text(robot(link("a")))
    command = "$(find xacro)/xacro $(find demo_description)/urdf/robt.urdf.xacro"
    (found,) = _launch(package / "launch", command, roots=(str(tmp_path / "src"),))
    assert found.severity.value == "error" and "robt.urdf.xacro" in found.message
    # The file that is there: nothing to say.
    fixed = "$(find xacro)/xacro $(find demo_description)/urdf/robot.urdf.xacro"
    assert _launch(package / "launch", fixed, roots=(str(tmp_path / "src"),)) == ()


def test_a_xacro_file_missing_beside_the_launch_files_folder(tmp_path: Path) -> None:
    # $(dirname)/../urdf/: written relative to the launch file, its folder here.
    (tmp_path / "urdf").mkdir()
    command = "$(dirname)/../scripts/env_run cfg xacro $(dirname)/../urdf/robot.urdf.xacro"
    (found,) = _launch(tmp_path / "launch", command)
    assert found.line == 2 and "urdf/robot.urdf.xacro" in found.message
    # The same file named by an absolute path written out: another machine may have it.
    absolute = f"$(dirname)/env_run cfg xacro {tmp_path}/urdf/robot.urdf.xacro"
    assert _launch(tmp_path / "launch", absolute) == ()


def test_a_file_the_build_may_make_is_not_proven_absent(tmp_path: Path) -> None:
    # xacro_add_files writes robot.urdf from robot.urdf.xacro: a missing .urdf may be made.
    assert _launch(tmp_path, "xacro $(dirname)/robot.urdf") == ()


def test_a_file_outside_the_linted_tree_stays_unknown(tmp_path: Path) -> None:
    command = "xacro $(dirname)/../elsewhere/robot.urdf.xacro"
    assert _launch(tmp_path / "launch", command) == ()
    (unknown,) = _launch(tmp_path / "launch", command, "unresolved")
    assert "may have it" in unknown.message


def test_a_file_that_is_there(tmp_path: Path) -> None:
    (tmp_path / "robot.urdf.xacro").write_text(robot(link("a")))
    assert _launch(tmp_path, "xacro $(dirname)/robot.urdf.xacro") == ()


ARM = robot('<xacro:macro name="arm" params="model"><xacro:include '
            'filename="$(dirname)/${model}.xacro"/><xacro:part/></xacro:macro>'
            '<xacro:arm model="part"/>')
PART = robot('<xacro:macro name="part"><link name="a"/></xacro:macro>')


def _arm(tmp_path: Path, options: str, distro: str | None) -> tuple[Diagnostic, ...]:
    (tmp_path / "robot.urdf.xacro").write_text(ARM, encoding="utf-8")
    (tmp_path / "part.xacro").write_text(PART, encoding="utf-8")
    return _launch(tmp_path, f"xacro {options} $(dirname)/robot.urdf.xacro", distro=distro)


def test_a_variable_include_in_the_legacy_order(tmp_path: Path) -> None:
    (found,) = _arm(tmp_path, "", "kinetic")
    assert found.severity.value == "error" and found.path.endswith("robot.urdf.xacro")
    assert found.line == 2 and "--inorder" in found.message and "'model'" in found.message
    (legacy,) = _arm(tmp_path, "--legacy", "melodic")
    assert legacy.line == 2


def test_in_order_processing_reads_the_variable_include(tmp_path: Path) -> None:
    assert _arm(tmp_path, "--inorder", "kinetic") == ()
    assert _arm(tmp_path, "-i", "lunar") == ()
    assert _arm(tmp_path, "", "melodic") == ()
    assert _arm(tmp_path, "", "noetic") == ()
    # The distribution not known: its order is not assumed.
    assert _arm(tmp_path, "", None) == ()


def test_the_legacy_order_reads_substitutions_and_xacro_symbols(tmp_path: Path) -> None:
    (tmp_path / "part.xacro").write_text(PART, encoding="utf-8")
    (tmp_path / "robot.urdf.xacro").write_text(robot(
        '<xacro:include filename="$(dirname)/part.xacro"/>'
        '<xacro:include filename="$(dirname)/part${\'\'}.xacro"/><xacro:part/>'))
    assert _launch(tmp_path, "xacro $(dirname)/robot.urdf.xacro", distro="kinetic") == ()


def test_an_undeclared_arg_in_an_elements_text(tmp_path: Path) -> None:
    plugin = ('<gazebo><plugin name="p" filename="libp.so"><robotNamespace>/$(arg namespace)'
              '</robotNamespace></plugin></gazebo>')
    (tmp_path / "robot.urdf.xacro").write_text(robot(link("a") + "\n" + plugin))
    (found,) = _launch(tmp_path, "xacro $(dirname)/robot.urdf.xacro")
    assert found.line == 3 and "$(arg namespace)" in found.message
    (tmp_path / "robot.urdf.xacro").write_text(robot(
        '<xacro:arg name="namespace" default="r"/>' + link("a") + "\n" + plugin))
    assert _launch(tmp_path, "xacro $(dirname)/robot.urdf.xacro") == ()


def test_many_includes_in_the_legacy_order_stay_linear(tmp_path: Path) -> None:
    # 20,000 includes in a macro never called: the legacy order walks every one (with a
    # ${pi} the linter reads) and finds none that stops it; then one more that does.
    includes = "".join(f'<xacro:include filename="p{i}${{pi}}.xacro"/>' for i in range(20_000))
    text = robot('<xacro:macro name="never">' + includes + '</xacro:macro>' + link("a"))
    (tmp_path / "robot.urdf.xacro").write_text(text)
    started = time.perf_counter()
    assert _launch(tmp_path, "xacro $(dirname)/robot.urdf.xacro", distro="kinetic") == ()
    assert time.perf_counter() - started < 30
    (tmp_path / "robot.urdf.xacro").write_text(text.replace(
        "</robot>", '<xacro:include filename="${n}.xacro"/></robot>'))
    (found,) = _launch(tmp_path, "xacro $(dirname)/robot.urdf.xacro", distro="kinetic")
    assert "'n'" in found.message


def test_a_description_file_that_is_not_well_formed(tmp_path: Path) -> None:
    # xacro reads the file with minidom (expat): '--' inside a comment stops it.
    underline = "<!------------->"
    text = robot(link("a")).replace("<link", underline + "\n<link")
    (tmp_path / "robot.urdf.xacro").write_text(text)
    (found,) = _launch(tmp_path, "xacro $(dirname)/robot.urdf.xacro")
    assert found.severity.value == "error" and found.path.endswith("robot.urdf.xacro")
    assert found.line == 2 and "not well-formed" in found.message
    (tmp_path / "robot.urdf.xacro").write_text(text.replace(underline, "<!-- ***** -->"))
    assert _launch(tmp_path, "xacro $(dirname)/robot.urdf.xacro") == ()


def test_an_included_file_that_is_not_well_formed(tmp_path: Path) -> None:
    (tmp_path / "part.xacro").write_text(robot("<link name='b'>"))
    (tmp_path / "robot.urdf.xacro").write_text(robot(
        link("a") + '\n<xacro:include filename="part.xacro"/>'))
    (found,) = _launch(tmp_path, "xacro $(dirname)/robot.urdf.xacro")
    # The included file's own fault, at its own line (where expat stops), as the top file's.
    assert found.path.endswith("part.xacro") and found.line == 2
    assert "not well-formed" in found.message
    # Under a condition the linter cannot decide: xacro may never read it.
    undecided = robot('<xacro:arg name="c" default="true"/>' + link("a") + '\n<xacro:if '
                      'value="$(arg c)"><xacro:include filename="part.xacro"/></xacro:if>')
    (quiet,) = lint_loaded(tmp_path, undecided, RULE, "c:=$(arg b)")
    assert quiet.severity.value == "info" and "when" in quiet.message
    (found,) = lint_loaded(tmp_path, undecided, RULE, "c:=true")
    assert found.severity.value == "error" and "not well-formed" in found.message


def test_a_file_over_the_readers_own_bound_is_not_refused_by_xacro(tmp_path: Path) -> None:
    # The linter's own refusals (a DTD entity here) are not xacro's: unknown, not an error.
    (tmp_path / "robot.urdf.xacro").write_text(
        '<!DOCTYPE robot [<!ENTITY e "x">]>' + robot(link("a")))
    assert _launch(tmp_path, "xacro $(dirname)/robot.urdf.xacro") == ()
    (unknown,) = _launch(tmp_path, "xacro $(dirname)/robot.urdf.xacro", "unresolved")
    assert "entity" in unknown.message


def test_a_missing_file_with_an_empty_arg_after_it(tmp_path: Path) -> None:
    # $(arg extra) gives no word: the file's word is still the one written from $(dirname).
    (tmp_path / "urdf").mkdir()
    launch = tmp_path / "launch"
    launch.mkdir()
    (launch / "robot.launch").write_text(
        '<launch>\n<arg name="extra" default=""/>\n<param name="robot_description" '
        'command="xacro $(dirname)/../urdf/robt.urdf.xacro $(arg extra)"/>\n'
        f'{RSP}</launch>', encoding="utf-8")
    options = LintOptions(package_paths=(), select=frozenset({RULE}))
    (found,) = lint_paths([str(launch / "robot.launch")], options).diagnostics
    assert found.line == 3 and "robt.urdf.xacro" in found.message


def test_an_undeclared_arg_in_any_elements_text(tmp_path: Path) -> None:
    # catvehicle: <updateRate>$(arg updateRate)</updateRate> of a plugin the knowledge base
    # does not read: xacro evaluates every text node all the same (eval_all).
    plugin = ('<gazebo><plugin name="p" filename="libp.so"><updateRate>$(arg rate)'
              '</updateRate></plugin></gazebo>')
    (tmp_path / "robot.urdf.xacro").write_text(robot(link("a") + "\n" + plugin))
    (found,) = _launch(tmp_path, "xacro $(dirname)/robot.urdf.xacro")
    assert found.line == 3 and "$(arg rate)" in found.message
    assert _launch(tmp_path, "xacro $(dirname)/robot.urdf.xacro rate:=20") == ()
    # A CDATA section is left as written: xacro evaluates text nodes only.
    (tmp_path / "robot.urdf.xacro").write_text(robot(link("a") + "\n" + plugin.replace(
        "$(arg rate)", "<![CDATA[$(arg rate)]]>")))
    assert _launch(tmp_path, "xacro $(dirname)/robot.urdf.xacro") == ()


def test_twenty_thousand_texts_are_read_in_linear_time(tmp_path: Path) -> None:
    texts = "".join(f"<k{i % 7}>v ${{pi}} {i}</k{i % 7}>" for i in range(20_000))
    (tmp_path / "robot.urdf.xacro").write_text(robot(link("a") + f"<gazebo>{texts}</gazebo>"))
    started = time.perf_counter()
    assert _launch(tmp_path, "xacro $(dirname)/robot.urdf.xacro") == ()
    assert time.perf_counter() - started < 30


def test_a_description_read_as_text_is_not_xacros_to_refuse(tmp_path: Path) -> None:
    # textfile= (or cat, or a Python launch file's open().read()): robot_state_publisher's
    # urdfdom parses it, not xacro's minidom; it takes a space before the declaration.
    (tmp_path / "robot.urdf").write_text(' <?xml version="1.0"?>\n' + robot(link("a")))
    (tmp_path / "robot.launch").write_text(
        '<launch><param name="robot_description" textfile="$(dirname)/robot.urdf"/>'
        f'{RSP}</launch>', encoding="utf-8")
    options = LintOptions(package_paths=(), select=frozenset({RULE, "unresolved"}))
    (unknown,) = lint_paths([str(tmp_path / "robot.launch")], options).diagnostics
    assert unknown.rule == "unresolved" and "not well-formed" in unknown.message
    # The same file run through xacro: minidom stops on it.
    (found,) = _launch(tmp_path, "xacro $(dirname)/robot.urdf")
    assert found.severity.value == "error" and "declaration" in found.message


def test_a_malformed_include_after_one_not_followed_is_still_proven(tmp_path: Path) -> None:
    # What was not followed before may define names, never make this file well-formed.
    (tmp_path / "part.xacro").write_text(robot("<link name='b'>"))
    (tmp_path / "robot.urdf.xacro").write_text(robot(
        '<xacro:include filename="$(find nowhere)/x.xacro"/>' + link("a")
        + '\n<xacro:include filename="part.xacro"/>'))
    (found,) = _launch(tmp_path, "xacro $(dirname)/robot.urdf.xacro")
    assert found.severity.value == "error" and found.path.endswith("part.xacro")
    assert "not well-formed" in found.message


def test_a_malformed_include_is_placed_at_the_element_left_open(tmp_path: Path) -> None:
    # abb_common's irb_6640_macro.xacro: '<parent link="...">' never closed; expat stops
    # at '</joint>' two lines on. No includer can complete a file that is not well-formed:
    # an error at the open tag even when the including .xacro is linted on its own.
    joint = ('<xacro:macro name="arm" params="prefix">\n<joint name="j" type="fixed">\n'
             '<parent link="a">\n<origin xyz="0 0 0"/>\n</joint>\n</xacro:macro>')
    (tmp_path / "arm_macro.xacro").write_text(robot(joint))
    (tmp_path / "arm.xacro").write_text(robot(
        link("a") + '\n<xacro:include filename="arm_macro.xacro"/>\n<xacro:arm prefix=""/>'))
    options = LintOptions(package_paths=(), select=frozenset({RULE}))
    found = [d for d in lint_paths([str(tmp_path / "arm.xacro")], options).diagnostics
             if d.path.endswith("arm_macro.xacro")]
    assert [(d.line, d.severity.value) for d in found] == [(4, "error")]
    assert "'<parent>' is never closed" in found[0].message
    (tmp_path / "arm_macro.xacro").write_text(robot(joint.replace('"a">', '"a"/>')))
    assert lint_paths([str(tmp_path / "arm.xacro")], options).diagnostics == ()
