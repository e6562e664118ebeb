"""Launch classes called as Python refuses them while launch loads the file."""

from __future__ import annotations

import time

from ros2_helpers import Load, rules

HEADER = """\
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, EmitEvent, RegisterEventHandler
from launch.event_handlers import OnProcessExit
from launch.substitutions import LaunchConfiguration, PathJoinSubstitution
from launch_ros.actions import Node
from launch_ros.substitutions import FindPackageShare

def generate_launch_description():
"""
FIRST = HEADER.count("\n") + 1


def node(parameters: str) -> str:
    return (f"    return LaunchDescription([Node(package='p', executable='e', "
            f"parameters=[{parameters}])])\n")


def test_path_join_given_its_parts_as_arguments_is_refused(load: Load) -> None:
    # launch/substitutions/path_join_substitution.py: __init__(self, substitutions): one list.
    tree = load({"a.launch.py": HEADER + node(
        "PathJoinSubstitution(FindPackageShare('p'), 'config', 'params.yaml')")}, "a.launch.py")
    assert rules(tree) == [("roslaunch_error", FIRST)]
    assert "3 were given" in tree.problems[0].message


def test_path_join_given_one_list_is_taken(load: Load) -> None:
    tree = load({"a.launch.py": HEADER + node(
        "PathJoinSubstitution([FindPackageShare('p'), 'config', 'params.yaml'])")}, "a.launch.py")
    assert rules(tree) == []


def test_a_keyword_only_default_given_positionally_is_refused(load: Load) -> None:
    # LaunchConfiguration(variable_name, *, default=None); DeclareLaunchArgument(name, *, ...).
    tree = load({"a.launch.py": HEADER
                 + "    x = LaunchConfiguration('x', 'fallback')\n"
                 + "    return LaunchDescription([DeclareLaunchArgument('x', default_value='1'),"
                 + " DeclareLaunchArgument('y', '2')])\n"}, "a.launch.py")
    assert rules(tree) == [("roslaunch_error", FIRST), ("roslaunch_error", FIRST + 1)]


def test_a_class_of_the_same_name_from_elsewhere_is_not_judged(load: Load) -> None:
    tree = load({"a.launch.py": HEADER.replace(
        "from launch.substitutions import LaunchConfiguration, PathJoinSubstitution",
        "from launch.substitutions import LaunchConfiguration\n"
        "from my_tools import PathJoinSubstitution") + node(
        "PathJoinSubstitution('a', 'b')")}, "a.launch.py")
    assert "roslaunch_error" not in [rule for rule, _ in rules(tree)]


def handler(event: str, imports: str) -> str:
    return HEADER + imports + (
        "    five = Node(package='p', executable='five')\n"
        "    return LaunchDescription([five, RegisterEventHandler(OnProcessExit(\n"
        f"        target_action=five, on_exit=[EmitEvent(event={event})]))])\n")


def test_emit_event_given_the_shutdown_action_is_refused(load: Load) -> None:
    # launch/actions/emit_event.py: RuntimeError unless is_a_subclass(event, Event);
    # launch.actions.Shutdown is an action (itself an EmitEvent), launch.events.Shutdown
    # the event.
    tree = load({"a.launch.py": handler("Shutdown()", "    from launch.actions import Shutdown\n")},
                "a.launch.py")
    assert rules(tree) == [("roslaunch_error", FIRST + 3)]
    assert "launch.actions.Shutdown" in tree.problems[0].message


def test_emit_event_given_the_shutdown_event_is_taken(load: Load) -> None:
    tree = load({"a.launch.py": handler("Shutdown(reason='done')",
                                        "    from launch.events import Shutdown\n")},
                "a.launch.py")
    assert rules(tree) == []


def test_emit_event_given_a_node_is_refused(load: Load) -> None:
    tree = load({"a.launch.py": handler("Node(package='p', executable='e')", "")}, "a.launch.py")
    assert ("roslaunch_error", FIRST + 2) in rules(tree)


def test_twenty_thousand_positional_parts_stay_fast(load: Load) -> None:
    parts = ", ".join("'p'" for _ in range(20_000))
    started = time.process_time()
    tree = load({"a.launch.py": HEADER + node(f"PathJoinSubstitution({parts})")}, "a.launch.py")
    assert time.process_time() - started < 10
    assert ("roslaunch_error", FIRST) in rules(tree)
