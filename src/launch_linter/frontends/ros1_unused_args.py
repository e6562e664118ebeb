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

from launch_linter.model.diagnostic import Location, Problem
from launch_linter.resolve.xml_safe import Element

ARG_READ = re.compile(r"\$\(\s*arg\s+([^\s()]+)\s*\)")
ARG_READ_BYTES = re.compile(rb"\$\(\s*arg\s+([^\s()]+)\s*\)")
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
WALK_WORDS = (b"eval", b"pass_all_args", b"subst_value")
"""What only the element walk reads right: an ``$(eval)``'s bare names (however spaced),
and the tags that hand arguments on unseen (:func:`_hands_on`)."""
FRAME = "frame"
"""An argument or setting whose name says it names a frame."""
FRAME_ENDINGS = ("frame", "frame_id", "frameid", "frame_name")
"""How the name of an argument that holds one frame ends (``imu_frame_id``,
``sensor_frame``, ``odometry_frame_ID``), unlike ``frame_rate`` or ``frame_tolerance``."""


def _names_a_frame(name: str) -> bool:
    return name.lower().endswith(FRAME_ENDINGS)


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

    __slots__ = ("column", "default", "instead", "line", "name", "passed", "sibling")

    def __init__(self, name: str, line: int, column: int, default: str | None = None,
                 passed: tuple[int, int] | None = None, instead: str | None = None,
                 sibling: tuple[str, int, int] | None = None) -> None:
        self.name = name
        self.line = line
        self.column = column
        self.default = default
        """Its ``default`` as written (None without one)."""
        self.passed = passed
        """For a frame argument: where the file gives an include's argument or a
        parameter of the same name a value of its own (line, column), where the declared
        one was meant to go."""
        self.instead = instead
        """That value as written (None when it is no ``value`` attribute)."""
        self.sibling = sibling
        """For a frame argument nothing of its name is set from: another frame argument
        the file hands on under its own name (``<param name="left_frame" value="$(arg
        left_frame)"/>``), as (that name, line, column): the file's way of passing its
        frames on, which this one missed."""

    @property
    def frame_forgotten(self) -> bool:
        """Whether it names a frame that nothing of its name is set from, in a file that
        hands its other frame arguments on under their own names: the author passed each
        frame on and missed this one (zed-ros-wrapper#248 and #392: ``imu_frame``
        declared beside ``left_camera_frame`` and the others, never given to the
        node)."""
        return self.passed is None and self.sibling is not None and _names_a_frame(self.name)

    @property
    def frame_dropped(self) -> bool:
        """Whether it names a frame (``frame`` in its name) that the file sets otherwise,
        to a value that is its own default copied or that reads no other argument: the
        user's frame is dropped where a tf lookup or a stamp needs it. A value built
        from other arguments (hector's ``odom_frame`` tied to ``$(arg base_frame)``) is
        a deliberate tie that leaves the argument dead, not a frame lost (the level of
        ``ros1_unused_arg``: docs/evaluation/camera_frames.md)."""
        if self.passed is None or self.instead is None or FRAME not in self.name.lower():
            return False
        return self.instead == self.default or (not ARG_READ.search(self.instead) and not (
            EVAL.search(self.instead)))


def _reads(text: str, pending: set[str], eval_only: bool) -> None:
    """Drop from ``pending`` the arguments ``text`` reads (only through ``$(eval)`` when
    the ``$(arg)`` reads are already dropped)."""
    if "$(" not in text:
        return
    if not eval_only:
        pending.difference_update(ARG_READ.findall(text))
    if EVAL.search(text):
        pending.difference_update(WORD.findall(text))


def _declared(root: Element) -> list[tuple[str, Element]]:
    """The arguments of the file's interface: ``<arg>`` directly under ``<launch>`` with
    a literal name and no ``value``."""
    out: list[tuple[str, Element]] = []
    for child in root.children:
        tag = child.tag  # the tag as written first: a ``lower()`` per child costs more
        # No character lowercases to fewer characters, so only a three-letter tag can be
        # some case of "arg": the others skip the ``lower()`` call.
        if tag != "arg" and (len(tag) != 3 or tag.lower() != "arg"):
            continue
        attrib = child.attrib
        name = attrib.get("name", "")
        if name and "$(" not in name and "value" not in attrib:
            out.append((name, child))
    return out


def unused_args(root: Element, data: bytes | None = None) -> list[UnusedArg]:
    """The arguments ``root`` (a file's ``<launch>``, parsed from ``data`` when given)
    declares directly with a ``default`` or no value and never reads; none when an
    ``<include pass_all_args>`` hands them all on."""
    declared = _declared(root)
    pending = {name for name, _ in declared}
    if pending and data is not None:
        # Every ``$(arg NAME)`` of the file's bytes in one pass: settles most files (every
        # argument read) before any element is walked, and leaves the walk only the
        # ``$(eval)`` names. A read in an XML comment counts here, which can only leave
        # an argument unreported.
        # Each name read is decoded once, however often the file reads it.
        pending.difference_update([
            read.decode("utf-8", "replace") for read in set(ARG_READ_BYTES.findall(data))])
        if not pending or (not any(word in data for word in WALK_WORDS) and not any(
                FRAME in name.lower() for name in pending)):
            # Nothing the walk could add: no eval, no argument handed on unseen, and no
            # frame argument whose namesake setting it would look for.
            return [UnusedArg(name, element.line, element.column, element.attrib.get("default"))
                    for name, element in declared if name in pending]
    eval_only = data is not None
    # With the ``$(arg)`` reads of the bytes dropped, a value can read an argument only
    # through ``$(eval)``: in a file whose bytes spell no ``eval`` (nor a character
    # reference, which could spell one) the walk has nothing to read in the values.
    read_values = data is None or b"eval" in data or b"&#" in data
    passed: dict[str, Element] = {}
    forwarded: dict[str, Element] = {}
    # In document order (the first include argument or parameter of a name is the one
    # named).
    stack: list[tuple[Element, str]] = [(child, INTERFACE) for child in reversed(root.children)]
    while stack and pending:
        element, parent = stack.pop()
        tag = element.tag.lower()
        if tag in HANDS_ON and _hands_on(element):
            return []
        if read_values:
            for value in element.attrib.values():
                _reads(value, pending, eval_only)
            if element.text:
                _reads(element.text, pending, eval_only)
        name = element.attrib.get("name", "")
        if _names_a_frame(name) and _forwards(element, tag, parent, name):
            forwarded.setdefault(name.rsplit("/", 1)[-1], element)
        if tag == "arg" and parent == "include" and FRAME in name.lower():
            passed.setdefault(name, element)
        elif tag == "param" and FRAME in name.lower() and "$(" not in name:
            # A parameter of the argument's name given something else: the value the
            # argument was declared to carry (``<param name="odom_frame" value="$(arg
            # base_frame)"/>`` beside an unread ``odom_frame``).
            passed.setdefault(name.rsplit("/", 1)[-1], element)
        if element.children:  # most are leaves: no generator made for them
            stack.extend((child, tag) for child in reversed(element.children))
    if not pending:
        # Every argument read: whatever comes after (even a pass_all_args) changes nothing.
        return []
    out: list[UnusedArg] = []
    for name, element in declared:
        if name not in pending:
            continue
        given = passed.get(name)
        sibling = next(((other, at.line, at.column) for other, at in forwarded.items()
                        if other != name), None)
        out.append(UnusedArg(
            name, element.line, element.column, element.attrib.get("default"),
            None if given is None else (given.line, given.column),
            None if given is None else given.attrib.get("value"), sibling))
    return out


def _forwards(element: Element, tag: str, parent: str, name: str) -> bool:
    """Whether ``element`` (an include's ``<arg>`` or a ``<param>``) is given the file's
    argument of its own name: ``value="$(arg NAME)"``, NAME its name's last part."""
    if not (tag == "param" or (tag == "arg" and parent == "include")):
        return False
    match = ARG_READ.fullmatch(element.attrib.get("value", "").strip())
    return match is not None and match.group(1) == name.rsplit("/", 1)[-1]


def unused_arg_problems(display: str, launch: Element, data: bytes) -> list[Problem]:
    """The ``ros1_unused_arg`` problems of a root file's ``<launch>`` element (its bytes
    ``data``), shown at ``display``."""
    problems: list[Problem] = []
    for arg in unused_args(launch, data):
        if arg.frame_forgotten and arg.sibling is not None:
            other, line, column = arg.sibling
            message = (f"argument '{arg.name}' is declared, but nothing in this file "
                       f"reads it: roslaunch accepts {arg.name}:=... and drops it "
                       f"without a word, while line {line} hands '{other}' on under "
                       f"its name; give '{arg.name}' on the same way "
                       f"(value=\"$(arg {arg.name})\") or remove it")
            # The related place marks the warning (ros1_unused_arg): a frame forgotten.
            related: tuple[Location, ...] = (Location(display, line, column),)
        elif arg.passed is None:
            message = (f"argument '{arg.name}' is declared, but nothing in this file "
                       f"reads it: roslaunch accepts {arg.name}:=... and drops it "
                       f"without a word; read it or remove it")
            related = ()
        else:
            message = (f"argument '{arg.name}' is declared, but nothing in this file "
                       f"reads it: line {arg.passed[0]} gives '{arg.name}' another "
                       f"value instead, so {arg.name}:=... given to this file is "
                       f"dropped without a word; pass value=\"$(arg {arg.name})\" "
                       f"there")
            # The related place marks the warning (ros1_unused_arg): a frame dropped.
            related = ((Location(display, arg.passed[0], arg.passed[1]),)
                       if arg.frame_dropped else ())
        problems.append(Problem("ros1_unused_arg", display, arg.line, arg.column, message,
                                related=related))
    return problems
