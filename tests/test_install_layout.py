"""Install layout (issue 27): share paths mapped back to source files, never by running
CMake or setup.py; unknown is not an error, absent needs proof."""

from __future__ import annotations

import time
from pathlib import Path

import pytest

from launch_linter.engine import LintOptions, lint_paths
from launch_linter.workspace.cmake_install import commands, read_cmake_layout
from launch_linter.workspace.install_layout import read_layout
from launch_linter.workspace.packages import PackageIndex
from launch_linter.workspace.python_install import read_setup_cfg, read_setup_py

AMENT = """<?xml version="1.0"?>
<package format="3"><name>{name}</name>
<buildtool_depend>{build}</buildtool_depend>
<export><build_type>{build}</build_type></export></package>
"""
CATKIN = """<?xml version="1.0"?>
<package format="2"><name>{name}</name><buildtool_depend>catkin</buildtool_depend></package>
"""
TF_NODE = ("Node(package='tf2_ros', executable='static_transform_publisher', "
           "arguments=['--frame-id', 'a', '--child-frame-id', 'b'])")
INNER = f"""from launch import LaunchDescription
from launch_ros.actions import Node
def generate_launch_description():
    return LaunchDescription([{TF_NODE}])
"""


def write(path: Path, text: str) -> Path:
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text)
    return path


def ament_package(root: Path, name: str, cmake: str | None = None,
                  build: str = "ament_cmake") -> Path:
    write(root / name / "package.xml", AMENT.format(name=name, build=build))
    if cmake is not None:
        write(root / name / "CMakeLists.txt", cmake)
    return root / name


def includer(package: str, share_path: str) -> str:
    return f"""import os
from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource
def generate_launch_description():
    path = os.path.join(get_package_share_directory('{package}'), '{share_path}')
    return LaunchDescription([IncludeLaunchDescription(PythonLaunchDescriptionSource(path))])
"""


def findings(path: Path) -> list[tuple[str, str]]:
    result = lint_paths([str(path)], LintOptions())
    return [(d.rule, d.message) for d in result.diagnostics]


def transforms(path: Path) -> list[str]:
    return [str(t.child) for t in lint_paths([str(path)], LintOptions()).transforms]


def test_a_directory_installs_under_its_last_name(tmp_path: Path) -> None:
    pkg = ament_package(tmp_path / "src", "demo", """
        project(demo)
        install(DIRECTORY bringup/launch description/urdf
                DESTINATION share/${PROJECT_NAME})""")
    write(pkg / "bringup" / "launch" / "inner.launch.py", INNER)
    top = write(pkg / "test" / "test_top_launch.py", includer("demo", "launch/inner.launch.py"))
    assert transforms(top) == ["b"]
    assert not [f for f in findings(top) if f[0] == "roslaunch_error"]


def test_a_trailing_slash_installs_the_contents(tmp_path: Path) -> None:
    pkg = ament_package(tmp_path / "src", "demo", """
        set(SHARE_DIR share/${PROJECT_NAME})
        project(demo)
        install(DIRECTORY bringup/launch/ DESTINATION ${SHARE_DIR}/launch)""")
    write(pkg / "bringup" / "launch" / "inner.launch.py", INNER)
    top = write(pkg / "top.launch.py", includer("demo", "launch/inner.launch.py"))
    # ${SHARE_DIR} was set before project(): the variable keeps the name known then ("demo"
    # from package.xml), which is the project's.
    assert transforms(top) == ["b"]
    layout = read_layout(str(pkg), "demo")
    assert [(r.source, r.target) for r in layout.rules] == [("bringup/launch", "launch")]


def test_a_file_proven_absent_after_the_layout_is_an_error(tmp_path: Path) -> None:
    pkg = ament_package(tmp_path / "src", "demo",
                        "install(DIRECTORY launch DESTINATION share/${PROJECT_NAME})")
    top = write(pkg / "launch" / "top.launch.py", includer("demo", "launch/gone.launch.py"))
    (error,) = [m for r, m in findings(top) if r == "roslaunch_error"]
    assert "included file not found" in error


def test_a_share_path_the_layout_does_not_explain_is_unresolved(tmp_path: Path) -> None:
    pkg = ament_package(tmp_path / "src", "demo",
                        "install(DIRECTORY launch DESTINATION share/${PROJECT_NAME})")
    top = write(pkg / "launch" / "top.launch.py", includer("demo", "generated/x.launch.py"))
    found = findings(top)
    assert not [f for f in found if f[0] == "roslaunch_error"]
    assert any("not explained by the install rules" in m for r, m in found if r == "unresolved")


def test_an_unknown_variable_makes_absence_unprovable(tmp_path: Path) -> None:
    pkg = ament_package(tmp_path / "src", "demo", """
        install(DIRECTORY ${MY_DIRS} DESTINATION share/${PROJECT_NAME})
        install(DIRECTORY launch DESTINATION share/${PROJECT_NAME})""")
    top = write(pkg / "launch" / "top.launch.py", includer("demo", "launch/gone.launch.py"))
    found = findings(top)
    assert not [f for f in found if f[0] == "roslaunch_error"]
    assert any("not known statically" in m for r, m in found if r == "unresolved")


def test_files_rename_and_filters(tmp_path: Path) -> None:
    layout = read_cmake_layout("""
        project(p)
        install(FILES a/b.yaml DESTINATION share/p/config RENAME c.yaml)
        install(PROGRAMS scripts/run.py DESTINATION lib/p)
        install(DIRECTORY cfg DESTINATION share/p FILES_MATCHING PATTERN "*.yaml"
                PATTERN "private" EXCLUDE)
        # install(DIRECTORY commented DESTINATION share/p)
        #[[ install(DIRECTORY bracket_commented DESTINATION share/p) ]]
        """, "p", "CMakeLists.txt")
    assert layout.explain("config/c.yaml").sources == ["a/b.yaml"]
    assert layout.explain("cfg/x.yaml").sources == ["cfg/x.yaml"]
    assert layout.explain("cfg/x.txt").sources == []
    assert layout.explain("cfg/private/x.yaml").sources == []
    assert layout.explain("commented/x").sources == []
    assert layout.explain("bracket_commented/x").sources == []
    assert layout.explain("run.py").sources == []
    assert layout.explain("cfg/x.yaml").complete


def test_rules_in_a_loop_or_regex_are_not_proof(tmp_path: Path) -> None:
    looped = read_cmake_layout("""
        foreach(dir launch config)
          install(DIRECTORY ${dir} DESTINATION share/${PROJECT_NAME})
        endforeach()""", "p", "CMakeLists.txt")
    assert not looped.explain("launch/x.py").complete
    regex = read_cmake_layout(
        'install(DIRECTORY launch DESTINATION share/p FILES_MATCHING REGEX ".*py")', "p", "C")
    assert not regex.explain("launch/x.py").complete


def test_ament_auto_package_installs_to_share(tmp_path: Path) -> None:
    layout = read_cmake_layout("ament_auto_package(INSTALL_TO_SHARE launch config)", "p", "C")
    assert layout.explain("config/a.yaml").sources == ["config/a.yaml"]


def test_setup_py_data_files(tmp_path: Path) -> None:
    pkg = tmp_path / "pyp"
    for name in ("launch/a.launch.py", "launch/b.launch.xml", "urdf/robot.urdf",
                 "urdf/parts/wheel.xacro", "config/.hidden.yaml", "config/c.yaml"):
        write(pkg / name, "x")
    source = b"""
import os
from glob import glob
from setuptools import setup
package_name = 'pyp'
data_files = [
    ('share/ament_index/resource_index/packages', ['resource/' + package_name]),
    ('share/' + package_name, ['package.xml']),
    (os.path.join('share', package_name, 'launch'), glob(os.path.join('launch', '*.launch.*'))),
    (f'share/{package_name}/config', glob('config/*')),
]
data_files += [(os.path.join('share', package_name, os.path.dirname(f)), [f])
               for f in glob('urdf/**/*', recursive=True)]
setup(name=package_name, data_files=data_files)
"""
    layout = read_setup_py(source, str(pkg), "pyp", "setup.py")
    assert layout.reasons == []
    assert layout.explain("launch/a.launch.py").sources == ["launch/a.launch.py"]
    assert layout.explain("launch/b.launch.xml").sources == ["launch/b.launch.xml"]
    assert layout.explain("urdf/parts/wheel.xacro").sources == ["urdf/parts/wheel.xacro"]
    assert layout.explain("config/c.yaml").sources == ["config/c.yaml"]
    assert layout.explain("config/.hidden.yaml").sources == []  # glob skips hidden names
    assert layout.explain("package.xml").sources == ["package.xml"]


def test_setup_py_is_never_run_and_unknowns_stay_unknown(tmp_path: Path) -> None:
    marker = tmp_path / "ran"
    source = f"""
import os
from setuptools import setup
open({str(marker)!r}, 'w').write('x')
setup(name='p', data_files=[('share/p/launch', os.listdir('launch'))])
""".encode()
    layout = read_setup_py(source, str(tmp_path), "p", "setup.py")
    assert not marker.exists()
    assert layout.rules == [] and layout.reasons
    assert not layout.explain("launch/x.py").complete


def test_setup_cfg_data_files(tmp_path: Path) -> None:
    write(tmp_path / "launch" / "x.launch.py", "x")
    layout = read_setup_cfg(
        "[options.data_files]\nshare/p/launch = launch/*.launch.py\nshare/p = package.xml\n",
        str(tmp_path), "p", "setup.cfg")
    assert layout.explain("launch/x.launch.py").sources == ["launch/x.launch.py"]
    assert layout.explain("package.xml").sources == ["package.xml"]


def test_ros1_packages_keep_the_source_folder(tmp_path: Path) -> None:
    # catkin runs $(find) from the source folder: install rules do not apply.
    write(tmp_path / "src" / "r1" / "package.xml", CATKIN.format(name="r1"))
    write(tmp_path / "src" / "r1" / "CMakeLists.txt",
          "install(DIRECTORY other/launch DESTINATION ${CATKIN_PACKAGE_SHARE_DESTINATION})")
    write(tmp_path / "src" / "r1" / "other" / "launch" / "b.launch", "<launch/>")
    top = write(tmp_path / "src" / "r1" / "launch" / "a.launch",
                '<launch><include file="$(find r1)/launch/b.launch"/></launch>')
    (error,) = [m for r, m in findings(top) if r == "roslaunch_error"]
    assert "included file not found" in error


def test_absolute_paths_outside_the_tree_are_unknown(tmp_path: Path) -> None:
    write(tmp_path / "src" / "r1" / "package.xml", CATKIN.format(name="r1"))
    top = write(tmp_path / "src" / "r1" / "launch" / "a.launch", """<launch>
      <include file="/opt/ros/noetic/share/amcl/examples/amcl_diff.launch"/>
      <include file="$(dirname)/missing_here.launch"/>
    </launch>""")
    found = findings(top)
    errors = [m for r, m in found if r == "roslaunch_error"]
    assert len(errors) == 1 and "missing_here.launch" in errors[0]
    assert any("amcl_diff.launch" in m and "outside the linted workspace" in m
               for r, m in found if r == "unresolved")


def test_xacro_includes_and_descriptions_follow_the_layout(tmp_path: Path) -> None:
    pkg = ament_package(tmp_path / "src", "desc",
                        "install(DIRECTORY description/urdf DESTINATION share/${PROJECT_NAME})")
    write(pkg / "description" / "urdf" / "robot.urdf.xacro", """<robot name="r"
      xmlns:xacro="http://www.ros.org/wiki/xacro">
      <xacro:include filename="$(find desc)/urdf/parts.xacro"/>
      <link name="base"/><xacro:arm/></robot>""")
    write(pkg / "description" / "urdf" / "parts.xacro", """<robot
      xmlns:xacro="http://www.ros.org/wiki/xacro"><xacro:macro name="arm">
      <link name="arm"/><joint name="j" type="fixed"><parent link="base"/>
      <child link="arm"/></joint></xacro:macro></robot>""")
    top = write(pkg / "launch" / "view.launch.py", """import os
from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.substitutions import Command
from launch_ros.actions import Node
def generate_launch_description():
    xacro_file = os.path.join(get_package_share_directory('desc'), 'urdf', 'robot.urdf.xacro')
    return LaunchDescription([Node(package='robot_state_publisher',
        executable='robot_state_publisher',
        parameters=[{'robot_description': Command(['xacro ', xacro_file])}])])
""")
    result = lint_paths([str(top)], LintOptions())
    assert [j.name for _, j in result.joints] == ["j"]


def test_hostile_cmake_is_bounded() -> None:
    start = time.process_time()
    deep = "install(" + "(" * 20_000 + "DIRECTORY x DESTINATION share/p" + ")" * 20_000 + ")"
    read_cmake_layout(deep, "p", "C")
    many = "set(A x)\n" + "set(A ${A}${A})\n" * 20_000 + "install(FILES ${A} DESTINATION share/p)\n"
    read_cmake_layout(many, "p", "C")
    unclosed = 'install(FILES "' + "x" * 2_000_000
    read_cmake_layout(unclosed, "p", "C")
    assert len(commands("a()\n" * 40_000)) == 20_000
    assert time.process_time() - start < 60


def test_hostile_setup_py_is_bounded(tmp_path: Path) -> None:
    start = time.process_time()
    deep = b"setup(data_files=" + b"[" * 100_000 + b"]" * 100_000 + b")"
    assert read_setup_py(deep, str(tmp_path), "p", "setup.py").reasons
    doubling = b"a = ['x']\n" + b"a = a + a\n" * 20_000 + b"setup(data_files=[('share/p', a)])"
    assert read_setup_py(doubling, str(tmp_path), "p", "setup.py").reasons
    for index in range(300):
        write(tmp_path / f"d{index}" / "f.txt", "x")
    globbing = b"setup(data_files=[('share/p', glob('**/*', recursive=True))] * 1)"
    read_setup_py(globbing, str(tmp_path), "p", "setup.py")
    assert time.process_time() - start < 60


def test_the_index_locates_through_the_layout(tmp_path: Path) -> None:
    pkg = ament_package(tmp_path, "demo", "install(DIRECTORY bringup/launch DESTINATION "
                        "share/demo)")
    write(pkg / "bringup" / "launch" / "x.py", "x")
    index = PackageIndex([str(tmp_path)])
    assert index.locate(str(pkg / "launch" / "x.py")).path == str(pkg / "bringup/launch/x.py")
    gone = index.locate(str(pkg / "launch" / "y.py"))
    assert gone.path is None and gone.absent


DUAL = """<?xml version="1.0"?>
<package format="3"><name>{name}</name>
<buildtool_depend condition="$ROS_VERSION == 1">catkin</buildtool_depend>
<buildtool_depend condition="$ROS_VERSION == 2">ament_python</buildtool_depend>
<export>
  <build_type condition="$ROS_VERSION == 1">catkin</build_type>
  <build_type condition="$ROS_VERSION == 2">ament_python</build_type>
</export></package>
"""


def test_a_package_for_both_ros_versions_is_read_for_the_one_asked(tmp_path: Path) -> None:
    # carla-simulator/ros-bridge: catkin under ROS_VERSION 1, ament_python under 2, and
    # setup() inside `if ROS_VERSION == 2:` (not read): a ROS 2 include of a launch file
    # the source holds is unknown, never "not found" because the first build type is catkin.
    from launch_linter.workspace.packages import package_ros_version

    manifest = write(tmp_path / "src" / "dual" / "package.xml", DUAL.format(name="dual"))
    assert package_ros_version(str(manifest)) is None
    assert package_ros_version(str(manifest), 1) == 1
    assert package_ros_version(str(manifest), 2) == 2
    write(tmp_path / "src" / "dual" / "setup.py",
          "import os\nif os.environ['ROS_VERSION'] == '2':\n"
          "    from setuptools import setup\n    setup(name='dual')\n")
    write(tmp_path / "src" / "dual" / "launch" / "inner.launch.py", INNER)
    top = write(tmp_path / "src" / "dual" / "launch" / "top.launch.py",
                includer("dual", "inner.launch.py"))
    assert not [m for r, m in findings(top) if r == "roslaunch_error"]


def test_a_ros1_find_of_a_ros2_package_proves_nothing_absent(tmp_path: Path) -> None:
    # pmb2_navigation: a catkin package left beside the ament one its $(find) names; the
    # ROS 1 package of that name (another branch) holds the file.
    ament_package(tmp_path / "src", "sensors",
                  "install(DIRECTORY launch DESTINATION share/${PROJECT_NAME})")
    write(tmp_path / "src" / "old" / "package.xml", CATKIN.format(name="old"))
    top = write(tmp_path / "src" / "old" / "launch" / "a.launch",
                '<launch><include file="$(find sensors)/launch/laser.launch"/></launch>')
    found = findings(top)
    assert not [f for f in found if f[0] == "roslaunch_error"]
    assert any("builds for ROS 2" in m for r, m in found if r == "unresolved")


def test_a_package_xml_is_parsed_once_for_both_questions(
        tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """Which ROS an XML launch file is (the engine) and whether the package has an install
    layout (``building_for`` 2) are answered from one parse of its package.xml."""
    from launch_linter.workspace import packages

    parsed: list[tuple[str, ...]] = []
    parse = packages.parse_xml

    def counted(data: bytes, text_tags: tuple[str, ...] = ()) -> object:
        if "build_type" in text_tags:
            parsed.append(text_tags)
        return parse(data, text_tags=text_tags)

    monkeypatch.setattr(packages, "parse_xml", counted)
    pkg = ament_package(tmp_path / "src", "demo",
                        "install(DIRECTORY bringup/launch DESTINATION share/${PROJECT_NAME})")
    write(pkg / "bringup" / "launch" / "inner.launch.py", INNER)
    top = write(pkg / "bringup" / "launch" / "top.launch.xml",
                '<launch>\n  <include file="$(find-pkg-share demo)/launch/inner.launch.py"/>\n'
                '</launch>\n')
    assert transforms(top) == ["b"]
    assert len(parsed) == 1


def test_a_package_found_twice_in_the_roots_proves_nothing_absent(tmp_path: Path) -> None:
    # Single-package repositories cloned side by side (a driver and its fork): the linted
    # one's parent folder is the root, colcon refuses two packages of one name, and which
    # copy's files get installed is unknown. One copy alone still proves absence.
    install = "install(DIRECTORY params DESTINATION share/${PROJECT_NAME})"
    fork = ament_package(tmp_path / "Fork", "driver", install)
    mine = ament_package(tmp_path / "mine", "driver", install)
    write(mine / "params" / "GS2.yaml", "x")
    index = PackageIndex([str(tmp_path)])
    unknown = index.locate(str(fork / "params" / "GS2.yaml"))
    assert unknown.path is None and not unknown.absent
    assert "found in 2 places" in unknown.reason
    alone = PackageIndex([str(tmp_path / "Fork")]).locate(str(fork / "params" / "GS2.yaml"))
    assert alone.path is None and alone.absent


def test_an_escaped_quote_in_an_unquoted_argument_opens_no_quoted_one() -> None:
    """CMake's unquoted argument takes ``\\"`` as an escape (point_lio's
    ``add_definitions(-DROOT_DIR=\\"${CMAKE_CURRENT_SOURCE_DIR}/\\")``): read as the start of
    a quoted argument, it swallowed every later command, and the package seemed to install
    nothing."""
    text = ('add_definitions(-DROOT_DIR=\\"${CMAKE_CURRENT_SOURCE_DIR}/\\")\n'
            "install(TARGETS mapping DESTINATION lib/${PROJECT_NAME})\n")
    found = commands(text)
    assert [name for name, _, _ in found] == ["add_definitions", "install"]
    assert [a.text for a in found[1][1]] == ["TARGETS", "mapping", "DESTINATION",
                                              "lib/${PROJECT_NAME}"]
    # A backslash at the very end of the text is a token too (nothing left unmatched).
    assert [name for name, _, _ in commands("set(a b\\")] == ["set"]


def test_twenty_thousand_escapes_in_one_argument_are_read_in_linear_time() -> None:
    started = time.process_time()
    found = commands("add_definitions(" + '-DA=\\"x\\"' * 20_000 + ")\ninstall(FILES a)\n")
    assert [name for name, _, _ in found] == ["add_definitions", "install"]
    assert time.process_time() - started < 60
