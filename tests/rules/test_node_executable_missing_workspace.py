"""node_executable_missing for a package of the linted workspace: its CMakeLists.txt or
setup.py, read statically, installs no such executable into lib/<package> (spot_ros2's
renamed nodes: kinematic_node once spot_inverse_kinematics_node was installed)."""

from __future__ import annotations

import time
from pathlib import Path

from hypothesis import given
from hypothesis import strategies as st

from launch_linter.engine import LintOptions, lint_paths
from launch_linter.workspace.executables import console_script, read_executables

RULE = "node_executable_missing"
MANIFEST = """<package format="3"><name>{name}</name>
<export><build_type>{build}</build_type></export></package>
"""
CMAKE = """project(drive)
find_package(rclcpp_components REQUIRED)
add_executable(driver_node src/driver.cpp)
add_library(driver_component SHARED src/component.cpp)
rclcpp_components_register_node(driver_component PLUGIN "drive::Driver"
  EXECUTABLE driver_component_node)
install(TARGETS driver_node DESTINATION lib/${PROJECT_NAME})
install(PROGRAMS scripts/teleop.py DESTINATION lib/${PROJECT_NAME} RENAME teleop)
install(DIRECTORY launch DESTINATION share/${PROJECT_NAME})
ament_package()
"""
LAUNCH = """from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='{package}', executable='{executable}'),
    ])
"""
SETUP_PY = """from setuptools import setup
package_name = 'pydrive'
setup(
    name=package_name,
    data_files=[('share/' + package_name + '/launch', ['launch/run.launch.py'])],
    entry_points={
        'console_scripts': [
            'walker = pydrive.walker:main',
        ],
    },
)
"""
SETUP_CFG = ("[develop]\nscript_dir=$base/lib/pydrive\n"
             "[install]\ninstall_scripts=$base/lib/pydrive\n")


def workspace(tmp_path: Path, cmake: str = CMAKE) -> Path:
    drive = tmp_path / "src" / "drive"
    (drive / "launch").mkdir(parents=True, exist_ok=True)
    (drive / "package.xml").write_text(MANIFEST.format(name="drive", build="ament_cmake"))
    (drive / "CMakeLists.txt").write_text(cmake)
    pydrive = tmp_path / "src" / "pydrive"
    (pydrive / "launch").mkdir(parents=True, exist_ok=True)
    (pydrive / "package.xml").write_text(MANIFEST.format(name="pydrive", build="ament_python"))
    (pydrive / "setup.py").write_text(SETUP_PY)
    (pydrive / "setup.cfg").write_text(SETUP_CFG)
    return tmp_path / "src"


def found(tmp_path: Path, package: str, executable: str, cmake: str = CMAKE
          ) -> list[tuple[int, str]]:
    source = workspace(tmp_path, cmake)
    path = source / "drive" / "launch" / "bringup.launch.py"
    path.write_text(LAUNCH.format(package=package, executable=executable))
    options = LintOptions(package_paths=(str(source),), select=frozenset({RULE}))
    return [(d.line, d.severity.value) for d in lint_paths([str(path)], options).diagnostics]


def test_an_executable_the_package_never_installs_is_an_error(tmp_path: Path) -> None:
    assert found(tmp_path, "drive", "kinematic_node") == [(7, "error")]


def test_what_cmake_installs_is_silent(tmp_path: Path) -> None:
    for executable in ("driver_node", "driver_component_node", "teleop"):
        assert found(tmp_path, "drive", executable) == []


def test_console_scripts_of_an_ament_python_package(tmp_path: Path) -> None:
    assert found(tmp_path, "pydrive", "walker") == []
    assert found(tmp_path, "pydrive", "runner") == [(7, "error")]


def test_rules_not_read_completely_prove_nothing(tmp_path: Path) -> None:
    for extra in ("add_subdirectory(tools)\n", "include(cmake/install.cmake)\n",
                  "install(TARGETS ${MY_TARGETS} DESTINATION lib/${PROJECT_NAME})\n",
                  "foreach(t a b)\n  install(TARGETS ${t} DESTINATION lib/drive)\nendforeach()\n",
                  "set_target_properties(driver_node PROPERTIES OUTPUT_NAME kinematic_node)\n",
                  "install(CODE \"message(hi)\")\n"):
        assert found(tmp_path, "drive", "kinematic_node", CMAKE + extra) == [], extra


def test_a_subdirectory_present_is_read(tmp_path: Path) -> None:
    cmake = CMAKE + "if(BUILD_TESTING)\n  add_subdirectory(tools)\nendif()\n"
    source = workspace(tmp_path, cmake)
    (source / "drive" / "tools").mkdir()
    (source / "drive" / "tools" / "CMakeLists.txt").write_text(
        "add_executable(kinematic_node k.cpp)\n"
        "install(TARGETS kinematic_node DESTINATION lib/${PROJECT_NAME})\n")
    read = read_executables(str(source / "drive"), "drive")
    assert read is not None and read.reasons == () and "kinematic_node" in read.names


def test_ament_cmake_auto(tmp_path: Path) -> None:
    cmake = ("project(drive)\nament_auto_add_executable(kinematic_node src/k.cpp)\n"
             "ament_auto_package(INSTALL_TO_SHARE launch)\n")
    assert found(tmp_path, "drive", "kinematic_node", cmake) == []
    assert found(tmp_path, "drive", "other_node", cmake) == [(7, "error")]


def test_scripts_outside_lib_are_unknown(tmp_path: Path) -> None:
    """Without install_scripts=$base/lib/<pkg>, setuptools installs to bin/: not proven."""
    source = workspace(tmp_path)
    (source / "pydrive" / "setup.cfg").write_text("[metadata]\nname=pydrive\n")
    read = read_executables(str(source / "pydrive"), "pydrive")
    assert read is not None and read.reasons


def test_a_package_outside_the_workspace_is_silent(tmp_path: Path) -> None:
    assert found(tmp_path, "nav2_bringup", "kinematic_node") == []


def test_twenty_thousand_install_rules(tmp_path: Path) -> None:
    """Linear in the rules; past the CMake reader's bounds (20,000 commands, 5,000
    arguments a command) the list is incomplete and proves nothing."""
    cmake = "project(drive)\n" + "".join(
        f"install(TARGETS t{i} DESTINATION lib/drive)\n" for i in range(15_000))
    cmake += "install(PROGRAMS " + " ".join(f"s{i}" for i in range(4_000)) + \
        " DESTINATION lib/drive)\n"
    started = time.process_time()
    assert len(cmake) < 1024 * 1024
    assert found(tmp_path, "drive", "t14999", cmake) == []
    assert found(tmp_path, "drive", "s3999", cmake) == []
    assert found(tmp_path, "drive", "missing", cmake) == [(7, "error")]
    many = cmake + "install(TARGETS x DESTINATION lib/drive)\n" * 5_000
    assert found(tmp_path, "drive", "missing", many) == []
    wide = "install(PROGRAMS " + " ".join(f"s{i}" for i in range(20_000)) + \
        " DESTINATION lib/drive)\n"
    assert found(tmp_path, "drive", "missing", wide) == []
    assert time.process_time() - started < 60


def test_console_scripts_nested_and_multiline(tmp_path: Path) -> None:
    """setuptools flattens nested lists and splits texts into lines (yield_lines):
    rmf_demos_bridges writes its two entries as one tuple inside the list."""
    source = workspace(tmp_path)
    (source / "pydrive" / "setup.py").write_text(SETUP_PY.replace(
        "'walker = pydrive.walker:main',",
        "('walker=' 'pydrive.walker:main', 'runner=pydrive.runner:main'),\n"
        "            'jumper = pydrive.jumper:main\\n# comment\\nhopper = pydrive.h:main',"))
    read = read_executables(str(source / "pydrive"), "pydrive")
    assert read is not None and read.reasons == ()
    assert read.names == {"walker", "runner", "jumper", "hopper"}


def test_twenty_thousand_console_scripts(tmp_path: Path) -> None:
    source = workspace(tmp_path)
    entries = ", ".join(f"'s{i} = pydrive.s:main'" for i in range(19_990))
    (source / "pydrive" / "setup.py").write_text(SETUP_PY.replace(
        "'walker = pydrive.walker:main',", entries))
    started = time.process_time()
    read = read_executables(str(source / "pydrive"), "pydrive")
    assert time.process_time() - started < 60
    assert read is not None and len(read.names) == 19_990


_WORD = st.text(st.characters(blacklist_characters="=#\n\r"), min_size=1).filter(
    lambda text: text.strip() != "")


@given(_WORD, _WORD, st.sampled_from(["=", " = ", "= "]))
def test_a_console_script_entry_is_read_as_its_name_and_target(
        name: str, target: str, equals: str) -> None:
    """One reading of `name = module:function`, shared by executables.py (the name
    installed) and node_declarations.py (the module holding the node)."""
    assert console_script(name + equals + target) == (name.strip(), target.strip())
    assert console_script(" # " + name + equals + target) is None
    assert console_script("  ") is None
