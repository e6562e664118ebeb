"""Where the target distribution comes from: flag, configuration, ROS_DISTRO, the files."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from launch_linter.cli import main
from launch_linter.model.distro import describe, is_known, normalise

POSITIONAL = (
    '<launch><node pkg="tf2_ros" exec="static_transform_publisher" name="a" '
    'args="0 0 0.2 0 0 0 base_link laser"/></launch>\n'
)


@pytest.fixture
def project(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    monkeypatch.chdir(tmp_path)
    monkeypatch.delenv("ROS_DISTRO", raising=False)
    (tmp_path / "a.launch.xml").write_text(POSITIONAL, encoding="utf-8")
    return tmp_path


def levels(capsys: pytest.CaptureFixture[str], *argv: str) -> tuple[int, list[str]]:
    status = main(["check", "--beliefs", "none", "--format", "json", "a.launch.xml", *argv])
    document = json.loads(capsys.readouterr().out)
    return status, [d["severity"] for d in document["diagnostics"]
                    if d["rule"] == "ros2_positional_args"]


def test_unknown_target_is_info(project: Path, capsys: pytest.CaptureFixture[str]) -> None:
    assert levels(capsys) == (0, ["info"])


def test_flag(project: Path, capsys: pytest.CaptureFixture[str]) -> None:
    assert levels(capsys, "--ros-distro", "Rolling") == (1, ["error"])
    assert levels(capsys, "--ros-distro", "foxy") == (0, [])


def test_config_key(project: Path, capsys: pytest.CaptureFixture[str]) -> None:
    (project / ".launch-linter.toml").write_text('ros-distro = "rolling"\n')
    assert levels(capsys) == (1, ["error"])
    assert levels(capsys, "--ros-distro", "humble") == (0, ["info"])


def test_ros_distro_environment_variable(
    project: Path, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setenv("ROS_DISTRO", "rolling")
    assert levels(capsys) == (1, ["error"])
    (project / ".launch-linter.toml").write_text('ros-distro = "galactic"\n')
    assert levels(capsys) == (0, [])
    monkeypatch.setenv("ROS_DISTRO", "not-a-distro")
    (project / ".launch-linter.toml").unlink()
    assert levels(capsys) == (0, ["info"])


def test_unknown_names_are_usage_errors(project: Path, capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["check", "a.launch.xml", "--ros-distro", "hubmle"]) == 2
    assert "unknown ROS distribution 'hubmle'" in capsys.readouterr().err
    (project / ".launch-linter.toml").write_text('ros-distro = "hubmle"\n')
    assert main(["check", "a.launch.xml"]) == 2


def test_profile_flag_and_key(project: Path, capsys: pytest.CaptureFixture[str]) -> None:
    assert levels(capsys, "--profile", "study") == (1, ["warning"])
    (project / ".launch-linter.toml").write_text('profile = "study"\n')
    assert levels(capsys) == (1, ["warning"])
    (project / ".launch-linter.toml").write_text('profile = "strict"\n')
    assert main(["check", "a.launch.xml"]) == 2


def test_helpers() -> None:
    assert normalise(" Humble ") == "humble" and normalise("") is None and normalise(None) is None
    assert is_known("noetic") and is_known("kilted") and not is_known("hubmle")
    assert describe(("humble", "iron", "jazzy")) == "Humble, Iron and Jazzy"


def test_indigo_and_jade_are_targets(tmp_path: Path, monkeypatch: pytest.MonkeyPatch,
                                     capsys: pytest.CaptureFixture[str]) -> None:
    """ROS 1 Indigo and Jade are accepted, and robot_state_publisher's release there
    installs state_publisher as well (indigo-devel 611d979, CMakeLists.txt 25-29, 62)."""
    monkeypatch.chdir(tmp_path)
    monkeypatch.delenv("ROS_DISTRO", raising=False)
    assert is_known("indigo") and is_known("jade") and not is_known("hydro")
    node = '<launch><node pkg="robot_state_publisher" type="{}" name="rsp"/></launch>\n'
    (tmp_path / "a.launch").write_text(node.format("state_publisher"), encoding="utf-8")
    argv = ["check", "--format", "json", "--select", "node_executable_missing", "a.launch"]
    for distro in ("indigo", "jade"):
        assert main([*argv, "--ros-distro", distro]) == 0
        assert json.loads(capsys.readouterr().out)["diagnostics"] == []
    (tmp_path / "a.launch").write_text(node.format("rsp_node"), encoding="utf-8")
    assert main([*argv, "--ros-distro", "indigo"]) == 1
    (found,) = json.loads(capsys.readouterr().out)["diagnostics"]
    assert "Indigo installs no executable 'rsp_node'" in found["message"]
