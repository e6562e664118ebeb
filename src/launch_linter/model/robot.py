"""Robot descriptions found in launch files, and the tf edges their URDF joints give."""

from __future__ import annotations

from dataclasses import dataclass, field
from enum import Enum

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


@dataclass(frozen=True)
class DescriptionSource:
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
    args: tuple[tuple[str, str | None], ...] = ()
    condition: Condition = field(default_factory=Condition)
    node: str | None = None
    text: str | None = None
    reason: str | None = None
    open_args: bool = False
    """True when a word of the xacro call is unresolved and may give more args."""


@dataclass(frozen=True)
class RobotJoint:
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
    condition: Condition = field(default_factory=Condition)
    unresolved: tuple[str, ...] = ()
    reasons: tuple[str, ...] = ()

    @property
    def dynamic(self) -> bool:
        return self.joint_type in MOVABLE_JOINTS

    @property
    def signature(self) -> tuple[str, str] | None:
        if self.parent is None or self.child is None:
            return None
        return (self.parent, self.child)


@dataclass(frozen=True)
class NodeRecord:
    """A launched node (or a Gazebo plugin, or a ros2_control controller): which program
    it runs, and the parameters it is given as ``(name, value)`` pairs (a value the linter
    cannot resolve is ``UNKNOWN_VALUE``; nested names joined with ``/`` in ROS 1 and
    ``.`` in ROS 2).

    ``kind`` is ``node``, ``gazebo_plugin`` or ``controller``; ``plugin`` the composable
    node's plugin, the plugin's filename or the controller's type. ``unread`` says why
    some of its parameters could not be read (a parameter file not found or not parsed):
    a parameter it does not set then has no known value. ``namespace`` is the node's
    namespace (None when unresolved); ``ros`` the ROS version of the launch file.
    """

    path: str
    line: int
    column: int
    package: str
    executable: str
    name: str | None = None
    params: tuple[tuple[str, str], ...] = ()
    condition: Condition = field(default_factory=Condition)
    kind: str = "node"
    plugin: str | None = None
    unread: tuple[str, ...] = ()
    namespace: str | None = "/"
    ros: int | None = None

    def given(self, name: str) -> str | None:
        """The value of the parameter ``name`` exactly as the node is given it (the last
        setting wins), None when it is not set."""
        found = None
        for key, value in self.params:
            if key == name:
                found = value
        return found

    def param(self, name: str) -> str | None:
        for key, value in self.params:
            if key == name or key.endswith("/" + name):
                return value
        return None


@dataclass(frozen=True)
class RobotElement:
    """A ``<link>`` or ``<joint>`` of an expanded description, by name, where it was written.

    ``name`` is None when the name could not be known; ``condition`` is the launch element's
    condition and the undecided ``xacro:if``/``xacro:unless`` around the element."""

    kind: str
    """``link`` or ``joint``."""
    name: str | None
    path: str
    line: int
    column: int
    condition: Condition = field(default_factory=Condition)


class FaultKind(str, Enum):
    """What xacro itself does with a fault of the description's source."""

    REFUSED = "refused"
    """xacro stops with an error: an undefined macro, a missing macro parameter, an
    undeclared ``$(arg)``, a block the call does not match."""
    DROPPED = "dropped"
    """xacro goes on and drops content silently: a block parameter the macro never inserts."""


@dataclass(frozen=True)
class DescriptionFault:
    """A fault of the xacro source that xacro itself refuses or silently drops.

    ``proven`` is false when an earlier element could not be followed (an include not
    read, an unsupported directive), so that what looks missing may be defined there;
    ``conditions`` are the undecided ``xacro:if``/``xacro:unless`` texts around it."""

    path: str
    line: int
    kind: FaultKind
    message: str
    proven: bool = True
    conditions: tuple[str, ...] = ()


@dataclass(frozen=True)
class RobotModel:
    """One expanded description as robot_state_publisher (urdfdom, then KDL) reads it.

    ``complete`` is true when nothing of it is unknown: the expansion followed every
    element and every link name and joint end is known, so that what is absent is proven
    absent. ``standalone`` is true for a ``.urdf``/``.xacro`` file linted as an input of
    its own (no launch file loads it in that tree)."""

    source: DescriptionSource
    elements: tuple[RobotElement, ...]
    joints: tuple[RobotJoint, ...]
    complete: bool
    faults: tuple[DescriptionFault, ...] = ()
    defines_macros: bool = False
    """Whether the description's files define xacro macros (an empty robot made of a
    macros-only file)."""
    standalone: bool = False
    plugins: tuple[NodeRecord, ...] = ()
    """Its ``<gazebo><plugin>`` blocks, as records of kind ``gazebo_plugin``: they run
    only when a simulator is given the description (see :func:`spawns_into_simulator`)."""

    @property
    def links(self) -> tuple[RobotElement, ...]:
        return tuple(e for e in self.elements if e.kind == "link")
