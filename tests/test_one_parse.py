"""Each ROS 2 Python launch file is parsed once per lint: the fix locator takes the syntax
tree the front-end built (``frontends/python_trees.py``) instead of parsing the file again."""

from __future__ import annotations

import ast
import collections
import json
from pathlib import Path

import pytest

from launch_linter.cli import main
from launch_linter.engine import LintOptions, lint_bytes

PYTHON = """from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package="tf2_ros", executable="static_transform_publisher",
             arguments=["0", "0", "0", "0", "0", "0", "{parent}", "{child}"]),
    ])
"""


def counting_parses(monkeypatch: pytest.MonkeyPatch) -> collections.Counter[str]:
    """Every ``ast.parse`` from now on, counted by the text parsed."""
    parses: collections.Counter[str] = collections.Counter()
    real = ast.parse

    def parse(source: str | bytes, *args: object, **kwargs: object) -> ast.AST:
        parses[source if isinstance(source, str) else source.decode()] += 1
        return real(source, *args, **kwargs)  # type: ignore[arg-type]

    monkeypatch.setattr(ast, "parse", parse)
    return parses


@pytest.mark.parametrize("cache", [[], ["--no-cache"]], ids=["cache", "no-cache"])
def test_check_fix_parses_each_python_file_once(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str],
    cache: list[str],
) -> None:
    monkeypatch.chdir(tmp_path)
    files = {"a.launch.py": PYTHON.format(parent="/base_link", child="laser"),
             "b.launch.py": PYTHON.format(parent="base_link", child="/imu")}
    for name, text in files.items():
        Path(name).write_text(text)
    parses = counting_parses(monkeypatch)
    main(["check", ".", "--fix", *cache])
    assert "fixed 2 finding(s)" in capsys.readouterr().err
    # Both files were fixed, so each was linted twice: before and after, two texts.
    after = {name: Path(name).read_text() for name in files}
    assert after["a.launch.py"] == files["a.launch.py"].replace("/base_link", "base_link")
    assert after["b.launch.py"] == files["b.launch.py"].replace("/imu", "imu")
    texts = {*files.values(), *after.values()}
    assert {text: parses[text] for text in texts} == dict.fromkeys(texts, 1)


def test_check_json_locates_a_python_fix_without_parsing_again(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str],
) -> None:
    path = tmp_path / "a.launch.py"
    text = PYTHON.format(parent="/base_link", child="laser")
    path.write_text(text)
    parses = counting_parses(monkeypatch)
    main(["check", str(path), "--format", "json", "--no-cache", "--exit-zero"])
    diagnostics = json.loads(capsys.readouterr().out)["diagnostics"]
    assert any(d["fix"] and d["fix"]["edits"] for d in diagnostics)  # the fix was located
    assert parses[text] == 1


def test_stdin_text_is_parsed_once(monkeypatch: pytest.MonkeyPatch) -> None:
    text = PYTHON.format(parent="/base_link", child="laser")
    parses = counting_parses(monkeypatch)
    result = lint_bytes(text.encode(), "robot.launch.py", LintOptions())
    assert any(d.fix is not None and d.fix.edits for d in result.diagnostics)
    assert parses[text] == 1
