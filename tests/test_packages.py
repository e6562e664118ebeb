"""``$(find pkg)``: package discovery under package roots, as rospkg does it."""

from __future__ import annotations

from pathlib import Path

import pytest

from launch_linter.workspace.packages import PackageIndex, default_package_roots


def package(folder: Path, name: str, extra: str = "") -> Path:
    folder.mkdir(parents=True, exist_ok=True)
    (folder / "package.xml").write_text(
        '<?xml version="1.0"?>\n<package format="2">\n'
        f"  <name> {name}\n</name>{extra}\n</package>\n"
    )
    return folder


def test_the_name_comes_from_package_xml_not_the_folder(tmp_path: Path) -> None:
    package(tmp_path / "src" / "folder_name", "real_name")
    index = PackageIndex([str(tmp_path / "src")])
    assert index.find("real_name") == str(tmp_path / "src" / "folder_name")
    assert index.find("folder_name") is None


def test_manifest_xml_packages_are_named_by_their_folder(tmp_path: Path) -> None:
    legacy = tmp_path / "legacy_pkg"
    legacy.mkdir()
    (legacy / "manifest.xml").write_text("<package/>")
    assert PackageIndex([str(tmp_path)]).find("legacy_pkg") == str(legacy)


def test_no_descent_into_packages_hidden_or_ignored_folders(tmp_path: Path) -> None:
    outer = package(tmp_path / "outer", "outer")
    package(outer / "nested", "nested")
    package(tmp_path / ".hidden" / "h", "hidden_pkg")
    (tmp_path / "ignored").mkdir()
    (tmp_path / "ignored" / "CATKIN_IGNORE").write_text("")
    package(tmp_path / "ignored" / "i", "ignored_pkg")
    (tmp_path / "stop").mkdir()
    (tmp_path / "stop" / "rospack_nosubdirs").write_text("")
    package(tmp_path / "stop" / "s", "below_nosubdirs")
    index = PackageIndex([str(tmp_path)])
    assert index.find("outer") == str(outer)
    for name in ("nested", "hidden_pkg", "ignored_pkg", "below_nosubdirs"):
        assert index.find(name) is None, name


def test_metapackages_are_not_found(tmp_path: Path) -> None:
    package(tmp_path / "meta", "meta", "<export><metapackage/></export>")
    package(tmp_path / "meta" / "inside", "inside")
    index = PackageIndex([str(tmp_path)])
    assert index.find("meta") is None
    assert index.find("inside") is None


def test_earlier_roots_win(tmp_path: Path) -> None:
    first = package(tmp_path / "a" / "p", "dup")
    package(tmp_path / "b" / "p", "dup")
    assert PackageIndex([str(tmp_path / "a"), str(tmp_path / "b")]).find("dup") == str(first)


def test_unreadable_or_missing_roots_are_skipped(tmp_path: Path) -> None:
    broken = tmp_path / "broken"
    broken.mkdir()
    (broken / "package.xml").write_text("<package><name>x</name>")
    index = PackageIndex([str(tmp_path / "missing"), str(tmp_path)])
    assert index.find("x") is None


def test_default_roots_are_the_workspace_src_holding_the_package(tmp_path: Path) -> None:
    robot = package(tmp_path / "ws" / "src" / "group" / "robot", "robot")
    (robot / "src").mkdir()  # the package's own C++ sources are not a workspace
    (robot / "launch").mkdir()
    launch = robot / "launch" / "a.launch"
    assert default_package_roots(str(launch)) == [str(tmp_path / "ws" / "src")]


def test_default_roots_without_a_workspace_are_the_package_parent(tmp_path: Path) -> None:
    robot = package(tmp_path / "loose" / "robot", "robot")
    assert default_package_roots(str(robot / "a.launch")) == [str(tmp_path / "loose")]


def test_default_roots_add_the_repository_that_holds_the_package(tmp_path: Path) -> None:
    # precision trial 3, ros-industrial/fanuc: moveit_cfgs/<robot>_moveit_config finds
    # <robot>_support at the repository's top (it was "not found under the package path").
    (tmp_path / "repo" / ".git").mkdir(parents=True)
    config = package(tmp_path / "repo" / "moveit_cfgs" / "robot_moveit_config", "cfg")
    package(tmp_path / "repo" / "robot_support", "robot_support")
    roots = default_package_roots(str(config / "a.launch"))
    assert roots == [str(tmp_path / "repo" / "moveit_cfgs"), str(tmp_path / "repo")]
    assert PackageIndex(roots).find("robot_support") == str(tmp_path / "repo" / "robot_support")
    # A repository that is the package itself, or none within reach: the parent alone.
    own = package(tmp_path / "own", "own")
    (own / ".git").mkdir()
    assert default_package_roots(str(own / "a.launch")) == [str(tmp_path)]
    deep = package(tmp_path / "repo" / "a" / "b" / "c" / "d" / "deep", "deep")
    assert default_package_roots(str(deep / "a.launch")) == [str(deep.parent)]


def test_no_default_roots_outside_a_package(tmp_path: Path) -> None:
    assert default_package_roots(str(tmp_path / "a.launch")) == []


def test_a_file_outside_the_packages_of_a_repository_has_the_repository(
        tmp_path: Path) -> None:
    """precision trial 6, Autonomous-Racing-PG/ar-tu-do: ros_ws/launch/*.launch, beside the
    workspace's ros_ws/src/<packages>, include $(find car_control)/... (every package of
    the repository was "not found under the package path")."""
    repo = tmp_path / "repo"
    (repo / ".git").mkdir(parents=True)
    package(repo / "ros_ws" / "src" / "car_control", "car_control")
    launch = repo / "ros_ws" / "launch" / "car.launch"
    assert default_package_roots(str(launch)) == [str(repo)]
    assert PackageIndex(default_package_roots(str(launch))).find("car_control") == str(
        repo / "ros_ws" / "src" / "car_control")
    assert default_package_roots(str(repo / "top.launch")) == [str(repo)]
    # Too far below the repository's top: no roots, as outside any repository.
    assert default_package_roots(str(repo / "a" / "b" / "c" / "x.launch")) == []


def test_the_engine_finds_the_roots_once_per_real_folder(tmp_path: Path) -> None:
    from launch_linter.engine import InputFile, LintOptions, load_options_for

    robot = package(tmp_path / "ws" / "src" / "robot", "robot")
    other = package(tmp_path / "loose" / "other", "other")
    (other / "o.launch").write_text("<launch/>")
    (robot / "link.launch").symlink_to(other / "o.launch")
    cache: dict[tuple[str, ...], PackageIndex] = {}

    def roots(name: str) -> list[str]:
        path = str(robot / name)
        return load_options_for(InputFile(path, path), LintOptions(), cache).packages.roots

    assert roots("a.launch") == roots("b.launch") == [str(tmp_path / "ws" / "src")]
    assert roots("link.launch") == [str(tmp_path / "loose")]
    assert roots("a.launch") == [str(tmp_path / "ws" / "src")]


def test_a_folders_package_is_walked_up_to_once(tmp_path: Path,
                                                monkeypatch: pytest.MonkeyPatch) -> None:
    """The ROS 1 parse-check probe asks for the package of every root with nodes: the
    launch files of one folder share one walk up, and each of them still depends on what
    that walk looked at (the results cache)."""
    from launch_linter.resolve import reads
    from launch_linter.workspace import packages

    launch = package(tmp_path / "pkg", "pkg") / "launch"
    launch.mkdir()
    walks: list[str] = []
    walk = packages.nearest_package_xml

    def counted(path: str) -> str | None:
        walks.append(path)
        return walk(path)

    monkeypatch.setattr(packages, "nearest_package_xml", counted)
    index = PackageIndex([])
    logs = []
    for name in ("a.launch", "b.launch"):
        with reads.recording() as log:
            assert index.package_xml_of(str(launch / name)) == str(tmp_path / "pkg" /
                                                                    "package.xml")
        logs.append(log)
    assert walks == [str(launch / "a.launch")]
    for log in logs:
        looked_at = {p for group in log.closure() for p in group.stamps}
        assert str(tmp_path / "pkg" / "package.xml") in looked_at
