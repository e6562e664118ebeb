"""A ROS 1 fragment in an ament package: an XML launch file only ROS 1 launch files name.

The shape of a MoveIt setup-assistant config (OnRobot-RG2FT-ROS's
``onrobot_rg2ft_moveit_config``) whose manifest was switched to ament_cmake: its
``planning_pipeline.launch.xml`` is included only by ``move_group.launch``, and roslaunch
reads every file an ``<include>`` names as roslaunch XML (its ``xmlloader``), whatever the
name; ``ros2 launch`` never runs it, so what it would refuse there is info."""

from __future__ import annotations

import time
from pathlib import Path

import pytest

from launch_linter.engine import LintOptions, lint_paths
from launch_linter.workspace import mentions

RULES = frozenset({"file_never_launched", "ros2_schema", "roslaunch_error"})
MANIFEST = """<package format="3"><name>arm_moveit</name>
<buildtool_depend>ament_cmake</buildtool_depend>
<export><build_type>ament_cmake</build_type></export></package>
"""
INSTALLS_LAUNCH = ("project(arm_moveit)\n"
                   "install(DIRECTORY launch DESTINATION share/${PROJECT_NAME})\n")
FRAGMENT = """<launch>
  <arg name="pipeline" default="ompl"/>
  <param name="planning_plugin" value="ompl_interface/OMPLPlanner"/>
  <node name="mover" pkg="arm_moveit" type="mover"/>
</launch>
"""
ROS1_INCLUDER = """<launch>
  <include ns="move_group" file="$(find arm_moveit)/launch/pipeline.launch.xml"/>
</launch>
"""
ROS2_XML_INCLUDER = ('<launch><include file="$(find-pkg-share arm_moveit)/launch/'
                     'pipeline.launch.xml"/></launch>\n')
ROS2_PY_INCLUDER = ("os.path.join(get_package_share_directory('arm_moveit'), 'launch', "
                    "'pipeline.launch.xml')\n")


@pytest.fixture(autouse=True)
def _fresh_mentions(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(mentions, "_names_by_folder", {})


def package(tmp_path: Path, files: dict[str, str]) -> Path:
    (tmp_path / ".git").mkdir()
    (tmp_path / "package.xml").write_text(MANIFEST)
    (tmp_path / "CMakeLists.txt").write_text(INSTALLS_LAUNCH)
    (tmp_path / "launch").mkdir()
    (tmp_path / "launch" / "pipeline.launch.xml").write_text(FRAGMENT)
    for name, text in files.items():
        (tmp_path / "launch" / name).write_text(text)
    return tmp_path / "launch" / "pipeline.launch.xml"


def levels(path: Path) -> set[tuple[str, str]]:
    options = LintOptions(package_paths=(str(path.parent.parent),), select=RULES)
    found = lint_paths([str(path)], options).diagnostics
    return {(d.rule, d.severity.value) for d in found if d.path.endswith("pipeline.launch.xml")}


def test_a_fragment_only_a_ros1_file_includes_is_info(tmp_path: Path) -> None:
    root = package(tmp_path, {"move_group.launch": ROS1_INCLUDER})
    found = levels(root)
    assert ("file_never_launched", "info") in found
    assert ("ros2_schema", "info") in found
    assert {level for _, level in found} == {"info"}
    options = LintOptions(package_paths=(str(tmp_path),), select=RULES)
    said = [d.message for d in lint_paths([str(root)], options).diagnostics
            if d.rule == "file_never_launched"]
    assert len(said) == 1 and "only ROS 1 launch files name it (move_group.launch)" in said[0]


@pytest.mark.parametrize("includers", [
    {"bringup.launch.xml": ROS2_XML_INCLUDER},
    {"bringup.launch.py": ROS2_PY_INCLUDER},
    {"move_group.launch": ROS1_INCLUDER, "bringup.launch.py": ROS2_PY_INCLUDER},
    # A *.launch file written in ROS 2 launch XML is a ROS 2 includer.
    {"bringup.launch": ROS2_XML_INCLUDER},
    # An *.xml includer is decided by its package, not proven ROS 1.
    {"outer.launch.xml": ROS1_INCLUDER},
    # A ROS 1 file naming it in a comment only includes nothing.
    {"notes.launch": "<launch>\n  <!-- see pipeline.launch.xml -->\n</launch>\n"},
])
def test_a_fragment_a_ros2_or_undecided_file_names_keeps_its_errors(
        tmp_path: Path, includers: dict[str, str]) -> None:
    found = levels(package(tmp_path, includers))
    assert "file_never_launched" not in {rule for rule, _ in found}
    assert ("ros2_schema", "error") in found


def test_a_scan_cut_by_a_bound_keeps_the_errors(tmp_path: Path,
                                                monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(mentions, "MAX_FILES", 1)
    found = levels(package(tmp_path, {"move_group.launch": ROS1_INCLUDER,
                                      "zz.launch.py": "# nothing\n"}))
    assert ("ros2_schema", "error") in found


def test_more_writers_than_kept_is_unknown(tmp_path: Path) -> None:
    writers = {f"w{i}.launch": ROS1_INCLUDER for i in range(mentions.MAX_WRITERS + 1)}
    root = package(tmp_path, writers)
    assert mentions.every_writer(str(root)) is None
    assert ("ros2_schema", "error") in levels(root)
    mentions._names_by_folder.clear()
    (tmp_path / "launch" / "w0.launch").unlink()
    found = mentions.every_writer(str(root))
    assert found is not None and len(found) == mentions.MAX_WRITERS


def test_twenty_thousand_ros1_writers(tmp_path: Path) -> None:
    """More writers than the scan reads: unknown, answered in bounded time."""
    root = package(tmp_path, {})
    for i in range(20_000):
        (tmp_path / "launch" / f"w{i}.launch").write_text(ROS1_INCLUDER)
    start = time.monotonic()
    found = levels(root)
    assert time.monotonic() - start < 20
    assert ("ros2_schema", "error") in found


def test_ros1_files_naming_twenty_thousand_files(tmp_path: Path) -> None:
    names = {f"n{part}.launch": "".join(f"<!-- f{part}_{i}.launch.xml -->\n"
                                        for i in range(2_000)) for part in range(10)}
    root = package(tmp_path, {"move_group.launch": ROS1_INCLUDER, **names})
    start = time.monotonic()
    found = levels(root)
    assert time.monotonic() - start < 10
    assert ("file_never_launched", "info") in found
