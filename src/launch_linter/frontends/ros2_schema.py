"""What ROS 2 ``launch`` and ``launch_ros`` accept on each XML/YAML action, and a checker.

Since ros2/launch#468 (November 2020, back-ported to Foxy), the front-end wraps every
exposed action's ``parse`` classmethod and then calls ``assert_entity_completely_parsed``:
an attribute (or YAML key) that ``parse`` did not read with ``get_attr``, or a nested tag
it did not read, makes launch raise ``ValueError`` and refuse the **whole file**. Some
nested entities (``<env>``, ``<remap>``, ``<param>``, ``<arg>`` of an include, ...) are
checked the same way by their parent's ``parse``; others (``<choice>``) are not. An action
tag that no parser exposes is ``RuntimeError: Unrecognized entity of the type: ...``.

The table below is that knowledge, read from the ``parse`` methods of ros2/launch and
ros2/launch_ros on the Humble, Iron, Jazzy and Rolling branches (launch 1.0.7, 2.0.4, 3.4.3,
3.7.1; launch_ros 0.19-0.28). It is the union over those branches: an attribute that only
newer distributions read (``emulate_tty``, ``respawn_max_retries``, ...) is accepted, since
the distribution is not known here. Each entry names its source file;
``tests/frontends/ros2/test_ros2_schema.py`` checks the table against a checkout of the
sources when one is available.
"""

from __future__ import annotations

from dataclasses import dataclass

LAUNCH = "ros2/launch"
LAUNCH_ROS = "ros2/launch_ros"
VERSIONS = "humble..rolling (launch 1.0.7-3.7.1, launch_ros 0.19.x-0.28.0)"


@dataclass(frozen=True)
class Nested:
    """A nested entity that its parent's ``parse`` reads and checks completely
    (``checked``) or reads without checking its attributes."""

    attributes: frozenset[str]
    nested: tuple[tuple[str, Nested], ...] = ()
    checked: bool = True
    required: tuple[str, ...] = ()
    """Attributes ``parse`` reads without ``optional=True`` (missing: AttributeError),
    those the action reader does not already report."""

    def child(self, tag: str) -> Nested | None:
        for name, spec in self.nested:
            if name == tag:
                return spec
        return None


@dataclass(frozen=True)
class ActionSpec:
    """One exposed action: the attributes its ``parse`` reads, the nested entities it
    reads, whether its other children are actions (``group``, ``timer``), and where that
    was read (repository, file)."""

    attributes: frozenset[str]
    nested: tuple[tuple[str, Nested], ...]
    has_actions: bool
    repo: str
    source: str
    required: tuple[str, ...] = ()
    """As :attr:`Nested.required`: only those the action reader does not report itself."""

    def child(self, tag: str) -> Nested | None:
        for name, spec in self.nested:
            if name == tag:
                return spec
        return None


def _attrs(*names: str) -> frozenset[str]:
    return frozenset(names)


CONDITION = _attrs("if", "unless")
"""``launch.Action.parse``: every action reads its condition."""

_NAME_VALUE = Nested(_attrs("name", "value"), required=("name", "value"))
_INCLUDE_ARG = Nested(_attrs("name", "value"))  # the action reader reports missing ones
_REMAP = Nested(_attrs("from", "to"), required=("from", "to"))
# launch_ros Node.parse_nested_parameters: a top-level <param> reads from, allow_substs and
# name, then name, type, value and nested <param>; a nested one reads name, type, value,
# param. Both are checked completely.
_PARAM_NESTED = Nested(_attrs("name", "type", "value"))
_PARAM_INNER = Nested(_attrs("name", "type", "value"), (("param", _PARAM_NESTED),))
_PARAM = Nested(
    _attrs("from", "allow_substs", "name", "type", "value"), (("param", _PARAM_INNER),)
)
_EXECUTE_PROCESS = _attrs(
    "cmd", "cwd", "name", "on_exit", "launch-prefix", "output", "respawn",
    "respawn_delay", "respawn_max_retries", "sigkill_timeout", "sigterm_timeout", "shell",
    "emulate_tty",
)
_NODE_OWN = _attrs(
    "args", "ros_args", "node-name", "name", "exec_name", "pkg", "exec", "namespace",
)
_NODE = (CONDITION | (_EXECUTE_PROCESS - {"cmd"}) | _NODE_OWN)
_NODE_NESTED = (("env", _NAME_VALUE), ("remap", _REMAP), ("param", _PARAM))
_COMPOSABLE_NODE = Nested(
    _attrs("pkg", "plugin", "name", "if", "unless", "namespace"),
    (("param", _PARAM), ("remap", _REMAP), ("extra_arg", _NAME_VALUE)),
    required=("pkg", "name"),  # 'plugin' is reported by the action reader
)

_ACTIONS_PATH = "launch/launch/actions/"
_ROS_PATH = "launch_ros/launch_ros/actions/"

ACTIONS: dict[str, ActionSpec] = {
    "append_env": ActionSpec(
        CONDITION | _attrs("name", "value", "prepend", "separator"), (), False,
        LAUNCH, _ACTIONS_PATH + "append_environment_variable.py", required=("name", "value")),
    "arg": ActionSpec(
        CONDITION | _attrs("name", "default", "description"),
        (("choice", Nested(_attrs("value"), checked=False, required=("value",))),), False,
        LAUNCH, _ACTIONS_PATH + "declare_launch_argument.py"),
    "executable": ActionSpec(
        CONDITION | _EXECUTE_PROCESS, (("env", _NAME_VALUE),), False,
        LAUNCH, _ACTIONS_PATH + "execute_process.py"),
    "group": ActionSpec(
        CONDITION | _attrs("scoped", "forwarding"), (("keep", _NAME_VALUE),), True,
        LAUNCH, _ACTIONS_PATH + "group_action.py"),
    "include": ActionSpec(
        CONDITION | _attrs("file"), (("arg", _INCLUDE_ARG),), False,
        LAUNCH, _ACTIONS_PATH + "include_launch_description.py"),
    "log": ActionSpec(
        CONDITION | _attrs("message"), (), False,
        LAUNCH, _ACTIONS_PATH + "log_info.py", required=("message",)),
    "reset_env": ActionSpec(
        CONDITION, (), False,
        LAUNCH, _ACTIONS_PATH + "reset_environment.py"),
    "reset": ActionSpec(
        CONDITION, (("keep", _NAME_VALUE),), False,
        LAUNCH, _ACTIONS_PATH + "reset_launch_configurations.py"),
    "set_env": ActionSpec(
        CONDITION | _attrs("name", "value"), (), False,
        LAUNCH, _ACTIONS_PATH + "set_environment_variable.py"),
    "let": ActionSpec(
        CONDITION | _attrs("name", "value"), (), False,
        LAUNCH, _ACTIONS_PATH + "set_launch_configuration.py"),
    "shutdown": ActionSpec(
        CONDITION | _attrs("reason"), (), False,
        LAUNCH, _ACTIONS_PATH + "shutdown_action.py"),
    "timer": ActionSpec(
        CONDITION | _attrs("period", "cancel_on_shutdown"), (), True,
        LAUNCH, _ACTIONS_PATH + "timer_action.py", required=("period",)),
    "unset_env": ActionSpec(
        CONDITION | _attrs("name"), (), False,
        LAUNCH, _ACTIONS_PATH + "unset_environment_variable.py"),
    "node": ActionSpec(
        _NODE, _NODE_NESTED, False,
        LAUNCH_ROS, _ROS_PATH + "node.py"),
    "node_container": ActionSpec(
        _NODE, (*_NODE_NESTED, ("composable_node", _COMPOSABLE_NODE)), False,
        LAUNCH_ROS, _ROS_PATH + "composable_node_container.py"),
    "load_composable_node": ActionSpec(
        CONDITION | _attrs("target"), (("composable_node", _COMPOSABLE_NODE),), False,
        LAUNCH_ROS, _ROS_PATH + "load_composable_nodes.py", required=("target",)),
    "push_ros_namespace": ActionSpec(
        CONDITION | _attrs("namespace"), (), False,
        LAUNCH_ROS, _ROS_PATH + "push_ros_namespace.py"),
    "push-ros-namespace": ActionSpec(
        CONDITION | _attrs("namespace"), (), False,
        LAUNCH_ROS, _ROS_PATH + "push_ros_namespace.py"),
    "ros_timer": ActionSpec(
        CONDITION | _attrs("period"), (), True,
        LAUNCH_ROS, _ROS_PATH + "ros_timer.py", required=("period",)),
    "set_parameter": ActionSpec(
        CONDITION | _attrs("name", "value"), (), False,
        LAUNCH_ROS, _ROS_PATH + "set_parameter.py", required=("name", "value")),
    "set_parameters_from_file": ActionSpec(
        CONDITION | _attrs("filename"), (), False,
        LAUNCH_ROS, _ROS_PATH + "set_parameters_from_file.py", required=("filename",)),
    "set_remap": ActionSpec(
        CONDITION | _attrs("from", "to"), (), False,
        LAUNCH_ROS, _ROS_PATH + "set_remap.py", required=("from", "to")),
    "set_ros_log_dir": ActionSpec(
        CONDITION | _attrs("new_log_dir"), (), False,
        LAUNCH_ROS, _ROS_PATH + "set_ros_log_dir.py", required=("new_log_dir",)),
    "set_use_sim_time": ActionSpec(
        CONDITION | _attrs("value"), (), False,
        LAUNCH_ROS, _ROS_PATH + "set_use_sim_time.py", required=("value",)),
}
"""Every action tag launch and launch_ros expose, as written (tags are not normalised:
``set-env`` is not ``set_env``; only the namespace action is exposed under both)."""

ROS1_TAGS = frozenset((
    "param", "rosparam", "remap", "machine", "test", "env", "master", "node-container",
))
"""Tags that are ROS 1 launch tags (or near misses) and no ROS 2 extension exposes as
actions: at the top of a ROS 2 file they are certainly refused."""


@dataclass(frozen=True)
class SchemaEntity:
    """What the checker needs of an entity: its tag, where it is, the attribute (or YAML
    key) names written, and its nested entities in order."""

    tag: str
    line: int
    column: int
    attributes: tuple[str, ...]
    children: tuple[SchemaEntity, ...]


@dataclass(frozen=True)
class SchemaProblem:
    """``refused`` problems make launch refuse the file; the others (a tag that only an
    extension package could provide) are unknown to the linter."""

    line: int
    column: int
    message: str
    refused: bool


def _close(a: str, b: str) -> bool:
    """Within two edits (one for short words): a likely misspelling."""
    limit = 1 if min(len(a), len(b)) <= 4 else 2
    if abs(len(a) - len(b)) > limit:
        return False
    previous = list(range(len(b) + 1))
    for i, char_a in enumerate(a, start=1):
        current = [i]
        for j, char_b in enumerate(b, start=1):
            current.append(min(previous[j] + 1, current[j - 1] + 1,
                               previous[j - 1] + (char_a != char_b)))
        previous = current
    return previous[-1] <= limit


def _hint(name: str, known: frozenset[str]) -> str:
    close = sorted(k for k in known if _close(name, k))
    return f" (did you mean '{close[0]}'?)" if close else ""


def _unread_attributes(entity: SchemaEntity, known: frozenset[str], xml: bool) -> list[str]:
    present = set(entity.attributes)
    unread: list[str] = []
    for name in entity.attributes:
        if name in known:
            continue
        # launch_xml reads NAME-sep together with NAME (a list attribute's separator).
        if xml and name.endswith("-sep") and name[:-4] in known and name[:-4] in present:
            continue
        unread.append(name)
    return unread


class _Checker:
    def __init__(self, launch_format: str) -> None:
        self.xml = launch_format == "xml"
        self.word = "attribute" if self.xml else "key"
        self.problems: list[SchemaProblem] = []

    def refuse(self, entity: SchemaEntity, message: str) -> None:
        self.problems.append(SchemaProblem(
            entity.line, entity.column,
            f"{message}; launch refuses the whole file, so none of its nodes start",
            True,
        ))

    def missing(self, entity: SchemaEntity, required: tuple[str, ...]) -> None:
        for name in required:
            if name not in entity.attributes:
                self.refuse(entity, f"<{entity.tag}> is missing the required {self.word}"
                                    f" '{name}'")

    def actions(self, entities: tuple[SchemaEntity, ...]) -> None:
        for entity in entities:
            self.action(entity)

    def action(self, entity: SchemaEntity) -> None:
        spec = ACTIONS.get(entity.tag)
        if spec is None:
            self.unknown_action(entity)
            return
        self.missing(entity, spec.required)
        for name in _unread_attributes(entity, spec.attributes, self.xml):
            self.refuse(entity, f"<{entity.tag}> has the {self.word} '{name}' that launch does"
                                f" not accept{_hint(name, spec.attributes)}")
        for child in entity.children:
            nested = spec.child(child.tag)
            if nested is not None:
                self.nested(child, nested)
            elif spec.has_actions:
                self.action(child)
            else:
                names = frozenset(n for n, _ in spec.nested)
                self.refuse(child, f"<{entity.tag}> has the nested tag <{child.tag}> that"
                                   f" launch does not accept{_hint(child.tag, names)}")

    def nested(self, entity: SchemaEntity, spec: Nested) -> None:
        self.missing(entity, spec.required)
        if not spec.checked:
            return
        for name in _unread_attributes(entity, spec.attributes, self.xml):
            self.refuse(entity, f"<{entity.tag}> has the {self.word} '{name}' that launch does"
                                f" not accept{_hint(name, spec.attributes)}")
        for child in entity.children:
            inner = spec.child(child.tag)
            if inner is None:
                names = frozenset(n for n, _ in spec.nested)
                self.refuse(child, f"<{entity.tag}> has the nested tag <{child.tag}> that"
                                   f" launch does not accept{_hint(child.tag, names)}")
            else:
                self.nested(child, inner)

    def unknown_action(self, entity: SchemaEntity) -> None:
        known = frozenset(ACTIONS)
        hint = _hint(entity.tag, known)
        if hint or entity.tag in ROS1_TAGS or entity.tag.replace("-", "_") in known:
            self.refuse(entity, f"<{entity.tag}> is not an action launch or launch_ros"
                                f" knows{hint}")
            return
        # Another package may expose it (ros_gz's <gz_server>, ...): unknown, not refused.
        self.problems.append(SchemaProblem(
            entity.line, entity.column,
            f"<{entity.tag}> is not an action of launch or launch_ros; if no installed "
            f"package provides it, launch refuses the file; not followed",
            False,
        ))


def check_launch(children: tuple[SchemaEntity, ...], launch_format: str
                 ) -> tuple[SchemaProblem, ...]:
    """The schema problems of the actions under a ``<launch>`` root (``launch_format``
    ``xml`` or ``yaml``)."""
    checker = _Checker(launch_format)
    checker.actions(children)
    return tuple(checker.problems)
