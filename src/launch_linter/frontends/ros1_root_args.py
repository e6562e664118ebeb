"""ROS 1 args that only the root file's command line could set, and it does not declare.

roslaunch puts every ``NAME:=VALUE`` of its command line in the root file's args, declared
or not (loader.py ``load_sysargs_into_context``), and ``pass_all_args`` hands the includer's
args on (xmlloader.py ``_include_tag``). An arg read where nothing set it raises
substitution_args' ``ArgException``, and xmlloader.py refuses the file: "[file] requires the
'x' arg to be set" (the root), "included file [file] requires the 'x' arg to be set" (an
include). When the root file declares the arg (``<arg name="x"/>``, no default) its command
line is the way in, and the value is unknown; when the root declares it nowhere, roslaunch
of that file refuses unless its user passes an undeclared ``x:=...``, which ``roslaunch
--ros-args`` does not list: the file is wrong. Read against ros_comm at 845f746
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
    """roslaunch's refusal of arg ``name``, read by ``element`` (its ``attribute``) in
    ``filename``, which the root file ``root`` declares nowhere: placed at the attribute in
    the root, or at the root's include (``include_site``) that passes all args down to
    ``filename``. None when another launch file names the root: it may be included by a
    file passing all its args, which then sets it."""
    if named_by_another_file(root) is not None:
        return None
    shown_root = display(root)
    way = (f"no <arg name=\"{name}\"> in it, so only {name}:=... on the command line could "
           f"set it (roslaunch --ros-args does not list it)")
    if filename == root:
        data, starts = root_text
        return Problem("roslaunch_error", shown_root,
                       attribute_line(data, starts, element, attribute), element.column,
                       f"[{shown_root}] requires the '{name}' arg to be set: roslaunch "
                       f"refuses the file; {way}; declare it with a default")
    if include_site is None:
        return None
    return Problem("roslaunch_error", include_site.path, include_site.line,
                   include_site.column,
                   f"included file [{display(filename)}] requires the '{name}' arg to be "
                   f"set: this include passes all args, but [{shown_root}] has {way}; "
                   f"declare it there with a default")
