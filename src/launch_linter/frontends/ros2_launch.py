"""Run ROS 2 launch actions statically and collect the static transforms they start.

This follows ``launch``/``launch_ros`` semantics: actions run in order against one set
of launch configurations; ``<group>`` (scoped by default) copies them and restores them
after, while ``<include>`` does not scope anything (configurations, environment and the
pushed ROS namespace set by an included file stay set after it, and those of the
includer are visible inside). ``<arg default=...>`` only sets a configuration that is not
set yet; ``<let>`` always sets it. A node's namespace is its own ``namespace`` under the
pushed ``ros_namespace`` configuration.

As in the ROS 1 loader, what launch would refuse becomes a ``roslaunch_error`` diagnostic
and the walk goes on; what cannot be known statically becomes a hole, and a transform that
depends on it stays in the output marked unresolved, with its presence condition. A value
set under a condition the linter cannot decide that outlives it (an include, an unscoped
group) becomes a hole.
"""

from __future__ import annotations

import os
from collections.abc import Callable
from typing import NamedTuple

from launch_linter.decode_ros2 import ComponentParam, Ros2Decoded, decode_component, decode_ros2
from launch_linter.frontends.known_launch import Started, started_by
from launch_linter.frontends.launchable import missing_executable
from launch_linter.frontends.node_names import unmatched_default_keys
from launch_linter.frontends.params import (
    CONTROLLER_MANAGER_NAME,
    EMBEDDED_COSTMAPS,
    MAX_PARAMS,
    SPAWNERS,
    PlacedDocument,
    ProcessParams,
    control_started,
    controllers_of,
    embedded_costmap,
    node_full_name,
    read_yaml_file_placed,
    ros2_file_params_and_misses,
    spawner_records,
)
from launch_linter.frontends.record import (
    Command,
    Reading,
    Site,
    transform_record,
    unresolved_message,
)
from launch_linter.frontends.robot.sources import (
    from_file_value,
    from_ros2_value,
    is_description_name,
)
from launch_linter.frontends.ros1 import LoadOptions
from launch_linter.frontends.ros2_actions import (
    STATIC_TF_EXECUTABLE,
    STATIC_TF_PACKAGE,
    Component,
    FileRead,
    Include,
    LoadComponents,
    Params,
    ParamsFile,
    ParamsUnknown,
    PushNamespace,
    RunNode,
    Uses,
    Where,
    is_literal,
)
from launch_linter.frontends.ros2_namespaces import MAX_REMAPPINGS, NamespaceWatch, tf_topic
from launch_linter.frontends.ros2_param_paths import (
    configurations_read,
    empty_defaults,
    given_at,
    reads_configuration,
)
from launch_linter.frontends.ros2_param_refusals import ParamFileChecks
from launch_linter.frontends.ros2_run import (
    MAX_ACTIONS_PER_TREE,
    MAX_FILES_PER_TREE,
    MAX_INCLUDE_DEPTH,
    NAMESPACE_KEY,
    STATIC_TF_PLUGIN,
    Ros2Runner,
    _Frame,
    _is_static_tf,
    _join_argv,
    _Scope,
    make_absolute,
    prefix_namespace,
)
from launch_linter.frontends.ros2_yaml import _yaml_is_string
from launch_linter.knowledge import bundled
from launch_linter.model.diagnostic import Location, Problem
from launch_linter.model.launch import (
    FileStatus,
    Forwarded,
    LaunchTree,
    UndeclaredUse,
    UnmatchedParamFile,
)
from launch_linter.model.record import replace
from launch_linter.model.robot import UNKNOWN_VALUE, NodeRecord
from launch_linter.model.transform import DECODED_FIELDS, ArgForm, Field
from launch_linter.resolve.ros2_substitution import Call, Subs, Text, parse, written
from launch_linter.resolve.value import Hole, Value, holes, is_resolved, resolved_text, text_of

MANY_NODE_PACKAGES = ("controller_manager", "rclcpp_components")
"""Packages whose processes run other nodes that take the same parameter files under their
own names (a controller manager's controllers, a container's components): a file none of
whose keys names the process's own node still reaches them."""


class _NodeParams(NamedTuple):
    """What :meth:`Ros2Loader._node_params` reads: the parameters in order (SetParameter's
    first), where each is written (``NodeRecord.param_lines``), why some are not read,
    the parameter files' documents, and what the node's process is given in order: a
    parameter file's document, or a dictionary's parameters (launch_ros writes each
    dictionary as a ``/**`` file: every node of the process gets it)."""

    params: tuple[tuple[str, str], ...]
    lines: tuple[tuple[str, str, int, int], ...]
    unread: tuple[str, ...]
    documents: list[object]
    process: list[object]
    placed: list[PlacedDocument]
    """The parameter files with where their keys are written (a controller's parameters
    placed at its section's keys)."""
    unmatched: tuple[tuple[str, tuple[tuple[str, int, int], ...]], ...] = ()
    """Each parameter file none of whose node keys matches the node (its shown path and
    node keys with their places), when its name and namespace are known."""
    files: tuple[str, ...] = ()
    """The parameter files read, shown."""


class Ros2Loader(Ros2Runner):
    """Loads one ROS 2 root file (and its includes) into a :class:`LaunchTree`."""

    def __init__(self, options: LoadOptions) -> None:
        super().__init__(options)
        self.knowledge = bundled() if options.knowledge is None else options.knowledge
        self.unmatched_param_files: list[UnmatchedParamFile] = []
        self.reached_param_files: set[str] = set()
        """Parameter files that some node of the tree takes (or may take) a section of."""
        self._root_file = ""
        self._judging_files = True
        """False while reading a file that a known launch file, not launch_ros, opens."""
        self.namespaces = NamespaceWatch()
        self._empty_defaults: dict[str, dict[str, Where]] = {}
        """The launch arguments each file read declares with an empty default."""
        self.spawned: tuple[str, ...] | None = ()
        self._param_files = ParamFileChecks(options.packages)

    def _tree(self, status: FileStatus, undeclared: tuple[UndeclaredUse, ...] = ()) -> LaunchTree:
        # A file that reaches another node it is given to was written for that one.
        unmatched = tuple(u for u in self.unmatched_param_files
                          if u.file not in self.reached_param_files)
        return replace(super()._tree(status, undeclared), unmatched_param_files=unmatched,
                       doubled_namespaces=self.namespaces.records(), spawned=self.spawned)

    def _push_namespace(self, action: PushNamespace, scope: _Scope, frame: _Frame) -> None:
        before = scope.configs.get(NAMESPACE_KEY)
        super()._push_namespace(action, scope, frame)
        after = scope.configs.get(NAMESPACE_KEY)
        self.namespaces.pushed(
            "/" if before is None else resolved_text(before),
            None if after is None else resolved_text(after),
            Location(self._display(action.where.path), action.where.line, action.where.column))

    # -- files -------------------------------------------------------------------------
    def load(self, path: str, data: bytes | None = None) -> LaunchTree:
        self._forget: list[Callable[[], None]] = []
        self._root_file = os.path.abspath(path)
        try:
            return super().load(path, data)
        finally:
            # The tree is read: no ``OpaqueFunction`` runs any more (``FileRead.forget``).
            # Emptied as it goes: an interpreter refers back to this loader.
            while self._forget:
                self._forget.pop()()

    def _read_file(self, absolute: str, data: bytes) -> FileRead:
        read = super()._read_file(absolute, data)
        if read.actions is not None:
            self._empty_defaults[absolute] = empty_defaults(read.actions)
        if read.forget is not None:
            self._forget.append(read.forget)
        return read

    # -- transforms --------------------------------------------------------------------
    def _namespace(self, subs: Subs | None, scope: _Scope, frame: _Frame, where: Where,
                   pushed: bool = True) -> tuple[str, tuple[Hole, ...]]:
        base = scope.configs.get(NAMESPACE_KEY) if pushed else None
        own = None if subs is None else self._resolve(subs, scope, frame, where)
        pending = (*holes(base or ()), *holes(own or ()))
        namespace = make_absolute(prefix_namespace(
            None if base is None else text_of(base), None if own is None else text_of(own)
        ))
        return (namespace or "/").replace("//", "/"), pending

    def _node(self, action: RunNode, scope: _Scope, frame: _Frame) -> None:
        if action.package is None or action.executable is None:
            return
        package = self._resolve(action.package, scope, frame, action.where)
        executable = self._resolve(action.executable, scope, frame, action.where)
        package_text = resolved_text(package)
        if package_text is not None:
            self._frame_node(action, scope, frame, package_text, resolved_text(executable))
            if (missing := missing_executable(self.options.packages, package_text,
                                              resolved_text(executable), self._display)):
                self._report(
                    "node_executable_missing", action.executable_at or action.where, missing)
        if not _is_static_tf(resolved_text(package), resolved_text(executable),
                             STATIC_TF_EXECUTABLE):
            return
        if action.arguments is None:
            values: list[Value] = []
            decoded = None
        else:
            values = [self._resolve(item, scope, frame, action.where) for item in action.arguments]
            items = tuple(text_of(value) for value in values)
            unresolved = frozenset(i for i, value in enumerate(values) if not is_resolved(value))
            decoded = decode_ros2(items, unresolved)
        self._emit(action.where, scope, frame, package, executable, action.name,
                   action.namespace, decoded, values, action.args_written, action.unknown,
                   pushed_namespace=action.pushed_namespace)

    def _frame_node(self, action: RunNode, scope: _Scope, frame: _Frame, package: str,
                    executable: str | None) -> None:
        """Keep a launched node with the parameters it is given (dictionaries and
        parameter files) and, for robot_state_publisher, its ``robot_description``; a
        controller manager's controllers are kept as nodes of their own."""
        where = action.where
        name_value = (None if action.name is None
                      else self._resolve(action.name, scope, frame, where))
        name = None if name_value is None else resolved_text(name_value)
        namespace, pending = self._namespace(action.namespace, scope, frame, where)
        known_namespace = None if pending else namespace
        # A controller manager without a name reads its file by its default name.
        section = (CONTROLLER_MANAGER_NAME if name is None and package == "controller_manager"
                   and executable == "ros2_control_node" else name)
        defaults = (self.knowledge.node_names(package, executable or "")
                    if name is None else ())
        given = self._node_params(action.parameters, scope, frame, where, section,
                                  known_namespace, defaults)
        described = False
        for group in action.parameters:
            if isinstance(group, Params):
                for key, subs in group.items:
                    if is_description_name(key.rsplit(".", 1)[-1]):
                        described = True
                        self._ros2_description(subs, scope, frame, where, name)
        if (package == "robot_state_publisher" and executable == "robot_state_publisher"
                and not described and not given.unread and action.arguments
                and not any(key == "robot_description" for key, _ in given.params)):
            self._description_argument(action.arguments[0], scope, frame, where, name)
        # SetParameter's parameters first: the node's own win over them.
        node = NodeRecord(
            self._display(frame.filename), where.line, where.column, package,
            executable or "", name, given.params, frame.condition,
            unread=given.unread, namespace=known_namespace, ros=2, param_lines=given.lines,
            included_at=frame.sites, remappings=None if action.remappings is None else tuple(
                (self._word(a, scope, frame, where), self._word(b, scope, frame, where))
                for a, b in action.remappings[:MAX_REMAPPINGS]),
            executable_line=0 if action.executable_at is None else action.executable_at.line)
        self.nodes.append(node)
        if frame.condition.always and self._judging_files:
            self.problems.extend(self._param_files.problems(node, section, given.placed, (
                lambda text: resolved_text(self._resolve(parse(text), scope, frame, where)))))
        if known_namespace is not None:
            self._watch_namespace(node, action, scope, frame)
        checked = ((name is not None or bool(defaults)) and not action.may_rename
                   and package not in MANY_NODE_PACKAGES
                   and (package, executable) not in EMBEDDED_COSTMAPS)
        self._unmatched(node, executable or "", given, checked,
                        is_literal(action.name) or bool(defaults), defaults)
        documents = given.documents
        costmap = embedded_costmap(node, given.process, scope.parameters)
        if costmap is not None:
            self.nodes.append(costmap)
        if package == "controller_manager" and documents:
            self.nodes.extend(controllers_of(node, documents, given.placed))
        if package == "controller_manager" and executable in SPAWNERS:
            self._spawned(node, action, scope, frame)

    def _watch_namespace(self, node: NodeRecord, action: RunNode, scope: _Scope,
                         frame: _Frame) -> None:
        """Tell the namespace watch where the node runs and its tf topic."""
        base = scope.configs.get(NAMESPACE_KEY)
        own = None if action.namespace is None else resolved_text(
            self._resolve(action.namespace, scope, frame, action.where))
        self.namespaces.node(
            node, "/" if base is None else resolved_text(base), own,
            f"{node.package}/{node.executable}",
            tf_topic(node.namespace or "/", node.remappings))

    def _word(self, subs: Subs, scope: _Scope, frame: _Frame, where: Where) -> str:
        """A name as the action gives it, ``UNKNOWN_VALUE`` when it is not resolved."""
        text = resolved_text(self._resolve(subs, scope, frame, where))
        return UNKNOWN_VALUE if text is None else text

    def _unmatched(self, node: NodeRecord, program: str, given: _NodeParams,
                   checked: bool, name_literal: bool, defaults: tuple[str, ...] = ()) -> None:
        """Keep the parameter files that give ``node`` nothing when its name as launched
        is known (``checked``); the others it is given reach it, or may."""
        missed = {shown for shown, _ in given.unmatched} if checked else set()
        self.reached_param_files.update(f for f in given.files if f not in missed)
        if not checked:
            return
        shown_node = ", ".join(node_full_name(name, node.namespace)
                               for name in (defaults or (node.name,)))
        for shown, keys in given.unmatched:
            self.unmatched_param_files.append(UnmatchedParamFile(
                node.path, node.line, node.column, node.condition, shown_node,
                node.package, program, shown, keys, name_literal, defaults))

    def _include(self, action: Include, scope: _Scope, frame: _Frame) -> None:
        """An include, its arguments kept as :class:`Forwarded` (marked not followed when
        its file was not read: then nothing after them was added)."""
        sites = {id(site) for site in self._included_at.values()}
        super()._include(action, scope, frame)
        # A file read is recorded with a new site: none new, the include was not followed.
        followed = any(id(site) not in sites for site in self._included_at.values())
        given: dict[str, str | None] = {}
        for name_subs, value_subs in action.args:
            name = resolved_text(self._resolve(name_subs, scope, frame, action.where))
            if name is not None:
                value = resolved_text(self._resolve(value_subs, scope, frame, action.where))
                given[name] = value
                self.forwarded.append(Forwarded(
                    name, "include", self._display(frame.filename), action.where.line,
                    action.where.column, frame.condition, value,
                    reads_configuration(value_subs, name), followed))
        if not followed and action.args_known:
            path = text_of(self._resolve(action.path, scope, frame, action.where))
            for started in started_by(path, 2, given, self.knowledge):
                self._started(started, scope, frame, action.where)

    def _started(self, started: Started, scope: _Scope, frame: _Frame, where: Where) -> None:
        """A known node that a launch file not followed starts (:mod:`.known_launch`), at
        the include, with the parameter file it is given read as that file gives it (the
        file's keys as written: nav2_bringup roots them at its namespace itself)."""
        # The launch file reads the file itself (nav2's RewrittenYaml), not launch_ros:
        # whether it is there is not this node's parameter-file question.
        self._judging_files = False
        try:
            given = self._node_params((ParamsFile((Text(started.parameter_file),)),),
                                      scope, frame, where, started.name, "/")
        finally:
            self._judging_files = True
        # nav2's RewrittenYaml may set a value to the launch argument's (Started.value).
        params = tuple((name, started.value(name, text)) for name, text in given.params)
        self.nodes.append(NodeRecord(
            self._display(frame.filename), where.line, where.column, started.package,
            started.executable, started.name, params, frame.condition,
            unread=given.unread, namespace=started.namespace, ros=2,
            param_lines=given.lines, included_at=frame.sites))

    def _description_argument(self, first: Subs, scope: _Scope, frame: _Frame, where: Where,
                              node: str | None) -> None:
        """robot_state_publisher without a ``robot_description`` parameter reads the URDF
        file its first argument names (``Node(arguments=[urdf])``, the Crystal to Eloquent
        way, still a fallback from Foxy to Rolling): ros/robot_state_publisher
        src/joint_state_listener.cpp 192-199 (dashing 64b5186), src/robot_state_publisher.cpp
        79-99 (foxy a1346e9) and 81-101 (humble 8b5af4f, rolling e0f77e6)."""
        path = self._resolve(first, scope, frame, where)
        self.descriptions.append(from_file_value(
            path, self._display(frame.filename), where.line, where.column, frame.condition,
            node, os.path.dirname(frame.filename)))

    def _spawned(self, spawner: NodeRecord, action: RunNode, scope: _Scope,
                 frame: _Frame) -> None:
        """The controllers a ``spawner`` loads (by name, and from its ``--param-file``s)."""
        words = None if action.arguments is None else [
            resolved_text(self._resolve(item, scope, frame, action.where))
            for item in action.arguments]
        records, names = spawner_records(spawner, words)
        self.nodes.extend(records)
        self.spawned = None if names is None or self.spawned is None else self.spawned + names

    def _uses(self, action: RunNode | LoadComponents | Uses, scope: _Scope, frame: _Frame
              ) -> None:
        super()._uses(action, scope, frame)  # and what ros2 control activates, as a spawner
        if isinstance(action, Uses) and action.controls is not None:
            names = control_started([resolved_text(self._resolve(w, scope, frame, action.where))
                                     for w in action.controls])
            self.spawned = None if names is None or self.spawned is None else self.spawned + names

    def _node_params(self, groups: tuple[Params | ParamsFile | ParamsUnknown, ...],
                     scope: _Scope, frame: _Frame, where: Where, name: str | None,
                     namespace: str | None, defaults: tuple[str, ...] = ()) -> _NodeParams:
        """The parameters a node is given (dictionaries and parameter files, in order),
        where each is written, why some are not read, and the parameter files' documents.
        A value's place: its dictionary key, its file's key (PyYAML's marks), else the
        node's element (SetParameter's, those of a file without marks)."""
        node_place = (self._display(frame.filename), where.line, where.column)
        params: list[tuple[str, str]] = []
        places: list[tuple[str, int, int]] = [node_place] * len(scope.parameters)
        unread: list[str] = []
        documents: list[object] = []
        placed: list[PlacedDocument] = []
        process: list[object] = []
        unmatched: list[tuple[str, tuple[tuple[str, int, int], ...]]] = []
        files: list[str] = []
        for group in groups:
            if isinstance(group, ParamsUnknown):
                unread.append(group.reason)
            elif isinstance(group, ParamsFile):
                path_value = self._resolve(group.path, scope, frame, where)
                path = resolved_text(path_value)
                if group.substitutions:
                    self.arguments.parameter_file(path)
                if path is None:
                    unread.append(f"parameter file {text_of(path_value)!r} is not resolved")
                    continue
                if not path:
                    unread.append(self._empty_param_file(group.path, frame, where))
                    continue
                document, why, keys = read_yaml_file_placed(path)
                if why is not None:
                    self._absent_param_file(path, frame, where, group.path)
                    unread.append(why)
                    continue
                documents.append(document)
                process.append(document)
                shown = self._display(path)
                placed.append(PlacedDocument(document, shown, keys, group.substitutions))
                files.append(shown)
                from_file, missed = ros2_file_params_and_misses(document, name, namespace)
                others = (None if namespace is None
                          else missed if name
                          else unmatched_default_keys(document, defaults, namespace)
                          if defaults else None)
                if others is not None:
                    unmatched.append((shown, tuple(
                        ("/".join(at), *keys.get(at, (0, 0))) for _, at in others)))
                for key, value, at in from_file:
                    params.append((key, value))
                    line_column = keys.get(at)
                    places.append(node_place if line_column is None
                                  else (shown, line_column[0], line_column[1]))
            else:
                dictionary: list[tuple[str, str]] = []
                for index, (key, subs) in enumerate(group.items):
                    if is_description_name(key.rsplit(".", 1)[-1]):
                        continue
                    text = resolved_text(self._resolve(subs, scope, frame, where))
                    params.append((key, UNKNOWN_VALUE if text is None else text))
                    dictionary.append(params[-1])
                    place = group.places[index] if index < len(group.places) else None
                    places.append(node_place if place is None else
                                  (self._display(place.path), place.line, place.column))
                    if reads_configuration(subs, key):
                        self.forwarded.append(Forwarded(key, "parameter", *places[-1],
                                                        frame.condition))
                process.append(ProcessParams(tuple(dictionary)))
        own = params[:MAX_PARAMS]
        given = tuple(scope.parameters) + tuple(own)
        lines = tuple((key, *place) for (key, _), place in zip(given, places))
        return _NodeParams(given, lines, tuple(unread), documents, process, placed,
                           tuple(unmatched), tuple(files))

    def _empty_param_file(self, path: Subs, frame: _Frame, where: Where) -> str:
        """Report a parameter-file path that resolves to empty (launch_ros leaves it out of
        the node's parameters: :mod:`.ros2_param_paths`); the reason it is unread."""
        calls = configurations_read(path)
        names = [written(call.args[0]) for call in calls]
        at = next((call.at for call in calls if call.at is not None), None)
        place = Where(frame.filename, *at) if at is not None else where
        shown = " and ".join(f"launch argument {n!r}" for n in dict.fromkeys(names)) \
            or "its text"
        roots = self._empty_defaults.get(self._root_file, {})
        left_to_user = [n for n in names if n in roots and n not in self.options.args]
        node = Location(self._display(frame.filename), where.line, where.column)
        if left_to_user or not frame.condition.always:
            why = (f"the root file's launch argument {left_to_user[0]!r} is left at its empty "
                   f"default, usually given on the command line" if left_to_user
                   else "the node runs under a condition")
            self._report("unresolved", place, f"parameter file path is empty ({shown}), so "
                         f"launch_ros would leave it out of the node's parameters; not "
                         f"decided: {why}")
        else:
            declared = self._empty_defaults.get(frame.filename, {})
            related = tuple(Location(self._display(d.path), d.line, d.column)
                            for d in (declared.get(n) for n in dict.fromkeys(names)) if d)
            self.problems.append(Problem(
                "ros2_param_file_missing", self._display(place.path), place.line,
                place.column, f"parameter file path is empty ({shown} at an empty value): "
                f"launch_ros leaves a path that is not a file out of the node's parameters "
                f"('Parameter file path is not a file'), so the node starts without them",
                related=(node, *related)))
        return f"parameter file path {written(path)!r} is empty"

    def _absent_param_file(self, path: str, frame: _Frame, where: Where, subs: Subs) -> None:
        """Report a provably absent parameter file (where the node's call reads it)."""
        if not os.path.isabs(path) or not frame.condition.always or not self._judging_files:
            return
        located = self.options.packages.locate(path, os.path.dirname(frame.filename), 2)
        if not located.absent:
            return
        node = Location(self._display(frame.filename), where.line, where.column)
        self.problems.append(Problem(
            "ros2_param_file_missing", node.path,
            *((at := given_at(subs, where)) or (where.line, where.column)),
            f"parameter file {self._quoted(path)!r} does not exist ({located.reason}): "
            f"launch_ros leaves a path that is not a file out of the node's parameters "
            f"('Parameter file path is not a file'), so the node starts without them",
            related=(node,) if at else ()))

    def _ros2_description(self, subs: Subs, scope: _Scope, frame: _Frame, where: Where,
                          node: str | None) -> None:
        command = None
        for sub in subs:
            if isinstance(sub, Call) and sub.name == "command" and sub.args:
                command = self._resolve(sub.args[0], scope, frame, where)
                break
            if (len(subs) == 1 and isinstance(sub, Call) and sub.name == "var"
                    and len(sub.args) == 1):
                # $(var x) of a <let> whose value is a command's output: that command.
                name = resolved_text(self._resolve(sub.args[0], scope, frame, where))
                command = None if name is None else scope.commands.get(name)
            if isinstance(sub, Call) and sub.name == "file-content" and sub.args:
                # open(path).read() or $(file-content path): a URDF file read as it is.
                path = self._resolve(sub.args[0], scope, frame, where)
                self.descriptions.append(replace(from_file_value(
                    path, self._display(frame.filename), where.line, where.column,
                    frame.condition, node, os.path.dirname(frame.filename)),
                    included_at=frame.sites))
                return
        value = self._resolve(subs, scope, frame, where) if command is None else ()
        source = from_ros2_value(value, command, self._display(frame.filename), where.line,
                                 where.column, frame.condition, node)
        if source is not None:
            self.descriptions.append(replace(source, included_at=frame.sites))

    def _component(self, component: Component, scope: _Scope, frame: _Frame) -> None:
        own = self._condition(component.condition, scope, frame, component.where)
        if own is None or component.package is None or component.plugin is None:
            return
        here = replace(frame, condition=frame.condition & own)
        for subs in component.uses:
            self._resolve(subs, scope, here, component.where)
        package = self._resolve(component.package, scope, here, component.where)
        plugin = self._resolve(component.plugin, scope, here, component.where)
        package_text, plugin_text = resolved_text(package), resolved_text(plugin)
        if package_text is not None and plugin_text is not None:
            name_value = (None if component.name is None
                          else self._resolve(component.name, scope, here, component.where))
            name = None if name_value is None else resolved_text(name_value)
            namespace, pending = self._namespace(component.namespace, scope, here,
                                                 component.where)
            given = self._node_params(component.parameters, scope, here, component.where,
                                      name, None if pending else namespace)
            self.nodes.append(NodeRecord(
                self._display(here.filename), component.where.line, component.where.column,
                package_text, "", name, given.params, here.condition,
                plugin=plugin_text, unread=given.unread,
                namespace=None if pending else namespace, ros=2, param_lines=given.lines,
                included_at=here.sites))
            self._unmatched(self.nodes[-1], plugin_text, given, name is not None,
                            is_literal(component.name))
        if not _is_static_tf(resolved_text(package), resolved_text(plugin), STATIC_TF_PLUGIN):
            return
        params: dict[str, ComponentParam] = {}
        values: dict[str, Value] = {}
        unknown: list[str] = []
        for source in component.parameters:
            if not isinstance(source, Params):
                unknown.append(source.reason if isinstance(source, ParamsUnknown)
                               else "parameters from a file")
                continue
            for name, subs in source.items:
                value = self._resolve(subs, scope, here, component.where)
                text = text_of(value)
                params[name] = ComponentParam(text, _yaml_is_string(text), is_resolved(value))
                values[name] = value
        decoded = decode_component(params, complete=not unknown)
        self._emit(component.where, scope, here, package, plugin, component.name,
                   component.namespace, decoded, list(values.values()), "",
                   "; ".join(unknown), argv=[f"{n}:={p.text}" for n, p in params.items()])

    def _emit(self, where: Where, scope: _Scope, frame: _Frame, package: Value,
              executable: Value, name_subs: Subs | None, namespace_subs: Subs | None,
              decoded: Ros2Decoded | None, values: list[Value], args_written: str,
              unknown: str, argv: list[str] | None = None, pushed_namespace: bool = True
              ) -> None:
        name_value = None if name_subs is None else self._resolve(name_subs, scope, frame, where)
        name = None if name_value is None else text_of(name_value) or None
        if name is not None and name_value is not None and is_resolved(name_value) and (
            "/" in name
        ):
            self._report("roslaunch_error", where,
                         f"node name cannot contain a namespace: {name}", node=name)
        namespace, namespace_holes = self._namespace(namespace_subs, scope, frame, where,
                                                     pushed_namespace)
        unresolved: set[Field] = set()
        if name_value is not None and not is_resolved(name_value):
            unresolved.add(Field.NAME)
        if namespace_holes:
            unresolved.add(Field.NAMESPACE)
        if not is_resolved(package):
            unresolved.add(Field.PACKAGE)
        if not is_resolved(executable):
            unresolved.add(Field.EXECUTABLE)
        if decoded is None:
            unresolved.update((*DECODED_FIELDS, Field.ARITY))
        else:
            unresolved.update(decoded.unresolved)
        all_holes = (*holes(name_value or ()), *namespace_holes, *holes(package),
                     *holes(executable), *(h for value in values for h in holes(value)))
        reasons = [f"{h.text}: {h.reason}" for h in all_holes]
        if unknown:
            reasons.append(unknown)
        reasons = list(dict.fromkeys(reasons))
        known = decoded is not None and decoded.form is not ArgForm.INVALID
        site = Site(self._display(frame.filename), where.line, where.column,
                    self.root_display, frame.included_from, frame.condition)
        command = Command(
            name, namespace, text_of(package), text_of(executable), args_written,
            " ".join(argv) if argv is not None else _join_argv(values),
            tuple(argv) if argv is not None else tuple(text_of(v) for v in values),
        )
        reading = Reading(ArgForm.UNKNOWN)
        if decoded is not None:
            reading = Reading(
                decoded.form, decoded.parent, decoded.child,
                decoded.translation if known else None, decoded.rotation if known else None,
                None, decoded.arity_issue, decoded.number_issues, decoded.arg_issues,
            )
        transform = transform_record(site, command, reading, unresolved, reasons,
                                     ros_version=2, launch_format=frame.launch_format)
        self.transforms.append(transform)
        if transform.unresolved:
            self._report("unresolved", where, unresolved_message(transform), node=name)


__all__ = [
    "MAX_ACTIONS_PER_TREE",
    "MAX_FILES_PER_TREE",
    "MAX_INCLUDE_DEPTH",
    "NAMESPACE_KEY",
    "STATIC_TF_EXECUTABLE",
    "STATIC_TF_PACKAGE",
    "STATIC_TF_PLUGIN",
    "Ros2Loader",
    "make_absolute",
    "prefix_namespace",
]
