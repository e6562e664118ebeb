from __future__ import annotations

import time
from pathlib import Path

from launch_linter import LintOptions, lint_paths
from launch_linter.model.diagnostic import Diagnostic
from launch_linter.workspace.node_declarations import declared_parameters

RULE = "node_param_undeclared"
MANIFEST = ('<package format="3"><name>demo</name><version>0.1.0</version>'
            '<description>d</description><maintainer email="a@b.c">a</maintainer>'
            '<license>BSD</license><export><build_type>{build}</build_type></export>'
            '</package>')


def cpp_package(root: Path, source: str, cmake: str = "", header: str = "") -> Path:
    package = root / "demo"
    (package / "src").mkdir(parents=True)
    (package / "package.xml").write_text(MANIFEST.format(build="ament_cmake"),
                                         encoding="utf-8")
    (package / "CMakeLists.txt").write_text(
        cmake or "project(demo)\nadd_executable(reader src/reader.cpp)\n", encoding="utf-8")
    (package / "src" / "reader.cpp").write_text(source, encoding="utf-8")
    if header:
        (package / "include" / "demo").mkdir(parents=True)
        (package / "include" / "demo" / "reader.hpp").write_text(header, encoding="utf-8")
    return package


def node_source(*declares: str) -> str:
    body = "".join(f"    {d};\n" for d in declares)
    return ('#include "rclcpp/rclcpp.hpp"\n'
            'class Reader : public rclcpp::Node {\n public:\n'
            f'  Reader() : Node("reader") {{\n{body}  }}\n}};\n')


def lint(package: Path, parameters: str) -> tuple[Diagnostic, ...]:
    launch = package / "launch" / "demo.launch.py"
    launch.parent.mkdir(exist_ok=True)
    launch.write_text(
        "from launch import LaunchDescription\n"
        "from launch_ros.actions import Node\n\n\n"
        "def generate_launch_description():\n"
        "    return LaunchDescription([Node(package='demo', executable='reader',\n"
        f"        parameters=[{parameters}])])\n", encoding="utf-8")
    options = LintOptions(package_paths=(str(package.parent),), select=frozenset({RULE}))
    return lint_paths([str(launch)], options).diagnostics


def test_a_parameter_close_to_a_declared_one_is_reported_at_its_key(tmp_path: Path) -> None:
    package = cpp_package(tmp_path, node_source('declare_parameter("number_particles", 200)',
                                                'declare_parameter("topics", 1)'))
    (found,) = lint(package, "{'particles': 300, 'topics': 2}")
    assert found.severity.value == "info" and found.line == 7
    assert "'number_particles'" in found.message and "src/reader.cpp" in found.message


def test_declared_builtin_or_far_from_every_declaration_is_silent(tmp_path: Path) -> None:
    package = cpp_package(tmp_path, node_source('declare_parameter<int>("rate", 10)'))
    assert lint(package, "{'rate': 5, 'use_sim_time': True, 'diagnostic_period': 1.0}") == ()


def test_a_slash_for_a_dot_is_reported(tmp_path: Path) -> None:
    package = cpp_package(tmp_path, node_source('declare_parameter("tree.path", "")'))
    (found,) = lint(package, "{'tree/path': 'x'}")
    assert "'tree.path'" in found.message


def test_declarations_it_cannot_read_leave_the_node_unjudged(tmp_path: Path) -> None:
    for extra in ('declare_parameter(name_, 1)', 'declare_parameters("", {{"a", 1}})',
                  'rclcpp::NodeOptions().allow_undeclared_parameters(true)',
                  'auto o = rclcpp::NodeOptions()'
                  '.automatically_declare_parameters_from_overrides(true)'):
        folder = tmp_path / str(abs(hash(extra)))
        package = cpp_package(folder, node_source('declare_parameter("number_particles", 2)',
                                                  extra))
        assert lint(package, "{'particles': 300}") == (), extra
    # A target whose sources are in a variable, an executable not found.
    variable = cpp_package(tmp_path / "v", node_source('declare_parameter("rate", 1)'),
                           "project(demo)\nadd_executable(reader ${SOURCES})\n")
    assert lint(variable, "{'rates': 5}") == ()
    other = cpp_package(tmp_path / "o", node_source('declare_parameter("rate", 1)'),
                        "project(demo)\nadd_executable(other src/reader.cpp)\n")
    assert lint(other, "{'rates': 5}") == ()


def test_headers_and_linked_libraries_of_the_package_are_read(tmp_path: Path) -> None:
    header = ('#pragma once\n'
              'struct P { void d(rclcpp::Node & n) { n.declare_parameter("rate", 1); } };\n')
    source = '#include "demo/reader.hpp"\n' + node_source()
    cmake = ("project(demo)\nadd_library(core src/core.cpp)\n"
             "add_executable(reader src/reader.cpp)\ntarget_link_libraries(reader core)\n")
    package = cpp_package(tmp_path, source, cmake, header)
    (package / "src" / "core.cpp").write_text(
        'void f(rclcpp::Node & n) { n.declare_parameter("frame_id", "base"); }\n',
        encoding="utf-8")
    assert declared_parameters(str(package), "reader") == (("frame_id", "rate"),
                                                           "src/reader.cpp")
    (found,) = lint(package, "{'frame': 'x', 'rate': 2}")
    assert "'frame_id'" in found.message


def test_a_python_node_and_the_modules_of_its_package(tmp_path: Path) -> None:
    package = tmp_path / "demo"
    (package / "demo").mkdir(parents=True)
    (package / "package.xml").write_text(MANIFEST.format(build="ament_python"),
                                         encoding="utf-8")
    (package / "setup.py").write_text(
        "from setuptools import setup\nsetup(name='demo', packages=['demo'],\n"
        "      entry_points={'console_scripts': ['reader = demo.reader:main']})\n",
        encoding="utf-8")
    (package / "demo" / "__init__.py").write_text("", encoding="utf-8")
    (package / "demo" / "reader.py").write_text(
        "from demo.base import Base\n\n\nclass Reader(Base):\n"
        "    def __init__(self):\n        super().__init__()\n"
        "        self.declare_parameter('max_speed', 1.0)\n\n\ndef main():\n    Reader()\n",
        encoding="utf-8")
    (package / "demo" / "base.py").write_text(
        "from rclpy.node import Node\n\n\nclass Base(Node):\n    def __init__(self):\n"
        "        super().__init__('reader')\n        self.declare_parameter('frame_id', 'a')\n",
        encoding="utf-8")
    (found,) = lint(package, "{'max_sped': 2.0, 'frame_id': 'b'}")
    assert "'max_speed'" in found.message and "demo/reader.py" in found.message
    # A module of the package that is not there: the declarations are not all known.
    (package / "demo" / "base.py").unlink()
    assert lint(package, "{'max_sped': 2.0}") == ()


def test_twenty_thousand_parameters_declarations_targets_and_includes(tmp_path: Path) -> None:
    """One pass per loop over the input: the parameters given (the first 500 compared),
    the declarations of a source, the targets of a CMakeLists.txt (50 libraries followed
    at most) and the includes of a source (100 files read at most)."""
    count = 20_000
    declares = [f'declare_parameter("p{i}", 1)' for i in range(count)]
    cmake = "project(demo)\n" + "".join(
        f"add_library(l{i} src/reader.cpp)\n" for i in range(count)) + (
        "add_executable(reader src/reader.cpp)\ntarget_link_libraries(reader "
        + " ".join(f"l{i}" for i in range(count)) + ")\n")
    package = cpp_package(tmp_path / "a", node_source(*declares))
    given = "{" + ", ".join(f"'q{i}x': 1" for i in range(count)) + "}"
    started = time.process_time()
    assert len(lint(package, given)) <= 500
    linked = cpp_package(tmp_path / "b", node_source(*declares[:10]), cmake)
    assert declared_parameters(str(linked), "reader") is None
    includes = "".join(f'#include "h{i}.hpp"\n' for i in range(count))
    many = cpp_package(tmp_path / "c", includes + node_source('declare_parameter("a", 1)'))
    for i in range(200):
        (many / "src" / f"h{i}.hpp").write_text("", encoding="utf-8")
    assert declared_parameters(str(many), "reader") is None
    assert time.process_time() - started < 60


def shared_file_package(root: Path, fusion_cmake_extra: str = "") -> Path:
    """Two nodes of one package given one ``/**`` parameter file (trial 9's antenna
    tracker bringup): ``fusion`` declares ``mag_declination_deg``, ``controller``
    declares ``elevation_min_deg``; the file also sets ``gps_timeout_sec``, which no
    node declares, close to ``fusion``'s ``imu_timeout_sec``."""
    package = root / "demo"
    (package / "src").mkdir(parents=True)
    (package / "launch").mkdir()
    (package / "package.xml").write_text(MANIFEST.format(build="ament_cmake"),
                                         encoding="utf-8")
    (package / "CMakeLists.txt").write_text(
        "project(demo)\nadd_executable(fusion src/fusion.cpp)\n"
        f"add_executable(controller src/controller.cpp)\n{fusion_cmake_extra}"
        "install(TARGETS fusion controller DESTINATION lib/${PROJECT_NAME})\n"
        "install(DIRECTORY launch DESTINATION share/${PROJECT_NAME})\n",
        encoding="utf-8")
    (package / "src" / "fusion.cpp").write_text(node_source(
        'declare_parameter("mag_declination_deg", -8.0)',
        'declare_parameter("imu_timeout_sec", 1.0)'), encoding="utf-8")
    (package / "src" / "controller.cpp").write_text(node_source(
        'declare_parameter("elevation_min_deg", 0.0)'), encoding="utf-8")
    (package / "launch" / "params.yaml").write_text(
        "/**:\n  ros__parameters:\n    elevation_min_deg: 0.0\n    gps_timeout_sec: 10.0\n",
        encoding="utf-8")
    (package / "launch" / "demo.launch.py").write_text(
        "import os\n"
        "from launch import LaunchDescription\n"
        "from launch_ros.actions import Node\n\n\n"
        "def generate_launch_description():\n"
        "    params = os.path.join(os.path.dirname(__file__), 'params.yaml')\n"
        "    return LaunchDescription([\n"
        "        Node(package='demo', executable='fusion', name='fusion',\n"
        "             parameters=[params]),\n"
        "        Node(package='demo', executable='controller', name='controller',\n"
        "             parameters=[params]),\n"
        "    ])\n", encoding="utf-8")
    return package


def lint_launch(package: Path) -> tuple[Diagnostic, ...]:
    options = LintOptions(package_paths=(str(package.parent),), select=frozenset({RULE}))
    return lint_paths([str(package / "launch" / "demo.launch.py")], options).diagnostics


def test_a_shared_file_entry_another_receiver_declares_is_not_reported(
        tmp_path: Path) -> None:
    # rclcpp applies a /** entry to every node that declares the name: elevation_min_deg
    # is the controller's; gps_timeout_sec, declared by no receiver, is still reported.
    found = lint_launch(shared_file_package(tmp_path))
    assert [d.line for d in found] == [4]
    assert "'gps_timeout_sec'" in found[0].message and "'imu_timeout_sec'" in found[0].message


def test_a_receiver_known_in_part_still_claims_what_it_declares(tmp_path: Path) -> None:
    # The controller links a library whose sources are generated (not all its
    # declarations known): what its own source declares is still its.
    package = shared_file_package(
        tmp_path, "add_library(mpc src/mpc.cpp ${GENERATED})\n"
                  "target_link_libraries(controller mpc)\n")
    found = lint_launch(package)
    assert [d.line for d in found] == [4]


GENERATED_CMAKE = ("project(demo)\n"
                   "generate_parameter_library(reader_parameters src/reader_parameters.yaml)\n"
                   "add_executable(reader src/reader.cpp)\n"
                   "target_link_libraries(reader reader_parameters)\n")
GENERATED_YAML = ("reader:\n"
                  "  default_tree:\n"
                  "    load_default_tree: {type: bool, default_value: false}\n"
                  "    tree_path: {type: string, default_value: ''}\n"
                  "  rate: {type: double, default_value: 10.0}\n")
LISTENER_SOURCE = ('#include "rclcpp/rclcpp.hpp"\n#include "reader_parameters.hpp"\n'
                   'class Reader : public rclcpp::Node {\n public:\n'
                   '  Reader() : Node("reader"),\n'
                   '    listener_(std::make_shared<reader::ParamListener>(this)) {}\n'
                   '  std::shared_ptr<reader::ParamListener> listener_;\n};\n')


def test_a_generated_parameter_library_is_read_as_the_declarations(tmp_path: Path) -> None:
    """ros2_ros_bt_py#178: `default_tree/load_default_tree` given where the node's
    generate_parameter_library YAML declares `default_tree.load_default_tree`."""
    package = cpp_package(tmp_path, LISTENER_SOURCE, GENERATED_CMAKE)
    (package / "src" / "reader_parameters.yaml").write_text(GENERATED_YAML, encoding="utf-8")
    assert declared_parameters(str(package), "reader") == (
        ("default_tree.load_default_tree", "default_tree.tree_path", "rate"),
        "src/reader_parameters.yaml")
    (found,) = lint(package, "{'default_tree/load_default_tree': True, 'rate': 5.0}")
    assert "'default_tree.load_default_tree'" in found.message
    assert lint(package, "{'default_tree.load_default_tree': True}") == ()


def test_a_mapped_or_unread_generated_library_leaves_the_declarations_unknown(
        tmp_path: Path) -> None:
    package = cpp_package(tmp_path, LISTENER_SOURCE, GENERATED_CMAKE)
    assert declared_parameters(str(package), "reader") is None  # the YAML is missing
    prefixed = LISTENER_SOURCE.replace("ParamListener>(this)", "ParamListener>(this, \"arm\")")
    (package / "src" / "reader.cpp").write_text(prefixed, encoding="utf-8")
    (package / "src" / "reader_parameters.yaml").write_text(GENERATED_YAML, encoding="utf-8")
    assert declared_parameters(str(package), "reader") is None  # names under a prefix
    (package / "src" / "reader.cpp").write_text(LISTENER_SOURCE, encoding="utf-8")
    (package / "src" / "reader_parameters.yaml").write_text(
        "reader:\n  joints: {type: string_array}\n  __map_joints:\n"
        "    gain: {type: double}\n", encoding="utf-8")
    assert declared_parameters(str(package), "reader") is None


def test_twenty_thousand_generated_parameters_are_bounded(tmp_path: Path) -> None:
    package = cpp_package(tmp_path, LISTENER_SOURCE, GENERATED_CMAKE)
    entries = "".join(f"  p{i}: {{type: int}}\n" for i in range(20_000))
    (package / "src" / "reader_parameters.yaml").write_text(f"reader:\n{entries}",
                                                            encoding="utf-8")
    started = time.process_time()
    assert declared_parameters(str(package), "reader") is None  # more than 5,000: unknown
    assert time.process_time() - started < 60
