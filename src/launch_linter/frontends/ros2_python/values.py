"""The values of the ROS 2 Python launch-file interpreter.

Plain Python values (``str``, numbers, lists, tuples, dicts) stand for themselves; the
classes here stand for what the linter models without running it: an :class:`Unknown`
(with why and where), launch substitutions kept unevaluated (:class:`SubsVal`), strings
known only at launch time (:class:`LazyStr`), launch objects, conditions, the file's own
functions and scopes.
"""

from __future__ import annotations

import ast
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any, Dict

from launch_linter.frontends.ros2_actions import Component, Predicate, Where
from launch_linter.resolve.ros2_substitution import Opaque, Subs, literal
from launch_linter.resolve.value import Value

LAUNCH_ROOTS = (
    "launch", "launch_ros", "launch_xml", "launch_yaml", "launch_testing", "launch_pytest",
)
ACTION_NAMES = frozenset({
    "Node", "IncludeLaunchDescription", "ComposableNodeContainer", "LoadComposableNodes",
    "ComposableNode", "GroupAction", "OpaqueFunction", "TimerAction", "LaunchDescription",
})

_LEGACY_NODE_KEYWORDS = {
    "node_executable": "executable",
    "node_name": "name",
    "node_namespace": "namespace",
}
"""launch_ros ``Node`` keywords of Foxy and before, and what replaced them."""

LEGACY_KEYWORDS: dict[str, dict[str, str]] = {
    "Node": _LEGACY_NODE_KEYWORDS,
    "LifecycleNode": _LEGACY_NODE_KEYWORDS,
    "ComposableNodeContainer": _LEGACY_NODE_KEYWORDS,
    "ComposableNode": {
        "node_plugin": "plugin", "node_name": "name", "node_namespace": "namespace",
    },
}
"""Foxy-era keywords per launch_ros action, and what replaced them. Foxy accepts them with a
deprecation warning (launch_ros foxy 68e2b62: actions/node.py, descriptions/
composable_node.py ``node_plugin``/``node_name``/``node_namespace``, actions/
composable_node_container.py); from Galactic on they are gone (galactic 31e27eb):
``ComposableNode.__init__(self, *, package, plugin, name=None, namespace=None, ...)`` takes
no other keyword, and ``Node`` (which ``LifecycleNode`` and ``ComposableNodeContainer``
forward their other keywords to) hands unknown ones to ``ExecuteProcess``, which refuses
them: TypeError, and ``ros2 launch`` refuses the file."""

REQUIRED_KEYWORDS = {
    "LifecycleNode": ("name", "namespace"),
    "ComposableNodeContainer": ("name", "namespace"),
}
"""launch_ros actions whose constructor has keyword-only parameters without a default from
Galactic on (``def __init__(self, *, name, namespace, ...)`` in launch_ros/actions/
lifecycle_node.py and composable_node_container.py, galactic 31e27eb, humble 25a207c,
jazzy 62c56e5, rolling f9ab937; ros2/launch_ros#157 made LifecycleNode's namespace
mandatory): a call without one raises TypeError and ``ros2 launch`` refuses the file.
Foxy's gave both a default (foxy 68e2b62)."""


def missing_keywords(name: str, kwargs: dict[str, object]) -> tuple[str, ...]:
    """The keywords ``name``'s constructor requires from Galactic on that ``kwargs`` lacks
    (a Foxy-era ``node_name=``/``node_namespace=`` does not stand for one there)."""
    return tuple(k for k in REQUIRED_KEYWORDS.get(name, ()) if k not in kwargs)


# -- values -----------------------------------------------------------------------------


@dataclass(frozen=True)
class Unknown:
    """A value the linter cannot know: why, and where it was written."""

    reason: str
    text: str
    line: int

    def __init__(self, reason: str, text: str, line: int) -> None:
        # The interpreter's frozen values are made by the thousand per file: each puts its
        # fields in the instance's dict, at a third to a half of the cost of the frozen
        # dataclass's ``object.__setattr__`` per field (assignment is still refused; a
        # subclass such as PartlyKnownList keeps its generated ``__init__``).
        fields = self.__dict__
        fields["reason"], fields["text"], fields["line"] = reason, text, line

    def describe(self) -> str:
        return f"line {self.line}: {self.text}: {self.reason}"

    def hole(self, prefix: str = "") -> Opaque:
        """A substitution standing for this value: shows its text, says where and why."""
        return Opaque(prefix + self.text, f"line {self.line}: {self.reason}")


@dataclass(frozen=True)
class PartlyKnownList(Unknown):
    """``unknown + [known, ...]`` (or the reverse): unknown as a value, but as launch
    entities the known operands' items are there for certain (``+`` of a list needs a list
    on the other side), so they are read and only the unknown part is not followed."""

    parts: tuple[object, ...] = ()


@dataclass(frozen=True)
class MoveItBuilderVal:
    """``moveit_configs_utils.MoveItConfigsBuilder``: the package its relative file paths
    are in (``package_name``, else ``<robot_name>_moveit_config``), the parameter name it
    gives the robot description, and the description chosen so far (the ``xacro`` command
    of ``.robot_description(file_path=...)``; None: the builder's default, which it reads
    from the package's ``.setup_assistant`` and the linter does not)."""

    package: Subs
    parameter: str
    description: object = None


@dataclass(frozen=True)
class MoveItConfigsVal:
    """What ``MoveItConfigsBuilder.to_moveit_configs()`` gives: only its robot description
    is modelled."""

    parameter: str
    description: object


@dataclass(frozen=True)
class XacroDocVal:
    """``xacro.process_file(...)``: the document whose ``toxml()`` is ``text`` (the xacro
    command's output, :mod:`.xacro_call`)."""

    text: SubsVal


@dataclass
class XacroParsedDoc:
    """``xacro.parse(open(path))``: the file's document, not yet expanded. It is mutable as
    xacro's is: ``xacro.process_doc(doc, mappings=...)`` expands it in place, and only then
    is its ``toxml()`` the description (``processed``, :mod:`.xacro_call`)."""

    path: Subs
    processed: object = None


class LinedDict(Dict[object, object]):
    """A dictionary written in the file (``{'key': value}``, ``d['key'] = value``), with
    where each key was last written: a parameter's value then has its own line. A
    dictionary made any other way is a plain ``dict`` (its keys' lines unknown)."""

    __slots__ = ("places",)

    def __init__(self) -> None:
        super().__init__()
        self.places: dict[object, Where] = {}


@dataclass(frozen=True)
class SubsVal:
    """A launch substitution object (or a list of them): evaluated only when it runs."""

    subs: Subs

    def __init__(self, subs: Subs) -> None:
        self.__dict__["subs"] = subs  # see Unknown.__init__


@dataclass(frozen=True)
class OpenFile:
    """``open(path)``: nothing is opened; ``.read()`` gives the file's text as the
    ``file-content`` substitution (a robot description read from a URDF file)."""

    path: Subs


@dataclass(frozen=True)
class LazyStr:
    """A Python string (or path) whose value the linter computes later, from the same
    facts launch would use: a package location, an environment variable."""

    subs: Subs
    path: bool = False

    def __init__(self, subs: Subs, path: bool = False) -> None:
        fields = self.__dict__  # see Unknown.__init__
        fields["subs"], fields["path"] = subs, path


@dataclass
class LaunchDescriptionVal:
    items: list[object]


@dataclass(frozen=True)
class CondVal:
    predicate: Predicate


@dataclass(frozen=True)
class SourceVal:
    path: Subs


@dataclass(frozen=True)
class ComponentVal:
    component: Component


@dataclass(frozen=True)
class ParamFileVal:
    """``launch_ros.parameter_descriptions.ParameterFile(param_file, *, allow_substs)``:
    ``substituted`` unless ``allow_substs`` is left out or written False."""

    path: object
    substituted: bool


@dataclass(frozen=True)
class ModuleVal:
    """A name imported from a module: ``launch_ros.actions.Node``, ``os.path``."""

    dotted: str

    def __init__(self, dotted: str) -> None:
        self.__dict__["dotted"] = dotted  # see Unknown.__init__

    @property
    def root(self) -> str:
        return self.dotted.split(".", 1)[0]

    @property
    def last(self) -> str:
        return self.dotted.rsplit(".", 1)[-1]


@dataclass(frozen=True)
class LaunchObject:
    """An instance of a launch class that starts no static transform. As an action of a
    launch description it still performs ``uses`` (under ``condition``) when it runs."""

    name: str
    where: Where | None = None
    condition: Predicate | None = None
    uses: tuple[Subs, ...] = ()
    parameter: tuple[Subs, Subs] | None = None
    """``SetParameter``'s name and value."""
    controls: tuple[Subs, ...] | None = None
    """``ExecuteProcess`` of ``ros2 control``: the words after ``control``."""
    dotted: str = ""
    """The class as imported (``launch.actions.Shutdown``): an action or an event."""


@dataclass(frozen=True)
class Builtin:
    name: str

    def __init__(self, name: str) -> None:
        self.__dict__["name"] = name  # see Unknown.__init__


@dataclass
class FuncVal:
    node: ast.FunctionDef | ast.AsyncFunctionDef | ast.Lambda
    closure: Env
    defaults: dict[str, object]


@dataclass(frozen=True)
class BoundMethod:
    target: object
    name: str

    def __init__(self, target: object, name: str) -> None:
        fields = self.__dict__  # see Unknown.__init__
        fields["target"], fields["name"] = target, name


@dataclass(frozen=True)
class HandlerVal:
    """A process event handler: the entities it starts when the event happens."""

    entities: list[object]


@dataclass(frozen=True)
class ContextVal:
    """The ``LaunchContext`` an ``OpaqueFunction`` receives."""

    resolver: Callable[[Subs], Value]


@dataclass(frozen=True)
class ConfigsVal:
    """``context.launch_configurations``."""

    resolver: Callable[[Subs], Value]


BUILTINS = ("str", "int", "float", "bool", "len", "list", "tuple", "dict", "range", "print",
            "sorted", "enumerate", "zip", "min", "max", "abs", "round", "open")


def _starts_actions(node: ast.AST) -> bool:
    """Whether a function's body calls a launch action class (a ``Node``, ...)."""
    return any(
        isinstance(inner, ast.Call) and _called_name(inner.func) in ACTION_NAMES
        for inner in ast.walk(node)
    )


class Env:
    """Python scopes: a function's locals in front of its enclosing scopes."""

    def __init__(self, parent: Env | None = None) -> None:
        self.vars: dict[str, object] = {}
        self.parent = parent

    def lookup(self, name: str) -> tuple[bool, object]:
        env: Env | None = self
        while env is not None:
            if name in env.vars:
                return True, env.vars[name]
            env = env.parent
        return False, None


class _OutOfSteps(Exception):
    pass


class _Return(Exception):
    def __init__(self, value: object) -> None:
        self.value = value


class _Break(Exception):
    pass


class _Continue(Exception):
    pass


def _text_of(value: object) -> str | None:
    return value if isinstance(value, str) else None


def _keyword(node: ast.Call, name: str) -> ast.expr | None:
    return next((k.value for k in node.keywords if k.arg == name), None)


def _called_name(node: ast.expr) -> str:
    if isinstance(node, ast.Name):
        return node.id
    if isinstance(node, ast.Attribute):
        return node.attr
    return ""


def _as_subs(value: str | LazyStr) -> Subs:
    return literal(value) if isinstance(value, str) else value.subs




def _plain(value: object) -> bool:
    return isinstance(value, (str, int, float, bool, list, tuple, dict)) or value is None


_COMPARE: dict[type, Callable[[Any, Any], bool]] = {
    ast.Eq: lambda a, b: a == b, ast.NotEq: lambda a, b: a != b,
    ast.Lt: lambda a, b: a < b, ast.LtE: lambda a, b: a <= b,
    ast.Gt: lambda a, b: a > b, ast.GtE: lambda a, b: a >= b,
    ast.In: lambda a, b: a in b, ast.NotIn: lambda a, b: a not in b,
    ast.Is: lambda a, b: a is b if a is None or b is None else a == b,
    ast.IsNot: lambda a, b: a is not b if a is None or b is None else a != b,
}

_PLAIN_BUILTINS: dict[str, Callable[..., object]] = {
    "int": int, "float": float, "bool": bool, "abs": abs, "round": round, "min": min,
    "max": max,
}


MAX_PERFORMED_ITEMS = 10_000
"""Items of an action's arguments looked at for the substitutions they hold."""


def performed(values: list[object]) -> tuple[Subs, ...]:
    """The launch substitutions held anywhere in an action's arguments (in lists, tuples,
    dict keys and values): what launch performs when the action runs. Iterative and
    bounded; a list that holds itself is looked at once."""
    found: list[Subs] = []
    pending: list[object] = list(values)
    seen: set[int] = set()
    looked = 0
    while pending and looked < MAX_PERFORMED_ITEMS:
        value = pending.pop()
        looked += 1
        if type(value) is str:  # most items: plain text holds no substitution
            continue
        if isinstance(value, SubsVal):
            found.append(value.subs)
        elif isinstance(value, (list, tuple, dict)):
            if id(value) in seen:
                continue
            seen.add(id(value))
            if isinstance(value, dict):
                pending.extend(value.keys())
                pending.extend(value.values())
            else:
                pending.extend(value)
    return tuple(found)
