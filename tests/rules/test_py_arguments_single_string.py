"""py_arguments_single_string: several arguments in one argv item."""

from __future__ import annotations

from typing import Callable, List, Tuple

from launch_linter import LintOptions, lint_text
from launch_linter.model import Diagnostic

Lint = Callable[..., List[Tuple[str, int]]]


def run_rule(text: str, rule: str, path: str) -> tuple[Diagnostic, ...]:
    """The diagnostics of ``rule`` alone for launch text ``text`` read as ``path``."""
    options = LintOptions(package_paths=(), select=frozenset({rule}))
    return lint_text(text, path, options).diagnostics


PYTHON = (
    "from launch import LaunchDescription\n"
    "from launch_ros.actions import Node\n"
    "def generate_launch_description():\n"
    "    return LaunchDescription([\n"
    "        Node(package='tf2_ros', executable='static_transform_publisher',\n"
    "             arguments={arguments}),\n"
    "    ])\n"
)


def test_one_python_list_item_with_every_argument() -> None:
    text = PYTHON.format(arguments="['--z 0.2 --frame-id base_link --child-frame-id laser']")
    (diagnostic,) = run_rule(text, "py_arguments_single_string", path="a.launch.py")
    assert (diagnostic.line, diagnostic.severity.value) == (5, "error")
    assert "'--z 0.2 --frame-id base_link --child-frame-id laser'" in diagnostic.message


def test_one_item_per_word_is_fine() -> None:
    text = PYTHON.format(arguments="'--z 0.2 --frame-id base_link --child-frame-id laser'"
                                   ".split()")
    assert run_rule(text, "py_arguments_single_string", path="a.launch.py") == ()


def test_a_frame_flag_value_with_a_space_is_not_this_mistake() -> None:
    text = PYTHON.format(arguments="['--frame-id', 'base link', '--child-frame-id', 'laser']")
    assert run_rule(text, "py_arguments_single_string", path="a.launch.py") == ()


def test_a_quoted_part_of_xml_args(lint: Lint) -> None:
    xml = ('<launch>\n  <node pkg="tf2_ros" exec="static_transform_publisher" name="t"\n'
           "        args=\"'0 0 0 0 0 0 map odom'\"/>\n</launch>")
    assert lint(xml, "py_arguments_single_string") == [("py_arguments_single_string", 2)]
