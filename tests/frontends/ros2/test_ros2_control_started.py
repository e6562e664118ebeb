"""Controllers that ``ros2 control`` activates from an executable action count as
spawned (``LaunchTree.spawned``), as a ``spawner`` node's do."""

from __future__ import annotations

import time
from pathlib import Path

from launch_linter.engine import LintOptions, lint_paths
from launch_linter.frontends.params import control_started
from launch_linter.resolve.bounded import PYTHON_MAX_ITEMS

PYTHON = """from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, ExecuteProcess, TimerAction
from launch.substitutions import LaunchConfiguration


def generate_launch_description():
    load = ExecuteProcess(cmd={cmd}, output='screen')
    return LaunchDescription([DeclareLaunchArgument('state', default_value='active'),
                              TimerAction(period=3.0, actions=[load])])
"""
CONTROLLER_TF = ("<launch>\n"
                 "  <node pkg=\"controller_manager\" exec=\"ros2_control_node\">\n"
                 "    <param from=\"$(dirname)/controllers.yaml\"/>\n"
                 "  </node>\n"
                 "  <executable cmd=\"{cmd}\"/>\n"
                 "</launch>\n")
CONTROLLERS = ("controller_manager:\n  ros__parameters:\n    steer:\n"
               "      type: ackermann_steering_controller/AckermannSteeringController\n"
               "steer:\n  ros__parameters:\n    enable_odom_tf: true\n")


def spawned(tmp_path: Path, text: str, name: str = "load.launch.py"
            ) -> tuple[str, ...] | None:
    path = tmp_path / name
    path.write_text(text)
    result = lint_paths([str(path)], LintOptions(package_paths=()), keep_trees=True)
    return result.trees[0].spawned


def python(cmd: str) -> str:
    return PYTHON.format(cmd=cmd)


def test_load_controller_set_active_is_a_start(tmp_path: Path) -> None:
    cmd = "['ros2', 'control', 'load_controller', '--set-state', 'active', 'jsb']"
    assert spawned(tmp_path, python(cmd)) == ("jsb",)


def test_load_controller_through_find_exec_and_a_shell_line(tmp_path: Path) -> None:
    cmd = ("[FindExecutable(name='ros2'), 'control', 'load_controller', '--set-state', "
           "'active', 'jsb']")
    text = python(cmd).replace("LaunchConfiguration\n",
                               "FindExecutable, LaunchConfiguration\n")
    assert spawned(tmp_path, text) == ("jsb",)
    shell = python("['ros2 control load_controller --set-state active jsb']").replace(
        "output='screen'", "output='screen', shell=True")
    assert spawned(tmp_path, shell) == ("jsb",)


def test_a_controller_only_loaded_or_configured_is_not_started(tmp_path: Path) -> None:
    assert spawned(tmp_path, python("['ros2', 'control', 'load_controller', 'jsb']")) == ()
    inactive = "['ros2', 'control', 'load_controller', '--set-state', 'inactive', 'jsb']"
    assert spawned(tmp_path, python(inactive)) == ()
    listing = "['ros2', 'control', 'list_controllers']"
    assert spawned(tmp_path, python(listing)) == ()


def test_a_state_from_a_launch_configuration(tmp_path: Path) -> None:
    cmd = ("['ros2', 'control', 'load_controller', '--set-state', "
           "LaunchConfiguration('state'), 'jsb']")
    assert spawned(tmp_path, python(cmd)) == ("jsb",)
    unknown = cmd.replace("LaunchConfiguration('state')", "LaunchConfiguration('other')")
    assert spawned(tmp_path, python(unknown)) is None


def test_xml_executable(tmp_path: Path) -> None:
    text = ('<launch><executable cmd="ros2 control set_controller_state steer active"/>'
            '</launch>')
    assert spawned(tmp_path, text, "load.launch.xml") == ("steer",)


def test_the_verbs_that_activate() -> None:
    assert control_started(["switch_controllers", "--activate", "a", "b", "--deactivate",
                            "c", "--strict"]) == ("a", "b")
    assert control_started(["switch_controllers", "--start", "a", "-c", "/cm"]) == ("a",)
    assert control_started(["load_controller", "x", "--set-state", "start"]) == ("x",)
    assert control_started(["load_controller", "-c", "/cm", "x", "p.yaml", "--set-state",
                            "active"]) == ("x",)
    assert control_started(["load_start_controller", "x"]) == ("x",)
    assert control_started(["set_controller_state", "x", "inactive"]) == ()
    assert control_started(["set_controller_state", "x", None]) is None
    assert control_started(["load_controller", None, "--set-state", "active"]) is None
    assert control_started([None, "x"]) is None
    assert control_started(["unload_controller", "x"]) == ()


def test_controller_rules_see_it(tmp_path: Path) -> None:
    """controller_tf_unrouted needs the controller started: silent on the old code."""
    (tmp_path / "controllers.yaml").write_text(CONTROLLERS)
    path = tmp_path / "robot.launch.xml"
    options = LintOptions(package_paths=(), select=frozenset({"controller_tf_unrouted"}))
    for cmd, expected in (("ros2 control load_controller --set-state active steer", 1),
                          ("ros2 control load_controller steer", 0)):
        path.write_text(CONTROLLER_TF.format(cmd=cmd))
        assert len(lint_paths([str(path)], options).diagnostics) == expected


def test_twenty_thousand_controllers_in_one_command(tmp_path: Path) -> None:
    """The Python reader keeps lists up to PYTHON_MAX_ITEMS; the verb's reader is linear
    in the words it is given."""
    count = PYTHON_MAX_ITEMS - 10
    names = ", ".join(f"'c{i}'" for i in range(count))
    cmd = f"['ros2', 'control', 'switch_controllers', '--activate', {names}]"
    started = time.process_time()
    found = spawned(tmp_path, python(cmd))
    assert found is not None and len(found) == count
    words = ["switch_controllers", *(["--activate", "a"] * 20_000)]
    assert len(control_started(words) or ()) == 20_000
    assert time.process_time() - started < 60
