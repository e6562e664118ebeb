"""``check --diff``: a patch that ``git apply`` and ``patch -p1`` accept for every file (no
final newline, Latin-1 bytes, a lone CR, a name with a newline), and the hint about the
fixes only ``--unsafe-fixes`` enables, as ruff words it."""

from __future__ import annotations

import shutil
import subprocess
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from launch_linter.cli import main
from launch_linter.report.diff import quoted_name, unified_diff

NODE = '<node pkg="tf" type="static_transform_publisher" name="a" args="0 0 0 0 0 0 {} 100"/>'
GIT = shutil.which("git")
PATCH = shutil.which("patch")


def _git_apply_check(folder: Path, patch: bytes) -> None:
    if GIT is None:
        pytest.skip("git is not installed")
    done = subprocess.run([GIT, "apply", "--check", "-"], cwd=folder, input=patch,
                          capture_output=True, check=False)
    assert done.returncode == 0, done.stderr.decode()


def _patch_dry_run(folder: Path, patch: bytes) -> None:
    if PATCH is None:
        pytest.skip("patch is not installed")
    done = subprocess.run([PATCH, "-p1", "--dry-run", "--batch", "--silent"], cwd=folder,
                          input=patch, capture_output=True, check=False)
    assert done.returncode == 0, (done.stdout + done.stderr).decode()


def _applied(folder: Path, patch: bytes) -> None:
    """Apply with git (which checks every byte of the context) into ``folder``."""
    if GIT is None:
        pytest.skip("git is not installed")
    done = subprocess.run([GIT, "apply", "-"], cwd=folder, input=patch, capture_output=True,
                          check=False)
    assert done.returncode == 0, done.stderr.decode()


def test_no_final_newline_is_marked_and_never_glues_the_next_header() -> None:
    first = unified_diff("a.launch", b"x\n/y", b"x\ny")
    assert first.endswith(b"-/y\n\\ No newline at end of file\n+y\n\\ No newline at end of file\n")
    second = unified_diff("b.launch", b"p\n", b"q\n")
    assert (first + second).count(b"\n--- a/b.launch\n") == 1


def test_only_the_last_line_gets_the_marker() -> None:
    patch = unified_diff("a.launch", b"a\nb\nc", b"a\nB\nc")
    assert patch == (b"--- a/a.launch\n+++ b/a.launch\n@@ -1,3 +1,3 @@\n a\n-b\n+B\n c\n"
                     b"\\ No newline at end of file\n")


def test_equal_files_give_nothing() -> None:
    assert unified_diff("a.launch", b"same", b"same") == b""


def test_names_that_could_forge_a_header_are_quoted() -> None:
    assert quoted_name("a/pkg/robot.launch") == b"a/pkg/robot.launch"
    assert quoted_name("a/x\n+++ b/evil") == b'"a/x\\n+++ b/evil"'
    assert quoted_name('a/t\tq"\\') == b'"a/t\\tq\\"\\\\"'
    assert quoted_name("a/é") == b'"a/\\303\\251"'


@pytest.mark.parametrize(
    ("name", "before", "after"),
    [
        ("plain.launch", b"<launch>\n  /a\n</launch>\n", b"<launch>\n  a\n</launch>\n"),
        ("nonl.launch", b"<launch>\n  /a\n</launch>", b"<launch>\n  a\n</launch>"),
        ("latin1.launch", b"<!-- caf\xe9 -->\n/a\n", b"<!-- caf\xe9 -->\na\n"),
        ("cr.launch", b"one\rtwo /a\nthree\x0cfour\n", b"one\rtwo a\nthree\x0cfour\n"),
        ("crlf.launch", b"a\r\n/b\r\nc", b"a\r\nb\r\nc"),
        ("new line\nname.launch", b"/a\n", b"a\n"),
        ("only.launch", b"", b"added"),
    ],
)
def test_git_and_patch_accept_it(tmp_path: Path, name: str, before: bytes, after: bytes) -> None:
    (tmp_path / name).write_bytes(before)
    patch = unified_diff(name, before, after)
    _git_apply_check(tmp_path, patch)
    if "\n" not in name:  # GNU patch reads quoted names, but not every version
        _patch_dry_run(tmp_path, patch)
    _applied(tmp_path, patch)
    assert (tmp_path / name).read_bytes() == after


_LINES = st.lists(st.sampled_from([b"a", b"b", b"/c", b"\r", b" d\x0c", b"\xe9", b""]),
                  max_size=12)


@settings(max_examples=40, deadline=None)
@given(before=_LINES, after=_LINES, end_before=st.booleans(), end_after=st.booleans())
def test_any_change_applies_with_git(
    tmp_path_factory: pytest.TempPathFactory, before: list[bytes], after: list[bytes],
    end_before: bool, end_after: bool,
) -> None:
    old = b"\n".join(before) + (b"\n" if end_before and before else b"")
    new = b"\n".join(after) + (b"\n" if end_after and after else b"")
    folder = tmp_path_factory.mktemp("apply")
    (folder / "f.launch").write_bytes(old)
    patch = unified_diff("f.launch", old, new)
    if old == new:
        assert patch == b""
        return
    _applied(folder, patch)
    assert (folder / "f.launch").read_bytes() == new


def test_check_diff_over_two_files_applies(
    tmp_path: Path, capsysbinary: pytest.CaptureFixture[bytes], monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.chdir(tmp_path)
    Path("pkg").mkdir()
    Path("pkg/a.launch").write_bytes(f"<launch>\n  {NODE.format('x /y')}\n</launch>".encode())
    Path("pkg/b.launch").write_bytes(
        f'<?xml version="1.0" encoding="ISO-8859-1"?>\n<launch>\n  <!-- caf\xe9 -->\n  '
        f"{NODE.format('/x y')}\n</launch>\n".encode("latin-1"))
    assert main(["check", str(tmp_path / "pkg"), "--diff"]) == 1
    out, err = capsysbinary.readouterr()
    assert out.startswith(b"--- a/pkg/")  # relative to the current folder, though given absolute
    assert b"Would fix 2 findings." in err
    _git_apply_check(tmp_path, out)
    _patch_dry_run(tmp_path, out)


ROS2 = ('<launch>\n  <node pkg="tf2_ros" exec="static_transform_publisher" '
        'args="1 0 0 0 0 0 map odom"/>\n</launch>\n')


def test_only_unsafe_fixes_say_how_to_enable_them(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.chdir(tmp_path)
    Path("a.launch.xml").write_text(ROS2)
    hint = "1 hidden fix can be enabled with the `--unsafe-fixes` option"
    assert main(["check", "a.launch.xml", "--diff"]) == 0
    out, err = capsys.readouterr()
    assert out == "" and f"No findings would be fixed ({hint})." in err
    main(["check", "a.launch.xml", "--fix"])
    out, err = capsys.readouterr()
    assert f"fixed 0 finding(s); {hint}." in err and Path("a.launch.xml").read_text() == ROS2
    main(["check", "a.launch.xml"])
    assert f"No fixes available ({hint})." in capsys.readouterr().err
    main(["check", "a.launch.xml", "--statistics"])
    out, err = capsys.readouterr()
    assert out.split()[-2:] == ["[1", "hidden]"] and hint in err
    assert main(["check", "a.launch.xml", "--diff", "--unsafe-fixes"]) == 1
    out, err = capsys.readouterr()
    assert "--frame-id map" in out and "Would fix 1 finding." in err and "hidden" not in err
    # A target where the fix is safe: no hint, a fix.
    main(["check", "a.launch.xml", "--ros-distro", "humble"])
    assert "[*] 1 fixable with the `--fix` option." in capsys.readouterr().err
