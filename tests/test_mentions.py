"""Which launch files another launch file of the workspace names (workspace.mentions)."""

from __future__ import annotations

from pathlib import Path

import pytest

from launch_linter.workspace import mentions
from launch_linter.workspace.mentions import named_by_another_file

PACKAGE = "<package format='3'><name>{}</name></package>\n"


@pytest.fixture(autouse=True)
def _fresh_cache() -> None:
    mentions._names_by_folder.clear()


def _write(root: Path, files: dict[str, str]) -> None:
    for name, text in files.items():
        path = root / name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text, encoding="utf-8")


def test_a_launch_file_naming_it(tmp_path: Path) -> None:
    _write(tmp_path, {
        "pkg/package.xml": PACKAGE.format("pkg"),
        "pkg/launch/rsp.launch.py": "# usage: ros2 launch pkg rsp.launch.py\n",
        "pkg/launch/bringup.launch.py": "os.path.join(share, 'launch', 'rsp.launch.py')\n",
    })
    found = named_by_another_file(str(tmp_path / "pkg/launch/rsp.launch.py"))
    assert found == str(tmp_path / "pkg/launch/bringup.launch.py")
    assert named_by_another_file(str(tmp_path / "pkg/launch/bringup.launch.py")) is None


def test_only_itself_or_a_non_launch_file_naming_it(tmp_path: Path) -> None:
    _write(tmp_path, {
        "pkg/package.xml": PACKAGE.format("pkg"),
        "pkg/launch/rsp.launch.py": "# usage: ros2 launch pkg rsp.launch.py\n",
        "pkg/README.md": "ros2 launch pkg rsp.launch.py\n",
        "pkg/config/params.yaml": "file: rsp.launch.py\n",
    })
    assert named_by_another_file(str(tmp_path / "pkg/launch/rsp.launch.py")) is None


def test_another_package_of_the_workspace(tmp_path: Path) -> None:
    _write(tmp_path, {
        "ws/src/desc/package.xml": PACKAGE.format("desc"),
        "ws/src/desc/launch/rsp.launch.xml": "<launch/>\n",
        "ws/src/bringup/package.xml": PACKAGE.format("bringup"),
        "ws/src/bringup/launch/all.launch.xml":
            '<launch><include file="$(find-pkg-share desc)/launch/rsp.launch.xml"/></launch>\n',
    })
    found = named_by_another_file(str(tmp_path / "ws/src/desc/launch/rsp.launch.xml"))
    assert found == str(tmp_path / "ws/src/bringup/launch/all.launch.xml")


def test_bounded_in_files(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(mentions, "MAX_FILES", 3)
    files = {f"launch/a{i:02d}.launch.py": "" for i in range(10)}
    files["launch/z.launch.py"] = "'a00.launch.py'\n"
    _write(tmp_path, files)
    assert named_by_another_file(str(tmp_path / "launch/a00.launch.py")) is None


def test_file_names_in_linear_time() -> None:
    # A pattern that starts at every letter of a long word would take minutes here.
    data = b"a" * 2_000_000 + b" rsp.launch.py " + b"x." * 500_000
    assert mentions._file_names(data) == {"rsp.launch", "rsp.launch.py"}


def test_an_include_written_since_is_seen(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    _write(tmp_path, {"launch/rsp.launch.py": ""})
    rsp = str(tmp_path / "launch/rsp.launch.py")
    assert named_by_another_file(rsp) is None
    _write(tmp_path, {"launch/all.launch.py": "'rsp.launch.py'\n"})
    monkeypatch.setattr(mentions, "FRESH_SECONDS", 0.0)
    assert named_by_another_file(rsp) == str(tmp_path / "launch/all.launch.py")
