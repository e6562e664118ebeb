"""The GitHub Action's steps, run as the runner would: each ``run`` script of action.yml in
bash, in a temporary repository, with the environment GitHub gives a composite action's
steps (``GITHUB_ACTION_PATH`` = this checkout, ``GITHUB_WORKSPACE``, ``GITHUB_OUTPUT``,
``GITHUB_PATH``, ``RUNNER_TEMP``, ...), each step's ``env`` with its ``${{ inputs.* }}``
filled in, and what one step appends to ``GITHUB_PATH`` on the next one's ``PATH``.

The install step builds and installs the package from this checkout with pip (network for
the locked dependencies), once for the module.
"""

from __future__ import annotations

import json
import os
import re
import subprocess
from pathlib import Path
from typing import Any

import pytest

yaml = pytest.importorskip("yaml")

ROOT = Path(__file__).resolve().parent.parent
ACTION = yaml.safe_load((ROOT / "action.yml").read_text())
EXPRESSION = re.compile(r"\$\{\{\s*inputs\.([\w-]+)\s*\}\}")
BAD = """<launch>
  <node pkg="tf2_ros" type="static_transform_publisher" name="a"
        args="0 0 0 0 0 0 base_link laser"/>
  <node pkg="tf2_ros" type="static_transform_publisher" name="b"
        args="0 0 0 0 0 0 mount laser"/>
</launch>
"""


def step(step_id_or_index: str | int) -> dict[str, Any]:
    steps = ACTION["runs"]["steps"]
    if isinstance(step_id_or_index, int):
        return dict(steps[step_id_or_index])
    (found,) = [s for s in steps if s.get("id") == step_id_or_index]
    return dict(found)


class Runner:
    """One job: a repository, the runner's files, and the PATH additions so far."""

    def __init__(self, tmp: Path) -> None:
        self.repo = tmp / "repo"
        self.repo.mkdir()
        subprocess.run(["git", "init", "-q", str(self.repo)], check=True)
        self.temp = tmp / "runner-temp"
        self.temp.mkdir()
        self.files = {name: tmp / name for name in
                      ("GITHUB_OUTPUT", "GITHUB_PATH", "GITHUB_ENV", "GITHUB_STEP_SUMMARY")}
        for file in self.files.values():
            file.touch()

    def inputs(self, given: dict[str, str]) -> dict[str, str]:
        defaults = {name: str(spec.get("default", "")) for name, spec in
                    ACTION["inputs"].items()}
        return {**defaults, **given}

    def run(self, definition: dict[str, Any],
            given: dict[str, str]) -> subprocess.CompletedProcess[str]:
        inputs = self.inputs(given)
        env = {k: v for k, v in os.environ.items() if k not in ("VIRTUAL_ENV", "PYTHONPATH")}
        added = self.files["GITHUB_PATH"].read_text().split()
        env["PATH"] = os.pathsep.join([*reversed(added), env["PATH"]])
        env.update({name: str(path) for name, path in self.files.items()})
        env.update(GITHUB_ACTION_PATH=str(ROOT), GITHUB_WORKSPACE=str(self.repo),
                   RUNNER_TEMP=str(self.temp), GITHUB_ACTIONS="true", CI="true")
        for name, value in definition.get("env", {}).items():
            env[name] = EXPRESSION.sub(lambda m: inputs[m.group(1)], str(value))
        assert definition["shell"] == "bash"
        script = self.temp / "step.sh"
        script.write_text(definition["run"])
        # how the runner runs a bash step
        return subprocess.run(["bash", "--noprofile", "--norc", "-eo", "pipefail", str(script)],
                              cwd=self.repo, env=env, capture_output=True, text=True,
                              check=False, timeout=600)

    def outputs(self) -> dict[str, str]:
        lines = self.files["GITHUB_OUTPUT"].read_text().splitlines()
        return dict(line.split("=", 1) for line in lines)


@pytest.fixture(scope="module")
def runner(tmp_path_factory: pytest.TempPathFactory) -> Runner:
    job = Runner(tmp_path_factory.mktemp("action"))
    installed = job.run(step(0), {})
    assert installed.returncode == 0, installed.stdout + installed.stderr
    return job


def test_run_scripts_take_inputs_only_through_the_environment() -> None:
    # an input spliced into a script is a shell injection; env values are not
    for definition in ACTION["runs"]["steps"]:
        assert "${{" not in definition.get("run", "")


def test_install_puts_the_command_on_path(runner: Runner) -> None:
    (added,) = runner.files["GITHUB_PATH"].read_text().split()
    assert (Path(added) / "launch-linter").is_file()
    assert str(Path(added)).startswith(str(runner.temp))


def test_findings_fail_the_step_with_annotations_and_sarif(runner: Runner) -> None:
    (runner.repo / "launch").mkdir(exist_ok=True)
    (runner.repo / "launch" / "robot.launch").write_text(BAD)
    done = runner.run(step("lint"), {"paths": "launch", "sarif-file": "out/ll.sarif"})
    assert done.returncode == 1, done.stdout + done.stderr
    assert "::error file=launch/robot.launch,line=4" in done.stdout
    assert "multiple_parents" in done.stdout
    sarif = json.loads((runner.repo / "out" / "ll.sarif").read_text())
    results = sarif["runs"][0]["results"]
    assert any(r["ruleId"] == "multiple_parents" for r in results)
    assert results[0]["locations"][0]["physicalLocation"]["artifactLocation"]["uri"] == (
        "launch/robot.launch")
    assert runner.outputs()["sarif-file"] == "out/ll.sarif"
    assert runner.outputs()["exit-code"] == "1"


def test_fail_on_and_extra_arguments(runner: Runner) -> None:
    (runner.repo / "launch").mkdir(exist_ok=True)
    (runner.repo / "launch" / "robot.launch").write_text(BAD)
    done = runner.run(step("lint"), {"paths": "launch", "fail-on": "error",
                                     "args": "--ignore multiple_parents"})
    assert done.returncode == 0, done.stdout + done.stderr
    assert "multiple_parents" not in done.stdout
    assert (runner.repo / "launch-linter.sarif").is_file()
