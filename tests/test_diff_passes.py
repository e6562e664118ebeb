"""``check --diff`` shows what ``--fix`` writes: ``--fix`` fixes, lints again and fixes
again until nothing changes (fixes that overlap wait for the next pass), and ``--diff``
runs the same passes on the texts fixed so far, so applying its output with ``git apply``
gives the bytes ``--fix`` writes."""

from __future__ import annotations

from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from tests.test_diff import _applied

from launch_linter.cli import main

TWO_PASSES = """\
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='tf2_ros', executable='static_transform_publisher',
             arguments=['0', '0', '0', '0', '0', '0', '/map', '/odom']),
    ])
"""
"""Both frames' leading slashes and the positional form: the flags rewrite overlaps the
slash fixes, so it waits for the second pass."""

HUMBLE = ("--ros-distro", "humble", "--unsafe-fixes", "--no-cache")


def _diff(capsysbinary: pytest.CaptureFixture[bytes], *argv: str) -> bytes:
    capsysbinary.readouterr()
    main(["check", *argv, "--diff"])
    return capsysbinary.readouterr().out


def _diff_then_fix(folder: Path, files: dict[str, bytes], argv: tuple[str, ...],
                   capsysbinary: pytest.CaptureFixture[bytes],
                   monkeypatch: pytest.MonkeyPatch) -> None:
    """Apply ``--diff``'s output in ``folder/patched`` and run ``--fix`` in
    ``folder/fixed``: the same bytes, and nothing left for another ``--diff``."""
    for side in ("patched", "fixed"):
        for name, data in files.items():
            (folder / side / name).parent.mkdir(parents=True, exist_ok=True)
            (folder / side / name).write_bytes(data)
    monkeypatch.chdir(folder / "patched")
    patch = _diff(capsysbinary, ".", *argv)
    if patch:
        _applied(folder / "patched", patch)
    assert _diff(capsysbinary, ".", *argv) == b""
    monkeypatch.chdir(folder / "fixed")
    main(["check", ".", *argv, "--fix"])
    capsysbinary.readouterr()
    for name in files:
        assert (folder / "patched" / name).read_bytes() == (folder / "fixed" / name).read_bytes()


def test_a_fix_of_the_second_pass_is_in_the_diff(
    tmp_path: Path, capsysbinary: pytest.CaptureFixture[bytes], monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.chdir(tmp_path)
    Path("a.launch.py").write_text(TWO_PASSES)
    patch = _diff(capsysbinary, "a.launch.py", *HUMBLE)
    assert b"+             arguments=['--x', '0', '--y', '0', '--z', '0', '--yaw', '0', " \
           b"'--pitch', '0', '--roll', '0', '--frame-id', 'map', '--child-frame-id', 'odom'])" \
           in patch
    assert Path("a.launch.py").read_text() == TWO_PASSES  # --diff changes no file
    _diff_then_fix(tmp_path, {"a.launch.py": TWO_PASSES.encode()}, HUMBLE, capsysbinary,
                   monkeypatch)


def test_the_summary_counts_the_fixes_of_every_pass(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.chdir(tmp_path)
    Path("a.launch.py").write_text(TWO_PASSES)
    assert main(["check", "a.launch.py", "--diff", *HUMBLE]) == 1
    assert "Would fix 3 findings." in capsys.readouterr().err
    main(["check", "a.launch.py", "--fix", *HUMBLE])
    assert "fixed 3 finding(s)" in capsys.readouterr().err


def test_parallel_workers_lint_the_fixed_texts(
    tmp_path: Path, capsysbinary: pytest.CaptureFixture[bytes], monkeypatch: pytest.MonkeyPatch
) -> None:
    files = {f"p{i}/a.launch.py": TWO_PASSES.encode() for i in range(3)}
    _diff_then_fix(tmp_path, files, (*HUMBLE, "--jobs", "2"), capsysbinary, monkeypatch)


def test_a_file_fix_would_not_write_is_not_in_the_diff(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    """An included file outside the paths given: reported, not fixed, not in the diff."""
    (tmp_path / "outside").mkdir()
    (tmp_path / "outside" / "inc.launch").write_text(
        '<launch><node pkg="tf" type="static_transform_publisher" name="s" '
        'args="0 0 0 0 0 0 /map odom 100"/></launch>\n')
    (tmp_path / "pkg").mkdir()
    (tmp_path / "pkg" / "root.launch").write_text(
        '<launch><include file="$(dirname)/../outside/inc.launch"/></launch>\n')
    monkeypatch.chdir(tmp_path / "pkg")
    assert main(["check", ".", "--diff", "--no-cache"]) == 0
    out, err = capsys.readouterr()
    assert out == ""
    assert "fixes not shown: --fix would not write it" in err


# -- a property: random fixable files, every fix kind, one or more passes ----------------

_FRAMES = st.sampled_from(["map", "/map", "odom", "/odom", "base_link", "/laser"])
_NUMBERS = st.sampled_from(["0", "1.5", "-2", "90", "180", "0.7071", "1", "0.5"])


@st.composite
def _ros2_python(draw: st.DrawFn) -> bytes:
    nodes = []
    for _ in range(draw(st.integers(1, 3))):
        values = draw(st.lists(_NUMBERS, min_size=3, max_size=7))
        words = [*values, draw(_FRAMES), draw(_FRAMES)]
        nodes.append("        Node(package='tf2_ros', executable='static_transform_publisher',\n"
                     f"             arguments=[{', '.join(repr(w) for w in words)}]),\n")
    return ("from launch import LaunchDescription\nfrom launch_ros.actions import Node\n\n\n"
            "def generate_launch_description():\n    return LaunchDescription([\n"
            + "".join(nodes) + "    ])\n").encode()


@st.composite
def _ros1_xml(draw: st.DrawFn) -> bytes:
    nodes = []
    for index in range(draw(st.integers(1, 3))):
        values = draw(st.lists(_NUMBERS, min_size=6, max_size=7))
        words = " ".join([*values, draw(_FRAMES), draw(_FRAMES), "100"])
        nodes.append(f'  <node pkg="tf" type="static_transform_publisher" name="s{index}" '
                     f'args="{words}"/>\n')
    return ("<launch>\n" + "".join(nodes) + "</launch>\n").encode()


@settings(max_examples=12, deadline=None,
          suppress_health_check=[HealthCheck.function_scoped_fixture, HealthCheck.too_slow])
@given(ros2=_ros2_python(), ros1=_ros1_xml(), final_newline=st.booleans())
def test_applying_the_diff_is_running_fix(
    tmp_path_factory: pytest.TempPathFactory, capsysbinary: pytest.CaptureFixture[bytes],
    monkeypatch: pytest.MonkeyPatch, ros2: bytes, ros1: bytes, final_newline: bool,
) -> None:
    cut = (lambda data: data) if final_newline else (lambda data: data.rstrip(b"\n"))
    files = {"a.launch.py": cut(ros2), "b.launch": cut(ros1)}
    _diff_then_fix(tmp_path_factory.mktemp("passes"), files, HUMBLE, capsysbinary,
                   monkeypatch)
