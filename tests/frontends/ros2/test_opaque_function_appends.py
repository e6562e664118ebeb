"""OpaqueFunction(function=f, args=[ld]): what f appends to the LaunchDescription it is
given runs after it (launch's visit of a description iterates the list f appends to);
spot_ros2's launch_setup(context, ld) adds its nodes with ld.add_action and returns
None."""

from __future__ import annotations

import time

from launch_linter.engine import lint_text

APPENDS = """from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, OpaqueFunction
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def launch_setup(context, ld):
    frame = LaunchConfiguration('frame').perform(context)
    {body}


def generate_launch_description():
    ld = LaunchDescription([DeclareLaunchArgument('frame', default_value='base_link')])
    ld.add_action(OpaqueFunction(function=launch_setup, args=[{given}]))
    return ld
"""
TF = ("Node(package='tf2_ros', executable='static_transform_publisher', "
      "arguments=['--frame-id', frame, '--child-frame-id', {child}])")


def transforms(body: str, given: str = "ld") -> list[tuple[str, str]]:
    result = lint_text(APPENDS.format(body=body, given=given), "a_launch.py")
    return [(t.parent, t.child) for t in result.transforms]


def test_actions_appended_to_the_given_description_are_followed() -> None:
    body = "ld.add_action(" + TF.format(child="'laser'") + ")"
    assert transforms(body) == [("base_link", "laser")]


def test_a_description_the_function_builds_itself_is_not_run() -> None:
    body = ("other = LaunchDescription()\n    other.add_action("
            + TF.format(child="'laser'") + ")")
    assert transforms(body) == []


def test_what_was_in_the_description_before_is_not_run_twice() -> None:
    body = "ld.add_action(" + TF.format(child="'laser'") + ")"
    imu = ("    ld.add_action(Node(package='tf2_ros', executable='static_transform_publisher',"
           " arguments=['--frame-id', 'base_link', '--child-frame-id', 'imu']))\n")
    text = APPENDS.format(body=body, given="ld").replace(
        "    ld.add_action(OpaqueFunction", imu + "    ld.add_action(OpaqueFunction")
    result = lint_text(text, "b_launch.py")
    assert sorted((t.parent, t.child) for t in result.transforms) == [
        ("base_link", "imu"), ("base_link", "laser")]


def test_twenty_thousand_appended_actions() -> None:
    body = ("for i in range(20000):\n        ld.add_action("
            + TF.format(child="'laser' + str(i)") + ")")
    started = time.process_time()
    found = transforms(body)
    assert time.process_time() - started < 60
    assert len(found) <= 20_000
