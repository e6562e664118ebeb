"""The hostile corpus: launch files (and folders) built to make a linter hang, blow up,
crash, forge its output or run something. Each case is written into a scratch folder by
:func:`materialise` (some are too large, or too special, to keep in git: FIFOs, 7 MB files,
symbolic-link loops).

A case names the file to lint; the test lints it together with a good file and holds the
run to the issue's standard (10 s of CPU, 1 GB of memory, exit 0/1, a diagnostic or status
for the hostile file, no internal error, every other input reported).
"""

from __future__ import annotations

import os
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

TF1 = 'pkg="tf2_ros" type="static_transform_publisher"'


def node(name: str, args: str = "0 0 0 0 0 0 base_link laser") -> str:
    return f'<node {TF1} name="{name}" args="{args}"/>'


def ros2_node(args: str = "0 0 0 0 0 0 a b") -> str:
    return f'<node pkg="tf2_ros" exec="static_transform_publisher" args="{args}"/>'


GOOD = f"<launch>{node('good')}</launch>"


@dataclass(frozen=True)
class Case:
    category: str
    build: Callable[[Path], str]
    """Writes the case under the folder given; returns the path to lint."""
    expect: str = ""
    """Words of a diagnostic the run must give on the case ("" when reading it is enough:
    a file that only looks hostile, such as a harmless encoding or an odd name)."""


def _write(folder: Path, name: str, content: str | bytes) -> str:
    path = folder / name
    path.parent.mkdir(parents=True, exist_ok=True)
    if isinstance(content, str):
        path.write_text(content, encoding="utf-8")
    else:
        path.write_bytes(content)
    return str(path)


def _text(name: str, content: str | bytes) -> Callable[[Path], str]:
    return lambda folder: _write(folder, name, content)


# -- work that grows without bound -------------------------------------------------------
def _doubling_args() -> str:
    lines = ['<launch><arg name="a0" default="0123456789abcdef"/>']
    lines += [f'<arg name="a{i}" default="$(arg a{i - 1})$(arg a{i - 1})"/>' for i in range(1, 64)]
    lines.append(node("n", "0 0 0 0 0 0 a $(arg a63)") + "</launch>")
    return "\n".join(lines)


def _doubling_let() -> str:
    lines = ['<launch><let name="v0" value="0123456789abcdef"/>']
    lines += [f'<let name="v{i}" value="$(var v{i - 1})$(var v{i - 1})"/>' for i in range(1, 64)]
    lines.append(ros2_node("0 0 0 0 0 0 a $(var v63)") + "</launch>")
    return "\n".join(lines)


def _undeclared_reads() -> str:
    # 20,000 declarations and 20,000 reads of near-miss names: every "did you mean" would
    # compare each read with each declaration.
    declared = "".join(f'<arg name="argument_{i}" default="x"/>' for i in range(20_000))
    reads = "".join(f'<set_parameter name="p{i}" value="$(var argument{i})"/>'
                    for i in range(20_000))
    return f"<launch>{declared}{reads}{ros2_node()}</launch>"


def _same_names() -> str:
    # 20,000 robot_state_publishers of one name under exclusive conditions, each reading a
    # description by a remap, and 20,000 parameters of that remapped name: the duplicate
    # name check and the remapped descriptions stay bounded.
    params = "".join(f'<param name="desc" textfile="/nonexistent/{i}.urdf"/>'
                     for i in range(20_000))
    nodes = "".join(f'<node if="$(eval arg(\'v\') == \'{i}\')" pkg="robot_state_publisher" '
                    f'type="robot_state_publisher" name="rsp">'
                    f'<remap from="robot_description" to="desc"/></node>'
                    for i in range(20_000))
    return f'<launch><arg name="v"/>{params}{nodes}{node("n")}</launch>'


def _prefixed_publishers(folder: Path) -> str:
    # One description of 40 joints published by 20,000 robot_state_publishers, each in its
    # namespace with its own tf_prefix: the prefixed copies of its frames stay bounded.
    links = "".join(f'<link name="l{i}"/>' for i in range(41))
    joints = "".join(f'<joint name="j{i}" type="fixed"><parent link="l{i}"/>'
                     f'<child link="l{i + 1}"/></joint>' for i in range(40))
    _write(folder, "many.urdf", f'<robot name="r">{links}{joints}</robot>')
    groups = "".join(f'<group ns="r{i}"><param name="tf_prefix" value="r{i}"/>'
                     f'<node pkg="robot_state_publisher" type="robot_state_publisher" '
                     f'name="rsp"/></group>' for i in range(20_000))
    return _write(folder, "prefixed_publishers.launch",
                  '<launch><param name="robot_description" '
                  f'textfile="$(dirname)/many.urdf"/>{groups}{node("n")}</launch>')


def _many_includes(folder: Path) -> str:
    _write(folder, "included/leaf.launch",
           "<launch>" + '<arg name="x" default="1"/>' * 3000 + node("leaf") + "</launch>")
    body = '<include file="$(dirname)/included/leaf.launch"/>' * 1900
    return _write(folder, "many_includes.launch", f"<launch>{body}</launch>")


def _eval_growth() -> str:
    evals = "".join(
        f'<arg name="e{i}" default="$(eval str([[list(range(2000))] * 400] * 1))"/>'
        for i in range(200)
    )
    formats = "".join(f'<arg name="f{i}" default="$(eval \'%9999d\' % 1 * 100)"/>'
                      for i in range(200))
    return f"<launch>{evals}{formats}{node('n')}</launch>"


_PYTHON_GROWTH = '''\
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    x = [1]
    for _ in range(200):
        x = [x, x]
    y = [0] * 10
    for _ in range(80):
        y = y * 2
    z = []
    for _ in range(1000000):
        z.append(z)
    s = "ab"
    for _ in range(200):
        s = s + s
    while True:
        s = s
    return LaunchDescription([Node(package="tf2_ros", executable="static_transform_publisher",
                                   arguments=["0", "0", "0", "0", "0", "0", "a", str(x)])])
'''


def _big_yaml(folder: Path) -> str:
    items = "".join(f"- arg: {{name: a{i}, default: 'x'}}\n" for i in range(200_000))
    return _write(folder, "big.launch.yaml", "launch:\n" + items)


_YAML_ALIASES = "launch:\n- arg: &a {name: x, default: [&b [1,1,1,1,1,1,1,1,1], " + ", ".join(
    "*b" for _ in range(50)) + "]}\n" + "".join("- arg: *a\n" for _ in range(5000))


def _attlist() -> str:
    default = "x" * 100_000
    return (f'<?xml version="1.0"?><!DOCTYPE launch [<!ATTLIST node junk CDATA "{default}">]>'
            "<launch>" + "<node/>" * 100_000 + "</launch>")


def _quadratic_prescan(folder: Path) -> str:
    return _write(folder, "prescan.launch", b"<launch>" + b"<node exec" * 600_000
                  + b"<!--<let " * 100_000)


def _tf_chain() -> str:
    return "<launch>" + "".join(node(f"c{i}", f"0 0 0 0 0 0 f{i} f{i + 1}")
                                for i in range(1500)) + "</launch>"


def _tf_loop() -> str:
    return "<launch>" + "".join(node(f"l{i}", f"0 0 0 0 0 0 f{i} f{(i + 1) % 700}")
                                for i in range(700)) + "</launch>"


def _tf_dense() -> str:
    # Every frame a parent of every other: very many loops.
    frames = [f"d{i}" for i in range(40)]
    nodes = [node(f"n{a}_{b}", f"0 0 0 0 0 0 {a} {b}") for a in frames for b in frames if a != b]
    return "<launch>" + "".join(nodes) + "</launch>"


def _many_parents() -> str:
    return "<launch>" + "".join(node(f"p{i}", f"0 0 0 0 0 0 parent{i} kid")
                                for i in range(1000)) + "</launch>"


def _symlink_loop(folder: Path) -> str:
    workspace = folder / "loop_ws" / "src"
    package = workspace / "pkg"
    (package / "launch").mkdir(parents=True, exist_ok=True)
    (package / "package.xml").write_text("<package><name>pkg</name></package>")
    for index in range(3):
        link = workspace / f"again{index}"
        if not link.exists():
            os.symlink(str(workspace), str(link))
    return _write(folder, "loop_ws/src/pkg/launch/find.launch",
                  "<launch>" + node("n", "0 0 0 0 0 0 $(find nowhere) b") + "</launch>")


def _backtracking_glob(folder: Path) -> str:
    sub = folder / "globbed" / ("a" * 200)
    sub.mkdir(parents=True, exist_ok=True)
    pattern = "*a" * 40 + "b/**"
    (folder / "globbed" / "launch-linter.toml").write_text(
        f'[per-path-ignores]\n"{pattern}" = ["tf"]\n')
    return _write(folder, f"globbed/{'a' * 200}/x.launch", GOOD)


# -- special files -------------------------------------------------------------------------
def _fifo(folder: Path) -> str:
    path = folder / "fifo.launch"
    if not path.exists():
        os.mkfifo(str(path))
    return str(path)


def _fifo_in_folder(folder: Path) -> str:
    sub = folder / "with_fifo"
    sub.mkdir(exist_ok=True)
    if not (sub / "pipe.launch").exists():
        os.mkfifo(str(sub / "pipe.launch"))
    if not (sub / "pipe.xml").exists():
        os.mkfifo(str(sub / "pipe.xml"))
    return str(sub)


def _special_includes(folder: Path) -> str:
    (folder / "a_folder.launch").mkdir(exist_ok=True)
    _fifo(folder)
    includes = "".join(f'<include file="{target}"/>' for target in (
        "/dev/zero", "/dev/urandom", str(folder / "a_folder.launch"), str(folder / "fifo.launch"),
        "/proc/self/status", "/proc/kmsg"))
    return _write(folder, "special_includes.launch", f"<launch>{includes}</launch>")


# -- encodings -----------------------------------------------------------------------------
_ENCODINGS = ("shift_jis", "utf-16-le", "utf-32", "big5", "rot13", "hex", "zlib", "utf-7",
              "idna", "base64", "UTF-9", "uTf-8\x00", "bogus-codec", "mbcs", "cp65001",
              "unicode_escape", "raw_unicode_escape", "punycode", "uu", "bz2", "quopri")


_READABLE = ("cp65001", "unicode_escape", "raw_unicode_escape")
"""Text codecs that read this ASCII file correctly: the file is fine."""


def _declared(encoding: str) -> bytes:
    return (f'<?xml version="1.0" encoding="{encoding}"?>'
            f"<launch>{node('enc')}</launch>").encode("latin-1")


_BOM_PYTHON = b"\xef\xbb\xbf" + b'''from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([Node(package="tf2_ros", executable="static_transform_publisher",
                                   arguments=["0", "0", "0", "0", "0", "0", "a", "b"])])
'''


# -- forged output -------------------------------------------------------------------------
_FORGED_XML = ("<launch>"
               + node("x&#10;good.launch:1:1: error: forged [self_transform]",
                      "0 0 0 0 0 0 base&#13;\u202emap child&#9;x")
               + "</launch>")

_FORGED_PYTHON = '''\
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package="tf2_ros", executable="static_transform_publisher", name="n\\x1b[2J\\x00",
             arguments=["0", "0", "nan", "0", "0", "inf", "a\\x00b\\n/x:1:1: error: forged",
                        "\\udcff\\x1b]0;title\\x07"]),
        Node(package="tf2_ros", executable="static_transform_publisher",
             arguments=["0", "0", "0", "0", "0", "0", "\\udcff\\x1b]0;title\\x07", "a\\x00b"]),
    ])
'''


def _odd_name(folder: Path) -> str:
    name = "odd\nname:1:1: error: forged [self_transform]\x1b[31m.launch"
    return _write(folder, name, GOOD)


# -- discovery -----------------------------------------------------------------------------
def _long_header(folder: Path) -> str:
    sub = folder / "header"
    header = "<!--\n" + "Licensed under the Apache License, Version 2.0.\n" * 4000 + "-->\n"
    _write(folder, "header/robot.xml", f'<?xml version="1.0"?>\n{header}'
                                       f"<launch>{node('after_header')}</launch>")
    return str(sub)


CASES: dict[str, Case] = {
    "doubling_args": Case("work", _text("doubling_args.launch", _doubling_args()), "longer than"),
    "doubling_let": Case("work", _text("doubling_let.launch.xml", _doubling_let()), "longer than"),
    "many_includes": Case("work", _many_includes, "work budget"),
    "same_names": Case("work", _text("same_names.launch", _same_names())),
    "prefixed_publishers": Case("work", _prefixed_publishers),
    "undeclared_reads": Case("work", _text("undeclared.launch.xml", _undeclared_reads()),
                             "does not exist"),
    "eval_growth": Case("work", _text("eval_growth.launch", _eval_growth())),
    "python_growth": Case("work", _text("growth.launch.py", _PYTHON_GROWTH), "not interpreted"),
    "big_yaml": Case("work", _big_yaml, "larger than"),
    "yaml_aliases": Case("work", _text("aliases.launch.yaml", _YAML_ALIASES)),
    "attlist": Case("work", _text("attlist.launch", _attlist()), "attribute-list"),
    "quadratic_prescan": Case("work", _quadratic_prescan),
    "tf_chain": Case("work", _text("chain.launch", _tf_chain())),
    "tf_loop": Case("work", _text("loop.launch", _tf_loop()), "and 696 more"),
    "tf_dense": Case("work", _text("dense.launch", _tf_dense()), "loop"),
    "many_parents": Case("work", _text("parents.launch", _many_parents()), "and 994 more"),
    "symlink_loop": Case("work", _symlink_loop),
    "backtracking_glob": Case("work", _backtracking_glob),
    "fifo": Case("special", _fifo, "not a regular file (a FIFO)"),
    "fifo_in_folder": Case("special", _fifo_in_folder, "not a regular file (a FIFO)"),
    "special_includes": Case("special", _special_includes, "not a regular file (a folder)"),
    "device": Case("special", lambda folder: "/dev/zero", "not a regular file (a device)"),
    "proc": Case("special", lambda folder: "/proc/self/environ", "not a regular file"),
    "bom_python": Case("encoding", _text("bom.launch.py", _BOM_PYTHON)),
    "bom_xml": Case("encoding", _text("bom.launch", b"\xef\xbb\xbf" + GOOD.encode())),
    **{f"encoding_{name}": Case("encoding", _text(f"enc_{index}.launch", _declared(name)),
                                "" if name in _READABLE else
                                "not well-formed" if "\x00" in name else "encoding")
       for index, name in enumerate(_ENCODINGS)},
    "forged_xml": Case("forged", _text("forged.launch", _FORGED_XML)),
    "forged_python": Case("forged", _text("forged.launch.py", _FORGED_PYTHON)),
    "odd_name": Case("forged", _odd_name),
    "long_header": Case("discovery", _long_header),
}
