"""ros2_param_file_refused: a value above ros__parameters in a node's parameter file (rcl's
parser refuses it: 'Cannot have a value before ros__parameters'; rcl_init fails)."""

from __future__ import annotations

import time
from pathlib import Path

from launch_linter.engine import LintOptions, lint_paths

RULE = "ros2_param_file_refused"

LAUNCH = ("import os\n"
          "from launch import LaunchDescription\n"
          "from launch.actions import DeclareLaunchArgument\n"
          "from launch_ros.actions import Node\n"
          "from launch_ros.parameter_descriptions import ParameterFile\n"
          "def generate_launch_description():\n"
          "    here = os.path.dirname(__file__)\n"
          "    return LaunchDescription([\n"
          "        DeclareLaunchArgument('kind', default_value='{default}'),\n"
          "        Node(package='demo', executable='talker', name='talker',\n"
          "             parameters=[{given}]),\n"
          "    ])\n")
PLAIN = "os.path.join(here, 'talker.yaml')"
SUBSTITUTED = "ParameterFile(param_file=os.path.join(here, 'talker.yaml'), allow_substs=True)"


def run(tmp_path: Path, params: str, given: str = PLAIN, default: str = "mushrooms"
        ) -> list[tuple[str, int, str]]:
    (tmp_path / "talker.yaml").write_text(params)
    path = tmp_path / "talker.launch.py"
    path.write_text(LAUNCH.format(given=given, default=default))
    options = LintOptions(package_paths=(), select=frozenset({RULE}))
    return [(Path(d.path).name, d.line, d.severity.value)
            for d in lint_paths([str(path)], options).diagnostics]


def test_values_at_the_top_level_are_an_error_at_the_first(tmp_path: Path) -> None:
    assert run(tmp_path, "# rates\nrate: 2.0\ntopic: chatter\n") == [("talker.yaml", 2, "error")]


def test_values_under_a_node_key_without_ros__parameters_are_an_error(tmp_path: Path) -> None:
    assert run(tmp_path, "talker:\n  rate: 2.0\n") == [("talker.yaml", 2, "error")]
    assert run(tmp_path, "talker:\n  frames: [a, b]\n") == [("talker.yaml", 2, "error")]


def test_values_under_ros__parameters_are_silent(tmp_path: Path) -> None:
    assert run(tmp_path, "talker:\n  ros__parameters:\n    rate: 2.0\n") == []
    assert run(tmp_path, "/**:\n  ros__parameters:\n    rate: 2.0\nother: {}\n") == []


def test_a_substituted_value_is_judged_once_it_resolves_to_one_plain_line(tmp_path: Path
                                                                          ) -> None:
    # launch_ros performs the $(...) first (ParameterFile(allow_substs=True)): the value
    # stays a scalar only when its text is one plain line.
    assert run(tmp_path, "kind: $(var kind)\n", SUBSTITUTED) == [("talker.yaml", 1, "error")]
    assert run(tmp_path, "kind: $(env KIND)\n", SUBSTITUTED) == []
    assert run(tmp_path, "kind: $(var kind)\n", SUBSTITUTED, default="{a: 1}") == []


def test_a_written_substitution_in_a_file_launch_does_not_substitute_is_a_value(
        tmp_path: Path) -> None:
    given = "ParameterFile(os.path.join(here, 'talker.yaml'))"
    assert run(tmp_path, "kind: $(env KIND)\n", given) == [("talker.yaml", 1, "error")]


def test_twenty_thousand_sections_stay_fast(tmp_path: Path) -> None:
    params = "".join(f"node{i}:\n  ros__parameters:\n    a: 1\n" for i in range(20_000))
    started = time.process_time()
    assert run(tmp_path, params + "last: 1\n") in ([], [("talker.yaml", 60_001, "error")])
    assert time.process_time() - started < 60
