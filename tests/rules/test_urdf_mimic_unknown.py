from __future__ import annotations

import time
from pathlib import Path

from _urdf import XACRO, joint, link, lint_loaded, lint_urdf, robot

from launch_linter import LintOptions, lint_paths

RULE = "urdf_mimic_unknown"
LIMIT = '<limit lower="0" upper="1" effort="1" velocity="1"/>'


def mimic_joint(name: str, parent: str, child: str, mimics: str) -> str:
    return (f'<joint name="{name}" type="revolute"><parent link="{parent}"/>'
            f'<child link="{child}"/>{LIMIT}\n<mimic joint="{mimics}" multiplier="-1"/></joint>')


def gripper(mimics: str) -> str:
    return robot(link("palm") + link("left") + link("right")
                 + joint("gripper_joint", "palm", "left", "revolute").replace(
                     "</joint>", LIMIT + "</joint>")
                 + "\n" + mimic_joint("right_joint", "palm", "right", mimics))


def test_a_mimic_of_a_joint_the_description_lacks() -> None:
    """rg2_simulation#2: the finger joints mimic 'gripper'; the joint is gripper_joint."""
    (found,) = lint_urdf(gripper("gripper"), RULE)
    assert found.line == 4 and found.node == "right_joint"
    assert "'gripper'" in found.message and "'gripper_joint'" in found.message
    # A file linted on its own: its users may give other args, so a warning.
    assert found.severity.value == "warning"
    assert lint_urdf(gripper("gripper_joint"), RULE) == ()


def test_a_joint_without_mimic_or_a_mimic_of_any_joint_is_fine() -> None:
    assert lint_urdf(robot(link("a") + link("b") + joint("j", "a", "b")), RULE) == ()
    # A mimic of a fixed joint names a joint that exists: not this rule's finding.
    text = robot(link("a") + link("b") + link("c") + joint("f", "a", "b")
                 + mimic_joint("m", "a", "c", "f"))
    assert lint_urdf(text, RULE) == ()


def test_an_error_where_joint_state_publisher_runs_on_it(tmp_path: Path) -> None:
    text = gripper("gripper")
    (alone,) = lint_loaded(tmp_path, text, RULE)
    assert alone.severity.value == "warning"
    launch = tmp_path / "robot.launch"
    launch.write_text(launch.read_text(encoding="utf-8").replace(
        "</launch>", '<node pkg="joint_state_publisher" type="joint_state_publisher" '
                     'name="jsp"/></launch>'), encoding="utf-8")
    options = LintOptions(package_paths=(), select=frozenset({RULE}))
    (found,) = lint_paths([str(launch)], options).diagnostics
    assert found.severity.value == "error"


def test_a_prefixed_macro_is_reported_once_where_its_mimic_is_written() -> None:
    """robotiq#115: the macro names its joints ${prefix}... but mimics 'finger_joint'."""
    macro = ('<xacro:macro name="hand" params="prefix">'
             + link("${prefix}palm") + link("${prefix}a") + link("${prefix}b")
             + joint("${prefix}finger_joint", "${prefix}palm", "${prefix}a", "revolute")
             .replace("</joint>", LIMIT + "</joint>")
             + "\n" + mimic_joint("${prefix}knuckle", "${prefix}palm", "${prefix}b",
                                  "finger_joint")
             + "</xacro:macro>\n")
    text = robot(link("base") + macro + '<xacro:hand prefix="l_"/>\n<xacro:hand prefix="r_"/>'
                 + joint("bl", "base", "l_palm") + joint("br", "base", "r_palm"))
    (found,) = lint_urdf(text, RULE)
    assert found.line == 4 and found.related[0].line == 5  # the mimic; the first call
    # With no prefix the name is right: nothing to say.
    plain = text.replace('prefix="l_"/>\n<xacro:hand prefix="r_"/>', 'prefix=""/>').replace(
        joint("bl", "base", "l_palm") + joint("br", "base", "r_palm"), joint("b", "base", "palm"))
    assert lint_urdf(plain, RULE) == ()


def test_an_undecided_condition_or_an_unknown_name_is_not_judged() -> None:
    body = (link("palm") + link("left") + link("right")
            + '<xacro:arg name="with_gripper" default="true"/>'
            + '<xacro:if value="$(arg with_gripper)">'
            + joint("gripper_joint", "palm", "left", "revolute").replace(
                "</joint>", LIMIT + "</joint>")
            + "</xacro:if>\n" + mimic_joint("right_joint", "palm", "right", "gripper_joint"))
    # The mimicked joint exists under a condition: it may be defined.
    assert lint_urdf(robot(body), RULE) == ()
    # A name read from the environment is not known: the mimic is not judged.
    unknown = robot(link("palm") + link("right")
                    + mimic_joint("right_joint", "palm", "right", "$(env GRIPPER_JOINT)"))
    assert lint_urdf(unknown, RULE) == ()


def test_twenty_thousand_mimics_are_judged_in_linear_time(tmp_path: Path) -> None:
    """Every mimic is looked up in a set of the joint names: a pass over the joints per
    mimic took minutes at this size."""
    count = 20_000
    links = "".join(f'<link name="l{i}"/>' for i in range(count + 1))
    joints = "".join(mimic_joint(f"j{i}", f"l{i}", f"l{i + 1}", f"j{(i + 1) % count}")
                     for i in range(count))
    path = tmp_path / "huge.urdf"
    path.write_text(f'<robot name="huge" {XACRO}>{links}{joints}'
                    f'{mimic_joint("bad", "l0", "x", "nowhere")}<link name="x"/></robot>',
                    encoding="utf-8")
    started = time.process_time()
    found = lint_paths([str(path)], LintOptions(package_paths=(),
                                                select=frozenset({RULE}))).diagnostics
    assert time.process_time() - started < 60
    assert [d.node for d in found] == ["bad"]
