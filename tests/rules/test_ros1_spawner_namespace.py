from __future__ import annotations

import time
from pathlib import Path

from launch_linter import LintOptions, lint_paths
from launch_linter.model import Diagnostic

RULE = "ros1_spawner_namespace"


def _robot(namespace: str | None) -> str:
    given = "" if namespace is None else f"<robotNamespace>{namespace}</robotNamespace>"
    return ('<robot name="arm"><link name="base_link"/><link name="l1"/>'
            '<joint name="j1" type="revolute"><parent link="base_link"/><child link="l1"/>'
            '<limit effort="1" velocity="1" lower="-1" upper="1"/></joint>'
            '<gazebo><plugin name="gazebo_ros_control" filename="libgazebo_ros_control.so">'
            f'{given}</plugin></gazebo></robot>\n')


def _lint(tmp_path: Path, body: str, namespace: str | None = "/arm") -> tuple[Diagnostic, ...]:
    (tmp_path / "robot.urdf").write_text(_robot(namespace), encoding="utf-8")
    (tmp_path / "sim.launch").write_text(
        '<launch>\n'
        '<param name="robot_description" textfile="$(dirname)/robot.urdf"/>\n'
        '<node pkg="gazebo_ros" type="spawn_model" name="spawn" '
        'args="-urdf -param robot_description -model arm"/>\n'
        '<node pkg="robot_state_publisher" type="robot_state_publisher" name="rsp"/>\n'
        f'{body}\n</launch>\n', encoding="utf-8")
    options = LintOptions(package_paths=(), select=frozenset({RULE}))
    return lint_paths([str(tmp_path / "sim.launch")], options).diagnostics


SPAWNER = ('<node pkg="controller_manager" type="spawner" name="spawner" '
           'args="joint_state_controller {extra}"/>')


def test_a_spawner_outside_the_plugins_namespace_reaches_no_manager(tmp_path: Path) -> None:
    """iiwa_stack#9: the spawner in / while <robotNamespace> puts the manager in /arm."""
    (found,) = _lint(tmp_path, SPAWNER.format(extra=""))
    assert found.line == 5 and found.severity.value == "warning"
    assert "/controller_manager/load_controller" in found.message and "/arm" in found.message
    assert found.related[0].path.endswith("robot.urdf")


def test_a_spawner_in_the_namespace_or_pointed_at_it_is_silent(tmp_path: Path) -> None:
    grouped = '<group ns="arm">' + SPAWNER.format(extra="") + "</group>"
    assert _lint(tmp_path, grouped) == ()
    for option in ("--namespace /arm", "--namespace=/arm", "--namespace arm"):
        assert _lint(tmp_path, SPAWNER.format(extra=option)) == (), option
    assert _lint(tmp_path, SPAWNER.format(extra=""), namespace="/") == ()
    assert _lint(tmp_path, SPAWNER.format(extra="--namespace /other")) != ()


def test_a_relative_namespace_option_is_under_the_spawners_namespace(tmp_path: Path) -> None:
    grouped = '<group ns="robots">' + SPAWNER.format(extra="--namespace arm") + "</group>"
    (found,) = _lint(tmp_path, grouped)
    assert "/robots/arm/controller_manager/load_controller" in found.message


def test_unknowns_keep_it_silent(tmp_path: Path) -> None:
    spawner = SPAWNER.format(extra="")
    # An argument not resolved: --namespace may be in it.
    assert _lint(tmp_path, SPAWNER.format(extra="$(env CM_ARGS)")) == ()
    # A program the knowledge base does not know may run a controller manager in /.
    assert _lint(tmp_path, spawner + '<node pkg="my_robot" type="hardware" name="hw"/>') == ()
    # No simulator plugin: the controller manager is a driver's, unknown here.
    (tmp_path / "robot.urdf").write_text('<robot name="arm"><link name="a"/></robot>',
                                         encoding="utf-8")
    (tmp_path / "bare.launch").write_text(f"<launch>{spawner}</launch>", encoding="utf-8")
    options = LintOptions(package_paths=(), select=frozenset({RULE}))
    assert lint_paths([str(tmp_path / "bare.launch")], options).diagnostics == ()


def test_many_spawners_are_judged_in_linear_time(tmp_path: Path) -> None:
    """Hostile: 20,000 spawners in /, each one finding."""
    body = "\n".join(f'<node pkg="controller_manager" type="spawner" name="s{i}" '
                     f'args="c{i} --namespace /x{i % 7}"/>' for i in range(20_000))
    start = time.process_time()
    found = _lint(tmp_path, body)
    assert time.process_time() - start < 60.0
    assert len(found) == 20_000
