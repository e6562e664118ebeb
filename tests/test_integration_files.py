"""The pre-commit hook definition and the integration guide agree with the code."""

from __future__ import annotations

import re
import sys
from pathlib import Path

import pytest

from launch_linter.workspace.discovery import LAUNCH_SUFFIXES

yaml = pytest.importorskip("yaml")

ROOT = Path(__file__).resolve().parent.parent


def hooks() -> dict[str, dict[str, object]]:
    listed = yaml.safe_load((ROOT / ".pre-commit-hooks.yaml").read_text())
    return {str(h["id"]): h for h in listed}


def hook() -> dict[str, object]:
    return hooks()["launch-linter"]


def test_robot_hook_lints_the_repository_when_a_description_changes() -> None:
    robot = hooks()["launch-linter-robot"]
    assert robot["entry"] == "launch-linter check" and robot["pass_filenames"] is False
    pattern = re.compile(str(robot["files"]))
    for name in ("urdf/robot.urdf", "urdf/robot.urdf.xacro", "urdf/arm.xacro"):
        assert pattern.search(name), name
    for name in ("launch/robot.launch", "urdf/robot.urdf.bak", "xacro.py"):
        assert not pattern.search(name), name
    guide = (ROOT / "docs" / "integration.md").read_text()
    assert "id: launch-linter-robot" in guide


def test_hook_runs_check() -> None:
    definition = hook()
    assert definition["id"] == "launch-linter"
    assert definition["entry"] == "launch-linter check"
    assert definition["language"] == "python"


def test_hook_matches_every_launch_suffix_and_nothing_else() -> None:
    pattern = re.compile(str(hook()["files"]))
    for suffix in LAUNCH_SUFFIXES:
        assert pattern.search(f"pkg/launch/robot{suffix}"), suffix
    for name in ("setup.py", "package.xml", "robot.launch.pyc", "launch/notes.txt"):
        assert not pattern.search(name), name


def test_guide_uses_the_same_pattern() -> None:
    guide = (ROOT / "docs" / "integration.md").read_text()
    assert f"files: '{hook()['files']}'" in guide


def test_guide_yaml_and_toml_examples_parse() -> None:
    # tomllib is new in Python 3.11; the package depends on tomli before.
    tomllib = pytest.importorskip("tomllib" if sys.version_info >= (3, 11) else "tomli")

    guide = (ROOT / "docs" / "integration.md").read_text()
    yaml_blocks = re.findall(r"```yaml\n(.*?)```", guide, re.DOTALL)
    assert len(yaml_blocks) >= 4
    for block in yaml_blocks:
        yaml.safe_load(block)
    (toml_block,) = re.findall(r"```toml\n(.*?)```", guide, re.DOTALL)
    tomllib.loads(toml_block)


def test_guide_config_example_is_accepted(tmp_path: Path) -> None:
    from launch_linter.workspace.config import load_config

    guide = (ROOT / "docs" / "integration.md").read_text()
    (toml_block,) = re.findall(r"```toml\n(.*?)```", guide, re.DOTALL)
    (tmp_path / ".launch-linter.toml").write_text(toml_block)
    config = load_config(str(tmp_path / ".launch-linter.toml"))
    assert config.fail_on == "error" and config.args["use_sim_time"] == "false"
