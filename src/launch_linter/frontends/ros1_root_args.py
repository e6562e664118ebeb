"""ROS 1 args that only the root file's command line could set, and it does not declare.

roslaunch puts every ``NAME:=VALUE`` of its command line in the root file's args, declared
or not (loader.py ``load_sysargs_into_context``), and ``pass_all_args`` hands the includer's
args on (xmlloader.py ``_include_tag``). An arg read where nothing set it raises
substitution_args' ``ArgException``, and xmlloader.py refuses the file: "[file] requires the
'x' arg to be set" (the root), "included file [file] requires the 'x' arg to be set" (an
include). When the root file declares the arg (``<arg name="x"/>``, no default) its command
line is the way in. When the root declares it nowhere, roslaunch of that file refuses
unless its user passes an undeclared ``x:=...`` (``roslaunch --ros-args`` does not list
it): a mistake (iai_kinect2's ``output="$(arg screen)"``) or a design (cartographer_ros'
demos read ``$(arg bag_filename)`` and their README gives ``bag_filename:=``). Judged on 13
files of 8 corpus repositories (docs/evaluation/ros1_undeclared_root_arg.jsonl): 9 true,
4 run by design with the arg on the command line, so the value is *unknown* (said as
``unresolved``, with roslaunch's refusal), never an error. Read against ros_comm at 845f746
(tools/roslaunch/src/roslaunch/loader.py, xmlloader.py, substitution_args.py).
"""

from __future__ import annotations

from collections.abc import Callable

from launch_linter.model.diagnostic import Location, Problem
from launch_linter.resolve.xml_safe import Element, attribute_line
from launch_linter.workspace.mentions import named_by_another_file


def declared_arg_names(launch: Element) -> frozenset[str] | None:
    """The names of every ``<arg>`` of a launch file (in groups too, under conditions or
    not); None when one is not literal (it could be any name)."""
    names: set[str] = set()
    stack = list(launch.children)
    while stack:
        element = stack.pop()
        tag = element.tag.lower()
        if tag == "arg":
            name = element.attrib.get("name", "")
            if "$" in name:
                return None
            names.add(name.strip())
        elif tag == "group":
            stack.extend(element.children)
    return frozenset(names)


def undeclared_root_arg(
    name: str,
    filename: str,
    root: str,
    display: Callable[[str], str],
    element: Element,
    attribute: str,
    root_text: tuple[bytes, list[int]],
    include_site: Location | None,
) -> Problem | None:
    """The unknown arg ``name`` (roslaunch refuses without it), read by ``element`` (its
    ``attribute``) in ``filename``, which the root file ``root`` declares nowhere: placed
    at the attribute in the root, or at the root's include (``include_site``) that passes
    all args down to ``filename``. None when another launch file names the root: it may
    be included by a file passing all its args, which then sets it."""
    if named_by_another_file(root) is not None:
        return None
    shown_root = display(root)
    way = (f"declares no <arg name=\"{name}\">, so only an undeclared {name}:=... on its "
           f"command line sets it (roslaunch --ros-args does not list it); not known (give "
           f"it with --arg {name}:=VALUE, or declare it with a default if none is meant)")
    if filename == root:
        data, starts = root_text
        return Problem("unresolved", shown_root,
                       attribute_line(data, starts, element, attribute), element.column,
                       f"roslaunch refuses this file (\"requires the '{name}' arg to be "
                       f"set\") unless the command line gives it: the file {way}")
    if include_site is None:
        return None
    return Problem("unresolved", include_site.path, include_site.line, include_site.column,
                   f"roslaunch refuses this include (\"included file [{display(filename)}] "
                   f"requires the '{name}' arg to be set\") unless the command line gives "
                   f"it: the include passes all args, but [{shown_root}] {way}")
