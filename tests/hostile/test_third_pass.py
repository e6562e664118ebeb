"""The third red-team pass (issue 22), each case by the real command line under 10 s of
CPU and 1 GB of memory. A launch file is linted together with a good file; a folder whose
own files are the attack (configuration, ``.gitignore``, folders) is linted alone, as
``check DIR``, and the launch file in it must be reported."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import pytest
from test_hostile_corpus import _survived, run
from third_pass import THIRD_PASS, remove_nested_folders


@pytest.fixture(scope="module")
def good(tmp_path_factory: pytest.TempPathFactory) -> str:
    from hostile_cases import GOOD

    path = tmp_path_factory.mktemp("good") / "good.launch"
    path.write_text(GOOD)
    return str(path)


@pytest.mark.parametrize("name", sorted(THIRD_PASS))
def test_third_pass_case(name: str, good: str, tmp_path: Path) -> None:
    case = THIRD_PASS[name]
    target = case.build(tmp_path)
    if case.category == "discovery":
        try:
            document: dict[str, Any] = json.loads(
                _survived(run("check", target, "--format", "json")))
        finally:
            if name == "nested_folders":
                remove_nested_folders(tmp_path)
        assert any(f["status"] == "ok" and f["transforms"] == 1 for f in document["files"]), \
            document["files"]
        return
    document = json.loads(_survived(run("check", target, good, "--format", "json",
                                        "--beliefs", "none")))
    files = {f["path"]: f for f in document["files"]}
    assert files[good]["status"] == "ok" and files[good]["transforms"] == 1, files
    assert all(f["status"] != "internal_error" for f in files.values()), files
    messages = [d["message"] for d in document["diagnostics"] if d["path"] != good]
    assert not case.expect or any(case.expect in m for m in messages), (case.expect, messages)


def test_a_huge_beliefs_file_named_by_a_repository_is_a_usage_error(tmp_path: Path) -> None:
    from third_pass import _big_beliefs

    done = run("check", _big_beliefs(tmp_path))
    stderr = done.stderr.decode("utf-8", "replace")
    assert done.returncode == 2 and "larger than" in stderr, stderr
    assert "Traceback" not in stderr and "MemoryError" not in stderr, stderr


FORGING = "&#10;x.launch:1:1: error: forged [self_transform]&#x85;&#x9b;2J&#x202e;"


def test_urdf_names_are_escaped_in_transforms(tmp_path: Path) -> None:
    from third_pass import _package

    package = _package(tmp_path, "forge")
    (package / "urdf" / "r.urdf").write_text(
        f'<robot name="r"><link name="base{FORGING}"/><link name="arm{FORGING}"/>'
        f'<joint name="j{FORGING}" type="fixed"><parent link="base{FORGING}"/>'
        f'<child link="arm{FORGING}"/></joint></robot>')
    launch = package / "launch" / "r.launch"
    launch.write_text('<launch><param name="robot_description" '
                      'command="$(find xacro)/xacro $(find forge)/urdf/r.urdf"/>'
                      '<node pkg="robot_state_publisher" type="robot_state_publisher" '
                      'name="rsp"/></launch>')
    out = _survived(run("transforms", str(launch)))
    assert "urdf fixed joint" in out
    # One line per edge: a newline in a name cannot start a line of its own.
    assert len(out.splitlines()) == 1, out
    assert all(line.startswith(str(package)) for line in out.splitlines()), out
    assert "\x85" not in out and "\x9b" not in out and "\u202e" not in out


def test_diff_headers_escape_the_file_name(tmp_path: Path) -> None:
    name = "odd\n+++ forged\n@@ -1 +1 @@\x1b[31m.launch"
    path = tmp_path / name
    path.write_text('<launch><node pkg="tf" type="static_transform_publisher" name="n" '
                    'args="0 0 0 0 0 0 a /b 100"/></launch>\n')
    done = run("check", str(path), "--diff")
    assert done.returncode == 1, done.stderr
    lines = done.stdout.decode().splitlines()
    assert [line[:3] for line in lines[:2]] == ["---", "+++"] and len(lines) == 5, lines
    assert "\x1b" not in done.stdout.decode()


@pytest.mark.parametrize("fmt", ["text", "json", "sarif", "junit", "gitlab", "github"])
def test_every_format_keeps_controls_and_bidi_inert(tmp_path: Path, fmt: str) -> None:
    """A file name and node name with a newline, ESC, C1 controls, separators and a bidi
    override: no output format carries them raw (JSON ones escape them as ``\\uNNNN``)."""
    path = tmp_path / "odd\n+x\x1b[2J\u202e\x85\u2028.launch"
    path.write_text('<launch><node pkg="tf" type="static_transform_publisher" '
                    'name="n&#x1b;]0;x&#x7;&#x9b;&#x202e;" args="0 0 0 0 0 0 a a 100"/>'
                    "</launch>")
    out = _survived(run("check", str(path), "--format", fmt))
    raw = [c for c in out if (ord(c) < 32 and c not in "\n\t") or 0x7F <= ord(c) < 0xA0
           or c in "\u2028\u2029\u202e"]
    assert raw == [], (fmt, raw)
    if fmt in ("json", "sarif", "gitlab"):
        assert "\u202e" in json.dumps(json.loads(out), ensure_ascii=False)
