"""The ROS 2 launch actions the linter models, as every ROS 2 front-end describes them.

ROS 2 launch turns XML, YAML and Python alike into a list of actions that it then runs
in order against one launch context. The front-ends here do the same: each reads its
format into these descriptions (values stay unevaluated substitutions), and
:mod:`launch_linter.frontends.ros2_launch` runs them, so argument scoping, namespaces,
conditions and includes behave the same whatever the format.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from typing import Union

from launch_linter.model.transform import LaunchFormat
from launch_linter.resolve.ros2_substitution import Call, Subs, Text, written
from launch_linter.resolve.value import Value

STATIC_TF_EXECUTABLE = "static_transform_publisher"
STATIC_TF_PACKAGE = "tf2_ros"


def may_publish_static_tf(package: object, executable: object) -> bool:
    """Whether a node whose package and executable evaluate to these values may be a
    static transform publisher: False only when one of them is known text naming another
    program (what :func:`launch_linter.frontends.ros2_run._is_static_tf` decides after
    resolution, decided early for what only such a node needs)."""
    if isinstance(executable, str) and executable != STATIC_TF_EXECUTABLE:
        return False
    return not (isinstance(package, str) and package != STATIC_TF_PACKAGE)


def is_literal(subs: Subs | None) -> bool:
    """Written as text: no launch configuration or other substitution in it."""
    return subs is not None and all(isinstance(sub, Text) for sub in subs)


@dataclass(frozen=True)
class Where:
    """Where an action is written: absolute path, 1-based line and column."""

    path: str
    line: int
    column: int

    def __init__(self, path: str, line: int, column: int) -> None:
        # Made for every action and call the interpreter evaluates: the fields are put in
        # the instance's dict, at less than half the cost of the frozen dataclass's
        # ``object.__setattr__`` per field (assignment is still refused).
        fields = self.__dict__
        fields["path"], fields["line"], fields["column"] = path, line, column


@dataclass(frozen=True)
class Predicate:
    """An ``if`` (``positive``) or ``unless`` condition on an action."""

    positive: bool
    expression: Subs


@dataclass(frozen=True)
class DeclareArg:
    where: Where
    condition: Predicate | None
    name: Subs
    default: Subs | None

    def __init__(self, where: Where, condition: Predicate | None, name: Subs,
                 default: Subs | None) -> None:
        # One per declared argument: the fields go in the instance's dict (see Where).
        fields = self.__dict__
        fields["where"], fields["condition"] = where, condition
        fields["name"], fields["default"] = name, default


@dataclass(frozen=True)
class SetVar:
    """``<let>`` / ``SetLaunchConfiguration``; ``value`` None unsets it."""

    where: Where
    condition: Predicate | None
    name: Subs
    value: Subs | None


@dataclass(frozen=True)
class SetEnv:
    """``<set_env>`` / ``SetEnvironmentVariable``; ``value`` None unsets it."""

    where: Where
    condition: Predicate | None
    name: Subs
    value: Subs | None


@dataclass(frozen=True)
class PushNamespace:
    where: Where
    condition: Predicate | None
    namespace: Subs


@dataclass(frozen=True)
class Group:
    """``<group>`` / ``GroupAction``: ``scoped`` keeps configurations set inside from
    leaking out; ``forwarding`` False starts the group without the outer ones."""

    where: Where
    condition: Predicate | None
    actions: tuple[Action, ...]
    scoped: Subs | bool = True
    forwarding: Subs | bool = True


@dataclass(frozen=True)
class Include:
    where: Where
    condition: Predicate | None
    path: Subs
    args: tuple[tuple[Subs, Subs], ...]
    args_known: bool = True
    """False when the arguments passed are not known (a Python expression the linter does
    not model): they may set any launch configuration."""
    arg_places: tuple[tuple[int, int], ...] = ()
    """Where each of ``args`` is written (line, column), when the front-end knows it."""


@dataclass(frozen=True)
class RunNode:
    """``<node>`` / ``Node``. ``arguments`` holds one entry per argv item, or None when
    the list cannot be known (``unknown`` says why)."""

    where: Where
    condition: Predicate | None
    package: Subs | None
    executable: Subs | None
    name: Subs | None
    namespace: Subs | None
    arguments: tuple[Subs, ...] | None
    args_written: str
    unknown: str = ""
    pushed_namespace: bool = True
    """False for ``ros2 run`` in an executable action: launch_ros's pushed namespace
    applies to ``Node`` actions only."""
    parameters: tuple[Params | ParamsFile | ParamsUnknown, ...] = ()
    """Kept for the nodes that tf rules need (robot_state_publisher's description,
    localization and odometry frame parameters)."""
    uses: tuple[Subs, ...] = ()
    """Every other substitution the action performs when it runs (remappings, parameters,
    other attributes), resolved only to check the launch configurations they read."""
    may_rename: bool = False
    """Its arguments or ROS arguments may remap its name or namespace (``__node:=``,
    ``__ns:=``, written or not known): its name as launched is then not ``name``."""
    remappings: tuple[tuple[Subs, Subs], ...] | None = None
    """Its topic remappings (from, to) as written; None when not known (not read, or not
    a list of pairs)."""
    executable_at: Where | None = None
    """Where its executable is written when that is not ``where`` (a Python ``Node(``'s
    ``executable=`` keyword on a line of its own): the word a fix changes."""

    def __init__(self, where: Where, condition: Predicate | None, package: Subs | None,
                 executable: Subs | None, name: Subs | None, namespace: Subs | None,
                 arguments: tuple[Subs, ...] | None, args_written: str, unknown: str = "",
                 pushed_namespace: bool = True,
                 parameters: tuple[Params | ParamsFile | ParamsUnknown, ...] = (),
                 uses: tuple[Subs, ...] = (), may_rename: bool = False,
                 remappings: tuple[tuple[Subs, Subs], ...] | None = None,
                 executable_at: Where | None = None) -> None:
        # One per node, fifteen fields: put in the instance's dict, a fifth of the cost of
        # the frozen dataclass's ``object.__setattr__`` per field (see Where).
        fields = self.__dict__
        fields["where"] = where
        fields["condition"] = condition
        fields["package"] = package
        fields["executable"] = executable
        fields["name"] = name
        fields["namespace"] = namespace
        fields["arguments"] = arguments
        fields["args_written"] = args_written
        fields["unknown"] = unknown
        fields["pushed_namespace"] = pushed_namespace
        fields["parameters"] = parameters
        fields["uses"] = uses
        fields["may_rename"] = may_rename
        fields["remappings"] = remappings
        fields["executable_at"] = executable_at


RENAMING_WORDS = ("__node", "__name", "__ns")
"""rcl's node name and namespace remappings (``__name`` the older spelling)."""


def may_rename(words: Sequence[str] | None) -> bool:
    """Arguments that may rename a node: not known (None), or naming a remapping of it."""
    if words is None:
        return True
    # One text searched, not each word three times (every node's arguments): no renaming
    # word holds a newline, so none is found across two words; all three start "__n".
    text = "\n".join(words)
    return "__n" in text and any(w in text for w in RENAMING_WORDS)


def _ros2_verb(items: Sequence[Subs]) -> str | None:
    """The verb of a ``ros2 VERB ...`` command's argv items (``run``, ``control``), None
    when the program is not ``ros2`` or the verb not literal. The program may be written
    as a path ending in ``/ros2`` or found with ``$(find-exec ros2)``."""
    if len(items) < 2:
        return None
    words = []
    for item in items[:2]:
        if len(item) == 1 and isinstance(item[0], Call) and item[0].name == "find-exec" and (
            [written(arg) for arg in item[0].args] == ["ros2"]
        ):
            words.append("ros2")  # FindExecutable(name='ros2'), $(find-exec ros2)
            continue
        if not all(isinstance(sub, Text) for sub in item):
            return None
        words.append("".join(sub.text for sub in item if isinstance(sub, Text)))
    program, verb = words
    return verb if program == "ros2" or program.endswith("/ros2") else None


def ros2_run(items: Sequence[Subs]) -> tuple[Subs, Subs, tuple[Subs, ...]] | None:
    """``ros2 run PKG EXEC ARGS...`` as an executable's argv items: (package, executable,
    arguments), or None when the command is something else."""
    if len(items) < 4 or _ros2_verb(items) != "run":
        return None
    return items[2], items[3], tuple(items[4:])


def ros2_control(items: Sequence[Subs]) -> tuple[Subs, ...] | None:
    """The words after ``ros2 control`` (ros2controlcli's verb and its arguments), None
    when the command is something else."""
    if len(items) < 3 or _ros2_verb(items) != "control":
        return None
    return tuple(items[2:])


SHELL_SPECIAL = frozenset("$`;|&<>*?()[]{}~!#\n")
"""What a shell reads other than as words and quotes (expansions, globs, several commands,
redirections, comments)."""


def shell_reads_as_words(line: str) -> bool:
    """Whether a shell (``shell=True``) splits ``line`` into the words ``shlex.split``
    gives, running one program."""
    return not any(character in SHELL_SPECIAL for character in line)


@dataclass(frozen=True)
class Params:
    """Parameters given by name (nested names joined with ``.``). launch gives each value
    YAML typing after substitution (``1.0`` is a double, ``map`` a string), whatever the
    format, so values are kept as substitutions."""

    items: tuple[tuple[str, Subs], ...]
    places: tuple[Where | None, ...] = ()
    """Where each item's key is written, in the items' order (None: not known; empty when
    the front-end keeps no places)."""

    def __init__(self, items: tuple[tuple[str, Subs], ...],
                 places: tuple[Where | None, ...] = ()) -> None:
        # One per ``parameters`` entry: the fields go in the instance's dict (see Where).
        fields = self.__dict__
        fields["items"], fields["places"] = items, places


@dataclass(frozen=True)
class ParamsFile:
    """A parameter file given to a node (``'file.yaml'``, ``ParameterFile``, ``from=``).
    ``substitutions``: launch performs the ``$(...)`` in the file (``allow_substs``)."""

    path: Subs
    substitutions: bool = False


@dataclass(frozen=True)
class ParamsUnknown:
    """Parameters from somewhere the linter does not read (a file, an expression)."""

    reason: str


@dataclass(frozen=True)
class Component:
    """``<composable_node>`` / ``ComposableNode`` inside a container or a load action."""

    where: Where
    condition: Predicate | None
    package: Subs | None
    plugin: Subs | None
    name: Subs | None
    namespace: Subs | None
    parameters: tuple[Params | ParamsFile | ParamsUnknown, ...]
    uses: tuple[Subs, ...] = ()
    """Every other substitution the action performs when it runs (remappings, parameters,
    other attributes), resolved only to check the launch configurations they read."""


@dataclass(frozen=True)
class LoadComponents:
    """``<node_container>``, ``<load_composable_node>`` and their Python classes."""

    where: Where
    condition: Predicate | None
    components: tuple[Component, ...]
    uses: tuple[Subs, ...] = ()
    """Every other substitution the action performs when it runs (remappings, parameters,
    other attributes), resolved only to check the launch configurations they read."""


@dataclass(frozen=True)
class Deferred:
    """Actions known only when the launch runs (a Python ``OpaqueFunction``): ``expand``
    receives a resolver for substitutions at that point and returns the actions."""

    where: Where
    condition: Predicate | None
    expand: Callable[[Callable[[Subs], Value]], Sequence[Action]]


@dataclass(frozen=True)
class Uses:
    """An action the linter does not otherwise model (``<set_parameter>``, ``LogInfo``,
    an ``ExecuteProcess`` ...): only the substitutions it performs when it runs, to check
    the launch configurations they read."""

    where: Where
    condition: Predicate | None
    uses: tuple[Subs, ...]
    parameter: tuple[Subs, Subs] | None = None
    """``SetParameter``/``<set_parameter>``: the name and value it gives every node
    launched after it in its scope."""
    controls: tuple[Subs, ...] | None = None
    """``ros2 control VERB ...`` run by an executable action: the words after ``control``
    (what it activates: ``frontends.params.control_started``)."""


@dataclass(frozen=True)
class Unfollowed:
    """Something that may launch nodes but that the linter cannot follow; or, with a rule
    other than ``unresolved``, a problem the reader met while running an
    ``OpaqueFunction`` (after the file's own problems were handed over)."""

    where: Where
    reason: str
    rule: str = "unresolved"


ACTION_TYPES = (
    DeclareArg, SetVar, SetEnv, PushNamespace, Group, Include, RunNode,
    LoadComponents, Deferred, Uses, Unfollowed,
)
"""The action classes, for ``isinstance`` (Python 3.8 has no run-time ``X | Y``)."""
Action = Union[
    DeclareArg, SetVar, SetEnv, PushNamespace, Group, Include, RunNode,
    LoadComponents, Deferred, Uses, Unfollowed,
]


@dataclass(frozen=True)
class Problem:
    """Something the reader of one file reports: ``rule`` is ``parse_error``,
    ``roslaunch_error`` or ``unresolved``."""

    rule: str
    line: int
    column: int
    message: str


@dataclass(frozen=True)
class FileRead:
    """One file read by a ROS 2 front-end; ``actions`` is None when it is unreadable."""

    launch_format: LaunchFormat
    actions: tuple[Action, ...] | None
    comments: tuple[tuple[int, str], ...] = ()
    element_lines: tuple[int, ...] = ()
    problems: tuple[Problem, ...] = ()
    forget: Callable[[], None] | None = field(default=None, compare=False, repr=False)
    """Lets go of what the file's ``OpaqueFunction`` actions (:class:`Deferred`) keep to
    run later (the scopes of a Python file's interpreter), once the launch tree is read:
    those scopes and the actions refer to each other, a cycle that would otherwise leave
    the file's syntax tree and its evaluation to the garbage collector."""
