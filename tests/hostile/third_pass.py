"""The third red-team pass's cases (issue 22): work that xacro, suppressions, includes,
``$(eval)``, the package crawl, configuration globs, beliefs and discovery did outside the
budget, and a repository's own files (``.gitignore``) that hung a plain ``check DIR``.
Scaled so that the code before the fix took a minute, ran out of memory or hung."""

from __future__ import annotations

import os
from pathlib import Path

from hostile_cases import GOOD, Case, _text, _write, node

XACRO_NS = 'xmlns:xacro="http://www.ros.org/wiki/xacro"'


def _package(folder: Path, name: str) -> Path:
    package = folder / name
    (package / "launch").mkdir(parents=True, exist_ok=True)
    (package / "urdf").mkdir(exist_ok=True)
    (package / "package.xml").write_text(f"<package><name>{name}</name></package>")
    return package


def _described(folder: Path, name: str, files: dict[str, str], count: int = 1,
               arg: str = "", launch: str = "robot", first: int = 0) -> str:
    """A launch file describing the robot ``files['robot.xacro']`` ``count`` times, the
    ``i``-th with the xacro arg ``{arg}:=r{i}`` when ``arg`` is given."""
    package = _package(folder, name)
    for file_name, content in files.items():
        _write(package, f"urdf/{file_name}", content)
    params = "".join(
        f'<group ns="r{i}"><param name="robot_description" command="$(find xacro)/xacro '
        f'$(find {name})/urdf/robot.xacro{f" {arg}:=r{i}" if arg else ""}"/>'
        f'<node pkg="robot_state_publisher" type="robot_state_publisher" name="rsp"/>'
        f'</group>' for i in range(first, first + count))
    return _write(package, f"launch/{launch}.launch", f"<launch>{params}{node('n')}</launch>")


def _doubling_macros(name: str) -> str:
    macros = ['<xacro:macro name="m0"><xacro:property name="p" value="${1 + 1}"/></xacro:macro>']
    macros += [f'<xacro:macro name="m{i}"><xacro:m{i - 1}/><xacro:m{i - 1}/></xacro:macro>'
               for i in range(1, 41)]
    return f'<robot name="{name}" {XACRO_NS}>{"".join(macros)}<xacro:m40/></robot>'


def _xacro_doubling(folder: Path) -> str:
    return _described(folder, "doubling", {"robot.xacro": _doubling_macros("d")})


def _big_body(elements: int) -> str:
    return "".join(f'<link name="l{i}"/>' for i in range(elements))


def _xacro_big_include(folder: Path) -> str:
    big = f'<robot {XACRO_NS}>{_big_body(40_000)}</robot>'
    includes = '<xacro:include filename="$(find bigincl)/urdf/big.xacro"/>' * 100
    return _described(folder, "bigincl", {"big.xacro": big,
                                          "robot.xacro": f'<robot name="r" {XACRO_NS}>'
                                                         f'{includes}</robot>'})


def _xacro_many_descriptions(folder: Path) -> str:
    return _described(folder, "manydesc", {"robot.xacro": _doubling_macros("m")}, count=12)


def _xacro_unread_args(folder: Path) -> str:
    """Twelve launch files, each describing one costly xacro with an arg it never reads
    (``prefix:=rI``): one expansion for the run, not twelve (36 s before)."""
    for index in range(12):
        _described(folder, "unread", {"robot.xacro": _doubling_macros("u")}, arg="prefix",
                   launch=f"r{index}", first=index)
    return str(folder / "unread" / "launch")


def _xacro_read_args(folder: Path) -> str:
    """Twelve descriptions of one costly xacro that reads its arg: twelve expansions,
    which together meet the launch tree's budget (36 s before)."""
    body = _doubling_macros("p").replace("<xacro:m40/>",
                                         '<xacro:arg name="prefix" default=""/>'
                                         '<link name="$(arg prefix)base"/><xacro:m40/>')
    return _described(folder, "readargs", {"robot.xacro": body}, count=12, arg="prefix")


def _xacro_copied_property(folder: Path) -> str:
    value = "x" * 8000
    macros = ['<xacro:macro name="c0"><link name="${big}"/></xacro:macro>']
    macros += [f'<xacro:macro name="c{i}"><xacro:c{i - 1}/><xacro:c{i - 1}/></xacro:macro>'
               for i in range(1, 18)]
    body = (f'<robot name="c" {XACRO_NS}><xacro:property name="big" value="{value}"/>'
            f'{"".join(macros)}<xacro:c17/></robot>')
    return _described(folder, "copied", {"robot.xacro": body})


def _xacro_escapes(folder: Path) -> str:
    body = f'<robot name="e" {XACRO_NS}><link name="{"$${x}" * 40_000}"/></robot>'
    return _described(folder, "escapes", {"robot.xacro": body})


def _xacro_special_include(folder: Path) -> str:
    fifo = folder / "xacro.fifo"
    if not fifo.exists():
        os.mkfifo(str(fifo))
    includes = "".join(f'<xacro:include filename="{target}"/>' for target in ("/dev/zero", fifo))
    return _described(folder, "special", {"robot.xacro": f'<robot name="s" {XACRO_NS}>'
                                                         f'{includes}</robot>'})


def _suppressions() -> str:
    # Every directive unused, each reported (and checked against every other directive).
    directives = "".join(f"<!-- launch-linter: disable=self_transform -->"
                         f'\n<arg name="a{i}" default="x"/>\n' for i in range(20_000))
    return f"<launch>{directives}{node('n')}</launch>"


def _many_arg_references() -> str:
    return ('<launch><arg name="a" default="x"/>'
            + node("n", "0 0 0 0 0 0 b " + "$(arg a)" * 200_000) + "</launch>")


def _big_list_literal(folder: Path) -> str:
    literal = "[" + "0," * 4_000_000 + "]"
    return _write(folder, "biglist.launch.py",
                  f"from launch import LaunchDescription\nX = {literal}\n"
                  "def generate_launch_description():\n    return LaunchDescription([])\n")


def _doubling_includes(folder: Path) -> str:
    for level in range(31):
        nxt = f'<include file="$(dirname)/d{level + 1}.launch"/>' * 2 if level < 30 else node("x")
        _write(folder, f"doubled/d{level}.launch", f"<launch>{nxt}</launch>")
    return str(folder / "doubled" / "d0.launch")


def _eval_format() -> str:
    return ('<launch><arg name="f" default="$(eval \'%01000000000d\' % 1)"/>'
            f"{node('n')}</launch>")


def _package_copies(folder: Path) -> str:
    manifest = ("<package><name>copy</name>" + "<!-- padding -->" * 47_000 + "</package>")
    for index in range(120):
        _write(folder, f"copies/src/copy{index}/package.xml", manifest)
    return _write(folder, "copies/src/copy0/launch/x.launch",
                  "<launch>" + node("n", "0 0 0 0 0 0 $(find missing) b") + "</launch>")


def _many_ignore_patterns(folder: Path) -> str:
    sub = folder / "ignores"
    patterns = "".join(f'"{"*a" * 8}{i}/**" = ["tf"]\n' for i in range(1000))
    _write(sub, ".launch-linter.toml", "[per-path-ignores]\n" + patterns)
    deep = "/".join("a" * 60 for _ in range(3))
    for index in range(200):
        _write(sub, f"{deep}/f{index}.launch", GOOD)
    return str(sub)


def _big_beliefs(folder: Path) -> str:
    """A repository whose configuration names a beliefs file of 60 MB of tiny items."""
    sub = folder / "beliefs_repo"
    _write(sub, ".launch-linter.toml", 'beliefs = "beliefs.json"\n')
    with open(sub / "beliefs.json", "wb") as handle:
        handle.write(b'{"format": "launch-linter-beliefs/1", "beliefs": [')
        handle.write(b"{}," * (20 * 1024 * 1024) + b"{}]}")
    _write(sub, "a.launch", GOOD)
    return str(sub)


def remove_nested_folders(folder: Path) -> None:
    """Remove what ``_nested_folders`` made, deepest first: pytest's own clean-up of old
    temporary folders recurses per level and fails on 1,500 of them (RecursionError)."""
    chain = [folder / "nested"]
    while (chain[-1] / "d").is_dir():
        chain.append(chain[-1] / "d")
    for path in reversed(chain):
        for child in path.iterdir():
            if not child.is_dir():
                child.unlink()
        path.rmdir()


def _nested_folders(folder: Path) -> str:
    sub = folder / "nested"
    deep = sub
    sub.mkdir(exist_ok=True)
    for _ in range(1500):
        deep = deep / "d"
        deep.mkdir(exist_ok=True)
    _write(sub, "beside.launch", GOOD)
    return str(sub)


def _gitignore_fifo(folder: Path) -> str:
    sub = folder / "fifo_repo"
    sub.mkdir(exist_ok=True)
    if not (sub / ".gitignore").exists():
        os.mkfifo(str(sub / ".gitignore"))
    _write(sub, "a.launch", GOOD)
    return str(sub)


def _gitignore_backtracking(folder: Path) -> str:
    sub = folder / "gitignore_repo"
    (sub / ".git").mkdir(parents=True, exist_ok=True)
    _write(sub, ".gitignore", "*a*a*a*a*a*a*a*a*a*a*a*b\n" * 20)
    _write(sub, f"{'a' * 200}/x.launch", GOOD)
    return str(sub)


def _gitignore_folder_stars(folder: Path) -> str:
    """``**`` segments and single stars together: ``pathspec``'s regular expression took
    minutes on a path of long folder names."""
    sub = folder / "folder_stars_repo"
    (sub / ".git").mkdir(parents=True, exist_ok=True)
    _write(sub, ".gitignore", "**/*a*a/**/*a*a*b\n**/a/**/a/**/a/**/a/**/a/**/a/**/b\n")
    _write(sub, "/".join(["a" * 200] * 6) + "/x.launch", GOOD)
    _write(sub, "a/" * 60 + "x.launch", GOOD)
    return str(sub)


def _exclude_backtracking(folder: Path) -> str:
    """A configuration's ``exclude`` glob that ``fnmatch``'s regular expression matches
    by backtracking (exponential on Python 3.8)."""
    sub = folder / "exclude_repo"
    _write(sub, ".launch-linter.toml",
           'extend-exclude = ["' + "*a" * 12 + '*b", "' + "*a" * 12 + '*/b"]\n')
    _write(sub, f"{'a' * 200}/{'a' * 200}.launch", GOOD)
    return str(sub)


def _cmake_loop_installs(folder: Path) -> str:
    """A package whose CMakeLists.txt (under its 1 MiB bound) names the launch file in
    roslaunch_add_file_check and wraps 19,000 installs in one loop of 300,000 items: each
    install expanded per item is 5.7 billion comparisons."""
    package = _package(folder, "loops")
    installs = "install(FILES ${d})\n" * 19_000
    _write(package, "CMakeLists.txt", f"roslaunch_add_file_check(launch/robot.launch)\n"
                                      f"foreach(d {'d ' * 300_000})\n{installs}endforeach()\n")
    return _write(package, "launch/robot.launch", f"<launch>{node('n')}</launch>")


def _observation_sources() -> str:
    """A costmap listing 60,000 observation sources: each names a sensor_frame parameter
    move_base looks up; kept without repeats by searching a list, that was 53 s."""
    items = " ".join(f"s{i}" for i in range(60_000))
    return (f'<launch><node pkg="move_base" type="move_base" name="move_base">'
            f'<param name="global_costmap/observation_sources" value="{items}"/></node>'
            f'{node("n")}</launch>')


def _sensor_frame_params() -> str:
    """A costmap listing 20,000 observation sources, each with its sensor_frame '/f' set by
    a <param>: 40,000 findings, each placed at the line that sets its value. Looked up by
    scanning the node's parameters per finding, that was 44 s of CPU."""
    count = 20_000
    items = " ".join(f"s{i}" for i in range(count))
    params = "".join(f'<param name="global_costmap/s{i}/sensor_frame" value="/f{i}"/>'
                     for i in range(count))
    return (f'<launch><node pkg="move_base" type="move_base" name="move_base">'
            f'<param name="global_costmap/observation_sources" value="{items}"/>{params}'
            f'</node>{node("n")}</launch>')


THIRD_PASS: dict[str, Case] = {
    # Stopped by its own step bound, or on a slow machine by the tree's 5 s first.
    "xacro_doubling": Case("work", _xacro_doubling, "its joints are not read"),
    "xacro_big_include": Case("work", _xacro_big_include),
    "xacro_many_descriptions": Case("work", _xacro_many_descriptions),
    "xacro_unread_args": Case("discovery", _xacro_unread_args),
    "xacro_read_args": Case("work", _xacro_read_args, "work budget of this launch tree"),
    "xacro_copied_property": Case("work", _xacro_copied_property, "characters of attribute text"),
    "xacro_escapes": Case("work", _xacro_escapes),
    "xacro_special_include": Case("special", _xacro_special_include, "not a regular file"),
    "suppressions": Case("work", _text("suppressions.launch", _suppressions()),
                         "suppresses nothing"),
    "many_arg_references": Case("work", _text("args.launch", _many_arg_references())),
    "big_list_literal": Case("work", _big_list_literal),
    "doubling_includes": Case("work", _doubling_includes, "work budget"),
    "eval_format": Case("work", _text("format.launch", _eval_format())),
    "package_copies": Case("work", _package_copies),
    "many_ignore_patterns": Case("discovery", _many_ignore_patterns),
    "nested_folders": Case("discovery", _nested_folders),
    "gitignore_fifo": Case("discovery", _gitignore_fifo),
    "gitignore_backtracking": Case("discovery", _gitignore_backtracking),
    "gitignore_folder_stars": Case("discovery", _gitignore_folder_stars),
    "exclude_backtracking": Case("discovery", _exclude_backtracking),
    "cmake_loop_installs": Case("work", _cmake_loop_installs),
    "observation_sources": Case("work", _text("sources.launch", _observation_sources())),
    "sensor_frame_params": Case("work", _text("frames.launch", _sensor_frame_params())),
}
