"""A guard clause (``if <unknown>: ... return X``) in a launch function returns X only under
its condition; Python runs the rest of the function otherwise (realsense-ros#2541's
view_model.launch.py returns an empty description when its model argument is missing)."""

from __future__ import annotations

import time

from ros2_helpers import Load

from launch_linter.frontends.ros2_python.evaluator import MAX_GUARD_CLAUSES

HEADER = """\
import sys

from launch import LaunchDescription
from launch.actions import OpaqueFunction
from launch_ros.actions import Node


def tf(child):
    return Node(package='tf2_ros', executable='static_transform_publisher',
                arguments=['--frame-id', 'base_link', '--child-frame-id', child])


"""


def _children(load: Load, body: str) -> list[tuple[str | None, tuple[tuple[str, bool], ...]]]:
    tree = load({"a.launch.py": HEADER + body}, "a.launch.py")
    return [(t.child, tuple((lit.text, lit.positive) for lit in t.condition.literals))
            for t in tree.transforms]


UNKNOWN = "python: len(sys.argv) > 3"


def test_the_rest_of_the_function_runs_when_the_guard_is_false(load: Load) -> None:
    found = _children(load, """def generate_launch_description():
    if len(sys.argv) > 3:
        print('usage')
        return LaunchDescription()
    return LaunchDescription([tf('laser')])
""")
    assert found == [("laser", ((UNKNOWN, False),))]


def test_both_sides_are_kept_each_under_its_condition(load: Load) -> None:
    found = _children(load, """def generate_launch_description():
    child = 'imu'
    if len(sys.argv) > 3:
        child = 'camera'
        return LaunchDescription([tf(child)])
    return LaunchDescription([tf(child)])
""")
    assert found == [("camera", ((UNKNOWN, True),)), ("imu", ((UNKNOWN, False),))]


def test_a_known_test_runs_as_python_does(load: Load) -> None:
    found = _children(load, """def generate_launch_description():
    if 1 > 0:
        return LaunchDescription([tf('first')])
    return LaunchDescription([tf('second')])
""")
    assert found == [("first", ())]
    assert _children(load, """def generate_launch_description():
    if 1 < 0:
        return LaunchDescription([tf('first')])
    return LaunchDescription([tf('second')])
""") == [("second", ())]


def test_an_opaque_function_returning_nothing_under_the_guard(load: Load) -> None:
    found = _children(load, """def setup(context):
    if len(sys.argv) > 3:
        return
    return [tf('laser')]


def generate_launch_description():
    return LaunchDescription([OpaqueFunction(function=setup)])
""")
    assert found == [("laser", ((UNKNOWN, False),))]


def test_a_value_that_is_not_launch_actions_is_unknown(load: Load) -> None:
    tree = load({"a.launch.py": HEADER + """def generate_launch_description():
    if len(sys.argv) > 3:
        return 'not a description'
    return LaunchDescription([tf('laser')])
"""}, "a.launch.py")
    assert tree.transforms == ()
    assert any("returned under the condition 'len(sys.argv) > 3'" in p.message
               for p in tree.problems)


def test_20000_guard_clauses_are_bounded(load: Load) -> None:
    # Hostile: an action after the n-th guard clause is under n conditions.
    guards = "".join(f"    if len(sys.argv) > {i}:\n        return LaunchDescription()\n"
                     for i in range(20_000))
    start = time.process_time()
    tree = load({"a.launch.py": HEADER + "def generate_launch_description():\n" + guards
                 + "    return LaunchDescription([tf('laser')])\n"}, "a.launch.py")
    assert time.process_time() - start < 20
    assert tree.transforms == ()
    assert any("stopped interpreting" in p.message for p in tree.problems)
    assert MAX_GUARD_CLAUSES < 20_000


def test_the_same_text_on_both_sides_is_that_text(load: Load) -> None:
    found = _children(load, """def child():
    if len(sys.argv) > 3:
        return 'laser'
    return 'laser'


def generate_launch_description():
    return LaunchDescription([tf(child())])
""")
    assert found == [("laser", ())]
