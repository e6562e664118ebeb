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
