"""Every case of the hostile corpus, linted with a good file by the real command line in a
child process held to 10 s of CPU and 1 GB of memory (the issue's standard)."""

from __future__ import annotations

import json
import os
import re
import resource
import subprocess
import sys
from pathlib import Path
from typing import Any

import pytest
from hostile_cases import CASES, GOOD

SRC = str(Path(__file__).resolve().parents[2] / "src")
CPU_SECONDS = 10
MEMORY_BYTES = 1024 * 1024 * 1024
_LINE = re.compile(r"^.+:\d+:\d+: (error|warning|info): .* \[[a-z_0-9]+\]$")


def _limits() -> None:
    resource.setrlimit(resource.RLIMIT_CPU, (CPU_SECONDS, CPU_SECONDS))
    resource.setrlimit(resource.RLIMIT_AS, (MEMORY_BYTES, MEMORY_BYTES))


def run(*args: str, cwd: Path | None = None) -> subprocess.CompletedProcess[bytes]:
    """The command line in a child process with the CPU and memory limits (a wall-clock
    timeout only guards against a hang that uses no CPU, such as a blocked open)."""
    return subprocess.run(
        [sys.executable, "-m", "launch_linter", *args], capture_output=True, timeout=120,
        check=False, preexec_fn=_limits, cwd=cwd,
        env={**os.environ, "PYTHONPATH": SRC, "NO_COLOR": "1"},
    )


@pytest.fixture(scope="module")
def good(tmp_path_factory: pytest.TempPathFactory) -> str:
    folder = tmp_path_factory.mktemp("good")
    path = folder / "good.launch"
    path.write_text(GOOD)
    return str(path)


def _survived(done: subprocess.CompletedProcess[bytes]) -> str:
    stderr = done.stderr.decode("utf-8", "replace")
    assert done.returncode in (0, 1), (done.returncode, stderr[-2000:])
    assert "Traceback" not in stderr and "internal error" not in stderr, stderr[-2000:]
    return done.stdout.decode("utf-8")


@pytest.mark.parametrize("name", sorted(CASES))
def test_hostile_case(name: str, good: str, tmp_path: Path) -> None:
    case = CASES[name]
    target = case.build(tmp_path)
    done = run("check", target, good, "--format", "json", "--beliefs", "none")
    document: dict[str, Any] = json.loads(_survived(done))
    files = {f["path"]: f for f in document["files"]}
    # Every other input is reported, and reported well.
    assert files[good]["status"] == "ok" and files[good]["transforms"] == 1, files
    assert all(f["status"] != "internal_error" for f in files.values()), files
    hostile = [p for p in files if p != good]
    assert hostile, files
    if case.category == "discovery":
        assert any(files[p]["transforms"] == 1 for p in hostile), files
        return
    if name.startswith("bom_"):
        assert all(files[p]["status"] == "ok" and files[p]["transforms"] >= 1 for p in hostile)
        return
    # The hostile file has its status; what the case is about is said where it happens.
    messages = [d["message"] for d in document["diagnostics"] if d["path"] != good]
    assert not case.expect or any(case.expect in m for m in messages), (case.expect, messages)


@pytest.mark.parametrize("name", sorted(n for n, c in CASES.items() if c.category == "forged"))
def test_forged_output_stays_one_line_per_finding(name: str, good: str, tmp_path: Path) -> None:
    target = CASES[name].build(tmp_path)
    text = _survived(run("check", target, good, "--beliefs", "none"))
    for line in text.splitlines():
        assert _LINE.match(line), line
        assert "\x1b" not in line and "\x00" not in line and "\u202e" not in line, line
    assert "forged [self_transform]" not in "\n".join(
        line for line in text.splitlines() if line.startswith("good.launch"))
    transforms = _survived(run("transforms", target, good))
    json_done = json.loads(_survived(run("transforms", target, good, "--format", "json")))
    assert len(transforms.splitlines()) == len(json_done["transforms"])
    assert "\x1b" not in transforms and "\x00" not in transforms
    for fmt in ("sarif", "github"):
        out = _survived(run("check", target, "--format", fmt, "--beliefs", "none"))
        assert "NaN" not in out.replace("NaN or infinite", "").replace("holds NaN", "")
        assert "\x1b" not in out and "\x00" not in out


def test_graphs_of_forged_names(tmp_path: Path) -> None:
    target = CASES["forged_python"].build(tmp_path)
    for suffix in (".dot", ".mmd"):
        output = tmp_path / f"graph{suffix}"
        done = run("graph", target, "-o", str(output))
        assert done.returncode == 0, done.stderr
        data = output.read_bytes()
        data.decode("utf-8")
        assert b"\x00" not in data and b"\x1b" not in data


@pytest.mark.parametrize("argv", [
    ["check", "{good}", "--min-z", "nan"],
    ["check", "{good}", "--min-z", "inf"],
    ["check", "{good}", "--min-z", "-1e309"],
    ["check", "{good}", "--beliefs", "/dev/zero"],
    ["check", "{good}", "--beliefs", "{tmp}/deep.json"],
    ["check", "{good}", "--beliefs", "{tmp}/nan.json"],
    ["check", "{good}", "--beliefs", "{tmp}"],
    ["check", "{good}", "--config", "/dev/zero"],
    ["check", "{good}", "--config", "{tmp}/deep.toml"],
    ["check", "{good}", "--config", "{tmp}/nan.toml"],
    ["check", "{good}", "--jobs", "100000000"],
    ["beliefs", "--db", "/dev/zero"],
    ["beliefs", "--db", "{tmp}"],
    ["beliefs", "--db", "{tmp}/nan.json"],
    ["mine", "{tmp}", "--db", "{tmp}/x.db", "--p0", "nan"],
])
def test_bad_command_line_values_are_usage_errors(argv: list[str], good: str,
                                                  tmp_path: Path) -> None:
    (tmp_path / "deep.json").write_text("[" * 100_000 + "]" * 100_000)
    (tmp_path / "nan.json").write_text(
        '{"format": "launch-linter-beliefs/1", "p0": 0.9, "beliefs": '
        '[{"class": "sig_implication", "if": ["a", "b"], "then": ["c", "d"], '
        '"n": 3, "e": 3, "z": NaN}]}')
    (tmp_path / "deep.toml").write_text("a = " + "[" * 100_000 + "]" * 100_000)
    (tmp_path / "nan.toml").write_text("min-z = nan\n")
    done = run(*(a.format(good=good, tmp=tmp_path) for a in argv))
    stderr = done.stderr.decode("utf-8", "replace")
    assert done.returncode == 2, stderr
    assert "Traceback" not in stderr and "internal error" not in stderr, stderr
