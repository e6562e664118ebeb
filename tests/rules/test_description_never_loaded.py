"""description_never_loaded: a description nothing loads has its findings at info.

The shape of realsense2_description's ``tests/one_of_each.xacro`` (precision trial 8): a
xacro file under ``tests/`` that the package does not install and that only the
package's test script runs through xacro (it lists the folder, naming no file)."""

from __future__ import annotations

import time
from pathlib import Path

import pytest

from launch_linter.engine import LintOptions, lint_paths
from launch_linter.workspace import loaders, mentions
from launch_linter.workspace.loaders import _Written, loader_of

CATKIN = """<package format="2"><name>cams</name>
<buildtool_depend>catkin</buildtool_depend></package>
"""
AMENT = """<package format="3"><name>cams</name>
<buildtool_depend>ament_cmake</buildtool_depend>
<export><build_type>ament_cmake</build_type></export></package>
"""
INSTALLS_URDF_CATKIN = ("project(cams)\nfind_package(catkin REQUIRED)\ncatkin_package()\n"
                        "install(DIRECTORY launch urdf\n"
                        "  DESTINATION ${CATKIN_PACKAGE_SHARE_DESTINATION})\n")
INSTALLS_URDF_AMENT = "project(cams)\ninstall(DIRECTORY urdf DESTINATION share/${PROJECT_NAME})\n"
# A fixed joint turned by 3.14 rad: rounded_pi warns on it.
ROBOT = """<robot name="two">
  <link name="base_link"/><link name="camera_link"/>
  <joint name="camera_joint" type="fixed">
    <parent link="base_link"/><child link="camera_link"/>
    <origin xyz="0 0 0" rpy="0 0 3.14"/>
  </joint>
</robot>
"""
TEST_SCRIPT = ("import os, subprocess\n"
               "for name in os.listdir('tests'):\n"
               "    if name.endswith('.xacro'):\n"
               "        subprocess.check_output(['xacro', 'tests/' + name])\n")


@pytest.fixture(autouse=True)
def _fresh_caches() -> None:
    loaders._written_by_folder.clear()
    mentions._names_by_folder.clear()


def package(root: Path, manifest: str = CATKIN, cmake: str = INSTALLS_URDF_CATKIN,
            files: dict[str, str] | None = None) -> Path:
    for name, text in {"package.xml": manifest, "CMakeLists.txt": cmake,
                       "tests/test_xacro.py": TEST_SCRIPT, **(files or {})}.items():
        (root / name).parent.mkdir(parents=True, exist_ok=True)
        (root / name).write_text(text, encoding="utf-8")
    return root


def levels(path: Path, package_root: Path) -> list[tuple[str, str]]:
    options = LintOptions(package_paths=(str(package_root),))
    found = lint_paths([str(path)], options).diagnostics
    return sorted({(d.rule, d.severity.value) for d in found})


def test_a_test_xacro_nothing_installs_or_names_is_info(tmp_path: Path) -> None:
    root = package(tmp_path, files={"tests/one_of_each.xacro": ROBOT})
    found = levels(root / "tests/one_of_each.xacro", root)
    assert ("description_never_loaded", "info") in found
    assert ("rounded_pi", "info") in found
    assert {level for _, level in found} == {"info"}


def test_what_xacro_makes_of_its_text_keeps_its_level(tmp_path: Path) -> None:
    # realsense2_description's tests/*.xacro call macros without the xacro: prefix:
    # whoever runs xacro on them (the package's test does) gets no camera.
    text = ROBOT.replace("</robot>", '<xacro:macro name="cam"><link name="c"/></xacro:macro>'
                         "<cam/></robot>").replace("<robot ", '<robot xmlns:xacro="x" ')
    root = package(tmp_path, files={"tests/one_of_each.xacro": text})
    found = levels(root / "tests/one_of_each.xacro", root)
    assert ("xacro_unexpanded", "warning") in found
    assert ("rounded_pi", "info") in found


def test_every_xacro_rule_is_counted_as_one_about_the_text() -> None:
    from launch_linter.rules import RULES
    from launch_linter.rules.description_never_loaded import XACRO_TEXT_RULES

    assert {r.id for r in RULES if r.id.startswith("xacro_")} <= XACRO_TEXT_RULES


def test_the_same_file_in_an_ament_package(tmp_path: Path) -> None:
    root = package(tmp_path, AMENT, INSTALLS_URDF_AMENT, {"tests/one_of_each.xacro": ROBOT})
    assert ("rounded_pi", "info") in levels(root / "tests/one_of_each.xacro", root)


def test_an_installed_description_keeps_its_warnings(tmp_path: Path) -> None:
    # Installed by a description package: other workspaces load it.
    root = package(tmp_path, files={"urdf/cams.urdf": ROBOT})
    found = levels(root / "urdf/cams.urdf", root)
    assert ("rounded_pi", "warning") in found
    assert "description_never_loaded" not in {rule for rule, _ in found}


@pytest.mark.parametrize("launch", [
    '<launch><param name="robot_description" '
    'command="xacro $(find cams)/tests/one_of_each.xacro"/></launch>\n',
    # A built name whose folder is the description's: it may be this file.
    '<launch><arg name="m" default="one_of_each"/><param name="robot_description" '
    'command="xacro $(find cams)/tests/$(arg m).xacro"/></launch>\n',
    "Command(['xacro ', os.path.join(share, name + '.xacro')])\n",
])
def test_a_file_that_may_load_it_keeps_its_warnings(tmp_path: Path, launch: str) -> None:
    root = package(tmp_path, files={"tests/one_of_each.xacro": ROBOT,
                                    "launch/view.launch": launch})
    found = levels(root / "tests/one_of_each.xacro", root)
    assert ("rounded_pi", "warning") in found
    assert "description_never_loaded" not in {rule for rule, _ in found}


def test_install_rules_not_all_read_prove_nothing(tmp_path: Path) -> None:
    root = package(tmp_path, cmake=INSTALLS_URDF_CATKIN + "add_subdirectory(more)\n",
                   files={"tests/one_of_each.xacro": ROBOT})
    assert ("rounded_pi", "warning") in levels(root / "tests/one_of_each.xacro", root)


def test_a_description_without_findings_gets_no_notice(tmp_path: Path) -> None:
    quiet = ROBOT.replace("3.14", "0")
    root = package(tmp_path, files={"tests/one_of_each.xacro": quiet})
    assert levels(root / "tests/one_of_each.xacro", root) == []


def test_names_built_elsewhere_reach_only_their_folder() -> None:
    written = _Written()
    written.add(b'"$(find p)/urdf/$(arg model).urdf.xacro" glob("launch/*.xacro") '
                b"$(find p)/urdf/_d435.urdf.xacro plain.urdf", "A")
    assert written.writer_of("/w/urdf/robot.urdf.xacro") == "A"
    assert written.writer_of("/w/launch/x.xacro") == "A"
    assert written.writer_of("/w/tests/robot.urdf.xacro") is None
    assert written.writer_of("/w/any/_d435.urdf.xacro") == "A"
    assert written.writer_of("/w/any/plain.urdf") == "A"
    assert written.writer_of("/w/any/other.urdf") is None


def test_a_name_joined_to_a_variable_reaches_every_folder() -> None:
    written = _Written()
    written.add(b"path = robot + '_arm.urdf'\nf'{robot}.xacro'\n", "A")
    assert written.writer_of("/w/tests/big_arm.urdf") == "A"
    assert written.writer_of("/w/tests/x.xacro") == "A"
    assert written.writer_of("/w/tests/x.urdf") is None


def test_a_scan_cut_by_its_bound_is_unknown(tmp_path: Path, monkeypatch: pytest.MonkeyPatch,
                                            ) -> None:
    root = package(tmp_path, files={"tests/one_of_each.xacro": ROBOT})
    monkeypatch.setattr(loaders, "MAX_FILES", 0)
    assert loader_of(str(root / "tests/one_of_each.xacro")) == str(tmp_path)


def test_hostile_names_are_read_in_linear_time() -> None:
    # 20,000 names, each the tail of the next: every backward read stops at the previous.
    data = b"a" * 300 + b".urdf" * 20_000 + b" $(x)" * 20_000 + b".xacro"
    written = _Written()
    started = time.perf_counter()
    written.add(data * 5, "A")
    for index in range(20_000):
        written.writer_of(f"/w/f/n{index}.urdf")
    assert time.perf_counter() - started < 5.0
