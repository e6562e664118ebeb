"""ROS 1 arguments a launch file declares for its user and never reads.

roslaunch scopes an ``<arg>`` to its own file: an included file sees only the arguments
its ``<include>`` passes (``pass_all_args`` aside). An argument with a ``default`` (or
none) is one a user sets on the command line or from an including file; when nothing in
its file reads it, roslaunch accepts the setting and drops it without a word. Every
element of the file is read, whatever its condition: a read in a branch the current
arguments skip is still a read.
"""

from __future__ import annotations

import re

from launch_linter.resolve.xml_safe import Element

ARG_READ = re.compile(r"\$\(\s*arg\s+([^\s()]+)\s*\)")
EVAL = re.compile(r"\$\(\s*eval\s")
WORD = re.compile(r"[A-Za-z_][A-Za-z0-9_]*")
"""In ``$(eval ...)`` an argument is read as a bare name (roslaunch's eval resolves
unknown names to arguments) or as ``arg('name')``: any word of the expression may be one."""
INTERFACE = "launch"
"""Where an ``<arg>`` declares an argument of the file's interface: directly under
``<launch>``. One in a ``<group>`` is as much the file's, but files use those as local
variables of a branch (each ``<group if>`` setting its own), not as settings offered to
their user; inside ``<include>`` an ``<arg>`` passes one."""


HANDS_ON = ("include", "rosparam")


def _hands_on(element: Element) -> bool:
    """Whether ``element`` may read arguments this scan cannot see: an ``<include>`` with
    ``pass_all_args`` (not literally false) or a ``<rosparam>`` that substitutes in a
    file (``subst_value``: the file may read ``$(arg)``)."""
    attrib = element.attrib
    if element.tag.lower() == "include":
        return attrib.get("pass_all_args", "false").strip().lower() not in ("false", "0", "")
    return ("file" in attrib and attrib.get("subst_value", "false").strip().lower()
            not in ("false", "0", ""))


class UnusedArg:
    """A declared argument of one file that nothing in the file reads."""

    __slots__ = ("column", "default", "instead", "line", "name", "passed")

    def __init__(self, name: str, line: int, column: int, default: str | None = None,
                 passed: tuple[int, int] | None = None, instead: str | None = None) -> None:
        self.name = name
        self.line = line
        self.column = column
        self.default = default
        """Its ``default`` as written (None without one)."""
        self.passed = passed
        """Where the file gives an include's argument or a parameter of the same name
        a value of its own (line, column): the declared one was meant to go there."""
        self.instead = instead
        """That value as written (None when it is no ``value`` attribute)."""

    @property
    def frame_dropped(self) -> bool:
        """Whether it names a frame (``frame`` in its name) that the file sets otherwise,
        to a value that is its own default copied or that reads no other argument: the
        user's frame is dropped where a tf lookup or a stamp needs it. A value built
        from other arguments (hector's ``odom_frame`` tied to ``$(arg base_frame)``) is
        a deliberate tie that leaves the argument dead, not a frame lost (the level of
        ``ros1_unused_arg``: docs/evaluation/camera_frames.md)."""
        if self.passed is None or self.instead is None or "frame" not in self.name.lower():
            return False
        return self.instead == self.default or (not ARG_READ.search(self.instead) and not (
            EVAL.search(self.instead)))


def _texts(element: Element) -> list[str]:
    return [*element.attrib.values(), element.text]


def _reads(text: str, out: set[str]) -> None:
    if "$(" not in text:
        return
    out.update(ARG_READ.findall(text))
    if EVAL.search(text):
        out.update(WORD.findall(text))


def unused_args(root: Element) -> list[UnusedArg]:
    """The arguments ``root`` (a file's ``<launch>``) declares directly with a ``default``
    or no value and never reads; none when an ``<include pass_all_args>`` hands them all on."""
    declared: list[tuple[str, Element]] = []
    passed: dict[str, Element] = {}
    read: set[str] = set()
    # In document order (the first include argument or parameter of a name is the one
    # named).
    stack: list[tuple[Element, str]] = [(child, INTERFACE) for child in reversed(root.children)]
    while stack:
        element, parent = stack.pop()
        tag = element.tag.lower()
        if tag in HANDS_ON and _hands_on(element):
            return []
        for text in _texts(element):
            _reads(text, read)
        name = element.attrib.get("name", "")
        if tag == "arg" and name and "$(" not in name:
            if parent == INTERFACE and "value" not in element.attrib:
                declared.append((name, element))
            elif parent == "include":
                passed.setdefault(name, element)
        elif tag == "param" and name and "$(" not in name:
            # A parameter of the argument's name given something else: the value the
            # argument was declared to carry (``<param name="odom_frame" value="$(arg
            # base_frame)"/>`` beside an unread ``odom_frame``).
            passed.setdefault(name.rsplit("/", 1)[-1], element)
        stack.extend((child, tag) for child in reversed(element.children))
    out: list[UnusedArg] = []
    for name, element in sorted(declared, key=lambda item: (item[1].line, item[1].column)):
        if name in read:
            continue
        given = passed.get(name)
        out.append(UnusedArg(
            name, element.line, element.column, element.attrib.get("default"),
            None if given is None else (given.line, given.column),
            None if given is None else given.attrib.get("value")))
    return out
