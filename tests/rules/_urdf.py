"""Run one rule over a tiny URDF or xacro text, as a file linted on its own or as the
description a launch file gives robot_state_publisher."""

from __future__ import annotations

from pathlib import Path

from launch_linter import LintOptions, lint_paths, lint_text
from launch_linter.model import Diagnostic

XACRO = 'xmlns:xacro="http://www.ros.org/wiki/xacro"'


def robot(body: str, name: str = "demo") -> str:
    return f'<robot name="{name}" {XACRO}>\n{body}\n</robot>\n'


def link(name: str) -> str:
    return f'<link name="{name}"/>'


def joint(name: str, parent: str, child: str, kind: str = "fixed") -> str:
    return (f'<joint name="{name}" type="{kind}"><parent link="{parent}"/>'
            f'<child link="{child}"/></joint>')


def lint_urdf(text: str, rule: str, path: str = "robot.urdf.xacro",
              args: dict[str, str] | None = None) -> tuple[Diagnostic, ...]:
    options = LintOptions(args=args or {}, package_paths=(), select=frozenset({rule}))
    return lint_text(text, path, options).diagnostics


def lint_loaded(tmp_path: Path, text: str, rule: str, xacro_args: str = "",
                publisher: bool = True) -> tuple[Diagnostic, ...]:
    """``text`` written as robot.urdf.xacro and loaded by a ROS 1 launch file."""
    (tmp_path / "robot.urdf.xacro").write_text(text, encoding="utf-8")
    node = ('<node pkg="robot_state_publisher" type="robot_state_publisher" name="rsp"/>'
            if publisher else "")
    (tmp_path / "robot.launch").write_text(
        '<launch><param name="robot_description" '
        f'command="xacro $(dirname)/robot.urdf.xacro {xacro_args}"/>{node}</launch>',
        encoding="utf-8")
    options = LintOptions(package_paths=(), select=frozenset({rule}))
    return lint_paths([str(tmp_path / "robot.launch")], options).diagnostics
