"""node_executable_missing: robot_state_publisher's state_publisher, gone from Noetic."""

from __future__ import annotations

import time
from pathlib import Path

from launch_linter.engine import LintOptions, lint_paths

RULE = "node_executable_missing"
NODE = '<node name="rsp{i}" pkg="robot_state_publisher" type="{type}"/>'


def run(tmp_path: Path, text: str, distro: str | None) -> list[tuple[int, str]]:
    path = tmp_path / "view.launch"
    path.write_text(text)
    options = LintOptions(package_paths=(), select=frozenset({RULE}), ros_distro=distro)
    return [(d.line, d.severity.value) for d in lint_paths([str(path)], options).diagnostics]


def launch(kind: str, count: int = 1) -> str:
    return "<launch>\n" + "\n".join(NODE.format(i=i, type=kind) for i in range(count)) + \
        "\n</launch>"


def test_state_publisher_on_noetic_is_an_error(tmp_path: Path) -> None:
    assert run(tmp_path, launch("state_publisher"), "noetic") == [(2, "error")]


def test_state_publisher_on_melodic_is_silent(tmp_path: Path) -> None:
    assert run(tmp_path, launch("state_publisher"), "melodic") == []


def test_state_publisher_without_a_distro_is_info(tmp_path: Path) -> None:
    assert run(tmp_path, launch("state_publisher"), None) == [(2, "info")]


def test_robot_state_publisher_is_silent(tmp_path: Path) -> None:
    assert run(tmp_path, launch("robot_state_publisher"), "noetic") == []
    assert run(tmp_path, launch("robot_state_publisher"), None) == []


def test_unknown_package_is_silent(tmp_path: Path) -> None:
    text = '<launch><node name="a" pkg="my_pkg" type="state_publisher"/></launch>'
    assert run(tmp_path, text, "noetic") == []


def test_twenty_thousand_nodes(tmp_path: Path) -> None:
    started = time.process_time()
    assert len(run(tmp_path, launch("state_publisher", 20_000), "noetic")) == 20_000
    assert time.process_time() - started < 60


SPAWNER = """from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([{nodes}])
"""
SPAWNER_NODE = """
        Node(
            package='controller_manager',
            executable='{exe}',
            arguments=['broadcaster{i}'],
        ),"""


def spawners(tmp_path: Path, exe: str, distro: str | None, count: int = 1
             ) -> list[tuple[int, str]]:
    path = tmp_path / "spawn.launch.py"
    path.write_text(SPAWNER.format(nodes="".join(
        SPAWNER_NODE.format(exe=exe, i=i) for i in range(count))))
    options = LintOptions(package_paths=(), select=frozenset({RULE}), ros_distro=distro)
    return [(d.line, d.severity.value) for d in lint_paths([str(path)], options).diagnostics]


def test_spawner_py_on_humble_is_an_error_at_the_executable_keyword(tmp_path: Path) -> None:
    # controller_manager 2.3.0 on (Humble's releases) installs the console script
    # 'spawner' and no scripts/spawner.py: the finding names the line to change.
    assert spawners(tmp_path, "spawner.py", "humble") == [(9, "error")]
    assert spawners(tmp_path, "spawner.py", "jazzy") == [(9, "error")]


def test_spawner_on_humble_and_spawner_py_before_are_silent(tmp_path: Path) -> None:
    assert spawners(tmp_path, "spawner", "humble") == []
    assert spawners(tmp_path, "unspawner", "rolling") == []
    # Foxy's and Galactic's releases are not in the knowledge base: unknown, silent.
    assert spawners(tmp_path, "spawner.py", "foxy") == []
    assert spawners(tmp_path, "spawner.py", None) == []


def test_ten_thousand_spawners_and_twenty_thousand_keywords(tmp_path: Path) -> None:
    # Ten thousand nodes: the most items of one list the front-end follows; the keyword
    # looked up for the executable's line is searched among each call's keywords.
    started = time.process_time()
    assert len(spawners(tmp_path, "spawner.py", "humble", 10_000)) == 10_000
    path = tmp_path / "keywords.launch.py"
    extra = "".join(f"k{i}={i}, " for i in range(20_000))
    path.write_text(SPAWNER.format(nodes=(
        f"Node({extra}package='controller_manager',\n            executable='spawner.py')")))
    options = LintOptions(package_paths=(), select=frozenset({RULE}), ros_distro="humble")
    assert [d.line for d in lint_paths([str(path)], options).diagnostics] == [7]
    assert time.process_time() - started < 60
