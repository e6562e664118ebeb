"""Running ROS 2 launch actions in order, with launch's rules: scopes of launch
configurations and environment, conditions, namespaces pushed, groups and includes. The
actions that start nodes are :mod:`.ros2_launch`'s."""

from __future__ import annotations

import os
import shlex
import typing
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

from launch_linter.frontends.ros1 import LoadOptions
from launch_linter.frontends.ros2_actions import (
    STATIC_TF_PACKAGE,
    Action,
    Component,
    DeclareArg,
    Deferred,
    FileRead,
    Group,
    Include,
    LoadComponents,
    Predicate,
    PushNamespace,
    RunNode,
    SetEnv,
    SetVar,
    Unfollowed,
    Uses,
    Where,
)
from launch_linter.frontends.ros2_declared import Declarations
from launch_linter.frontends.ros2_include import (
    environment_names,
    find_included,
    required_arguments,
)
from launch_linter.frontends.ros2_include_args import ArgumentWatch
from launch_linter.frontends.ros2_python import read_python
from launch_linter.frontends.ros2_xml import read_xml
from launch_linter.frontends.ros2_yaml import read_yaml
from launch_linter.frontends.xml_dialect import reads_as_python
from launch_linter.model.budget import Budget, BudgetExceeded
from launch_linter.model.diagnostic import Location, Problem
from launch_linter.model.included import through_include
from launch_linter.model.launch import (
    Comment,
    FileStatus,
    Forwarded,
    LaunchTree,
    UndeclaredUse,
    holds_directive,
)
from launch_linter.model.record import replace
from launch_linter.model.robot import UNKNOWN_VALUE, DescriptionSource, NodeRecord
from launch_linter.model.transform import (
    ALWAYS,
    Condition,
    ConditionLiteral,
    LaunchFormat,
    StaticTransform,
)
from launch_linter.resolve.ros2_substitution import (
    Call,
    Ros2Scope,
    Subs,
    SubstitutionError,
    resolve,
    to_bool,
    written,
)
from launch_linter.resolve.value import (
    Hole,
    Value,
    holes,
    is_resolved,
    resolved_text,
    shown_value,
    text_of,
    why_unresolved,
)
from launch_linter.resolve.xml_safe import read_launch_bytes

STATIC_TF_PLUGIN = "tf2_ros::StaticTransformBroadcasterNode"
MAX_INCLUDE_DEPTH = 32
MAX_FILES_PER_TREE = 2_000
MAX_ACTIONS_PER_TREE = 200_000
NAMESPACE_KEY = "ros_namespace"
"""The launch configuration in which ``push_ros_namespace`` keeps the namespace."""

@dataclass
class _Scope:
    """Launch configurations and environment, shared by everything that runs in it."""

    configs: dict[str, Value]
    env: dict[str, str]
    condition: Condition
    """The presence condition under which this scope was opened."""
    resolvers: dict[str, Ros2Scope] = field(default_factory=dict)
    """What substitutions see here, by the file being run: made once, not per value."""
    parameters: list[tuple[str, str]] = field(default_factory=list)
    """What ``SetParameter`` gives every node launched after it here (a value under an
    unresolved condition is unknown)."""
    commands: dict[str, Value] = field(default_factory=dict)
    """The program a configuration's value is the output of (``<let name="x"
    value="$(command 'xacro ...')"/>``): the command line, resolved where the ``let`` ran,
    so that a robot description read through ``$(var x)`` is read as that xacro call."""

    def copy(self, condition: Condition) -> _Scope:
        return _Scope(dict(self.configs), dict(self.env), condition,
                      parameters=list(self.parameters), commands=dict(self.commands))


IncludeCall = typing.Tuple[str, typing.Tuple[typing.Tuple[str, str], ...]]
"""An included file and the values of the arguments it is given (as written if unknown)."""


@dataclass(frozen=True)
class _Frame:
    """Where the actions being run come from."""

    filename: str
    launch_format: LaunchFormat
    chain: tuple[str, ...]
    included_from: tuple[str, int] | None
    condition: Condition
    calls: tuple[IncludeCall, ...] = ()
    """(file, values of the arguments it was given) of each include on the way here."""
    sites: tuple[Location, ...] = ()
    """The include actions on the way here, from the root's: two runs of one file through
    different includes are two instances (``NodeRecord.included_at``)."""


@dataclass
class _Budget:
    actions: int = 0
    anon: dict[str, str] = field(default_factory=dict)


def prefix_namespace(base: str | None, namespace: str | None) -> str | None:
    """launch_ros's rule: a relative namespace goes under the pushed one."""
    if base is None:
        return namespace
    if namespace is None:
        return base
    if namespace.startswith("/"):
        return namespace
    return base.rstrip("/") + "/" + namespace if namespace else base


def make_absolute(namespace: str | None) -> str | None:
    if namespace is None or namespace.startswith("/"):
        return namespace
    return "/" + namespace


def _join_argv(values: list[Value]) -> str:
    """The argv items as one line: resolved items quoted as a shell would need."""
    return " ".join(
        shlex.quote(text_of(value)) if is_resolved(value) else text_of(value) for value in values
    )


def _is_static_tf(package: str | None, executable: str | None, wanted: str) -> bool:
    """A static transform publisher, or possibly one when a value is unresolved."""
    if executable is not None and executable != wanted:
        return False
    if package is not None and package != STATIC_TF_PACKAGE:
        return False
    return executable is not None or package is not None


class Ros2Runner:
    """Runs the actions of one root file (and its includes) in order."""

    def __init__(self, options: LoadOptions) -> None:
        self.options = options
        self.transforms: list[StaticTransform] = []
        self.problems: list[Problem] = []
        self.files: list[str] = []
        self.comments: list[Comment] = []
        self.element_lines: list[tuple[str, int]] = []
        self.descriptions: list[DescriptionSource] = []
        self.nodes: list[NodeRecord] = []
        self.forwarded: list[Forwarded] = []
        self.budget = _Budget()
        self.work = Budget()
        self._where: Where | None = None
        """The action being run (where the work budget ran out, if it does)."""
        self.root_display = ""
        self._displayed: dict[str, str] = {}
        self.declarations = Declarations()
        self.arguments = ArgumentWatch(self.declarations)
        self._reading: tuple[Where, _Frame] | None = None
        """Where the value being resolved is read (for the launch configurations it reads)."""
        self._included_at: dict[str, Location] = {}
        """The include being run for each included file (its place)."""
        self.include_sites: dict[str, Location] = {}
        """Each included file's first include, by the file's shown path."""
        self._reported_included: set[tuple[str, str, int, int, str]] = set()

    # -- diagnostics -------------------------------------------------------------------
    def _display(self, path: str) -> str:
        # Every record and problem of a file names it: worked out once per path.
        shown = self._displayed.get(path)
        if shown is None:
            shown = self._displayed[path] = self.options.display_path(path)
        return shown

    def _quoted(self, path: str) -> str:
        """A path a message quotes, shown as the report shows file paths (an empty
        one as it is)."""
        return self._display(path) if path else path

    def _report(self, rule: str, where: Where, message: str, node: str | None = None) -> None:
        problem = Problem(rule, self._display(where.path), where.line, where.column, message,
                          node)
        site = self._included_at.get(where.path) if rule == "unresolved" else None
        if site is not None:
            # Once per cause and place in a tree, naming the first include that reached it.
            key = (rule, where.path, where.line, where.column, message)
            if key in self._reported_included:
                return
            self._reported_included.add(key)
            problem = through_include(problem, site)
        self.problems.append(problem)

    # -- files -------------------------------------------------------------------------
    def load(self, path: str, data: bytes | None = None) -> LaunchTree:
        absolute = os.path.abspath(path)
        self.root_display = self._display(absolute)
        if data is None:
            try:
                data = read_launch_bytes(absolute)
            except OSError as exc:
                if self.root_display not in self.files:
                    self.files.append(self.root_display)
                self._report("parse_error", Where(absolute, 1, 1),
                             f"cannot read file: {exc.strerror or exc}")
                return self._tree(FileStatus.UNREADABLE)
        try:
            read = self._read_file(absolute, data)
            if read.actions is None:
                return self._tree(FileStatus.PARSE_ERROR)
            configs: dict[str, Value] = {
                name: (value,) if value else () for name, value in self.options.args.items()
            }
            scope = _Scope(configs, dict(self.options.env), Condition())
            frame = _Frame(absolute, read.launch_format, (absolute,), None, Condition(),
                           ((absolute, ()),))
            self._run(read.actions, scope, frame)
        except BudgetExceeded as exc:
            self.arguments.abandon()
            self._report("unresolved", self._where or Where(absolute, 1, 1),
                         exc.message)
            self.declarations.opened("the launch was followed only in part")
        self.problems.extend(self.arguments.problems())
        return self._tree(FileStatus.OK,
                          self.declarations.facts(absolute, self._display, self.root_display))

    def _tree(self, status: FileStatus, undeclared: tuple[UndeclaredUse, ...] = ()
              ) -> LaunchTree:
        return LaunchTree(
            root=self.root_display,
            status=status,
            transforms=tuple(self.transforms),
            # An attribute resolved twice (a node's name, then its other substitutions)
            # reports what launch refuses in it once.
            problems=tuple(dict.fromkeys(self.problems)),
            files=tuple(self.files),
            comments=tuple(self.comments),
            element_lines=tuple(self.element_lines),
            descriptions=tuple(self.descriptions),
            nodes=tuple(self.nodes),
            undeclared=undeclared,
            forwarded=tuple(self.forwarded),
        )

    # -- launch configurations read but never declared -----------------------------------
    def _missing(self, name: str, at: tuple[int, int] | None) -> None:
        """``resolve`` read ``name`` without a default where it is not set; ``at``, where
        the read is written when the front-end knows it (the ``LaunchConfiguration`` call
        that names it), else the action's place."""
        if self._reading is not None:
            where, frame = self._reading
            if at is not None:
                where = Where(where.path, at[0], at[1])
            self.declarations.read_unset(name, where, bool(frame.condition.literals))

    def _read_file(self, absolute: str, data: bytes) -> FileRead:
        display = self._display(absolute)
        if display not in self.files:
            self.files.append(display)
        if reads_as_python(absolute, data):
            # __file__ is where the launch file runs from: its installed place.
            read = read_python(absolute, data, self.work, self.options.env,
                               lambda: self.options.packages.installed(absolute))
        elif absolute.endswith((".yaml", ".yml")):
            read = read_yaml(absolute, data)
        else:
            read = read_xml(absolute, data)
        if holds_directive(read.comments):
            self.comments.extend(Comment(display, line, text) for line, text in read.comments)
            self.element_lines.extend((display, line) for line in read.element_lines)
        for problem in read.problems:
            self._report(problem.rule, Where(absolute, problem.line, problem.column),
                         problem.message)
        return read

    # -- resolution --------------------------------------------------------------------
    def _anonymous(self, name: str) -> str:
        anon = self.budget.anon
        if name not in anon:
            anon[name] = f"{name}_anon{len(anon) + 1}"
        return anon[name]

    def _substitution_scope(self, scope: _Scope, frame: _Frame) -> Ros2Scope:
        made = scope.resolvers.get(frame.filename)
        # The scope's own mappings, read when a value is resolved: one Ros2Scope serves
        # every value resolved in this scope and file (unless a mapping was replaced).
        if made is None or made.configs is not scope.configs or made.env is not scope.env:
            made = Ros2Scope(scope.configs, scope.env, self.options.packages.find,
                             self._anonymous, frame.filename, self.work, self._missing,
                             self.arguments.read)
            scope.resolvers[frame.filename] = made
        return made

    def _resolve(self, subs: Subs, scope: _Scope, frame: _Frame, where: Where) -> Value:
        self._reading = (where, frame)
        try:
            return resolve(subs, self._substitution_scope(scope, frame))
        except SubstitutionError as exc:
            self._report("roslaunch_error", where, str(exc))
            return (Hole(written(subs), str(exc)),)

    def _condition(self, predicate: Predicate | None, scope: _Scope, frame: _Frame,
                   where: Where) -> Condition | None:
        """The action's own presence condition; None when it is skipped."""
        if predicate is None:
            return ALWAYS
        value = self._resolve(predicate.expression, scope, frame, where)
        try:
            truth = to_bool(value)
        except ValueError as exc:
            self._report("roslaunch_error", where, f"{'if' if predicate.positive else 'unless'}:"
                         f" {exc}")
            truth = None
        if truth is None:
            return Condition((ConditionLiteral(text_of(value), predicate.positive),))
        return Condition() if truth == predicate.positive else None

    @staticmethod
    def _certain(scope: _Scope, condition: Condition) -> bool:
        """Whether an effect under ``condition`` holds wherever ``scope`` is seen."""
        return all(literal in scope.condition.literals for literal in condition.literals)

    def _set(self, scope: _Scope, name: str, value: Value, condition: Condition,
             written: str) -> None:
        if not self._certain(scope, condition):
            value = (Hole(written, f"'{name}' is set under an unresolved condition"),)
        scope.configs[name] = value
        scope.commands.pop(name, None)

    # -- actions -----------------------------------------------------------------------
    def _run(self, actions: tuple[Action, ...] | list[Action], scope: _Scope, frame: _Frame
             ) -> None:
        step = self.work.step
        for action in actions:
            step()
            self._where = action.where
            self.budget.actions += 1
            if self.budget.actions > MAX_ACTIONS_PER_TREE:
                self._report("roslaunch_error", action.where,
                             f"more than {MAX_ACTIONS_PER_TREE} launch actions; not followed")
                return
            self._run_one(action, scope, frame)

    def _run_one(self, action: Action, scope: _Scope, frame: _Frame) -> None:
        if isinstance(action, Unfollowed):
            self._report(action.rule, action.where, action.reason)
            self.declarations.opened(action.reason, action.rule)
            return
        self.declarations.declares(action)
        self.arguments.declares(action)
        own = self._condition(action.condition, scope, frame, action.where)
        if own is None:
            self.arguments.skipped(action)
            return
        # Most actions have no condition of their own: they run in the frame as it is.
        here = frame if not own.literals else replace(frame, condition=frame.condition & own)
        handler = _ACTIONS.get(type(action))
        if handler is not None:
            handler(self, action, scope, here)

    def _uses(self, action: RunNode | LoadComponents | Uses, scope: _Scope, frame: _Frame
              ) -> None:
        """Resolve what the action performs, for the launch configurations it reads; a
        ``SetParameter`` gives its parameter to the nodes launched after it."""
        for subs in action.uses:
            self._resolve(subs, scope, frame, action.where)
        if isinstance(action, Uses) and action.parameter is not None:
            name = resolved_text(self._resolve(action.parameter[0], scope, frame,
                                               action.where))
            value = resolved_text(self._resolve(action.parameter[1], scope, frame,
                                                action.where))
            if name is not None:
                certain = value is not None and self._certain(scope, frame.condition)
                scope.parameters.append((name, value if certain and value is not None
                                         else UNKNOWN_VALUE))

    def _components(self, action: LoadComponents, scope: _Scope, frame: _Frame) -> None:
        self._uses(action, scope, frame)
        for component in action.components:
            self._component(component, scope, frame)

    def _deferred(self, action: Deferred, scope: _Scope, frame: _Frame) -> None:
        expanded = action.expand(lambda subs: self._resolve(subs, scope, frame, action.where))
        self._run(list(expanded), scope, frame)

    def _name(self, subs: Subs, scope: _Scope, frame: _Frame, where: Where, what: str
              ) -> str | None:
        value = self._resolve(subs, scope, frame, where)
        name = resolved_text(value)
        if name is None:
            reasons = "; ".join(f"{h.text}: {h.reason}" for h in holes(value))
            self._report("unresolved", where, f"{what} {text_of(value)!r} is unresolved: {reasons}")
        return name

    def _declare(self, action: DeclareArg, scope: _Scope, frame: _Frame) -> None:
        name = self._name(action.name, scope, frame, action.where, "argument name")
        if name is None or name in scope.configs or action.default is None:
            return
        default = self._resolve(action.default, scope, frame, action.where)
        self._set(scope, name, default, frame.condition, f"$(var {name})")

    def _let(self, action: SetVar, scope: _Scope, frame: _Frame) -> None:
        name = self._name(action.name, scope, frame, action.where, "configuration name")
        if name is None:
            return
        if action.value is None:
            scope.configs.pop(name, None)
            return
        value = self._resolve(action.value, scope, frame, action.where)
        self._set(scope, name, value, frame.condition, f"$(var {name})")
        command = action.value[0] if len(action.value) == 1 else None
        if (isinstance(command, Call) and command.name == "command" and command.args
                and self._certain(scope, frame.condition)):
            scope.commands[name] = self._resolve(command.args[0], scope, frame, action.where)

    def _set_env(self, action: SetEnv, scope: _Scope, frame: _Frame) -> None:
        name = self._name(action.name, scope, frame, action.where, "environment variable")
        if name is None:
            return
        if action.value is None:
            scope.env.pop(name, None)
            return
        value = self._resolve(action.value, scope, frame, action.where)
        text = resolved_text(value)
        # The environment holds text only: an unknown value makes the variable unknown.
        if text is None or not self._certain(scope, frame.condition):
            scope.env.pop(name, None)
        else:
            scope.env[name] = text

    def _push_namespace(self, action: PushNamespace, scope: _Scope, frame: _Frame) -> None:
        pushed = self._resolve(action.namespace, scope, frame, action.where)
        previous = scope.configs.get(NAMESPACE_KEY)
        if not is_resolved(pushed) or (previous is not None and not is_resolved(previous)):
            reasons = "; ".join(
                f"{h.text}: {h.reason}" for h in (*holes(pushed), *holes(previous or ()))
            )
            self._set(scope, NAMESPACE_KEY, (Hole(text_of(pushed), reasons),), frame.condition,
                      "push_ros_namespace")
            return
        namespace = make_absolute(prefix_namespace(
            None if previous is None else text_of(previous), text_of(pushed)
        ))
        self._set(scope, NAMESPACE_KEY, (namespace or "/",), frame.condition,
                  "push_ros_namespace")

    def _flag(self, value: Subs | bool, scope: _Scope, frame: _Frame, where: Where,
              attribute: str) -> bool:
        if isinstance(value, bool):
            return value
        resolved = self._resolve(value, scope, frame, where)
        text = (resolved_text(resolved) or "").strip().lower()
        if text not in ("true", "false"):
            self._report("roslaunch_error", where,
                         f"{attribute}: {text_of(resolved)!r} is not 'true' or 'false'")
            return True
        return text == "true"

    def _group(self, action: Group, scope: _Scope, frame: _Frame) -> None:
        scoped = self._flag(action.scoped, scope, frame, action.where, "scoped")
        forwarding = self._flag(action.forwarding, scope, frame, action.where, "forwarding")
        if not scoped:
            self._run(action.actions, scope, frame)
            return
        inner = scope.copy(frame.condition)
        if not forwarding:
            inner.configs = {}
        self._run(action.actions, inner, frame)

    def _include(self, action: Include, scope: _Scope, frame: _Frame) -> None:
        path_value = self._resolve(action.path, scope, frame, action.where)
        passed: dict[str, tuple[int, int]] = {}  # where each is given, by name
        given_values: list[tuple[str, Value]] = []
        if not action.args_known:
            self.declarations.opened(
                f"line {action.where.line}: the arguments of an include are unknown")
        places = action.arg_places or ((0, 0),) * len(action.args)
        for (name_subs, value_subs), place in zip(action.args, places):
            name = self._name(name_subs, scope, frame, action.where, "include argument")
            if name is None:
                self.declarations.opened(f"line {action.where.line}: an include argument's name is "
                             f"unresolved")
                continue
            # Passed from here on (the include is not scoped): reads before it still fail,
            # like the read of this very value, which launch performs before setting it.
            passed[name] = place
            value = self._resolve(value_subs, scope, frame, action.where)
            given_values.append((name, value))
            self._set(scope, name, value, frame.condition, f"$(var {name})")
        given = tuple(sorted((name, text_of(value)) for name, value in given_values))
        known = all(is_resolved(value) for _, value in given_values)
        path = resolved_text(path_value)
        if path is None:
            reasons = why_unresolved(path_value, quoted=True)
            self._report("unresolved", action.where,
                         f"include file {shown_value(path_value)!r} not followed: {reasons}")
            self.declarations.opened(f"line {action.where.line}: an include is not followed")
            return
        absolute, located = find_included(path, frame.filename, self.options.packages)
        if absolute is None:
            shown = path if path.startswith("~") else self._quoted(path)
            if path.startswith("~") and not self.options.study_errors:
                # os.path.expanduser('~') is the launching user's home: not knowable here.
                self._report("unresolved", action.where, f"include file {shown!r} not followed: "
                             f"it is under the user's home directory, which depends on the machine")
                self.declarations.opened(f"line {action.where.line}: an include is not followed")
                return
            variables = [v for v in environment_names(action.path) if v not in scope.env]
            if variables and not self.options.study_errors:
                # os.getenv('TEST_LAUNCH_DIR', '') is set by whoever runs the file.
                self._report("unresolved", action.where, f"include file {shown!r} not followed: "
                             f"it depends on the environment ({', '.join(variables)}; give "
                             f"them with --env)")
                self.declarations.opened(f"line {action.where.line}: an include is not followed")
                return
            if located is not None and not located.absent and not self.options.study_errors:
                self._report("unresolved", action.where,
                             f"include file {shown!r} not followed: {located.reason}")
                self.declarations.opened(f"line {action.where.line}: an include is not followed")
                return
            self._report("roslaunch_error", action.where, f"included file not found: {shown}")
            self.declarations.opened(f"line {action.where.line}: an include is not followed")
            return
        call = (absolute, given)
        if call in frame.calls:
            # A cycle is the same file given the same argument values under a condition that
            # held; a recursion that changes its arguments ends when its condition turns
            # false, and one whose values or condition are unknown may end too.
            cycle = " -> ".join(self._display(p) for p in (*frame.chain, absolute))
            if known and frame.condition.always:
                self._report("roslaunch_error", action.where, f"include cycle: {cycle}")
            else:
                self._report("unresolved", action.where,
                             f"include of {self._display(absolute)} repeats with the same "
                             f"unknown argument values or condition ({cycle}); not followed")
            self.declarations.opened(f"line {action.where.line}: an include is not followed")
            return
        if len(frame.chain) > MAX_INCLUDE_DEPTH or len(self.files) >= MAX_FILES_PER_TREE:
            self._report("unresolved", action.where,
                         f"includes nested deeper than {MAX_INCLUDE_DEPTH} levels; not followed")
            self.declarations.opened(f"line {action.where.line}: an include is not followed")
            return
        try:
            data = read_launch_bytes(absolute)
        except OSError as exc:
            self._report("roslaunch_error", action.where,
                         f"cannot read included file {self._display(absolute)}: "
                         f"{exc.strerror or exc}")
            self.declarations.opened(f"line {action.where.line}: an include is not followed")
            return
        self.work.produce(len(data))
        site = self._included_at[absolute] = Location(
            self._display(frame.filename), action.where.line, action.where.column)
        self.include_sites.setdefault(self._display(absolute), site)
        read = self._read_file(absolute, data)
        if read.actions is None:
            self.declarations.opened(f"line {action.where.line}: an include is not followed")
            return
        for name in required_arguments(read.actions):
            if name not in passed:
                self._report(
                    "roslaunch_error", action.where,
                    f"the included file declares argument '{name}' without a default and the "
                    f"include does not pass it: launch stops with 'Included launch description "
                    f"missing required argument'",
                )
        inner = _Frame(absolute, read.launch_format, (*frame.chain, absolute),
                       (self._display(frame.filename), action.where.line), frame.condition,
                       (*frame.calls, call), (*frame.sites, site))
        self.arguments.start(action, absolute, passed if action.args_known else {})
        self.arguments.file_read(data, reads_as_python(absolute, data))
        # Inside the file its arguments hold as given, even under an undecided condition (an
        # event handler): all it starts carries it. After it they hold only under it.
        uncertain = [] if self._certain(scope, frame.condition) else given_values
        scope.configs.update(uncertain)
        self._run(read.actions, scope, inner)
        for name, value in uncertain:
            if scope.configs.get(name) is value:
                self._set(scope, name, value, frame.condition, f"$(var {name})")
        self.arguments.finish(self._display)

    # -- defined by a subclass, further on ---------------------------------------------------
    def _component(self, component: Component, scope: _Scope, frame: _Frame) -> None:
        """Defined by :class:`.ros2_launch.Ros2Loader`."""
        raise NotImplementedError

    def _node(self, action: RunNode, scope: _Scope, frame: _Frame) -> None:
        """Defined by :class:`.ros2_launch.Ros2Loader`."""
        raise NotImplementedError


def _run_node(runner: Ros2Runner, action: RunNode, scope: _Scope, frame: _Frame) -> None:
    runner._uses(action, scope, frame)
    runner._node(action, scope, frame)  # the subclass's, looked up on the runner


_ACTIONS: dict[type, Callable[[Ros2Runner, Any, _Scope, _Frame], None]] = {
    DeclareArg: Ros2Runner._declare,
    SetVar: Ros2Runner._let,
    SetEnv: Ros2Runner._set_env,
    PushNamespace: lambda runner, *given: runner._push_namespace(*given),  # the subclass's
    Group: Ros2Runner._group,
    Include: lambda runner, *given: runner._include(*given),  # the subclass's (its record)
    RunNode: _run_node,
    LoadComponents: Ros2Runner._components,
    Deferred: Ros2Runner._deferred,
    Uses: lambda runner, *given: runner._uses(*given),  # the subclass's (ros2 control)
}
"""What running each kind of action does (an ``Unfollowed`` is reported before)."""
