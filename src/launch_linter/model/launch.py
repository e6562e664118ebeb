"""A launch tree: one input file with everything it includes, as the front-end saw it."""

from __future__ import annotations

from collections.abc import Iterable
from enum import Enum

from launch_linter.model.diagnostic import Location, Problem
from launch_linter.model.record import Record, _open, _seal, _set
from launch_linter.model.robot import DescriptionSource, NodeRecord, RobotJoint, RobotModel
from launch_linter.model.transform import Condition, StaticTransform


class FileStatus(str, Enum):
    OK = "ok"
    PARSE_ERROR = "parse_error"
    UNREADABLE = "unreadable"
    INTERNAL_ERROR = "internal_error"
    """The linter itself failed on this file (a bug to report); the other files are fine."""


class FileRecord(Record):
    """One input file and how reading it went."""

    path: str
    status: FileStatus
    transforms: int

    __slots__ = ("path", "status", "transforms")

    def __init__(self, path: str, status: FileStatus, transforms: int) -> None:
        _set(self, "path", path)
        _set(self, "status", status)
        _set(self, "transforms", transforms)


class Comment(Record):
    """An XML comment (or YAML/Python comment) with the line it ends on."""

    path: str
    line: int
    text: str

    __slots__ = ("path", "line", "text")

    def __init__(self, path: str, line: int, text: str) -> None:
        _set(self, "path", path)
        _set(self, "line", line)
        _set(self, "text", text)


DIRECTIVE_MARKER = "launch-linter:"
"""What every suppression directive's comment holds. A file's comments and element lines
only feed directives, so front-ends keep them only for files with a comment that holds it."""


def may_hold_directive(data: bytes) -> bool:
    """Whether the file ``data`` may hold a suppression directive: it spells the marker in
    ASCII, or it is in an encoding that does not (UTF-16 or UTF-32, with zero bytes)."""
    return DIRECTIVE_MARKER.encode() in data or b"\x00" in data


def holds_directive(comments: Iterable[tuple[int, str]]) -> bool:
    """Whether any of ``comments`` (line, text) may be a suppression directive."""
    return any(DIRECTIVE_MARKER in text for _, text in comments)


class UndeclaredUse(Record):
    """A ROS 2 launch configuration read without a default (``$(var x)``,
    ``LaunchConfiguration('x')``) that nothing in the tree declares, sets or passes: launch
    stops there with "launch configuration 'x' does not exist" unless something the linter
    did not see sets it. The facts only; the rule ``ros2_undeclared_arg`` words them."""

    name: str
    path: str
    line: int
    column: int
    root: str
    """The tree's root file, the one launched."""
    conditional: bool
    """Read under a condition the linter cannot decide (it may never be read)."""
    open_reason: str | None
    """Something in the tree the linter did not follow, which could set it."""
    included_by: str | None
    """Another launch file that names the root: the root is (also) included, and its
    includer may pass the argument."""
    similar: str | None
    """A configuration the tree does declare with a close name (a likely misspelling)."""

    __slots__ = (
        "name", "path", "line", "column", "root", "conditional", "open_reason", "included_by",
        "similar",
    )

    def __init__(
        self,
        name: str,
        path: str,
        line: int,
        column: int,
        root: str,
        conditional: bool,
        open_reason: str | None,
        included_by: str | None,
        similar: str | None = None,
    ) -> None:
        _set(self, "name", name)
        _set(self, "path", path)
        _set(self, "line", line)
        _set(self, "column", column)
        _set(self, "root", root)
        _set(self, "conditional", conditional)
        _set(self, "open_reason", open_reason)
        _set(self, "included_by", included_by)
        _set(self, "similar", similar)


class Forwarded(Record):
    """A value a ROS 2 launch file passes on: a node parameter that reads the launch
    configuration of its own name, ``{'x': LaunchConfiguration('x')}`` (``kind``
    ``parameter``, at the value's key), or any include argument (``include``, at the
    include). ``own``: the value reads the configuration of its own name (``x:=$(var
    x)``); ``value``: its text, None when unresolved; ``followed``: the include's file was
    read (an argument of an include not followed says what the launch means to run)."""

    name: str
    kind: str
    path: str
    line: int
    column: int
    condition: Condition
    value: str | None
    own: bool
    followed: bool

    __slots__ = ("name", "kind", "path", "line", "column", "condition", "value", "own",
                 "followed")

    def __init__(self, name: str, kind: str, path: str, line: int, column: int,
                 condition: Condition, value: str | None = None, own: bool = True,
                 followed: bool = True) -> None:
        _set(self, "name", name)
        _set(self, "kind", kind)
        _set(self, "path", path)
        _set(self, "line", line)
        _set(self, "column", column)
        _set(self, "condition", condition)
        _set(self, "value", value)
        _set(self, "own", own)
        _set(self, "followed", followed)


class UnmatchedParamFile(Record):
    """A ROS 2 parameter file given to a node of known name (``name=`` written, its
    namespace resolved, no ``__node``/``__ns`` remapping among its arguments) none of whose
    node keys (the keys above ``ros__parameters``) matches the node's full name ``node``
    as rclcpp matches them: the node takes nothing from it. At the node (``path``,
    ``line``, ``column``); ``file`` is the parameter file, ``keys`` its node keys as
    matched (nested keys joined with ``/``) with where each is written (0, 0 unknown);
    ``name_literal``: the node's name is written as text (no launch configuration in it),
    or the launch file names none and ``names`` are those its program gives its nodes.
    ``names``: the names (without namespace) of the process's nodes the keys were matched
    against; empty: the node's own name, the last part of ``node``."""

    path: str
    line: int
    column: int
    condition: Condition
    node: str
    package: str
    executable: str
    """The executable, or the composable node's plugin."""
    file: str
    keys: tuple[tuple[str, int, int], ...]
    name_literal: bool
    names: tuple[str, ...]

    __slots__ = ("path", "line", "column", "condition", "node", "package", "executable",
                 "file", "keys", "name_literal", "names")

    def __init__(self, path: str, line: int, column: int, condition: Condition, node: str,
                 package: str, executable: str, file: str,
                 keys: tuple[tuple[str, int, int], ...], name_literal: bool = False,
                 names: tuple[str, ...] = ()) -> None:
        _set(self, "path", path)
        _set(self, "line", line)
        _set(self, "column", column)
        _set(self, "condition", condition)
        _set(self, "node", node)
        _set(self, "package", package)
        _set(self, "executable", executable)
        _set(self, "file", file)
        _set(self, "keys", keys)
        _set(self, "name_literal", name_literal)
        _set(self, "names", names)


class DoubledNamespace(Record):
    """A ROS 2 node launched under a namespace whose last name was pushed twice: an outer
    push (a group's ``PushRosNamespace``, an include's) and an inner one of the same name
    (the included file's own push, or the node's relative ``namespace=``). ``namespace``
    is the node's as launched (``/robot1/robot1``), ``pushes`` the outer and inner push's
    places, ``tf_topic`` the topic the node's tf goes to (None when its remappings are not
    known) and ``tree_tf_topic`` the one the tree's other nodes under the namespace pushed
    once use (None when none is known)."""

    path: str
    line: int
    column: int
    condition: Condition
    node: str
    program: str
    namespace: str
    pushes: tuple[Location, Location]
    tf_topic: str | None
    tree_tf_topic: str | None

    __slots__ = ("path", "line", "column", "condition", "node", "program", "namespace",
                 "pushes", "tf_topic", "tree_tf_topic")

    def __init__(self, path: str, line: int, column: int, condition: Condition, node: str,
                 program: str, namespace: str, pushes: tuple[Location, Location],
                 tf_topic: str | None = None, tree_tf_topic: str | None = None) -> None:
        _set(self, "path", path)
        _set(self, "line", line)
        _set(self, "column", column)
        _set(self, "condition", condition)
        _set(self, "node", node)
        _set(self, "program", program)
        _set(self, "namespace", namespace)
        _set(self, "pushes", pushes)
        _set(self, "tf_topic", tf_topic)
        _set(self, "tree_tf_topic", tree_tf_topic)


class NodeDeclarations(Record):
    """The parameters a ROS 2 executable of the workspace declares (``names``, read from
    ``source``, a file of package ``package``): all of them when ``complete``, else only
    those its readable sources declare with a literal name (a part of the node is not
    known: a generated source, a name that is not a literal)."""

    package: str
    executable: str
    names: tuple[str, ...]
    source: str
    complete: bool

    __slots__ = ("package", "executable", "names", "source", "complete")

    def __init__(self, package: str, executable: str, names: tuple[str, ...],
                 source: str, complete: bool = True) -> None:
        _set(self, "package", package)
        _set(self, "executable", executable)
        _set(self, "names", names)
        _set(self, "source", source)
        _set(self, "complete", complete)


class LaunchTree(Record):
    """Everything read from one root file, its includes included."""

    root: str
    status: FileStatus
    transforms: tuple[StaticTransform, ...]
    problems: tuple[Problem, ...]
    """What the front-end noticed (parse errors, roslaunch errors, unresolved values)."""
    files: tuple[str, ...]
    comments: tuple[Comment, ...]
    element_lines: tuple[tuple[str, int], ...]
    descriptions: tuple[DescriptionSource, ...]
    """The ``robot_description`` sources the launch files give."""
    nodes: tuple[NodeRecord, ...]
    """Launched nodes that tf rules need (robot_state_publisher, localization, odometry)."""
    joints: tuple[RobotJoint, ...]
    """URDF joints of the descriptions a robot_state_publisher of the tree publishes."""
    robots: tuple[RobotModel, ...]
    """The expanded descriptions themselves (links, joints, xacro faults), one per source
    that a robot_state_publisher of the tree publishes, for the URDF structure rules."""
    undeclared: tuple[UndeclaredUse, ...]
    """ROS 2 launch configurations read where nothing declares, sets or passes them."""
    parse_check_only: bool
    """The root is proven to be only an input of ``roslaunch_add_file_check`` (parsed by a
    test, never started): not one running system (``workspace/launch_checks.py``)."""
    forwarded: tuple[Forwarded, ...]
    """ROS 2 launch configurations passed on under their own name (``Forwarded``)."""
    unmatched_param_files: tuple[UnmatchedParamFile, ...]
    """ROS 2 parameter files that give the node they are passed to nothing."""
    doubled_namespaces: tuple[DoubledNamespace, ...]
    """ROS 2 nodes under a namespace pushed twice (``DoubledNamespace``)."""
    spawned: tuple[str, ...] | None
    """The ros2_control controllers the tree's spawners load, by name; None when a
    spawner's words are not all read."""
    declarations: tuple[NodeDeclarations, ...]
    """The parameters workspace nodes of the tree declare, where their source shows them
    completely (``workspace/node_declarations.py``)."""
    built_here: tuple[str, ...]
    """The packages of the tree's nodes whose release the knowledge base describes and
    whose source is under a linted root: their own build files, not that release,
    decide which executables they have (a source checkout shadows the installed one)."""

    __slots__ = (
        "root", "status", "transforms", "problems", "files", "comments", "element_lines",
        "descriptions", "nodes", "joints", "robots", "undeclared", "parse_check_only",
        "forwarded", "unmatched_param_files", "doubled_namespaces", "spawned",
        "declarations", "built_here",
    )

    def __init__(
        self,
        root: str,
        status: FileStatus,
        transforms: tuple[StaticTransform, ...],
        problems: tuple[Problem, ...],
        files: tuple[str, ...],
        comments: tuple[Comment, ...] = (),
        element_lines: tuple[tuple[str, int], ...] = (),
        descriptions: tuple[DescriptionSource, ...] = (),
        nodes: tuple[NodeRecord, ...] = (),
        joints: tuple[RobotJoint, ...] = (),
        robots: tuple[RobotModel, ...] = (),
        undeclared: tuple[UndeclaredUse, ...] = (),
        parse_check_only: bool = False,
        forwarded: tuple[Forwarded, ...] = (),
        unmatched_param_files: tuple[UnmatchedParamFile, ...] = (),
        doubled_namespaces: tuple[DoubledNamespace, ...] = (),
        spawned: tuple[str, ...] | None = (),
        declarations: tuple[NodeDeclarations, ...] = (),
        built_here: tuple[str, ...] = (),
    ) -> None:
        _open(self)  # made for every root file: see _open
        self.root = root
        self.status = status
        self.transforms = transforms
        self.problems = problems
        self.files = files
        self.comments = comments
        self.element_lines = element_lines
        self.descriptions = descriptions
        self.nodes = nodes
        self.joints = joints
        self.robots = robots
        self.undeclared = undeclared
        self.parse_check_only = parse_check_only
        self.forwarded = forwarded
        self.unmatched_param_files = unmatched_param_files
        self.doubled_namespaces = doubled_namespaces
        self.spawned = spawned
        self.declarations = declarations
        self.built_here = built_here
        _seal(self)
