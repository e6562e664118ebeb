"""ros2_unused_include_arg: an include argument the included description (and what it
includes) neither declares nor reads, in Python, XML and YAML; anything the linter cannot
see makes the include's arguments unknown and silent."""

from __future__ import annotations

import time
from pathlib import Path

from launch_linter import LintOptions, lint_paths

RULE = "ros2_unused_include_arg"
PY_HEAD = ("import os\n"
           "from launch import LaunchDescription\n"
           "from launch.actions import DeclareLaunchArgument, IncludeLaunchDescription\n"
           "from launch.actions import OpaqueFunction, LogInfo\n"
           "from launch.conditions import IfCondition\n"
           "from launch.launch_description_sources import PythonLaunchDescriptionSource\n"
           "from launch.substitutions import LaunchConfiguration\n"
           "from launch_ros.actions import Node\n"
           "HERE = os.path.dirname(__file__)\n")


def py(*actions: str, before: str = "") -> str:
    body = "".join(f"        {a},\n" for a in actions)
    return (PY_HEAD + before + "def generate_launch_description():\n"
            f"    return LaunchDescription([\n{body}    ])\n")


def include(name: str, args: str, extra: str = "") -> str:
    return (f"IncludeLaunchDescription(PythonLaunchDescriptionSource(os.path.join(HERE, "
            f"'{name}')), launch_arguments={{{args}}}.items(){extra})")


def lint(tmp_path: Path, files: dict[str, str], root: str = "main.launch.py",
         options: LintOptions | None = None) -> list[tuple[str, int, str]]:
    for name, text in files.items():
        (tmp_path / name).write_text(text, encoding="utf-8")
    # XML without a package.xml would be read as ROS 1 (whose roslaunch refuses unused
    # include arguments: roslaunch_error).
    result = lint_paths([str(tmp_path / root)], options or LintOptions(package_paths=(), ros=2))
    return [(Path(d.path).name, d.line, d.message) for d in result.diagnostics
            if d.rule == RULE]


def test_an_argument_the_included_file_never_uses(tmp_path: Path) -> None:
    """husarion_ugv_ros#640: publish_robot_state:=False passed to a file without it."""
    child = py("DeclareLaunchArgument('namespace', default_value='')",
               "Node(package='p', executable='e', namespace=LaunchConfiguration('namespace'))")
    main = py(include("child.launch.py", "'namespace': '',\n"
                      "            'publish_robot_state': 'False'"))
    [(name, line, message)] = lint(tmp_path, {"child.launch.py": child, "main.launch.py": main})
    assert (name, line) == ("main.launch.py", PY_HEAD.count("\n") + 4)
    assert "'publish_robot_state' is passed to" in message and "child.launch.py" in message
    fixed = py("DeclareLaunchArgument('namespace', default_value='')",
               "DeclareLaunchArgument('publish_robot_state', default_value='True')",
               "Node(package='p', executable='e', "
               "condition=IfCondition(LaunchConfiguration('publish_robot_state')))")
    assert lint(tmp_path, {"child.launch.py": fixed}) == []


def test_a_misspelt_argument_is_left_to_ros2_include_arg_misspelt(tmp_path: Path) -> None:
    (tmp_path / "child.launch.xml").write_text(
        '<launch>\n<arg name="use_sim_time" default="false"/>\n'
        '<node pkg="p" exec="e"><param name="use_sim_time" value="$(var use_sim_time)"/>'
        '</node>\n</launch>\n')
    main = ('<launch>\n<include file="$(dirname)/child.launch.xml">\n'
            '  <arg name="use_sim_time" value="true"/>\n'
            '  <arg name="use_sime_time" value="true"/>\n</include>\n</launch>\n')
    assert lint(tmp_path, {"main.launch.xml": main}, "main.launch.xml") == []


def test_yaml_includes_are_read_too(tmp_path: Path) -> None:
    (tmp_path / "child.launch.yaml").write_text("launch:\n- node: {pkg: p, exec: e}\n")
    main = ("launch:\n- include:\n    file: $(dirname)/child.launch.yaml\n    arg:\n"
            "    - {name: rate, value: '5'}\n")
    assert [(n, line) for n, line, _ in lint(tmp_path, {"main.launch.yaml": main},
                                             "main.launch.yaml")] == [("main.launch.yaml", 5)]


def test_reads_anywhere_in_the_included_tree_count(tmp_path: Path) -> None:
    """A read in a file the included file includes, in an OpaqueFunction, in a node a
    false condition skips, in a function the linter does not model: all uses."""
    reads = {
        "grandchild": py("Node(package='p', executable='e', "
                         "parameters=[{'r': LaunchConfiguration('x')}])"),
        "opaque": py("OpaqueFunction(function=setup)", before=(
            "def setup(context):\n"
            "    return [LogInfo(msg=context.launch_configurations['x'])]\n")),
        "skipped": py("Node(package='p', executable='e', condition=IfCondition('false'), "
                      "parameters=[{'r': LaunchConfiguration('x')}])"),
        "unmodelled": py("Node(package='p', executable='e', parameters=[rewritten])",
                         before="rewritten = RewrittenYaml(root_key=LaunchConfiguration('x'))\n"),
    }
    (tmp_path / "grandchild.launch.py").write_text(reads["grandchild"])
    main = py(include("child.launch.py", "'x': '1'"))
    for case, text in reads.items():
        child = py(include("grandchild.launch.py", "")) if case == "grandchild" else text
        assert lint(tmp_path, {"child.launch.py": child, "main.launch.py": main}) == [], case


def test_what_the_linter_cannot_see_is_silent(tmp_path: Path) -> None:
    unseen = {
        "dynamic name": ("child.launch.py", py(
            "Node(package='p', executable='e', parameters=[{'r': LaunchConfiguration(NAME)}])",
            before="NAME = 'y'\n")),
        "skipped include": ("child.launch.py", py(
            include("missing.launch.py", "", ", condition=IfCondition('false')"))),
        "include not found": ("child.launch.py", py(include("missing.launch.py", ""))),
        "parameter substitutions": ("child.launch.xml", (
            '<launch><node pkg="p" exec="e"><param from="$(dirname)/p.yaml" '
            'allow_substs="true"/></node></launch>')),
    }
    for case, (name, text) in unseen.items():
        main = py(include(name, "'x': '1'"))
        assert lint(tmp_path, {name: text, "main.launch.py": main}) == [], case


def test_a_parameter_file_with_substitutions_is_read(tmp_path: Path) -> None:
    """autoware's pose initializer: its parameter file, loaded with allow_substs, reads
    the argument ($(var x)); one that holds literals does not (a shape estimator's)."""
    (tmp_path / "child.launch.xml").write_text(
        '<launch><node pkg="p" exec="e"><param from="$(dirname)/p.yaml" allow_substs="true"/>'
        '</node></launch>')
    main = py(include("child.launch.xml", "'x': '1'"))
    (tmp_path / "p.yaml").write_text("/**:\n  ros__parameters:\n    r: $(var x)\n")
    assert lint(tmp_path, {"main.launch.py": main}) == []
    (tmp_path / "p.yaml").write_text("/**:\n  ros__parameters:\n    r: false\n")
    assert len(lint(tmp_path, {"main.launch.py": main})) == 1


def test_a_file_chosen_by_an_argument_is_an_interface(tmp_path: Path) -> None:
    """autoware's vehicle_interface.launch.xml of $(var vehicle_model)_launch: each
    vehicle's file fills the arguments its own way."""
    (tmp_path / "sample_vehicle.launch.xml").write_text("<launch/>")
    main = ('<launch><arg name="vehicle" default="sample"/>\n'
            '<include file="$(dirname)/$(var vehicle)_vehicle.launch.xml">\n'
            '<arg name="engage" value="true"/></include></launch>\n')
    assert lint(tmp_path, {"main.launch.xml": main}, "main.launch.xml") == []


def test_every_run_of_one_include_must_leave_it_unused(tmp_path: Path) -> None:
    """One include line run twice with the included file reading the argument in one run
    only (a branch on another argument)."""
    (tmp_path / "child.launch.xml").write_text(
        '<launch><arg name="mode" default="a"/>\n'
        '<group if="$(eval \'$(var mode)\' == \'b\')"><include file="$(dirname)/g.launch.xml"/>'
        '</group></launch>\n')
    (tmp_path / "g.launch.xml").write_text('<launch><node pkg="p" exec="$(var x)"/></launch>')
    main = ('<launch>\n<include file="$(dirname)/child.launch.xml">'
            '<arg name="x" value="e"/></include>\n</launch>\n')
    assert lint(tmp_path, {"main.launch.xml": main}, "main.launch.xml") == []


def test_the_study_profile_has_no_such_rule(tmp_path: Path) -> None:
    (tmp_path / "child.launch.xml").write_text("<launch/>")
    main = ('<launch><include file="$(dirname)/child.launch.xml">'
            '<arg name="x" value="1"/></include></launch>')
    assert len(lint(tmp_path, {"main.launch.xml": main}, "main.launch.xml")) == 1
    study = LintOptions(package_paths=(), ros=2, profile="study")
    assert lint(tmp_path, {}, "main.launch.xml", study) == []


def test_twenty_thousand_arguments_and_includes_stay_linear(tmp_path: Path) -> None:
    """20,000 arguments to one include (each a near miss of one of 20,000 declared names),
    and 20,000 includes each passing one: bounded "did you mean", no quadratic work."""
    declared = "".join(f'<arg name="argument_{i}" default="x"/>' for i in range(20_000))
    (tmp_path / "child.launch.xml").write_text(f"<launch>{declared}</launch>")
    passed = "".join(f'<arg name="argument{i}" value="1"/>' for i in range(20_000))
    many_args = f'<launch><include file="$(dirname)/child.launch.xml">{passed}</include></launch>'
    many_includes = "<launch>" + (
        '<include file="$(dirname)/leaf.launch.xml"><arg name="y" value="1"/></include>'
        * 20_000) + "</launch>"
    (tmp_path / "leaf.launch.xml").write_text('<launch><node pkg="p" exec="e"/></launch>')
    started = time.process_time()
    # The first 32 near misses are compared (misspelt: the other rule), the rest unused.
    (tmp_path / "args.launch.xml").write_text(many_args, encoding="utf-8")
    result = lint_paths([str(tmp_path / "args.launch.xml")], LintOptions(package_paths=(), ros=2))
    assert sum(d.rule == RULE for d in result.diagnostics) == 20_000 - 32
    assert sum(d.rule == "ros2_include_arg_misspelt" for d in result.diagnostics) == 32
    (tmp_path / "includes.launch.xml").write_text(many_includes, encoding="utf-8")
    result = lint_paths([str(tmp_path / "includes.launch.xml")],
                        LintOptions(package_paths=(), ros=2))
    found = sum(d.rule == RULE for d in result.diagnostics)
    # The tree's work budget is CPU time (5 s): on a slow or loaded machine it may cut the
    # last includes, and then says so; a quadratic walk would be cut after a few thousand.
    cut = any("work budget" in d.message for d in result.diagnostics if d.rule == "unresolved")
    assert found == 20_000 or (cut and found >= 10_000), found
    assert time.process_time() - started < 60


def test_a_decorated_entry_point_may_declare_what_it_is_passed(tmp_path: Path) -> None:
    """beluga: ``@with_launch_arguments(get_launch_arguments())`` declares the arguments
    around ``generate_launch_description``; the decorator is not read, so: unknown."""
    child = py("Node(package='p', executable='e')",
               before="def with_launch_arguments(arguments):\n"
                      "    return lambda function: function\n"
                      "@with_launch_arguments([DeclareLaunchArgument('map')])\n")
    main = py(include("child.launch.py", "'map': 'map.yaml'"))
    assert lint(tmp_path, {"child.launch.py": child, "main.launch.py": main}) == []
    undecorated = child.replace("@with_launch_arguments([DeclareLaunchArgument('map')])\n", "")
    assert len(lint(tmp_path, {"child.launch.py": undecorated})) == 1
