"""The launch API as the linter models it: one handler per launch class.

:data:`HANDLERS` is the explicit table from a class name of ``launch``/``launch_ros``
(whatever module it is imported from) to the method that builds the action, substitution
or condition it stands for; any other launch class is an object that starts nothing.
"""

from __future__ import annotations

import ast
import shlex
from collections.abc import Callable, Mapping, Sequence

from launch_linter.frontends.ros2_actions import (
    Action,
    Component,
    DeclareArg,
    Deferred,
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
    may_publish_static_tf,
    may_rename,
    ros2_control,
    ros2_run,
    shell_reads_as_words,
)
from launch_linter.frontends.ros2_python import moveit, xacro_call
from launch_linter.frontends.ros2_python.node_arguments import NodeArguments
from launch_linter.frontends.ros2_python.signatures import is_action_class, positional_refusal
from launch_linter.frontends.ros2_python.values import (
    _LEGACY_NODE_KEYWORDS,
    LAUNCH_ROOTS,
    ComponentVal,
    CondVal,
    ContextVal,
    FuncVal,
    HandlerVal,
    LaunchDescriptionVal,
    LaunchObject,
    ModuleVal,
    ParamFileVal,
    SourceVal,
    SubsVal,
    Unknown,
    _keyword,
    _OutOfSteps,
    _starts_actions,
    missing_keywords,
    performed,
)
from launch_linter.resolve.ros2_substitution import Call, Opaque, Subs, Text, literal, written
from launch_linter.resolve.value import Value

_BUILT_ACTIONS = (DeclareArg, SetVar, SetEnv, PushNamespace, Group, Include, RunNode,
                  LoadComponents, Deferred)
"""What the modelled launch action classes build (never an event)."""

# -- the interpreter -----------------------------------------------------------------------

_OS_CALLS = frozenset({
    "os.path.join", "os.path.dirname", "os.path.abspath", "os.path.realpath",
    "os.path.normpath", "os.getenv", "os.environ.get", "pathlib.Path", "os.path.expanduser",
})
"""The ``os``/``pathlib`` functions the interpreter models (:meth:`.Calls.os_call`)."""


def _substitution(kind: str, arity: int, texts: int = -1) -> Callable[..., object]:
    """A launch substitution class, as a method of :class:`Interpreter` (``texts``: the
    position of the argument whose items launch turns into text, see :meth:`Calls.subs`)."""

    def make(self: Interpreter, args: list[object], kwargs: dict[str, object],
             node: ast.Call) -> object:
        values = list(args) + list(kwargs.values())
        subs = tuple(self.subs(v, node, "substitution argument", i == texts)
                     for i, v in enumerate(values[:arity]) if v is not None)
        site = self.where(node)
        return SubsVal((Call(kind, subs, self.segment(node), (site.line, site.column)),))

    return make


class Interpreter(NodeArguments):
    """The whole interpreter: the evaluator with the launch API."""

    # -- the launch library ---------------------------------------------------------------
    def library(self, module: ModuleVal, args: list[object], kwargs: dict[str, object],
                node: ast.Call) -> object:
        dotted, name, root = module.dotted, module.last, module.root
        if dotted in _OS_CALLS:
            return self.os_call(dotted, args, node)
        if root == "ament_index_python":
            return self.ament(name, args, node)
        if dotted == "xacro.process_file":
            return xacro_call.process_file(self, args, kwargs, node)
        if dotted == "xacro.parse":
            return xacro_call.parse(self, args, kwargs, node)
        if dotted == "xacro.process_doc":
            return xacro_call.process_doc(self, args, kwargs, node)
        if root == "moveit_configs_utils" and name == "MoveItConfigsBuilder":
            return moveit.builder(self, args, kwargs, node)
        if root not in LAUNCH_ROOTS:
            return self.unknown(node, f"calls '{dotted}', which the linter does not model")
        if name == "Parameter" and ".substitutions" in dotted:
            # launch_ros.substitutions.Parameter is $(param); descriptions.Parameter is not.
            return _substitution("param", 2)(self, args, kwargs, node)
        self.refused_call(dotted, args, kwargs, node)
        self.legacy_keywords(name, kwargs, node)
        missing = missing_keywords(name, kwargs)
        if missing:  # ros2_missing_keyword decides with the target distribution
            legacy = [k for k in _LEGACY_NODE_KEYWORDS if k in kwargs]
            self.problem("ros2_missing_keyword", node, f"{name}(...) without "
                         + " and ".join(f"{k}=" for k in missing)
                         + (f" ({', '.join(legacy)}= removed after Foxy)" if legacy else ""))
        handler = HANDLERS.get(name)
        if handler is None:
            path = self.arg(args, kwargs, 0, "param_file")
            if name == "ParameterFile" and path is not None:
                # A node's parameters list reads its path; an unknown allow_substs may
                # substitute (launch_ros/parameter_descriptions.py ParameterFile).
                return ParamFileVal(path, kwargs.get("allow_substs", False) is not False)
            if name == "ParameterValue" and args:
                return args[0]
            return self.launch_object(name, args, kwargs, node, dotted)
        result: object = handler(self, args, kwargs, node)
        return result

    def refused_call(self, dotted: str, args: list[object], kwargs: dict[str, object],
                     node: ast.Call) -> None:
        """A call of a launch class that raises while launch loads the file (see
        :mod:`.signatures`): too many positional arguments, an action given as an event."""
        refusal = positional_refusal(dotted, len(args))
        if refusal is not None:
            self.problem("roslaunch_error", node, refusal)
        event = kwargs.get("event")
        if dotted.rsplit(".", 1)[-1] == "EmitEvent" and is_action_class(dotted) and (
            (isinstance(event, LaunchObject) and is_action_class(event.dotted))
            or isinstance(event, _BUILT_ACTIONS)
        ):
            what = event.dotted if isinstance(event, LaunchObject) else "a launch action"
            self.problem("roslaunch_error", node, (
                f"EmitEvent(event=...) is given {what}, an action, not an event: launch "
                f"raises RuntimeError 'EmitEvent() expected an event instance' while it loads "
                f"the file (launch.actions.EmitEvent.__init__, Foxy to Rolling; the event "
                f"classes are in launch.events and launch_ros.events)"))

    def launch_object(self, name: str, args: list[object], kwargs: dict[str, object],
                      node: ast.Call, dotted: str = "",
                      controls: tuple[Subs, ...] | None = None) -> LaunchObject:
        """A launch class the linter does not model (``SetParameter``, ``LogInfo``, an
        ``ExecuteProcess``): as an action it performs the substitutions it was given."""
        uses = performed([*args, *(v for k, v in kwargs.items() if k != "condition")])
        parameter = None
        if name == "SetParameter":
            key, value = self.arg(args, kwargs, 0, "name"), self.arg(args, kwargs, 1, "value")
            if key is not None and value is not None:
                parameter = (self.subs(key, node, "parameter name"),
                             self.subs(_parameter_text(value), node, "parameter value"))
        return LaunchObject(name, self.where(node), self.condition(kwargs, node), uses,
                            parameter, controls=controls, dotted=dotted)

    def launch_LaunchDescription(self, args: list[object], kwargs: dict[str, object],
                                 node: ast.Call) -> object:
        initial = self.arg(args, kwargs, 0, "initial_entities")
        if initial is None:
            return LaunchDescriptionVal([])
        if isinstance(initial, (list, tuple)):
            return LaunchDescriptionVal([self.guard(item) for item in initial])
        return LaunchDescriptionVal([initial])

    def launch_Node(self, args: list[object], kwargs: dict[str, object], node: ast.Call
                    ) -> object:
        def pick(name: str, legacy: str) -> object:
            """The keyword's value, else its Foxy-era name's (None when neither is given)."""
            return kwargs[name] if name in kwargs else kwargs.get(legacy)

        arguments = kwargs.get("arguments")
        items: tuple[Subs, ...] | None
        unknown = ""
        if arguments is None:
            items = ()
        elif isinstance(arguments, (list, tuple)):
            items = tuple(self.subs(item, node, "arguments item") for item in arguments)
        else:
            items = None
            if isinstance(arguments, Unknown):
                unknown = arguments.describe()
            else:
                unknown = f"line {node.lineno}: arguments is not a list"
                if isinstance(arguments, str):
                    self.problem("roslaunch_error", node, "arguments is one string, not a "
                                 "list: launch passes each of its characters as an argument")
        executable = pick("executable", "node_executable")
        executable_written = _keyword(node, "executable") or _keyword(node, "node_executable")
        package = kwargs.get("package")
        # The arguments as written are shown only for a static transform publisher.
        args_written = (self.segment(_keyword(node, "arguments") or node)
                        if may_publish_static_tf(package, executable) else "")
        return RunNode(
            where=self.where(node),
            condition=self.condition(kwargs, node),
            package=self.optional_subs(package, node, "package"),
            executable=self.optional_subs(executable, node, "executable"),
            name=self.optional_subs(pick("name", "node_name"), node, "name"),
            namespace=self.optional_subs(pick("namespace", "node_namespace"), node, "namespace"),
            arguments=items,
            args_written=args_written,
            unknown=unknown,
            parameters=self.parameters(kwargs.get("parameters"), node),
            uses=performed([v for k, v in kwargs.items() if k != "condition"]),
            may_rename=may_rename(_words(arguments, kwargs.get("ros_arguments"))),
            remappings=self.remappings(kwargs.get("remappings"), node),
            executable_at=None if executable_written is None else self.where(executable_written),
        )

    def launch_ExecuteProcess(self, args: list[object], kwargs: dict[str, object],
                              node: ast.Call) -> object:
        """``ExecuteProcess(cmd=['ros2', 'run', PKG, EXEC, ARGS...])`` starts that node;
        other processes are not transforms."""
        cmd = self.arg(args, kwargs, 0, "cmd")
        if not isinstance(cmd, (list, tuple)):
            return self.launch_object("ExecuteProcess", args, kwargs, node)
        items = [self.subs(item, node, "cmd item") for item in cmd]
        if kwargs.get("shell") is True:
            # launch joins the items with spaces and a shell splits the line again: known
            # only when every item is literal text (a value's spaces would split too).
            line = " ".join(written(item) for item in items)
            if not all(isinstance(sub, Text) for item in items for sub in item) or (
                not shell_reads_as_words(line)
            ):
                return self.launch_object("ExecuteProcess", args, kwargs, node)
            try:
                words = shlex.split(line)
            except ValueError:
                return self.launch_object("ExecuteProcess", args, kwargs, node)
            items = [literal(word) for word in words]
        run = ros2_run(items)
        if run is None:
            return self.launch_object("ExecuteProcess", args, kwargs, node,
                                      controls=ros2_control(items))
        package, executable, arguments = run
        return RunNode(
            where=self.where(node), condition=self.condition(kwargs, node), package=package,
            executable=executable, name=None, namespace=None, arguments=arguments,
            args_written=self.segment(_keyword(node, "cmd") or node), pushed_namespace=False,
            uses=performed([*args, *(v for k, v in kwargs.items() if k != "condition")]),
        )

    def launch_DeclareLaunchArgument(self, args: list[object], kwargs: dict[str, object],
                                     node: ast.Call) -> object:
        name = self.arg(args, kwargs, 0, "name")
        default = self.arg(args, kwargs, 1, "default_value")
        return DeclareArg(self.where(node), self.condition(kwargs, node),
                          self.subs(name, node, "argument name"),
                          self.optional_subs(default, node, "default value"))

    def _assignment(self, action: type[SetVar] | type[SetEnv], args: list[object],
                    kwargs: dict[str, object], node: ast.Call, sets: bool) -> object:
        """``Set…(name, value)`` or, with ``sets`` false, ``Unset…(name)``."""
        where, condition = self.where(node), self.condition(kwargs, node)
        name = self.subs(self.arg(args, kwargs, 0, "name"), node, "name")
        value = self.subs(self.arg(args, kwargs, 1, "value"), node, "value") if sets else None
        return action(where, condition, name, value)

    def launch_SetLaunchConfiguration(self, args: list[object], kwargs: dict[str, object],
                                      node: ast.Call) -> object:
        return self._assignment(SetVar, args, kwargs, node, sets=True)

    def launch_UnsetLaunchConfiguration(self, args: list[object], kwargs: dict[str, object],
                                        node: ast.Call) -> object:
        return self._assignment(SetVar, args, kwargs, node, sets=False)

    def launch_SetEnvironmentVariable(self, args: list[object], kwargs: dict[str, object],
                                      node: ast.Call) -> object:
        return self._assignment(SetEnv, args, kwargs, node, sets=True)

    def launch_UnsetEnvironmentVariable(self, args: list[object], kwargs: dict[str, object],
                                        node: ast.Call) -> object:
        return self._assignment(SetEnv, args, kwargs, node, sets=False)

    def launch_PushRosNamespace(self, args: list[object], kwargs: dict[str, object],
                                node: ast.Call) -> object:
        return PushNamespace(self.where(node), self.condition(kwargs, node),
                             self.subs(self.arg(args, kwargs, 0, "namespace"), node, "namespace"))

    launch_PushROSNamespace = launch_PushRosNamespace

    def launch_GroupAction(self, args: list[object], kwargs: dict[str, object],
                           node: ast.Call) -> object:
        actions = self.actions(self.arg(args, kwargs, 0, "actions"), node)
        configurations = kwargs.get("launch_configurations")
        if isinstance(configurations, dict):
            where = self.where(node)
            actions = tuple(
                SetVar(where, None, self.subs(k, node, "name"), self.subs(v, node, "value"))
                for k, v in configurations.items()
            ) + actions
        flags: list[bool | Subs] = []
        for key in ("scoped", "forwarding"):
            value = kwargs.get(key, True)
            flags.append(value if isinstance(value, bool) else self.subs(value, node, key))
        return Group(self.where(node), self.condition(kwargs, node), actions,
                     scoped=flags[0], forwarding=flags[1])

    def launch_TimerAction(self, args: list[object], kwargs: dict[str, object],
                           node: ast.Call) -> object:
        actions = self.actions(self.arg(args, kwargs, 1, "actions"), node)
        return Group(self.where(node), self.condition(kwargs, node), actions, scoped=False)

    def launch_RegisterEventHandler(self, args: list[object], kwargs: dict[str, object],
                                    node: ast.Call) -> object:
        handler = self.arg(args, kwargs, 0, "event_handler")
        if not isinstance(handler, HandlerVal):
            return LaunchObject("RegisterEventHandler")
        where = self.where(node)
        text = self.segment(node.args[0] if node.args else node)
        reason = f"line {node.lineno}: runs only when the process event happens"
        predicate = Predicate(True, (Opaque(f"python: {text}", reason),))
        return Group(where, predicate, self.actions(handler.entities, node), scoped=False)

    def _handler(self, args: list[object], kwargs: dict[str, object], node: ast.Call
                 ) -> object:
        return HandlerVal([v for k, v in kwargs.items() if k.startswith("on_")])

    launch_OnProcessStart = _handler
    launch_OnProcessExit = _handler
    launch_OnExecutionComplete = _handler
    launch_OnShutdown = _handler
    launch_OnProcessIO = _handler

    def launch_IncludeLaunchDescription(self, args: list[object], kwargs: dict[str, object],
                                        node: ast.Call) -> object:
        source = self.arg(args, kwargs, 0, "launch_description_source")
        path = source.path if isinstance(source, SourceVal) else self.subs(
            source, node, "launch file")
        launch_arguments = kwargs.get("launch_arguments")
        pairs: list[tuple[Subs, Subs]] = []
        if isinstance(launch_arguments, dict):
            launch_arguments = list(launch_arguments.items())
        if isinstance(launch_arguments, (list, tuple)):
            for pair in launch_arguments:
                if isinstance(pair, (tuple, list)) and len(pair) == 2:
                    pairs.append((self.subs(pair[0], node, "argument name"),
                                  self.subs(pair[1], node, "argument value")))
        elif launch_arguments is not None:
            self.problem("unresolved", node, "launch_arguments of this include are unknown")
        pairs_known = isinstance(launch_arguments, (list, tuple)) and all(
            isinstance(pair, (tuple, list)) and len(pair) == 2 for pair in launch_arguments)
        known = launch_arguments is None or pairs_known
        return Include(self.where(node), self.condition(kwargs, node), path, tuple(pairs),
                       args_known=known, arg_places=self._arg_places(pairs, node))

    def _arg_places(self, pairs: list[tuple[Subs, Subs]], node: ast.Call
                    ) -> tuple[tuple[int, int], ...]:
        """Where each argument name is written in the include's own ``launch_arguments``
        (a string literal there); (0, 0) when elsewhere (a dictionary built before) or
        when the include is made in a helper function (reported at the helper's call)."""
        written_at: dict[str, tuple[int, int]] = {}
        given = next((k.value for k in node.keywords if k.arg == "launch_arguments"), None)
        if given is not None and not self.call_sites:
            for inner in ast.walk(given):
                if isinstance(inner, ast.Constant) and isinstance(inner.value, str):
                    written_at.setdefault(inner.value, (inner.lineno, inner.col_offset + 1))
        return tuple(written_at.get(written(name), (0, 0)) for name, _ in pairs)

    def _source(self, args: list[object], kwargs: dict[str, object], node: ast.Call
                ) -> object:
        return SourceVal(self.subs(self.arg(args, kwargs, 0, "launch_file_path"), node,
                                   "launch file"))

    launch_PythonLaunchDescriptionSource = _source
    launch_XMLLaunchDescriptionSource = _source
    launch_YAMLLaunchDescriptionSource = _source
    launch_AnyLaunchDescriptionSource = _source
    launch_FrontendLaunchDescriptionSource = _source

    def launch_OpaqueFunction(self, args: list[object], kwargs: dict[str, object],
                              node: ast.Call) -> object:
        function = self.arg(args, kwargs, 0, "function")
        extra_args = kwargs.get("args") or []
        extra_kwargs = kwargs.get("kwargs") or {}
        if not isinstance(function, FuncVal) or not isinstance(extra_args, (list, tuple)) or (
            not isinstance(extra_kwargs, dict)
        ):
            return Unfollowed(self.where(node), f"line {node.lineno}: OpaqueFunction of "
                                                f"{self.segment(node)} is not followed")
        where = self.where(node)

        def expand(resolver: Callable[[Subs], Value]) -> Sequence[Action]:
            return self.deferred(function, list(extra_args), dict(extra_kwargs), resolver,
                                 node, where)

        self.deferring = True
        return Deferred(where, self.condition(kwargs, node), expand)

    def deferred(self, function: FuncVal, args: list[object], kwargs: dict[str, object],
                 resolver: Callable[[Subs], Value], node: ast.Call, where: Where
                 ) -> Sequence[Action]:
        self.steps = 0
        # The file's problems were handed over when it was read; what the function's body
        # meets now (a loop over an unknown value, ...) is reported through the actions.
        recorded = len(self.problems)
        # What the function appends to a LaunchDescription it is given runs after it:
        # launch's visit of a description iterates the very list the function appends to.
        given = [(d, len(d.items)) for d in (*args, *kwargs.values())
                 if isinstance(d, LaunchDescriptionVal)]
        try:
            result = self.call_function(function, [ContextVal(resolver), *args],
                                        {str(k): v for k, v in kwargs.items()}, node)
        except (_OutOfSteps, RecursionError):
            return (Unfollowed(where, f"line {node.lineno}: OpaqueFunction too complex to "
                                      f"follow"),)
        finally:
            met = self.problems[recorded:]
            del self.problems[recorded:]
        name = getattr(function.node, "name", "<lambda>")
        # What the reader could not follow is said as met in the function; what a rule
        # judges (a keyword launch_ros refuses, ...) is as wrong there as anywhere.
        notes = tuple(
            Unfollowed(Where(self.path, p.line, p.column),
                       f"in OpaqueFunction {name}(): {p.message}")
            if p.rule == "unresolved" else
            Unfollowed(Where(self.path, p.line, p.column), p.message, p.rule)
            for p in met
        )
        appended = [item for d, before in given for item in d.items[before:]]
        found = (*(self.actions(result, node) if result is not None else ()),
                 *(self.actions(appended, node) if appended else ()))
        # A log message or a parameter set (an unmodelled action) starts nothing: a
        # function that returns only those returned none of the actions it builds.
        followed = [action for action in found if not isinstance(action, Uses)]
        if not followed and not any(note.rule == "unresolved" for note in notes) and (
            _starts_actions(function.node)
        ):
            notes = (*notes, Unfollowed(where, f"line {node.lineno}: OpaqueFunction "
                                              f"{name}() builds launch actions but "
                                              f"returns none the linter can follow"))
        return (*notes, *found)

    launch_LaunchConfiguration = _substitution("var", 2, texts=1)
    launch_EnvironmentVariable = _substitution("env", 2)
    launch_FindPackageShare = _substitution("find-pkg-share", 1)
    launch_FindPackagePrefix = _substitution("find-pkg-prefix", 1)
    launch_FindExecutable = _substitution("find-exec", 1)
    launch_PythonExpression = _substitution("eval", 1)
    launch_AnonName = _substitution("anon", 1)
    launch_Command = _substitution("command", 1)
    launch_ThisLaunchFileDir = _substitution("dirname", 0)
    launch_ThisLaunchFile = _substitution("filename", 0)
    launch_NotSubstitution = _substitution("not", 1)
    launch_AndSubstitution = _substitution("and", 2)
    launch_OrSubstitution = _substitution("or", 2)
    launch_EqualsSubstitution = _substitution("equals", 2)
    launch_NotEqualsSubstitution = _substitution("not-equals", 2)
    launch_IfElseSubstitution = _substitution("if", 3)
    launch_LaunchLogDir = _substitution("launch_log_dir", 0)

    def launch_TextSubstitution(self, args: list[object], kwargs: dict[str, object],
                                node: ast.Call) -> object:
        return SubsVal(self.subs(self.arg(args, kwargs, 0, "text"), node, "text"))

    def launch_PathJoinSubstitution(self, args: list[object], kwargs: dict[str, object],
                                    node: ast.Call) -> object:
        parts = self.arg(args, kwargs, 0, "substitutions")
        if not isinstance(parts, (list, tuple)):
            return self.unknown(node, "PathJoinSubstitution of an unknown list")
        return SubsVal((Call("path-join", tuple(self.subs(p, node, "path part") for p in parts),
                             self.segment(node)),))

    def launch_PathSubstitution(self, args: list[object], kwargs: dict[str, object],
                                node: ast.Call) -> object:
        path = self.arg(args, kwargs, 0, "path")
        return SubsVal((Call("path-join", (self.subs(path, node, "path"),),
                             self.segment(node)),))

    def launch_IfCondition(self, args: list[object], kwargs: dict[str, object],
                           node: ast.Call) -> object:
        value = self.arg(args, kwargs, 0, "predicate_expression")
        return CondVal(Predicate(True, self.subs(value, node, "condition")))

    def launch_UnlessCondition(self, args: list[object], kwargs: dict[str, object],
                               node: ast.Call) -> object:
        value = self.arg(args, kwargs, 0, "predicate_expression")
        return CondVal(Predicate(False, self.subs(value, node, "condition")))

    def launch_LaunchConfigurationEquals(self, args: list[object], kwargs: dict[str, object],
                                         node: ast.Call) -> object:
        name = self.subs(self.arg(args, kwargs, 0, "launch_configuration_name"), node, "name")
        expected = self.subs(self.arg(args, kwargs, 1, "expected_value") or "", node, "value")
        # An unset configuration compares as None (launch catches the KeyError): never the
        # "does not exist" failure of a LaunchConfiguration.
        unset = (Opaque(self.segment(node), f"line {node.lineno}: the configuration may be "
                                            f"unset (compared as None)"),)
        variable = Call("var", (name, unset), self.segment(node))
        return CondVal(Predicate(True, (Call("equals", ((variable,), expected),
                                             self.segment(node)),)))

    def launch_LaunchConfigurationNotEquals(self, args: list[object], kwargs: dict[str, object],
                                            node: ast.Call) -> object:
        condition = self.launch_LaunchConfigurationEquals(args, kwargs, node)
        assert isinstance(condition, CondVal)
        return CondVal(Predicate(False, condition.predicate.expression))

    def launch_ComposableNode(self, args: list[object], kwargs: dict[str, object],
                              node: ast.Call) -> object:
        return ComponentVal(Component(
            where=self.where(node),
            condition=self.condition(kwargs, node),
            package=self.optional_subs(kwargs.get("package"), node, "package"),
            plugin=self.optional_subs(kwargs.get("plugin", kwargs.get("node_plugin")), node,
                                      "plugin"),
            name=self.optional_subs(kwargs.get("name", kwargs.get("node_name")), node, "name"),
            namespace=self.optional_subs(kwargs.get("namespace", kwargs.get("node_namespace")),
                                         node, "namespace"),
            parameters=self.parameters(kwargs.get("parameters"), node),
            uses=performed([v for k, v in kwargs.items() if k != "condition"]),
        ))

    def _container(self, args: list[object], kwargs: dict[str, object], node: ast.Call
                   ) -> object:
        descriptions = kwargs.get("composable_node_descriptions") or []
        if not isinstance(descriptions, (list, tuple)):
            return Unfollowed(self.where(node), f"line {node.lineno}: composable nodes of "
                                                f"{self.segment(node)} are unknown")
        components = tuple(d.component for d in descriptions if isinstance(d, ComponentVal))
        others = [v for k, v in kwargs.items()
                  if k not in ("condition", "composable_node_descriptions")]
        return LoadComponents(self.where(node), self.condition(kwargs, node), components,
                              performed(others))

    launch_ComposableNodeContainer = _container
    launch_LoadComposableNodes = _container


HANDLERS: Mapping[
    str, Callable[[Interpreter, list[object], dict[str, object], ast.Call], object]
] = {
    "LaunchDescription": Interpreter.launch_LaunchDescription,
    "Node": Interpreter.launch_Node,
    "ExecuteProcess": Interpreter.launch_ExecuteProcess,
    "DeclareLaunchArgument": Interpreter.launch_DeclareLaunchArgument,
    "SetLaunchConfiguration": Interpreter.launch_SetLaunchConfiguration,
    "UnsetLaunchConfiguration": Interpreter.launch_UnsetLaunchConfiguration,
    "SetEnvironmentVariable": Interpreter.launch_SetEnvironmentVariable,
    "UnsetEnvironmentVariable": Interpreter.launch_UnsetEnvironmentVariable,
    "PushRosNamespace": Interpreter.launch_PushRosNamespace,
    "PushROSNamespace": Interpreter.launch_PushROSNamespace,
    "GroupAction": Interpreter.launch_GroupAction,
    "TimerAction": Interpreter.launch_TimerAction,
    "RegisterEventHandler": Interpreter.launch_RegisterEventHandler,
    "OnProcessStart": Interpreter.launch_OnProcessStart,
    "OnProcessExit": Interpreter.launch_OnProcessExit,
    "OnExecutionComplete": Interpreter.launch_OnExecutionComplete,
    "OnShutdown": Interpreter.launch_OnShutdown,
    "OnProcessIO": Interpreter.launch_OnProcessIO,
    "IncludeLaunchDescription": Interpreter.launch_IncludeLaunchDescription,
    "PythonLaunchDescriptionSource": Interpreter.launch_PythonLaunchDescriptionSource,
    "XMLLaunchDescriptionSource": Interpreter.launch_XMLLaunchDescriptionSource,
    "YAMLLaunchDescriptionSource": Interpreter.launch_YAMLLaunchDescriptionSource,
    "AnyLaunchDescriptionSource": Interpreter.launch_AnyLaunchDescriptionSource,
    "FrontendLaunchDescriptionSource": Interpreter.launch_FrontendLaunchDescriptionSource,
    "OpaqueFunction": Interpreter.launch_OpaqueFunction,
    "LaunchConfiguration": Interpreter.launch_LaunchConfiguration,
    "EnvironmentVariable": Interpreter.launch_EnvironmentVariable,
    "FindPackageShare": Interpreter.launch_FindPackageShare,
    "FindPackagePrefix": Interpreter.launch_FindPackagePrefix,
    "FindExecutable": Interpreter.launch_FindExecutable,
    "PythonExpression": Interpreter.launch_PythonExpression,
    "AnonName": Interpreter.launch_AnonName,
    "Command": Interpreter.launch_Command,
    "ThisLaunchFileDir": Interpreter.launch_ThisLaunchFileDir,
    "ThisLaunchFile": Interpreter.launch_ThisLaunchFile,
    "NotSubstitution": Interpreter.launch_NotSubstitution,
    "AndSubstitution": Interpreter.launch_AndSubstitution,
    "OrSubstitution": Interpreter.launch_OrSubstitution,
    "EqualsSubstitution": Interpreter.launch_EqualsSubstitution,
    "NotEqualsSubstitution": Interpreter.launch_NotEqualsSubstitution,
    "IfElseSubstitution": Interpreter.launch_IfElseSubstitution,
    "LaunchLogDir": Interpreter.launch_LaunchLogDir,
    "TextSubstitution": Interpreter.launch_TextSubstitution,
    "PathJoinSubstitution": Interpreter.launch_PathJoinSubstitution,
    "PathSubstitution": Interpreter.launch_PathSubstitution,
    "IfCondition": Interpreter.launch_IfCondition,
    "UnlessCondition": Interpreter.launch_UnlessCondition,
    "LaunchConfigurationEquals": Interpreter.launch_LaunchConfigurationEquals,
    "LaunchConfigurationNotEquals": Interpreter.launch_LaunchConfigurationNotEquals,
    "ComposableNode": Interpreter.launch_ComposableNode,
    "ComposableNodeContainer": Interpreter.launch_ComposableNodeContainer,
    "LoadComposableNodes": Interpreter.launch_LoadComposableNodes,
}
"""Every launch class the linter models, by its name: the handler builds the action,
substitution or condition it stands for from the call's arguments."""


def _parameter_text(value: object) -> object:
    """A ``SetParameter`` value as the text a node is given (``True`` as ``true``)."""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, (int, float)):
        return repr(value)
    return value


def _words(*lists: object) -> list[str] | None:
    """The literal text of ``Node`` arguments lists (an item made of pieces joined), for
    :func:`may_rename`; None when a list is not known (not a list, not literal pieces)."""
    out: list[str] = []
    for value in lists:
        if value is None:
            continue
        if not isinstance(value, (list, tuple)):
            return None
        for item in value:
            pieces = item if isinstance(item, (list, tuple)) else (item,)
            out.append("".join(p for p in pieces if isinstance(p, str)))
    return out
