"""Folder discovery: every launch file once, workspace-aware, .gitignore, exclusions."""

from __future__ import annotations

import json
import os
from pathlib import Path

import pytest
from tests.workspace_fixture import LINTED, build_workspace

from launch_linter.cli import main
from launch_linter.engine import LintOptions, lint_paths
from launch_linter.workspace.discovery import (
    Exclusions,
    discover,
    has_launch_root,
    is_workspace_folder,
)
from launch_linter.workspace.gitignore import gitignore_predicate
from launch_linter.workspace.packages import package_ros_version


@pytest.fixture
def ws(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    workspace = build_workspace(tmp_path)
    monkeypatch.chdir(workspace)
    return workspace


def _found(workspace: Path, **kwargs: object) -> list[str]:
    found = discover([str(workspace)], **kwargs)  # type: ignore[arg-type]
    return sorted(os.path.relpath(f.path, workspace) for f in found)


def test_workspace_discovery_finds_each_launch_file_once(ws: Path) -> None:
    assert _found(ws, ignored=gitignore_predicate().ignored) == list(LINTED)


def test_without_gitignore_the_ignored_files_come_back(ws: Path) -> None:
    found = _found(ws)
    assert "src/scratch/x.launch" in found
    assert "src/ros1_pkg/launch/old.tmp.launch" in found
    assert not any(f.startswith(("build/", "install/", "log/")) for f in found)


def test_workspace_folders_only_beside_src_or_marked(tmp_path: Path) -> None:
    (tmp_path / "pkg" / "build").mkdir(parents=True)
    assert not is_workspace_folder(str(tmp_path / "pkg"), "build")
    (tmp_path / "pkg" / "src").mkdir()
    assert is_workspace_folder(str(tmp_path / "pkg"), "build")
    (tmp_path / "other" / "log").mkdir(parents=True)
    (tmp_path / "other" / "log" / "COLCON_IGNORE").write_text("")
    assert is_workspace_folder(str(tmp_path / "other"), "log")
    assert not is_workspace_folder(str(tmp_path / "other"), "launch")


def test_exclude_and_extend_exclude(ws: Path) -> None:
    extended = _found(ws, exclusions=Exclusions.of(None, ["*_launch.py"], str(ws)))
    assert "src/ros2_pkg/launch/bringup_launch.py" not in extended
    anchored = _found(ws, exclusions=Exclusions.of(None, ["src/ros1_pkg/build"], str(ws)))
    assert "src/ros1_pkg/build/keep.launch" not in anchored
    # --exclude replaces the defaults: hidden folders are walked again.
    hidden = ws / ".hidden" / "h.launch"
    hidden.parent.mkdir()
    hidden.write_text("<launch/>")
    assert ".hidden/h.launch" not in _found(ws)
    assert ".hidden/h.launch" in _found(ws, exclusions=Exclusions.of(["nothing"], [], str(ws)))


def test_a_file_named_explicitly_is_linted_even_if_excluded(ws: Path) -> None:
    path = "src/scratch/x.launch"
    found = discover([path], Exclusions.of(None, ["scratch"]), gitignore_predicate().ignored)
    assert [f.display for f in found] == [path]


def test_one_file_by_two_names_and_a_symlink_is_linted_once(ws: Path) -> None:
    link = ws / "src" / "alias.launch"
    link.symlink_to(ws / "src" / "ros1_pkg" / "launch" / "part.launch")
    found = discover(["./src/ros1_pkg/launch/part.launch", "src/ros1_pkg/launch/part.launch",
                      str(link)])
    assert [f.display for f in found] == ["src/ros1_pkg/launch/part.launch"]


def test_launch_root_is_the_root_element(tmp_path: Path) -> None:
    cases = {
        "a.xml": '<?xml version="1.0"?>\n<!-- c -->\n<launch>\n</launch>',
        "b.xml": "<robot><launch/></robot>",
        "c.xml": "<launcher/>",
        "d.xml": "\ufeff<launch/>",
    }
    for name, text in cases.items():
        (tmp_path / name).write_text(text, encoding="utf-8")
    verdicts = {n: has_launch_root(str(tmp_path / n)) for n in cases}
    assert verdicts == {"a.xml": True, "b.xml": False, "c.xml": False, "d.xml": True}


def test_python_and_yaml_launch_files_by_content(tmp_path: Path) -> None:
    (tmp_path / "robot.py").write_text("def generate_launch_description():\n    return 1\n")
    (tmp_path / "setup.py").write_text("from setuptools import setup\n")
    (tmp_path / "robot.yaml").write_text("# c\nlaunch:\n- node: {pkg: a, exec: b}\n")
    (tmp_path / "params.yaml").write_text("ros__parameters:\n  a: 1\n")
    names = sorted(os.path.basename(f.path) for f in discover([str(tmp_path)]))
    assert names == ["robot.py", "robot.yaml"]


def test_findings_of_an_included_file_linted_on_its_own_are_reported_once(ws: Path) -> None:
    options = LintOptions(select=frozenset({"leading_slash"}))
    result = lint_paths(["."], options, ignored=gitignore_predicate().ignored)
    slashes = [d for d in result.diagnostics if d.rule == "leading_slash"]
    assert [(d.path, d.line) for d in slashes] == [("src/ros1_pkg/launch/part.launch", 2)]
    # The transforms contract keeps the file under each root.
    roots = sorted(t.root for t in result.transforms if t.child == "laser")
    assert roots == ["src/ros1_pkg/launch/main.launch", "src/ros1_pkg/launch/part.launch"]


def test_check_with_no_path_lints_the_current_folder(
    ws: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    assert main(["check", "--format", "json", "--exit-zero"]) == 0
    document = json.loads(capsys.readouterr().out)
    assert sorted(f["path"] for f in document["files"]) == list(LINTED)


def test_cli_exclude_options_and_config_keys(
    ws: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    main(["check", "--format", "json", "--extend-exclude", "*_launch.py,*.launch.xml"])
    paths = {f["path"] for f in json.loads(capsys.readouterr().out)["files"]}
    assert "src/ros2_pkg/launch/bringup_launch.py" not in paths
    assert "src/ros1_pkg/launch/robot.launch.xml" not in paths
    (ws / ".launch-linter.toml").write_text('extend-exclude = ["src/ros1_pkg"]\n')
    main(["check", "--format", "json"])
    paths = {f["path"] for f in json.loads(capsys.readouterr().out)["files"]}
    assert not any(p.startswith("src/ros1_pkg") for p in paths) and paths
    main(["check", "--format", "json", "--no-respect-gitignore"])
    paths = {f["path"] for f in json.loads(capsys.readouterr().out)["files"]}
    assert "src/scratch/x.launch" in paths


def test_package_xml_decides_the_ros_version(ws: Path) -> None:
    assert package_ros_version(str(ws / "src/ros2_pkg/package.xml")) == 2
    assert package_ros_version(str(ws / "src/ros1_pkg/package.xml")) == 1
    result = lint_paths(["src/ros2_pkg/launch/env.xml"])
    # ROS 2's $(env NAME default) is valid: no ROS 1 error for it.
    assert not [d for d in result.diagnostics if d.rule == "roslaunch_error"]
    assert [t.child for t in result.transforms] == ["imu"]
    forced = lint_paths(["src/ros2_pkg/launch/env.xml"], LintOptions(ros=1))
    assert any(d.rule == "roslaunch_error" for d in forced.diagnostics)


def test_the_ros_key_overrides_the_package(ws: Path, capsys: pytest.CaptureFixture[str]) -> None:
    (ws / ".launch-linter.toml").write_text("ros = 1\n")
    main(["check", "src/ros2_pkg/launch/env.xml", "--format", "json"])
    rules = {d["rule"] for d in json.loads(capsys.readouterr().out)["diagnostics"]}
    assert "roslaunch_error" in rules
    main(["check", "src/ros2_pkg/launch/env.xml", "--format", "json", "--ros", "2"])
    rules = {d["rule"] for d in json.loads(capsys.readouterr().out)["diagnostics"]}
    assert "roslaunch_error" not in rules


def test_without_a_package_content_decides(tmp_path: Path) -> None:
    path = tmp_path / "env.xml"
    path.write_text(ENV_ONLY)
    result = lint_paths([str(path)])
    assert any(d.rule == "roslaunch_error" for d in result.diagnostics)


ENV_ONLY = '<launch>\n  <arg name="f" default="$(env ROBOT_FRAME base_link)"/>\n</launch>\n'


def test_rostest_files_with_a_launch_root(tmp_path: Path) -> None:
    (tmp_path / "tf.test").write_text(
        '<launch>\n  <node pkg="tf2_ros" type="static_transform_publisher" name="t"\n'
        '        args="0 0 0 0 0 0 a b"/>\n  <test test-name="t" pkg="p" type="t.py"/>\n'
        "</launch>\n")
    (tmp_path / "data.test").write_text("not xml at all\n")
    names = [os.path.basename(f.path) for f in discover([str(tmp_path)])]
    assert names == ["tf.test"]
    result = lint_paths([str(tmp_path)])
    assert [t.child for t in result.transforms] == ["b"]


def test_a_pytest_module_named_like_a_launch_test_is_not_a_broken_launch_file(
    tmp_path: Path,
) -> None:
    (tmp_path / "test_talker_launch.py").write_text("def test_x():\n    assert True\n")
    (tmp_path / "other_launch.py").write_text("def test_x():\n    assert True\n")
    messages = {os.path.basename(d.path): d.message for d in lint_paths([str(tmp_path)])
                .diagnostics}
    assert "test_talker_launch.py" not in messages
    assert "not a launch file" in messages["other_launch.py"]


def test_an_empty_run_says_so_and_a_missing_path_is_a_usage_error(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.chdir(tmp_path)
    assert main(["check", str(tmp_path)]) == 0
    assert "No files found" in capsys.readouterr().err
    assert main(["check", "missing.launch"]) == 2
    assert "missing.launch" in capsys.readouterr().err
