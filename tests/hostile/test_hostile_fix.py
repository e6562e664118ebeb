"""``--fix`` on hostile files (the third red-team pass): it edits only the words a finding
names, only in files under the paths given, atomically, and skips when anything disagrees.
Each case runs the real command line under the 10 s / 1 GB limit."""

from __future__ import annotations

import os
import stat
import subprocess
import sys
from pathlib import Path

import pytest
from test_hostile_corpus import SRC, _limits, run

from launch_linter.commands.fix_write import WriteGuard, write_atomically
from launch_linter.engine import lint_bytes
from launch_linter.fix import apply_edits

TF = 'pkg="tf" type="static_transform_publisher"'


def node(name: str, frames: str = "a /b") -> str:
    return f'<node {TF} name="{name}" args="0 0 0 0 0 0 {frames} 100"/>'


def _fixed(done: subprocess.CompletedProcess[bytes]) -> str:
    stderr = done.stderr.decode("utf-8", "replace")
    assert done.returncode in (0, 1), stderr
    assert "Traceback" not in stderr and "internal error" not in stderr, stderr
    return stderr


@pytest.mark.parametrize("before", [
    "<!-- a lone CR\r here -->",  # expat counts a lone CR as a line end
    "<!-- CRLF\r\n here -->\r\n",
    "<!-- é, ünïcode, 日本語 -->",  # expat's columns count characters, not bytes
    "\t<!-- \u2028 a separator that is no line end -->",
])
def test_the_xml_edit_lands_on_its_own_words(tmp_path: Path, before: str) -> None:
    # The decoy before the node reads the same; a line table that disagreed with the
    # parser (or a column used as a byte offset) edited the decoy.
    text = f'<launch>{node("decoy")}\n{before}{node("target")}</launch>\n'
    path = tmp_path / "a.launch"
    path.write_bytes(text.encode())
    _fixed(run("check", str(path), "--fix", "--select", "leading_slash"))
    after = path.read_bytes().decode()
    assert after == text.replace("a /b", "a b"), after


def test_a_miss_is_skipped_never_moved_to_another_node(tmp_path: Path) -> None:
    path = tmp_path / "a.launch"
    text = f"<launch>{node('x')}</launch>"
    path.write_text(text)
    (diagnostic,) = [d for d in lint_bytes(text.encode(), str(path)).diagnostics
                     if d.fix is not None]
    assert diagnostic.fix is not None
    shifted = ("é" + text).encode()  # the words moved: nothing is where the fix says
    skipped: list[str] = []
    out, applied = apply_edits(shifted, [diagnostic.fix], skipped)
    assert out == shifted and applied == [] and "no longer holds '/b'" in skipped[0]


@pytest.mark.parametrize("newline", ["\r", "\r\n"])
def test_python_edit_with_lone_cr_and_bom(tmp_path: Path, newline: str) -> None:
    text = newline.join([
        "from launch import LaunchDescription",
        "from launch_ros.actions import Node  # é\u00a0ü",
        "def generate_launch_description():",
        "    return LaunchDescription([Node(package='tf2_ros', "
        "executable='static_transform_publisher', name='é',",
        "        arguments=['0', '0', '0', '0', '0', '0', 'a', '/b'])])",
        ""])
    path = tmp_path / "a.launch.py"
    path.write_bytes(b"\xef\xbb\xbf" + text.encode())
    _fixed(run("check", str(path), "--fix", "--select", "leading_slash"))
    assert path.read_bytes() == b"\xef\xbb\xbf" + text.replace("'/b'", "'b'").encode()


def test_fix_never_writes_outside_the_paths_given(tmp_path: Path) -> None:
    outside = tmp_path / "outside"
    outside.mkdir()
    (outside / "inc.launch").write_text(f"<launch>{node('inc')}</launch>")
    (outside / "abs.launch").write_text(f"<launch>{node('abs')}</launch>")
    (outside / "linked.launch").write_text(f"<launch>{node('linked')}</launch>")
    tree = tmp_path / "tree"
    tree.mkdir()
    os.symlink(str(outside / "linked.launch"), str(tree / "link.launch"))
    root = tree / "root.launch"
    root.write_text(f'<launch><include file="../outside/inc.launch"/>'
                    f'<include file="{outside / "abs.launch"}"/>{node("root")}</launch>')
    before = {p: p.read_bytes() for p in outside.iterdir()}
    stderr = _fixed(run("check", ".", "--fix", "--select", "leading_slash", cwd=tree))
    assert {p: p.read_bytes() for p in outside.iterdir()} == before
    assert os.path.islink(tree / "link.launch")
    assert "a b" in root.read_text()
    assert stderr.count("not under the paths given") == 2, stderr
    assert "symbolic link leads it out" in stderr, stderr


def test_output_file_is_never_an_input(tmp_path: Path) -> None:
    path = tmp_path / "g.launch"
    text = f"<launch>{node('g')}</launch>"
    path.write_text(text)
    for extra in ([], ["--fix"]):
        done = run("check", "-o", str(path), str(path), *extra)
        assert done.returncode == 2, done.stderr
        assert b"refusing to overwrite" in done.stderr
    assert path.read_text() == text


def test_stdin_keeps_its_encoding() -> None:
    # Read as UTF-8 with replacement, é became U+FFFD (three bytes) and the edit shifted.
    text = ('<?xml version="1.0" encoding="ISO-8859-1"?>\n<launch><!-- é à -->'
            f'{node("é")}</launch>\n')
    done = subprocess.run(
        [sys.executable, "-m", "launch_linter", "check", "-", "--fix"],
        input=text.encode("latin-1"), capture_output=True, timeout=120, check=False,
        preexec_fn=_limits, env={**os.environ, "PYTHONPATH": SRC})
    assert done.stdout == text.replace("a /b", "a b").encode("latin-1"), done.stderr


def test_write_is_atomic_keeps_the_mode_and_refuses_a_changed_file(tmp_path: Path) -> None:
    path = tmp_path / "a.launch"
    path.write_bytes(b"old")
    os.chmod(path, 0o640)
    inode = os.stat(path).st_ino
    assert write_atomically(str(path), b"changed", b"new") == "it changed since it was read"
    assert path.read_bytes() == b"old"
    assert write_atomically(str(path), b"old", b"new") is None
    assert path.read_bytes() == b"new" and stat.S_IMODE(os.stat(path).st_mode) == 0o640
    assert os.stat(path).st_ino != inode  # a new file renamed over the old one
    assert sorted(os.listdir(tmp_path)) == ["a.launch"]  # no temporary file left


def test_write_guard(tmp_path: Path) -> None:
    (tmp_path / "in").mkdir()
    inside = tmp_path / "in" / "a.launch"
    inside.write_text("x")
    guard = WriteGuard([str(tmp_path / "in")], [str(inside)])
    assert guard.refusal(str(inside)) == "it is the report's output file"
    assert WriteGuard([str(tmp_path / "in")]).refusal(str(inside)) is None
    os.mkfifo(str(tmp_path / "in" / "fifo.launch"))
    assert WriteGuard([str(tmp_path)]).refusal(
        str(tmp_path / "in" / "fifo.launch")) == "it is not a regular file"
