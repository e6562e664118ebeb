from __future__ import annotations

from pathlib import Path

import pytest

from launch_linter import LintOptions, lint_paths

RULE = "py_name_error"
HEAD = """from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
"""


def _lint(tmp_path: Path, body: str) -> list[tuple[int, str]]:
    path = tmp_path / "demo.launch.py"
    path.write_text(HEAD + body, encoding="utf-8")
    options = LintOptions(package_paths=(), select=frozenset({RULE}))
    return [(d.line, d.severity.value) for d in lint_paths([str(path)], options).diagnostics]


RENAMED = """
def generate_launch_description():
    declare_cmd = DeclareLaunchArgument('config_file', default_value='a.yaml')
    ld = LaunchDescription()
    ld.add_action(decalre_cmd)
    return ld
"""


def test_a_name_bound_nowhere_is_a_name_error(tmp_path: Path) -> None:
    assert _lint(tmp_path, RENAMED) == [(7, "error")]


def test_the_corrected_name_is_silent(tmp_path: Path) -> None:
    assert _lint(tmp_path, RENAMED.replace("decalre_cmd", "declare_cmd")) == []


@pytest.mark.parametrize("binding", [
    "from helpers import decalre_cmd\n",
    "import decalre_cmd\n",
    "decalre_cmd = None\n",
    "def decalre_cmd():\n    pass\n",
    "for decalre_cmd in []:\n    pass\n",
    "try:\n    pass\nexcept ValueError as decalre_cmd:\n    pass\n",
])
def test_a_name_bound_anywhere_is_not_judged(tmp_path: Path, binding: str) -> None:
    # Bound somewhere (however the linter reads its value), Python finds it or raises
    # another error; the linter does not judge what it cannot see run.
    assert _lint(tmp_path, binding + RENAMED) == []


@pytest.mark.parametrize("escape", [
    "from helpers import *\n",
    "globals()['x'] = 1\n",
    "try:\n    import foo\nexcept Exception:\n    pass\n",
])
def test_a_file_that_may_bind_names_unseen_is_not_judged(tmp_path: Path, escape: str) -> None:
    assert _lint(tmp_path, escape + RENAMED) == []


def test_builtins_and_module_attributes_are_names(tmp_path: Path) -> None:
    body = """
def generate_launch_description():
    print(__file__, len([]), __name__)
    return LaunchDescription([])
"""
    assert _lint(tmp_path, body) == []


def test_under_an_undecided_if_it_is_not_judged(tmp_path: Path) -> None:
    body = """import os


def generate_launch_description():
    ld = LaunchDescription()
    if os.environ.get('NOPE') == '1':
        ld.add_action(decalre_cmd)
    return ld
"""
    assert _lint(tmp_path, body) == []


def test_builtins_are_those_of_every_python_ros2_runs_on_not_the_running_one() -> None:
    # Read from the linter's data, not from the running interpreter's ``dir(builtins)``:
    # under Python 3.8 the names 3.10-3.13 added would otherwise be false NameErrors.
    from launch_linter.frontends.ros2_python.names import PYTHON_BUILTINS
    newer = {"aiter", "anext", "EncodingWarning", "ExceptionGroup", "BaseExceptionGroup",
             "PythonFinalizationError"}
    assert newer <= PYTHON_BUILTINS
    assert {"print", "len", "__file__", "__name__"} <= PYTHON_BUILTINS
    assert "decalre_cmd" not in PYTHON_BUILTINS


@pytest.mark.parametrize("use", ["anext(iter([]), None)", "ExceptionGroup('x', [ValueError()])"])
def test_a_builtin_of_a_newer_python_is_silent(tmp_path: Path, use: str) -> None:
    body = f"\ndef generate_launch_description():\n    {use}\n    return LaunchDescription()\n"
    assert _lint(tmp_path, body) == []


def test_the_whole_tree_is_walked_only_for_a_name_found_nowhere(
        tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """Walking every node of the syntax tree costs more than parsing it: a file whose
    names are all found in scope never pays for it."""
    from launch_linter.frontends.ros2_python import names, reader

    walked: list[object] = []

    def counted(tree: object) -> object:
        walked.append(tree)
        return names.bound_names(tree)  # type: ignore[arg-type]

    monkeypatch.setattr(reader, "bound_names", counted)
    assert _lint(tmp_path, RENAMED.replace("decalre_cmd", "declare_cmd")) == []
    assert walked == []
    assert _lint(tmp_path, RENAMED) != [] and len(walked) == 1
