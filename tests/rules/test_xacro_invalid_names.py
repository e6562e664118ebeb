"""xacro_error for names beginning with '__': xacro's safe_eval (ros/xacro 9941961,
1.13.13/1.14.9/2.0.7) refuses an expression whose own names include one."""

from __future__ import annotations

import time
from pathlib import Path

from _urdf import link, robot

from launch_linter import LintOptions, lint_paths
from launch_linter.model.diagnostic import Diagnostic

RULE = "xacro_error"
# Universal_Robots_ROS2_Driver's read_model_data: properties named '__limits' and so on.
LIMITS = ('<xacro:property name="__limits" value="${dict(a=1)}"/>\n'
          '<xacro:property name="lower" value="${__limits[\'a\']}"/>\n'
          '<link name="l${lower}"/>')


def _lint(folder: Path, body: str, distro: str | None = "humble",
          standalone: bool = False) -> tuple[Diagnostic, ...]:
    (folder / "robot.urdf.xacro").write_text(robot(link("a") + "\n" + body), encoding="utf-8")
    (folder / "robot.launch").write_text(
        '<launch><param name="robot_description" command="xacro $(dirname)/robot.urdf.xacro"/>'
        '<node pkg="robot_state_publisher" type="robot_state_publisher" name="rsp"/></launch>',
        encoding="utf-8")
    entry = folder / ("robot.urdf.xacro" if standalone else "robot.launch")
    options = LintOptions(package_paths=(), select=frozenset({RULE}), ros_distro=distro)
    return lint_paths([str(entry)], options).diagnostics


def test_a_property_whose_name_xacro_refuses_to_read_is_placed_at_its_definition(
        tmp_path: Path) -> None:
    (found,) = _lint(tmp_path, LIMITS)
    assert found.severity.value == "error" and found.line == 3
    assert "property '__limits'" in found.message and "invalid name(s)" in found.message
    # The fix: the property renamed.
    assert _lint(tmp_path, LIMITS.replace("__limits", "sec_limits")) == ()


def test_an_old_distribution_and_an_unread_name_are_silent(tmp_path: Path) -> None:
    # Kinetic's xacro (kinetic-devel never had safe_eval) and Eloquent's (its last release
    # predates 2.0.7) evaluate the name; a name never read is never refused.
    assert _lint(tmp_path, LIMITS, distro="kinetic") == ()
    assert _lint(tmp_path, LIMITS, distro="eloquent") == ()
    never_read = '<xacro:property name="__unused" value="1"/>'
    assert _lint(tmp_path, never_read) == ()


def test_an_attribute_with_two_underscores_is_refused_where_it_is_read(
        tmp_path: Path) -> None:
    (found,) = _lint(tmp_path, '<link name="${pi.__class__}"/>')
    assert found.line == 3 and "__class__" in found.message


def test_a_name_only_inside_a_comprehension_is_not_claimed(tmp_path: Path) -> None:
    # Compiled into the comprehension's own code object (before Python 3.12), which
    # xacro's check of co_names does not see: what the target does is not known.
    body = '<link name="l${[__x for __x in [1]][0]}"/>'
    assert _lint(tmp_path, body) == ()


def test_the_description_linted_on_its_own_is_an_error_too(tmp_path: Path) -> None:
    # No includer can make a refused name readable.
    (found,) = _lint(tmp_path, LIMITS, standalone=True)
    assert found.severity.value == "error" and found.line == 3


def test_twenty_thousand_reads_and_names_are_said_once_in_linear_time(
        tmp_path: Path) -> None:
    reads = "".join(f'<link name="l{i}_${{__limits[\'a\']}}"/>' for i in range(20_000))
    names = '<link name="${[' + ", ".join(["__limits"] * 20_000) + '][0]}"/>'
    started = time.perf_counter()
    found = _lint(tmp_path, LIMITS + reads + names)
    assert [d.line for d in found] == [3] and time.perf_counter() - started < 60
