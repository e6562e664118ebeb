"""Configuration files: discovery, checking, and command-line precedence."""

from __future__ import annotations

import json
import os
from pathlib import Path

import pytest

from launch_linter.cli import main
from launch_linter.model import Severity
from launch_linter.workspace.config import ConfigError, config_for, find_config, load_config

NODE = '<node pkg="tf2_ros" type="static_transform_publisher" name="{name}" args="{args}"/>'


def launch(*nodes: tuple[str, str]) -> str:
    body = "\n".join("  " + NODE.format(name=n, args=a) for n, a in nodes)
    return f"<launch>\n{body}\n</launch>\n"


# self_transform (error) on line 2, leading_slash (info) on line 3
ROBOT = launch(("a", "0 0 0 0 0 0 base_link base_link"), ("b", "0 0 1 0 0 0 map /odom"))


@pytest.fixture
def project(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    """A project folder (the working directory) with ``launch/robot.launch``."""
    (tmp_path / "launch").mkdir()
    (tmp_path / "launch" / "robot.launch").write_text(ROBOT)
    monkeypatch.chdir(tmp_path)
    return tmp_path


def check(capsys: pytest.CaptureFixture[str], *argv: str) -> tuple[int, list[tuple[str, str]], str]:
    """Run ``check --format json``: (status, [(rule, severity)], stderr)."""
    status = main(["check", "--format", "json", *argv])
    out, err = capsys.readouterr()
    if status == 2:
        return status, [], err
    document = json.loads(out)
    return status, [(d["rule"], d["severity"]) for d in document["diagnostics"]], err


BOTH = [("self_transform", "error"), ("leading_slash", "info")]


def test_no_config_file(project: Path, capsys: pytest.CaptureFixture[str]) -> None:
    assert check(capsys, "--beliefs", "none", "launch") == (1, BOTH, "")


def test_launch_linter_toml_found_by_walking_up(
    project: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    (project / ".launch-linter.toml").write_text('ignore = ["leading_slash"]\nbeliefs = "none"\n')
    status, found, _ = check(capsys, "launch/robot.launch")
    assert (status, found) == (1, [("self_transform", "error")])
    assert find_config(str(project / "launch" / "robot.launch")) == str(
        project / ".launch-linter.toml"
    )


def test_pyproject_table(project: Path, capsys: pytest.CaptureFixture[str]) -> None:
    (project / "pyproject.toml").write_text(
        '[project]\nname = "x"\n\n[tool.launch-linter]\nselect = ["tf"]\nbeliefs = "none"\n'
    )
    assert check(capsys, "launch")[1] == [("leading_slash", "info")]


def test_pyproject_without_the_table_is_passed_over(project: Path) -> None:
    (project / "launch" / "pyproject.toml").write_text('[project]\nname = "x"\n')
    (project / ".launch-linter.toml").write_text('select = ["tf"]\n')
    assert find_config(str(project / "launch" / "robot.launch")) == str(
        project / ".launch-linter.toml"
    )


def test_launch_linter_toml_wins_over_pyproject_in_one_folder(project: Path) -> None:
    (project / "pyproject.toml").write_text('[tool.launch-linter]\nselect = ["must"]\n')
    (project / ".launch-linter.toml").write_text('select = ["tf"]\n')
    assert load_config(str(find_config("launch"))).select == ("tf",)


def test_explicit_config_file(project: Path, capsys: pytest.CaptureFixture[str]) -> None:
    (project / ".launch-linter.toml").write_text('select = ["tf"]\n')
    (project / "strict.toml").write_text('select = ["must"]\nbeliefs = "none"\n')
    found = check(capsys, "--config", "strict.toml", "launch")[1]
    assert found == [("self_transform", "error")]


def test_command_line_overrides_the_file(project: Path, capsys: pytest.CaptureFixture[str]) -> None:
    (project / ".launch-linter.toml").write_text(
        'ignore = ["leading_slash"]\nfail-on = "error"\nbeliefs = "none"\n'
    )
    assert check(capsys, "launch")[:2] == (1, [("self_transform", "error")])
    assert check(capsys, "--ignore", "self_transform", "launch")[:2] == (
        0, [("leading_slash", "info")]
    )
    assert check(capsys, "--ignore", "self_transform", "--fail-on", "info", "launch")[0] == 1


def test_file_fail_on_applies(project: Path, capsys: pytest.CaptureFixture[str]) -> None:
    (project / ".launch-linter.toml").write_text(
        'ignore = ["self_transform"]\nfail-on = "error"\nbeliefs = "none"\n'
    )
    assert check(capsys, "launch")[0] == 0


def test_severity_by_rule_and_by_category(
    project: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    (project / ".launch-linter.toml").write_text(
        'beliefs = "none"\n[severity]\nmust = "info"\ntf = "error"\nleading_slash = "info"\n'
    )
    status, found, _ = check(capsys, "launch")
    assert (status, found) == (0, [("self_transform", "info"), ("leading_slash", "info")])
    config = load_config(str(project / ".launch-linter.toml"))
    assert config.severity["tf_cycle"] is Severity.ERROR
    assert config.severity["leading_slash"] is Severity.INFO


def test_args_and_env_from_file_and_command_line(
    project: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    (project / "launch" / "robot.launch").write_text(
        launch(("a", "0 0 0 0 0 0 $(arg parent) $(optenv CHILD odom)"))
    )
    (project / ".launch-linter.toml").write_text(
        'beliefs = "none"\n[args]\nparent = "base_link"\n[env]\nCHILD = "base_link"\n'
    )
    assert check(capsys, "launch")[1] == [("self_transform", "error")]
    assert check(capsys, "--arg", "parent:=map", "launch")[1] == []
    assert check(capsys, "--env", "CHILD=laser", "launch")[1] == []


def test_toml_scalars_become_launch_text(project: Path) -> None:
    (project / ".launch-linter.toml").write_text("[args]\nsim = true\nrate = 10\nscale = 0.5\n")
    assert load_config(".launch-linter.toml").args == {"sim": "true", "rate": "10", "scale": "0.5"}


def test_relative_paths_are_relative_to_the_file(project: Path) -> None:
    (project / "conf").mkdir()
    (project / "conf" / "lint.toml").write_text(
        'beliefs = "../beliefs.json"\npackage-path = ["../src", "/opt/ros"]\n'
    )
    config = load_config("conf/lint.toml")
    assert config.beliefs == str(project / "beliefs.json")
    assert config.package_path == (str(project / "src"), "/opt/ros")
    (project / "conf" / "lint.toml").write_text('beliefs = "study"\n')
    assert load_config("conf/lint.toml").beliefs == "study"


def test_per_path_ignores(project: Path, capsys: pytest.CaptureFixture[str]) -> None:
    (project / "launch" / "sim").mkdir()
    (project / "launch" / "sim" / "world.launch").write_text(ROBOT)
    (project / ".launch-linter.toml").write_text(
        'beliefs = "none"\n[per-path-ignores]\n"launch/sim/**" = ["must"]\n'
        '"robot.launch" = ["leading_slash"]\n'
    )
    status = main(["check", "--format", "json", "launch"])
    document = json.loads(capsys.readouterr().out)
    found = [(os.path.basename(d["path"]), d["rule"]) for d in document["diagnostics"]]
    assert status == 1
    assert found == [("robot.launch", "self_transform"), ("world.launch", "leading_slash")]


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ('slect = ["tf"]\n', "unknown key(s) 'slect' (did you mean 'select'?)"),
        ('select = ["dup_sgi"]\n', "unknown rule id(s) 'dup_sgi' (did you mean 'dup_sig'?)"),
        ('ignore = ["nonsense"]\n', "'ignore': unknown rule id(s) 'nonsense'"),
        ("[severity]\ndup_sig = 'fatal'\n", "'severity.dup_sig' must be error, warning or info"),
        ("[severity]\nnot_a_rule = 'info'\n", "'severity': unknown rule id(s) 'not_a_rule'"),
        ('[per-path-ignores]\n"a/*" = ["bogus"]\n', "unknown rule id(s) 'bogus'"),
        ('min-z = "high"\n', "'min-z' must be a number"),
        ('fail-on = "never"\n', "'fail-on' must be error, warning or info"),
        ("select = [1]\n", "'select' must be a list of strings"),
        ("args = 3\n", "'args' must be a table"),
        ("[args]\nx = [1]\n", "'args.x' must be a string, number or boolean"),
        ("select = [\n", "not valid TOML"),
    ],
)
def test_bad_files_are_usage_errors(
    project: Path, capsys: pytest.CaptureFixture[str], text: str, expected: str
) -> None:
    (project / ".launch-linter.toml").write_text(text)
    status, _, err = check(capsys, "--beliefs", "none", "launch")
    assert status == 2
    assert expected in err
    assert ".launch-linter.toml" in err


def test_pyproject_named_explicitly_needs_the_table(project: Path) -> None:
    (project / "pyproject.toml").write_text('[project]\nname = "x"\n')
    with pytest.raises(ConfigError, match=r"no \[tool.launch-linter\] table"):
        load_config("pyproject.toml")


def test_missing_explicit_file(project: Path, capsys: pytest.CaptureFixture[str]) -> None:
    status, _, err = check(capsys, "--config", "nowhere.toml", "launch")
    assert status == 2 and "cannot read configuration file nowhere.toml" in err


def test_paths_under_different_config_files(project: Path) -> None:
    (project / "a").mkdir()
    (project / "b").mkdir()
    (project / "a" / ".launch-linter.toml").write_text("")
    (project / "b" / ".launch-linter.toml").write_text("")
    with pytest.raises(ConfigError, match="different configuration files"):
        config_for(["a", "b"])
    assert config_for(["a", "b"], explicit="a/.launch-linter.toml").path == (
        "a/.launch-linter.toml"
    )


def test_transforms_command_reads_args_from_the_file(
    project: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    (project / "launch" / "robot.launch").write_text(
        launch(("a", "0 0 0 0 0 0 base_link $(arg child)"))
    )
    (project / ".launch-linter.toml").write_text('[args]\nchild = "laser"\n')
    assert main(["transforms", "--format", "json", "launch"]) == 0
    (transform,) = json.loads(capsys.readouterr().out)["transforms"]
    assert transform["child"] == "laser"
