"""Robot descriptions found in launch files, and the tf edges their URDF joints give."""

from __future__ import annotations

import math
from enum import Enum

from launch_linter.model.diagnostic import Location
from launch_linter.model.record import Record, _open, _seal, _set
from launch_linter.model.transform import Condition

UNKNOWN_VALUE = "\x00unknown"
"""The value recorded for a node's frame parameter that the linter cannot resolve."""
MOVABLE_JOINTS = ("revolute", "continuous", "prismatic", "floating", "planar")


SIMULATOR_SPAWNERS = frozenset({
    ("gazebo_ros", "spawn_model"), ("gazebo_ros", "spawn_entity.py"),
    ("ros_gz_sim", "create"), ("ros_ign_gazebo", "create"),
})
"""Nodes that give a robot description to a simulator, which then runs its plugins."""


def spawns_into_simulator(node: NodeRecord) -> bool:
    """Whether ``node`` spawns a robot description into Gazebo (classic or gz-sim)."""
    return node.kind == "node" and (node.package, node.executable) in SIMULATOR_SPAWNERS


class DescriptionKind(str, Enum):
    """How a launch file gives ``robot_description``."""

    XACRO = "xacro"
    """``xacro FILE name:=value ...`` run by the launch file (``command=``, ``Command``)."""
    FILE = "file"
    """A URDF file read as it is (``textfile=``, ``open(path).read()``)."""
    LITERAL = "literal"
    """URDF text written in the launch file itself."""


class DescriptionSource(Record):
    """A ``robot_description`` a launch file gives, where it does, and what it names.

    ``file`` is the absolute path of the description (None when unresolved, then
    ``reason`` says why); ``args`` are the ``name:=value`` words of the xacro call (a value
    of None is unresolved); ``text`` is a literal URDF.
    """

    path: str
    line: int
    column: int
    kind: DescriptionKind
    file: str | None
    args: tuple[tuple[str, str | None], ...]
    condition: Condition
    node: str | None
    text: str | None
    reason: str | None
    open_args: bool
    """True when a word of the xacro call is unresolved and may give more args."""
    open_file: tuple[str, str, str] | None
    """When ``file`` is unknown only because an environment variable in its name is not
    given: (the path before it, the text after it, the variable's name)."""
    namespace: str | None
    """The ROS 1 namespace the ``robot_description`` parameter is set in (``/r1/``), where
    a spawner finds it by its relative name; None when unknown or not ROS 1."""
    included_at: tuple[Location, ...]
    """The include actions through which the launch file giving it was run (ROS 2), from
    the root's: one line run through two includes gives two sources."""
    near: str | None
    """The folder of the ROS 1 launch file that gives it (roslaunch's ``$(dirname)``): a
    description file named under it that is not there is provably absent, as an included
    launch file is; None for ROS 2 (its launch files run from the install space)."""
    xacro_options: tuple[str, ...]
    """The option words of the xacro call (``--inorder``, ``-i``, ``--legacy``)."""
    wrapper: str | None
    """The program the command runs xacro through (``env_run <config file> xacro ...``),
    which may set the environment xacro reads; None when the command runs xacro itself."""

    __slots__ = (
        "path", "line", "column", "kind", "file", "args", "condition", "node", "text", "reason",
        "open_args", "open_file", "namespace", "included_at", "near", "xacro_options",
        "wrapper",
    )

    def __init__(
        self,
        path: str,
        line: int,
        column: int,
        kind: DescriptionKind,
        file: str | None,
        args: tuple[tuple[str, str | None], ...] = (),
        condition: Condition | None = None,
        node: str | None = None,
        text: str | None = None,
        reason: str | None = None,
        open_args: bool = False,
        open_file: tuple[str, str, str] | None = None,
        namespace: str | None = None,
        included_at: tuple[Location, ...] = (),
        near: str | None = None,
        xacro_options: tuple[str, ...] = (),
        wrapper: str | None = None,
    ) -> None:
        _set(self, "path", path)
        _set(self, "line", line)
        _set(self, "column", column)
        _set(self, "kind", kind)
        _set(self, "file", file)
        _set(self, "args", args)
        _set(self, "condition", Condition() if condition is None else condition)
        _set(self, "node", node)
        _set(self, "text", text)
        _set(self, "reason", reason)
        _set(self, "open_args", open_args)
        _set(self, "open_file", open_file)
        _set(self, "namespace", namespace)
        _set(self, "included_at", included_at)
        _set(self, "near", near)
        _set(self, "xacro_options", xacro_options)
        _set(self, "wrapper", wrapper)


class RobotJoint(Record):
    """One URDF joint as a tf edge: parent link -> child link, at the joint's file:line.

    ``dynamic`` is true for movable joints (robot_state_publisher publishes them from
    joint states); their frame and parent are known, their values are not constant.
    ``rpy`` is roll, pitch, yaw as URDF writes it. ``unresolved`` names the fields that
    could not be known (``parent``, ``child``, ``translation``, ``rotation``) and
    ``reasons`` why.
    """

    path: str
    line: int
    column: int
    name: str
    joint_type: str
    parent: str | None
    child: str | None
    translation: tuple[float, float, float] | None
    rpy: tuple[float, float, float] | None
    source: DescriptionSource
    condition: Condition
    unresolved: tuple[str, ...]
    reasons: tuple[str, ...]
    defined: tuple[str, int, int] | None
    """For a joint a xacro macro made: where its ``<joint>`` is written in the macro
    (``path``/``line`` are then the outermost call of the macro)."""
    origin_at: tuple[str, int, int] | None
    """Where its ``<origin>`` is (the call, as for the joint, when a macro made it): a
    finding about the joint's values points there; None without an ``<origin>``."""
    child_at: tuple[str, int, int] | None
    """For a joint a xacro macro made: where its ``<child>`` is written in the macro (a
    fault of the macro itself, every call's, is shown there)."""

    __slots__ = (
        "path", "line", "column", "name", "joint_type", "parent", "child", "translation", "rpy",
        "source", "condition", "unresolved", "reasons", "defined", "origin_at", "child_at",
    )

    def __init__(
        self,
        path: str,
        line: int,
        column: int,
        name: str,
        joint_type: str,
        parent: str | None,
        child: str | None,
        translation: tuple[float, float, float] | None,
        rpy: tuple[float, float, float] | None,
        source: DescriptionSource,
        condition: Condition | None = None,
        unresolved: tuple[str, ...] = (),
        reasons: tuple[str, ...] = (),
        defined: tuple[str, int, int] | None = None,
        origin_at: tuple[str, int, int] | None = None,
        child_at: tuple[str, int, int] | None = None,
    ) -> None:
        _set(self, "path", path)
        _set(self, "line", line)
        _set(self, "column", column)
        _set(self, "name", name)
        _set(self, "joint_type", joint_type)
        _set(self, "parent", parent)
        _set(self, "child", child)
        _set(self, "translation", translation)
        _set(self, "rpy", rpy)
        _set(self, "source", source)
        _set(self, "condition", Condition() if condition is None else condition)
        _set(self, "unresolved", unresolved)
        _set(self, "reasons", reasons)
        _set(self, "defined", defined)
        _set(self, "origin_at", origin_at)
        _set(self, "child_at", child_at)

    @property
    def dynamic(self) -> bool:
        return self.joint_type in MOVABLE_JOINTS

    @property
    def signature(self) -> tuple[str, str] | None:
        if self.parent is None or self.child is None:
            return None
        return (self.parent, self.child)


class NodeRecord(Record):
    """A launched node (or a Gazebo plugin, or a ros2_control controller): which program
    it runs, and the parameters it is given as ``(name, value)`` pairs (a value the linter
    cannot resolve is ``UNKNOWN_VALUE``; nested names joined with ``/`` in ROS 1 and
    ``.`` in ROS 2).

    ``kind`` is ``node``, ``gazebo_plugin`` or ``controller``; ``plugin`` the composable
    node's plugin, the plugin's filename or the controller's type. ``unread`` says why
    some of its parameters could not be read (a parameter file not found or not parsed):
    a parameter it does not set then has no known value. ``namespace`` is the node's
    namespace (None when unresolved); ``ros`` the ROS version of the launch file.
    ``param_lines`` says where a parameter was set, when the front-end knows it: ``(name,
    path, line, column)``: a ROS 1 ``<param>`` or ``<rosparam>`` inside the node's element
    (a ``<rosparam>`` file's key), a ROS 2 ``parameters=`` dictionary key, XML/YAML
    ``<param>`` or parameter file key; ROS 2 front-ends give every parameter a place, in
    the order of ``params`` (the node's element where the value's own place is unknown).
    ``included_at`` lists the include actions through which its launch file was run, from
    the root's (ROS 2): one node line run through two different includes is two nodes.
    ``remappings`` are the topic remapping rules ``(from, to)`` its process is given (ROS 2
    ``remappings=``, a simulator plugin's ``<ros><remapping>``; a controller also its
    spawner's ``--controller-ros-args``), in order, ``UNKNOWN_VALUE`` for a name not
    resolved; None when they are not known. ``args`` are a ROS 1 ``controller_manager``
    node's ``args`` words as roslaunch splits them (None when one is not resolved; empty
    for other nodes): a spawner's ``--namespace`` names where it calls the controller
    manager.
    ``executable_line`` is the line that writes the executable when it is not ``line`` (a
    ROS 2 Python ``Node(``'s ``executable=`` keyword), 0 otherwise.
    """

    path: str
    line: int
    column: int
    package: str
    executable: str
    name: str | None
    params: tuple[tuple[str, str], ...]
    condition: Condition
    kind: str
    plugin: str | None
    unread: tuple[str, ...]
    namespace: str | None
    ros: int | None
    param_lines: tuple[tuple[str, str, int, int], ...]
    included_at: tuple[Location, ...]
    remappings: tuple[tuple[str, str], ...] | None
    args: tuple[str, ...] | None
    executable_line: int

    __slots__ = (
        "path", "line", "column", "package", "executable", "name", "params", "condition", "kind",
        "plugin", "unread", "namespace", "ros", "param_lines", "included_at", "remappings",
        "args", "executable_line", "_last_given", "_last_set",
    )
    _private = ("_last_given", "_last_set")
    _last_given: dict[str, str] | None
    _last_set: dict[str, tuple[str, int, int]] | None

    def __init__(
        self,
        path: str,
        line: int,
        column: int,
        package: str,
        executable: str,
        name: str | None = None,
        params: tuple[tuple[str, str], ...] = (),
        condition: Condition | None = None,
        kind: str = "node",
        plugin: str | None = None,
        unread: tuple[str, ...] = (),
        namespace: str | None = "/",
        ros: int | None = None,
        param_lines: tuple[tuple[str, str, int, int], ...] = (),
        included_at: tuple[Location, ...] = (),
        remappings: tuple[tuple[str, str], ...] | None = (),
        args: tuple[str, ...] | None = (),
        executable_line: int = 0,
    ) -> None:
        _open(self)  # made for every launched node: see _open
        self.path = path
        self.line = line
        self.column = column
        self.package = package
        self.executable = executable
        self.name = name
        self.params = params
        self.condition = Condition() if condition is None else condition
        self.kind = kind
        self.plugin = plugin
        self.unread = unread
        self.namespace = namespace
        self.ros = ros
        self.param_lines = param_lines
        self.included_at = included_at
        self.remappings = remappings
        self.args = args
        self.executable_line = executable_line
        self._last_given = None
        self._last_set = None
        _seal(self)

    def given(self, name: str) -> str | None:
        """The value of the parameter ``name`` exactly as the node is given it (the last
        setting wins), None when it is not set."""
        last = self._last_given
        if last is None:
            # Indexed once: rules ask a node for each of thousands of listed parameters.
            last = dict(self.params)
            _set(self, "_last_given", last)
        return last.get(name)

    def where_set(self, name: str) -> tuple[str, int, int] | None:
        """Where the parameter ``name`` was last set (path, line, column), None when the
        front-end does not know."""
        last = self._last_set
        if last is None:
            last = {key: (path, line, column) for key, path, line, column in self.param_lines}
            _set(self, "_last_set", last)
        return last.get(name)

    def param(self, name: str) -> str | None:
        for key, value in self.params:
            if key == name or key.endswith("/" + name):
                return value
        return None


class RobotElement(Record):
    """A ``<link>``, ``<joint>`` or top-level ``<material>`` of an expanded description, by
    name, where it was written.

    ``name`` is None when the name could not be known (a ``<material>`` without a name is
    ``''``, as urdfdom keeps it); ``condition`` is the launch element's condition and the
    undecided ``xacro:if``/``xacro:unless`` around the element. For an element a xacro
    macro made, ``path``/``line`` are the outermost call and ``defined`` is where the
    element is written in the macro; ``included`` is the ``xacro:include`` that read the
    file the element (or its outermost call) is written in, None in the top file."""

    kind: str
    """``link``, ``joint``, ``material``, or ``origin``: an ``<origin>`` urdfdom ignores
    (a second one in a link's ``<visual>``, ``<collision>``, ``<inertial>`` or in a joint),
    named after its owner (``<visual> of link 'x'``), or ``mimic``: a joint's ``<mimic>``,
    named after the joint it mimics, just after its joint (and that joint's ignored
    ``<origin>`` elements) in the description's ``elements``, or ``outside_gazebo``: a
    ``<plugin>`` or ``<sensor>`` straight under ``<robot>`` (Gazebo reads them only inside
    ``<gazebo>``), named ``<plugin> 'libx.so'`` or ``<sensor> 'name'``, or
    ``gazebo_reference``: a ``<gazebo reference=...>`` straight under ``<robot>`` that holds
    a ``<sensor>`` or ``<plugin>``, named by the link or joint it names (Gazebo's URDF
    reader puts its content into that link or joint only), or ``gazebo_properties``: one
    that holds only simulation properties (material, friction, damping)."""
    name: str | None
    path: str
    line: int
    column: int
    condition: Condition
    defined: tuple[str, int, int] | None
    included: tuple[str, int, int] | None

    __slots__ = ("kind", "name", "path", "line", "column", "condition", "defined", "included")

    def __init__(
        self,
        kind: str,
        name: str | None,
        path: str,
        line: int,
        column: int,
        condition: Condition | None = None,
        defined: tuple[str, int, int] | None = None,
        included: tuple[str, int, int] | None = None,
    ) -> None:
        _set(self, "kind", kind)
        _set(self, "name", name)
        _set(self, "path", path)
        _set(self, "line", line)
        _set(self, "column", column)
        _set(self, "condition", Condition() if condition is None else condition)
        _set(self, "defined", defined)
        _set(self, "included", included)


MALFORMED_XML = "not well-formed XML"
"""How a ``REFUSED`` fault's message starts when the file is not well-formed XML: a fault
of that file alone, whoever includes it."""


INVALID_NAMES = "use of invalid name(s)"
"""How a ``REFUSED`` fault's message starts when xacro refuses an expression for reading a
name that begins with ``__``: whatever defines the name, no includer changes that."""
OWN_FAULTS = (MALFORMED_XML, INVALID_NAMES)
"""The starts of the refusals that are faults of the file alone, whoever includes it."""


class FaultKind(str, Enum):
    """What xacro itself does with a fault of the description's source."""

    REFUSED = "refused"
    """xacro stops with an error: an undefined macro, a missing macro parameter, an
    undeclared ``$(arg)``, a block the call does not match."""
    DROPPED = "dropped"
    """xacro goes on and drops content silently: a block parameter the macro never inserts."""
    PARAM_AS_ARG = "param_as_arg"
    """A macro's body reads its own parameter X as ``$(arg X)``, which reads xacro args
    only: the value a call gives X is ignored (and xacro stops where no arg X is
    declared: then a ``REFUSED`` fault with the same path, line and name)."""
    UNEXPANDED = "unexpanded"
    """xacro goes on but leaves written xacro unexpanded or drops its text: a macro called
    without the ``xacro:`` prefix (Noetic's and ROS 2's xacro; ``name`` is the macro), the
    text after a ``${``/``$(`` never closed (xacro before 1.13.5)."""


class DescriptionFault(Record):
    """A fault of the xacro source that xacro itself refuses or silently drops.

    ``proven`` is false when an earlier element could not be followed (an include not
    read, an unsupported directive), so that what looks missing may be defined there;
    ``conditions`` are the undecided ``xacro:if``/``xacro:unless`` texts around it;
    ``name`` the arg of a refused ``$(arg)`` or of a ``PARAM_AS_ARG`` fault (whose
    ``message`` names the macro: ``macro 'camera'``)."""

    path: str
    line: int
    kind: FaultKind
    message: str
    proven: bool
    conditions: tuple[str, ...]
    name: str | None

    __slots__ = ("path", "line", "kind", "message", "proven", "conditions", "name")

    def __init__(
        self,
        path: str,
        line: int,
        kind: FaultKind,
        message: str,
        proven: bool = True,
        conditions: tuple[str, ...] = (),
        name: str | None = None,
    ) -> None:
        _set(self, "path", path)
        _set(self, "line", line)
        _set(self, "kind", kind)
        _set(self, "message", message)
        _set(self, "proven", proven)
        _set(self, "conditions", conditions)
        _set(self, "name", name)


class IgnoredArg(Record):
    """A xacro mapping (``name:=value``) that no file of the description names, where the
    launch file writes it (``line`` 0 when the launch file's text does not show it once),
    with the xacro args the description declares that are close to it."""

    name: str
    path: str
    line: int
    column: int
    close: tuple[str, ...]

    __slots__ = ("name", "path", "line", "column", "close")

    def __init__(self, name: str, path: str, line: int, column: int,
                 close: tuple[str, ...]) -> None:
        _set(self, "name", name)
        _set(self, "path", path)
        _set(self, "line", line)
        _set(self, "column", column)
        _set(self, "close", close)


class RobotModel(Record):
    """One expanded description as robot_state_publisher (urdfdom, then KDL) reads it.

    ``complete`` is true when nothing of it is unknown: the expansion followed every
    element and every link name and joint end is known, so that what is absent is proven
    absent. ``standalone`` is true for a ``.urdf``/``.xacro`` file linted as an input of
    its own (no launch file loads it in that tree)."""

    source: DescriptionSource
    elements: tuple[RobotElement, ...]
    joints: tuple[RobotJoint, ...]
    complete: bool
    faults: tuple[DescriptionFault, ...]
    defines_macros: bool
    """Whether the description's files define xacro macros (an empty robot made of a
    macros-only file)."""
    standalone: bool
    plugins: tuple[NodeRecord, ...]
    """Its ``<gazebo><plugin>`` blocks, as records of kind ``gazebo_plugin``: they run
    only when a simulator is given the description (see :func:`spawns_into_simulator`)."""
    ignored_args: tuple[IgnoredArg, ...]
    """The ``name:=value`` mappings of the xacro call that no file of the description
    names (xacro keeps them and nothing reads them): see ``frontends/robot/xacro_ignored``."""

    __slots__ = (
        "source", "elements", "joints", "complete", "faults", "defines_macros", "standalone",
        "plugins", "ignored_args",
    )

    def __init__(
        self,
        source: DescriptionSource,
        elements: tuple[RobotElement, ...],
        joints: tuple[RobotJoint, ...],
        complete: bool,
        faults: tuple[DescriptionFault, ...] = (),
        defines_macros: bool = False,
        standalone: bool = False,
        plugins: tuple[NodeRecord, ...] = (),
        ignored_args: tuple[IgnoredArg, ...] = (),
    ) -> None:
        _set(self, "source", source)
        _set(self, "elements", elements)
        _set(self, "joints", joints)
        _set(self, "complete", complete)
        _set(self, "faults", faults)
        _set(self, "defines_macros", defines_macros)
        _set(self, "standalone", standalone)
        _set(self, "plugins", plugins)
        _set(self, "ignored_args", ignored_args)

    @property
    def links(self) -> tuple[RobotElement, ...]:
        return tuple(e for e in self.elements if e.kind == "link")


def pose_turn(pose: str) -> tuple[float, float, float] | None:
    """An SDF ``<pose>``'s roll, pitch and yaw (``x y z roll pitch yaw``); None when it is
    not six finite numbers."""
    words = pose.split()
    if len(words) != 6:
        return None
    try:
        roll, pitch, yaw = (float(w) for w in words[3:])
    except ValueError:
        return None
    if not all(math.isfinite(v) for v in (roll, pitch, yaw)):
        return None
    return (roll, pitch, yaw)
