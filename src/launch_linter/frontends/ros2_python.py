"""ROS 2 Python launch files, read as a syntax tree: never imported, never executed.

``ros2 launch`` imports a ``*.launch.py`` file and calls its ``generate_launch_description()``.
The linter parses the file with :func:`ast.parse` and interprets a small, safe part of
Python over the tree: literals, names, lists/tuples/dicts, ``+``/``*``/``%`` on known
values, f-strings, comparisons, ``if``/``for`` over known values, comprehensions, calls of
functions defined in the same file (bounded), and the launch classes it models
(``LaunchDescription``, ``Node``, ``DeclareLaunchArgument``, ``LaunchConfiguration``,
``GroupAction``, ``PushRosNamespace``, ``IncludeLaunchDescription`` and its sources,
``ComposableNodeContainer``/``LoadComposableNodes``/``ComposableNode``, ``TimerAction``,
``OpaqueFunction``, ``RegisterEventHandler``, the substitution classes, ``IfCondition``
and friends, ``get_package_share_directory``, ``os.path.join``, ``os.environ``). Launch
substitutions stay unevaluated until the actions run, exactly as in launch, so
``DeclareLaunchArgument`` defaults and ``LaunchConfiguration`` values are known when they
are statically known. Anything else is *unknown*: it carries the line and text of the
expression, so the transform that depends on it is reported as unresolved with that place.
An ``if`` on an unknown value runs both branches, each under a presence condition.

Nothing from the file is imported, no attribute of a real object is looked up, and every
loop, call depth and value size is bounded.
"""

from __future__ import annotations

import ast
import os
import re
import string
import tokenize
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from io import BytesIO
from typing import Any

from launch_linter.frontends.ros2_actions import (
    Action,
    Component,
    DeclareArg,
    Deferred,
    FileRead,
    Group,
    Include,
    LoadComponents,
    Params,
    ParamsUnknown,
    Predicate,
    Problem,
    PushNamespace,
    RunNode,
    SetEnv,
    SetVar,
    Unfollowed,
    Where,
    ros2_run,
)
from launch_linter.model.budget import Budget
from launch_linter.model.launch import DIRECTIVE_MARKER
from launch_linter.model.transform import LaunchFormat
from launch_linter.resolve.ros2_substitution import Call, Opaque, Sub, Subs, Text, literal
from launch_linter.resolve.value import Value, holes, resolved_text
from launch_linter.resolve.xml_safe import MAX_BYTES

FORMAT = LaunchFormat.ROS2_PYTHON
MAX_STEPS = 200_000
MAX_CALL_DEPTH = 16
MAX_ITEMS = 10_000
MAX_TEXT = 100_000
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


# -- values -----------------------------------------------------------------------------


@dataclass(frozen=True, slots=True)
class Unknown:
    """A value the linter cannot know: why, and where it was written."""

    reason: str
    text: str
    line: int

    def describe(self) -> str:
        return f"line {self.line}: {self.text}: {self.reason}"

    def hole(self, prefix: str = "") -> Opaque:
        """A substitution standing for this value: shows its text, says where and why."""
        return Opaque(prefix + self.text, f"line {self.line}: {self.reason}")


@dataclass(frozen=True, slots=True)
class SubsVal:
    """A launch substitution object (or a list of them): evaluated only when it runs."""

    subs: Subs


@dataclass(frozen=True)
class OpenFile:
    """``open(path)``: nothing is opened; ``.read()`` gives the file's text as the
    ``file-content`` substitution (a robot description read from a URDF file)."""

    path: Subs


@dataclass(frozen=True, slots=True)
class LazyStr:
    """A Python string (or path) whose value the linter computes later, from the same
    facts launch would use: a package location, an environment variable."""

    subs: Subs
    path: bool = False


@dataclass(slots=True)
class LaunchDescriptionVal:
    items: list[object]


@dataclass(frozen=True, slots=True)
class CondVal:
    predicate: Predicate


@dataclass(frozen=True, slots=True)
class SourceVal:
    path: Subs


@dataclass(frozen=True, slots=True)
class ComponentVal:
    component: Component


@dataclass(frozen=True, slots=True)
class ModuleVal:
    """A name imported from a module: ``launch_ros.actions.Node``, ``os.path``."""

    dotted: str

    @property
    def root(self) -> str:
        return self.dotted.split(".")[0]

    @property
    def last(self) -> str:
        return self.dotted.rsplit(".", 1)[-1]


@dataclass(frozen=True, slots=True)
class LaunchObject:
    """An instance of a launch class that starts no static transform."""

    name: str


@dataclass(frozen=True, slots=True)
class Builtin:
    name: str


@dataclass(slots=True)
class FuncVal:
    node: ast.FunctionDef | ast.AsyncFunctionDef | ast.Lambda
    closure: Env
    defaults: dict[str, object]


@dataclass(frozen=True, slots=True)
class BoundMethod:
    target: object
    name: str


@dataclass(frozen=True, slots=True)
class HandlerVal:
    """A process event handler: the entities it starts when the event happens."""

    entities: list[object]


@dataclass(frozen=True, slots=True)
class ContextVal:
    """The ``LaunchContext`` an ``OpaqueFunction`` receives."""

    resolver: Callable[[Subs], Value]


@dataclass(frozen=True, slots=True)
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


# -- the interpreter -----------------------------------------------------------------------


def _substitution(kind: str, arity: int) -> Callable[..., object]:
    """A launch substitution class, as a method of :class:`Interpreter`."""

    def make(self: Interpreter, args: list[object], kwargs: dict[str, object],
             node: ast.Call) -> object:
        values = list(args) + list(kwargs.values())
        subs = tuple(self.subs(v, node, "substitution argument")
                     for v in values[:arity] if v is not None)
        return SubsVal((Call(kind, subs, self.segment(node)),))

    return make


@dataclass(slots=True)
class Interpreter:
    path: str
    source: str
    problems: list[Problem] = field(default_factory=list)
    steps: int = 0
    depth: int = 0
    branches: list[Predicate] = field(default_factory=list)
    call_sites: list[ast.AST] = field(default_factory=list)
    """Calls of the file's own functions being run, outermost first."""
    lines: list[str] = field(default_factory=list)
    scopes: list[Env] = field(default_factory=list)
    """Every scope made, emptied at the end: a function and the scope it was defined in
    refer to each other, a cycle that would keep the file's syntax tree alive until the
    garbage collector finds it."""
    deferring: bool = False
    """Whether an ``OpaqueFunction`` will be run later, in its scopes (then they stay)."""
    served: list[object] = field(default_factory=list)
    """What a script gives ``LaunchService.include_launch_description``."""

    # -- helpers -------------------------------------------------------------------------
    def scope(self, parent: Env | None) -> Env:
        env = Env(parent)
        self.scopes.append(env)
        return env

    def forget_scopes(self) -> None:
        if self.deferring:
            return
        for env in self.scopes:
            env.vars.clear()
            env.parent = None
        self.scopes.clear()

    def step(self) -> None:
        self.steps += 1
        if self.steps > MAX_STEPS:
            raise _OutOfSteps

    def segment(self, node: ast.AST) -> str:
        """The first characters of the source text of ``node``, on one line."""
        if not self.lines:
            self.lines = self.source.splitlines(keepends=True)
        first = getattr(node, "lineno", 0) - 1
        last = getattr(node, "end_lineno", None)
        if not 0 <= first < len(self.lines) or last is None:
            return type(node).__name__
        # Columns are UTF-8 byte offsets; three lines are plenty for a short excerpt.
        chunk = [line.encode("utf-8") for line in self.lines[first:min(last, first + 3)]]
        if last - 1 < first + 3:
            chunk[-1] = chunk[-1][:getattr(node, "end_col_offset", None)]
        chunk[0] = chunk[0][getattr(node, "col_offset", 0):]
        text = " ".join(b"".join(chunk).decode("utf-8", "replace").split())
        return text if len(text) <= 120 else text[:117] + "..."

    def text_value(self, subs: Subs, node: ast.AST) -> object:
        """Text when every part is known, else a lazy string; refused when too long."""
        if sum(len(sub.text) for sub in subs if isinstance(sub, Text)) > MAX_TEXT:
            return self.unknown(node, f"text longer than {MAX_TEXT} characters")
        if all(isinstance(sub, Text) for sub in subs):
            return "".join(sub.text for sub in subs if isinstance(sub, Text))
        return LazyStr(subs)

    def unknown(self, node: ast.AST, reason: str) -> Unknown:
        return Unknown(reason, self.segment(node), getattr(node, "lineno", 1))

    def where(self, node: ast.AST) -> Where:
        """Where an action is reported: inside a helper function of the file, at the call
        of that helper, so that each call is its own place (to point at and suppress)."""
        site = self.call_sites[0] if self.call_sites else node
        return Where(self.path, getattr(site, "lineno", 1), getattr(site, "col_offset", 0) + 1)

    def problem(self, rule: str, node: ast.AST, message: str) -> None:
        where = self.where(node)
        self.problems.append(Problem(rule, where.line, where.column, message))

    def guard(self, value: object) -> object:
        """An action added under an unknown Python ``if`` is present only under it."""
        if not self.branches or not isinstance(value, Action):
            return value
        action: Action = value
        for predicate in reversed(self.branches):
            action = Group(action.where, predicate, (action,), scoped=False)
        return action

    # -- statements ------------------------------------------------------------------------
    def run_block(self, body: Sequence[ast.stmt], env: Env) -> None:
        for statement in body:
            self.run(statement, env)

    def run(self, node: ast.stmt, env: Env) -> None:
        self.step()
        if isinstance(node, ast.Expr):
            self.eval(node.value, env)
        elif isinstance(node, ast.Assign):
            value = self.eval(node.value, env)
            for target in node.targets:
                self.assign(target, value, env)
        elif isinstance(node, ast.AnnAssign):
            if node.value is not None:
                self.assign(node.target, self.eval(node.value, env), env)
        elif isinstance(node, ast.AugAssign):
            self.aug_assign(node, env)
        elif isinstance(node, ast.Return):
            raise _Return(None if node.value is None else self.eval(node.value, env))
        elif isinstance(node, ast.If):
            self.run_if(node, env)
        elif isinstance(node, ast.For):
            self.run_for(node, env)
        elif isinstance(node, ast.FunctionDef | ast.AsyncFunctionDef):
            defaults = self.defaults(node.args, env)
            env.vars[node.name] = FuncVal(node, env, defaults)
        elif isinstance(node, ast.Import):
            for alias in node.names:
                if alias.asname:
                    env.vars[alias.asname] = ModuleVal(alias.name)
                else:
                    top = alias.name.split(".")[0]
                    env.vars[top] = ModuleVal(top)
        elif isinstance(node, ast.ImportFrom):
            module = node.module or ""
            for alias in node.names:
                if alias.name != "*":
                    env.vars[alias.asname or alias.name] = ModuleVal(f"{module}.{alias.name}")
        elif isinstance(node, ast.Try):
            self.run_block(node.body, env)
            self.run_block(node.orelse, env)
            self.run_block(node.finalbody, env)
        elif isinstance(node, ast.With):
            for item in node.items:
                # ``with open(path) as f``: f.read() is the file's text, read by nobody.
                if isinstance(item.optional_vars, ast.Name):
                    value = self.eval(item.context_expr, env)
                    if isinstance(value, OpenFile):
                        env.vars[item.optional_vars.id] = value
            self.run_block(node.body, env)
        elif isinstance(node, ast.Break):
            raise _Break
        elif isinstance(node, ast.Continue):
            raise _Continue
        elif isinstance(node, ast.ClassDef):
            env.vars[node.name] = self.unknown(node, "classes are not interpreted")
        elif isinstance(node, ast.While):
            self.not_followed(node, "a while loop is not followed")

    def not_followed(self, node: ast.stmt, reason: str) -> None:
        """Report a statement skipped while it may start launch actions."""
        for inner in ast.walk(node):
            if isinstance(inner, ast.Call) and _called_name(inner.func) in ACTION_NAMES:
                self.problem("unresolved", node, f"{reason}: the launch actions in it "
                             f"(line {inner.lineno}) are not seen")
                return

    def defaults(self, arguments: ast.arguments, env: Env) -> dict[str, object]:
        values: dict[str, object] = {}
        positional = [*arguments.posonlyargs, *arguments.args]
        for arg, default in zip(positional[len(positional) - len(arguments.defaults):],
                                arguments.defaults, strict=True):
            values[arg.arg] = self.eval(default, env)
        for arg, kw_default in zip(arguments.kwonlyargs, arguments.kw_defaults, strict=True):
            if kw_default is not None:
                values[arg.arg] = self.eval(kw_default, env)
        return values

    def assign(self, target: ast.expr, value: object, env: Env) -> None:
        if isinstance(target, ast.Name):
            env.vars[target.id] = value
        elif isinstance(target, ast.Tuple | ast.List):
            names = target.elts
            if isinstance(value, list | tuple) and len(value) == len(names):
                for name, item in zip(names, value, strict=True):
                    self.assign(name, item, env)
            else:
                reason = value if isinstance(value, Unknown) else self.unknown(
                    target, "cannot unpack this value")
                for name in names:
                    self.assign(name, reason, env)
        elif isinstance(target, ast.Subscript):
            container = self.eval(target.value, env)
            key = self.eval(target.slice, env)
            if isinstance(container, dict) and isinstance(key, str | int | float | bool):
                container[key] = value

    def aug_assign(self, node: ast.AugAssign, env: Env) -> None:
        current = self.eval(node.target, env) if isinstance(node.target, ast.Name) else None
        value = self.eval(node.value, env)
        if isinstance(node.op, ast.Add) and isinstance(current, list) and isinstance(
            value, list | tuple
        ):
            self.extend(current, value)
            return
        if isinstance(node.target, ast.Name):
            env.vars[node.target.id] = self.binary(node.op, current, value, node)

    def extend(self, target: list[object], items: Sequence[object]) -> None:
        if len(target) + len(items) > MAX_ITEMS:
            raise _OutOfSteps
        target.extend(self.guard(item) for item in items)

    def run_if(self, node: ast.If, env: Env) -> None:
        test = self.truth(self.eval(node.test, env))
        if test is True:
            self.run_block(node.body, env)
            return
        if test is False:
            self.run_block(node.orelse, env)
            return
        text = self.segment(node.test)
        before = dict(env.vars)
        results: list[dict[str, object]] = []
        for positive, body in ((True, node.body), (False, node.orelse)):
            env.vars = dict(before)
            reason = f"Python condition at line {node.lineno} depends on an unknown value"
            self.branches.append(Predicate(positive, (Opaque(f"python: {text}", reason),)))
            try:
                self.run_block(body, env)
            finally:
                self.branches.pop()
            results.append(env.vars)
        env.vars = self.merge(before, results[0], results[1], node)

    def merge(self, before: dict[str, object], then: dict[str, object],
              otherwise: dict[str, object], node: ast.If) -> dict[str, object]:
        merged = dict(before)
        text = self.segment(node.test)
        for name in set(then) | set(otherwise):
            a, b = then.get(name), otherwise.get(name)
            if a is b:
                merged[name] = a
            elif isinstance(a, list) and isinstance(b, list):
                merged[name] = [
                    *self.under(a, True, text, node), *self.under(b, False, text, node)
                ]
            else:
                merged[name] = self.unknown(node.test, f"'{name}' depends on the condition "
                                                       f"'{text}'")
        return merged

    def under(self, items: list[object], positive: bool, text: str, node: ast.If
              ) -> list[object]:
        reason = f"Python condition at line {node.lineno} depends on an unknown value"
        self.branches.append(Predicate(positive, (Opaque(f"python: {text}", reason),)))
        try:
            return [self.guard(item) for item in items]
        finally:
            self.branches.pop()

    def iterate(self, value: object, node: ast.AST) -> list[object] | Unknown:
        if isinstance(value, list | tuple):
            return list(value)
        if isinstance(value, dict):
            return list(value)
        if isinstance(value, str):
            return list(value)
        if isinstance(value, Unknown):
            return value
        return self.unknown(node, "cannot iterate over this value")

    def run_for(self, node: ast.For, env: Env) -> None:
        items = self.iterate(self.eval(node.iter, env), node.iter)
        if isinstance(items, Unknown):
            self.not_followed(node, f"the loop over {items.text} ({items.reason})")
            return
        for item in items:
            self.assign(node.target, item, env)
            try:
                self.run_block(node.body, env)
            except _Break:
                return
            except _Continue:
                continue
        self.run_block(node.orelse, env)

    # -- expressions ---------------------------------------------------------------------
    def eval(self, node: ast.expr, env: Env) -> object:
        self.step()
        if isinstance(node, ast.Constant):
            if isinstance(node.value, str | int | float | bool) or node.value is None:
                return node.value
            return self.unknown(node, "unsupported constant")
        if isinstance(node, ast.Name):
            found, value = env.lookup(node.id)
            if found:
                return value
            if node.id == "__file__":
                return self.path
            if node.id == "__name__":
                return "__launch__"
            if node.id in BUILTINS:
                return Builtin(node.id)
            return self.unknown(node, f"name '{node.id}' is not known here")
        if isinstance(node, ast.List | ast.Tuple):
            items = self.sequence(node.elts, env, node)
            if isinstance(items, Unknown):
                return items
            return items if isinstance(node, ast.List) else tuple(items)
        if isinstance(node, ast.Dict):
            return self.mapping(node, env)
        if isinstance(node, ast.Attribute):
            return self.attribute(self.eval(node.value, env), node.attr, node)
        if isinstance(node, ast.Call):
            return self.call(node, env)
        if isinstance(node, ast.BinOp):
            return self.binary(node.op, self.eval(node.left, env), self.eval(node.right, env),
                               node)
        if isinstance(node, ast.JoinedStr):
            return self.fstring(node, env)
        if isinstance(node, ast.Compare):
            return self.compare(node, env)
        if isinstance(node, ast.BoolOp):
            return self.boolean(node, env)
        if isinstance(node, ast.UnaryOp):
            return self.unary(node, env)
        if isinstance(node, ast.IfExp):
            test = self.truth(self.eval(node.test, env))
            if test is None:
                return self.unknown(node, "depends on a condition the linter cannot decide")
            return self.eval(node.body if test else node.orelse, env)
        if isinstance(node, ast.Subscript):
            return self.subscript(self.eval(node.value, env), self.eval(node.slice, env), node)
        if isinstance(node, ast.ListComp | ast.GeneratorExp):
            return self.comprehension(node, env)
        if isinstance(node, ast.Lambda):
            return FuncVal(node, env, self.defaults(node.args, env))
        return self.unknown(node, f"{type(node).__name__} expressions are not interpreted")

    def sequence(self, elements: list[ast.expr], env: Env, node: ast.AST
                 ) -> list[object] | Unknown:
        items: list[object] = []
        for element in elements:
            if isinstance(element, ast.Starred):
                inner = self.iterate(self.eval(element.value, env), element)
                if isinstance(inner, Unknown):
                    return inner
                items.extend(inner)
            else:
                items.append(self.eval(element, env))
            if len(items) > MAX_ITEMS:
                return self.unknown(node, f"more than {MAX_ITEMS} items")
        return items

    def mapping(self, node: ast.Dict, env: Env) -> object:
        result: dict[object, object] = {}
        for key_node, value_node in zip(node.keys, node.values, strict=True):
            value = self.eval(value_node, env)
            if key_node is None:
                if not isinstance(value, dict):
                    return self.unknown(value_node, "cannot unpack this mapping")
                result.update(value)
                continue
            key = self.eval(key_node, env)
            if not isinstance(key, str | int | float | bool) and key is not None:
                return self.unknown(key_node, "dictionary key is not a known constant")
            result[key] = value
        return result

    def truth(self, value: object) -> bool | None:
        if isinstance(value, str | int | float | bool | list | tuple | dict) or value is None:
            return bool(value)
        if isinstance(value, Unknown | SubsVal | LazyStr):
            return None
        return True

    def attribute(self, base: object, name: str, node: ast.Attribute) -> object:
        if isinstance(base, ModuleVal):
            return ModuleVal(f"{base.dotted}.{name}")
        if isinstance(base, Unknown):
            return base
        if isinstance(base, ContextVal) and name == "launch_configurations":
            return ConfigsVal(base.resolver)
        if isinstance(base, list | dict | str | SubsVal | LazyStr | LaunchDescriptionVal |
                      ConfigsVal | OpenFile):
            return BoundMethod(base, name)
        if isinstance(base, LaunchObject) and base.name == "LaunchService" and (
            name == "include_launch_description"
        ):
            return BoundMethod(base, name)
        return self.unknown(node, f"attribute '{name}' is not interpreted")

    def fstring(self, node: ast.JoinedStr, env: Env) -> object:
        parts: list[Sub] = []
        for value in node.values:
            if isinstance(value, ast.Constant) and isinstance(value.value, str):
                parts.append(Text(value.value))
                continue
            if not isinstance(value, ast.FormattedValue):
                return self.unknown(value, "unexpected part of an f-string")
            if value.format_spec is not None or value.conversion not in (-1, 115):
                return self.unknown(value, "formatted values are not interpreted")
            inner = self.eval(value.value, env)
            if isinstance(inner, LazyStr):
                parts.extend(inner.subs)
            elif isinstance(inner, str | int | float | bool):
                parts.append(Text(str(inner)))
            elif isinstance(inner, Unknown):
                return inner
            else:
                return self.unknown(value, "a launch object cannot be put into a string")
        return self.text_value(tuple(parts), node)

    def binary(self, op: ast.operator, left: object, right: object, node: ast.AST) -> object:
        if isinstance(left, Unknown):
            return left
        if isinstance(right, Unknown):
            return right
        if isinstance(op, ast.Add):
            if isinstance(left, LazyStr | str) and isinstance(right, LazyStr | str):
                return self.text_value((*_as_subs(left), *_as_subs(right)), node)
            if isinstance(left, list) and isinstance(right, list):
                if len(left) + len(right) > MAX_ITEMS:
                    return self.unknown(node, f"more than {MAX_ITEMS} items")
                return left + right
            if isinstance(left, tuple) and isinstance(right, tuple):
                if len(left) + len(right) > MAX_ITEMS:
                    return self.unknown(node, f"more than {MAX_ITEMS} items")
                return left + right
        if isinstance(op, ast.Div) and isinstance(left, LazyStr) and left.path and isinstance(
            right, str | LazyStr
        ):
            return LazyStr((Call("path-join", (left.subs, _as_subs(right)),
                                 self.segment(node)),), path=True)
        if isinstance(op, ast.Mod) and isinstance(left, str):
            args = right if isinstance(right, tuple) else (right,)
            if all(isinstance(a, str | int | float | bool) for a in args) and (
                "%" not in _SAFE_PERCENT.sub("", left)
            ):
                try:
                    formatted = left % args
                except (TypeError, ValueError, OverflowError):
                    return self.unknown(node, "the % formatting fails")
                if len(formatted) > MAX_TEXT:
                    return self.unknown(node, "text too long")
                return formatted
        if isinstance(op, ast.Mult):
            count, item = (right, left) if isinstance(right, int) else (left, right)
            if isinstance(count, int) and not isinstance(count, bool) and isinstance(
                item, str | list | tuple
            ):
                if len(item) * max(count, 0) > MAX_ITEMS * 10:
                    return self.unknown(node, "value too large")
                return item * count
        numbers = (int, float)
        if isinstance(left, numbers) and isinstance(right, numbers) and not isinstance(
            op, ast.Pow | ast.LShift
        ):
            operations: dict[type, Callable[[Any, Any], object]] = {
                ast.Add: lambda a, b: a + b, ast.Sub: lambda a, b: a - b,
                ast.Mult: lambda a, b: a * b, ast.Div: lambda a, b: a / b,
                ast.FloorDiv: lambda a, b: a // b, ast.Mod: lambda a, b: a % b,
            }
            operation = operations.get(type(op))
            if operation is not None:
                try:
                    result = operation(left, right)
                except (ArithmeticError, ValueError):
                    return self.unknown(node, "the arithmetic fails")
                if isinstance(result, int) and abs(result) > 10**18:
                    return self.unknown(node, "number too large")
                return result
        return self.unknown(node, "this operation is not interpreted")

    def compare(self, node: ast.Compare, env: Env) -> object:
        left = self.eval(node.left, env)
        for op, right_node in zip(node.ops, node.comparators, strict=True):
            right = self.eval(right_node, env)
            if not _plain(left) or not _plain(right):
                return self.unknown(node, "compares a value the linter does not know")
            try:
                outcome = _COMPARE[type(op)](left, right)
            except (TypeError, KeyError):
                return self.unknown(node, "this comparison is not interpreted")
            if not outcome:
                return False
            left = right
        return True

    def boolean(self, node: ast.BoolOp, env: Env) -> object:
        value: object = None
        for operand in node.values:
            value = self.eval(operand, env)
            truth = self.truth(value)
            if truth is None:
                return self.unknown(node, "depends on a value the linter does not know")
            if truth == isinstance(node.op, ast.Or):
                return value
        return value

    def unary(self, node: ast.UnaryOp, env: Env) -> object:
        operand = self.eval(node.operand, env)
        if isinstance(node.op, ast.Not):
            truth = self.truth(operand)
            return self.unknown(node, "depends on an unknown value") if truth is None else (
                not truth)
        if isinstance(operand, int | float) and not isinstance(operand, bool):
            if isinstance(node.op, ast.USub):
                return -operand
            if isinstance(node.op, ast.UAdd):
                return operand
        return self.unknown(node, "this operation is not interpreted")

    def subscript(self, base: object, key: object, node: ast.Subscript) -> object:
        if isinstance(base, Unknown):
            return base
        if isinstance(key, Unknown):
            return key
        if isinstance(base, ConfigsVal) and isinstance(key, str):
            return _performed(base.resolver, (Call("var", (literal(key),), self.segment(node)),),
                              node, self)
        if isinstance(base, ModuleVal) and base.dotted == "os.environ" and isinstance(key, str):
            return LazyStr((Call("env", (literal(key),), self.segment(node)),))
        try:
            if isinstance(base, dict):
                return base[key]
            if isinstance(base, list | tuple | str) and isinstance(key, int):
                return base[key]
        except (KeyError, IndexError, TypeError):
            return self.unknown(node, "the key or index is not there")
        return self.unknown(node, "this subscript is not interpreted")

    def comprehension(self, node: ast.ListComp | ast.GeneratorExp, env: Env) -> object:
        if len(node.generators) != 1 or node.generators[0].is_async:
            return self.unknown(node, "nested comprehensions are not interpreted")
        generator = node.generators[0]
        items = self.iterate(self.eval(generator.iter, env), generator.iter)
        if isinstance(items, Unknown):
            return items
        inner = self.scope(env)
        out: list[object] = []
        for item in items:
            self.assign(generator.target, item, inner)
            keep = [self.truth(self.eval(test, inner)) for test in generator.ifs]
            if any(k is None for k in keep):
                return self.unknown(node, "a filter depends on an unknown value")
            if all(keep):
                out.append(self.eval(node.elt, inner))
        return out

    # -- calls ---------------------------------------------------------------------------
    def call(self, node: ast.Call, env: Env) -> object:
        function = self.eval(node.func, env)
        args: list[object] = []
        for arg in node.args:
            if isinstance(arg, ast.Starred):
                inner = self.iterate(self.eval(arg.value, env), arg)
                if isinstance(inner, Unknown):
                    return self.unknown(node, f"its arguments are unknown ({inner.reason})")
                args.extend(inner)
            else:
                args.append(self.eval(arg, env))
        kwargs: dict[str, object] = {}
        for keyword in node.keywords:
            value = self.eval(keyword.value, env)
            if keyword.arg is None:
                if not isinstance(value, dict):
                    return self.unknown(node, "its keyword arguments are unknown")
                kwargs.update({str(k): v for k, v in value.items()})
            else:
                kwargs[keyword.arg] = value
        if isinstance(function, Unknown):
            return self.unknown(node, f"calls {function.text}, which is unknown")
        if isinstance(function, FuncVal):
            self.call_sites.append(node)
            try:
                return self.call_function(function, args, kwargs, node)
            finally:
                self.call_sites.pop()
        if isinstance(function, BoundMethod):
            return self.method(function, args, kwargs, node)
        if isinstance(function, Builtin):
            return self.builtin(function.name, args, node)
        if isinstance(function, ModuleVal):
            return self.library(function, args, kwargs, node)
        return self.unknown(node, "calls something that is not a function")

    def call_function(self, function: FuncVal, args: list[object], kwargs: dict[str, object],
                      node: ast.AST) -> object:
        if self.depth >= MAX_CALL_DEPTH:
            return self.unknown(node, f"calls nested deeper than {MAX_CALL_DEPTH}")
        spec = function.node.args
        local = self.scope(function.closure)
        names = [a.arg for a in (*spec.posonlyargs, *spec.args)]
        for name, value in zip(names, args, strict=False):
            local.vars[name] = value
        if len(args) > len(names):
            if spec.vararg is None:
                return self.unknown(node, "too many arguments")
            local.vars[spec.vararg.arg] = tuple(args[len(names):])
        elif spec.vararg is not None:
            local.vars[spec.vararg.arg] = ()
        extra: dict[str, object] = {}
        for name, value in kwargs.items():
            if name in names or name in (a.arg for a in spec.kwonlyargs):
                local.vars[name] = value
            else:
                extra[name] = value
        if spec.kwarg is not None:
            local.vars[spec.kwarg.arg] = extra
        for name in [*names, *(a.arg for a in spec.kwonlyargs)]:
            if name not in local.vars:
                local.vars[name] = function.defaults.get(
                    name, self.unknown(node, f"argument '{name}' is not given"))
        self.depth += 1
        try:
            if isinstance(function.node, ast.Lambda):
                return self.eval(function.node.body, local)
            self.run_block(function.node.body, local)
        except _Return as result:
            return result.value
        except (_Break, _Continue):
            return self.unknown(node, "break or continue outside a loop")
        finally:
            self.depth -= 1
        return None

    def builtin(self, name: str, args: list[object], node: ast.Call) -> object:
        if name == "print":
            return None
        if name == "open" and args and isinstance(args[0], (str, LazyStr)):
            return OpenFile(self.subs(args[0], node, "file name"))
        if any(isinstance(a, Unknown) for a in args):
            return next(a for a in args if isinstance(a, Unknown))
        if name == "str" and len(args) == 1:
            if isinstance(args[0], str | int | float | bool) or args[0] is None:
                return str(args[0])
            if isinstance(args[0], LazyStr):
                return LazyStr(args[0].subs)
        if name in ("list", "tuple") and len(args) == 1:
            items = self.iterate(args[0], node)
            if isinstance(items, Unknown):
                return items
            return items if name == "list" else tuple(items)
        if name in ("list", "tuple", "dict") and not args:
            return {"list": [], "tuple": (), "dict": {}}[name]
        if name == "len" and len(args) == 1 and isinstance(args[0], list | tuple | str | dict):
            return len(args[0])
        bounds = [a for a in args if isinstance(a, int)]
        if name == "range" and len(bounds) == len(args) and 1 <= len(args) <= 3:
            try:
                numbers = range(*bounds)
            except ValueError:
                return self.unknown(node, "range() with a zero step")
            if len(numbers) > MAX_ITEMS:
                return self.unknown(node, "range too long")
            return list(numbers)
        if name in ("enumerate", "zip", "sorted"):
            lists = [self.iterate(a, node) for a in args]
            if any(isinstance(items, Unknown) for items in lists):
                return self.unknown(node, "iterates over an unknown value")
            sequences = [items for items in lists if isinstance(items, list)]
            if name == "enumerate" and len(sequences) == 1:
                return [(i, v) for i, v in enumerate(sequences[0])]
            if name == "zip":
                return [tuple(group) for group in zip(*sequences, strict=False)]
            if name == "sorted" and len(sequences) == 1 and all(
                isinstance(v, str | int | float) for v in sequences[0]
            ):
                try:
                    return sorted(sequences[0])  # type: ignore[type-var]
                except TypeError:
                    return self.unknown(node, "cannot sort these values")
        if name in ("int", "float", "bool", "abs", "round", "min", "max") and all(
            isinstance(a, str | int | float | bool) for a in args
        ) and args:
            try:
                return _PLAIN_BUILTINS[name](*args)
            except (TypeError, ValueError, OverflowError):
                return self.unknown(node, f"{name}() fails on these values")
        return self.unknown(node, f"{name}() on these values is not interpreted")

    def method(self, method: BoundMethod, args: list[object], kwargs: dict[str, object],
               node: ast.Call) -> object:
        target, name = method.target, method.name
        if isinstance(target, OpenFile) and name == "read" and not args:
            return LazyStr((Call("file-content", (target.path,), self.segment(node)),))
        if isinstance(target, list):
            if name == "append" and len(args) == 1:
                self.extend(target, [args[0]])
                return None
            if name == "extend" and len(args) == 1:
                items = self.iterate(args[0], node)
                if isinstance(items, Unknown):
                    target.append(items)
                else:
                    self.extend(target, items)
                return None
            if name == "insert" and len(args) == 2 and isinstance(args[0], int):
                target.insert(args[0], self.guard(args[1]))
                return None
        if isinstance(target, LaunchObject) and target.name == "LaunchService" and (
            name == "include_launch_description" and len(args) == 1
        ):
            # A script-style file: what it would serve is its launch description.
            self.served.append(args[0])
            return None
        if isinstance(target, LaunchDescriptionVal) and name in ("add_action", "add_entity"):
            if len(args) == 1:
                target.items.append(self.guard(args[0]))
            return None
        if isinstance(target, dict):
            if name == "items" and not args:
                return list(target.items())
            if name == "keys" and not args:
                return list(target)
            if name == "values" and not args:
                return list(target.values())
            if name == "get" and 1 <= len(args) <= 2:
                return target.get(args[0], args[1] if len(args) == 2 else None)
            if name == "update" and len(args) == 1 and isinstance(args[0], dict):
                target.update(args[0])
                return None
        if isinstance(target, str):
            return self.string_method(target, name, args, node)
        if isinstance(target, SubsVal | LazyStr) and name == "perform":
            if len(args) == 1 and isinstance(args[0], ContextVal):
                return _performed(args[0].resolver, target.subs, node, self)
            return self.unknown(node, "perform() without the launch context")
        if isinstance(target, ConfigsVal) and name == "get" and 1 <= len(args) <= 2:
            key = args[0]
            if isinstance(key, str):
                default = args[1] if len(args) == 2 else None
                subs: Subs = (Call("var", (literal(key),), self.segment(node)),)
                value = target.resolver(subs)
                text = resolved_text(value)
                if text is not None:
                    return text
                if all("is not set" in h.reason for h in holes(value)):
                    return default
                return self.unknown(node, "; ".join(h.reason for h in holes(value)))
        return self.unknown(node, f"method '{name}' is not interpreted")

    def string_method(self, target: str, name: str, args: list[object], node: ast.Call
                      ) -> object:
        if name == "join" and len(args) == 1 and isinstance(args[0], list | tuple) and all(
            isinstance(item, str | LazyStr) for item in args[0]
        ):
            parts: list[Sub] = []
            for position, item in enumerate(args[0]):
                if position:
                    parts.extend(literal(target))
                parts.extend(_as_subs(item))
            return self.text_value(tuple(parts), node)
        if name == "format":
            return self.format(target, args, node)
        if not all(isinstance(a, str | int) for a in args):
            return self.unknown(node, f"str.{name}() on unknown values")
        simple: dict[str, Callable[..., object]] = {
            "split": str.split, "strip": str.strip, "lstrip": str.lstrip,
            "rstrip": str.rstrip, "lower": str.lower, "upper": str.upper,
            "replace": str.replace, "startswith": str.startswith, "endswith": str.endswith,
        }
        if name == "replace" and len(args) >= 2 and isinstance(args[1], str) and (
            len(target) * (len(args[1]) + 1) > MAX_TEXT
        ):
            return self.unknown(node, "str.replace() could make too long a text")
        if name in simple:
            try:
                return simple[name](target, *args)
            except (TypeError, ValueError):
                return self.unknown(node, f"str.{name}() fails")
        return self.unknown(node, f"str.{name}() is not interpreted")

    def format(self, template: str, args: list[object], node: ast.Call) -> object:
        """``str.format`` with plain ``{}``/``{0}`` fields only (no specs: they are
        unbounded in size)."""
        parts: list[Sub] = []
        automatic = 0
        try:
            fields = list(string.Formatter().parse(template))
        except ValueError:
            return self.unknown(node, "malformed format string")
        for text, field_name, spec, conversion in fields:
            parts.extend(literal(text))
            if field_name is None:
                continue
            if spec or conversion or not (field_name == "" or field_name.isdigit()):
                return self.unknown(node, "str.format() with this field is not interpreted")
            index = automatic if field_name == "" else int(field_name)
            automatic += 1
            if index >= len(args):
                return self.unknown(node, "str.format() is missing an argument")
            value = args[index]
            if isinstance(value, LazyStr):
                parts.extend(value.subs)
            elif isinstance(value, str | int | float | bool):
                parts.extend(literal(str(value)))
            else:
                return self.unknown(node, "str.format() of an unknown value")
        return self.text_value(tuple(parts), node)

    # -- the launch library ---------------------------------------------------------------
    def library(self, module: ModuleVal, args: list[object], kwargs: dict[str, object],
                node: ast.Call) -> object:
        dotted, name = module.dotted, module.last
        if dotted in ("os.path.join", "os.path.dirname", "os.path.abspath", "os.path.realpath",
                      "os.path.normpath", "os.getenv", "os.environ.get", "pathlib.Path",
                      "os.path.expanduser"):
            return self.os_call(dotted, args, node)
        if module.root == "ament_index_python":
            return self.ament(name, args, node)
        if module.root not in LAUNCH_ROOTS:
            return self.unknown(node, f"calls '{dotted}', which the linter does not model")
        if name == "Parameter" and ".substitutions" in dotted:
            # launch_ros.substitutions.Parameter is $(param); descriptions.Parameter is not.
            return _substitution("param", 2)(self, args, kwargs, node)
        handler = getattr(self, f"launch_{name}", None)
        if handler is None:
            if name in ("ParameterValue", "ParameterFile") and args:
                return args[0] if name == "ParameterValue" else self.unknown(
                    node, "parameters from a file")
            return LaunchObject(name)
        result: object = handler(args, kwargs, node)
        return result

    def os_call(self, dotted: str, args: list[object], node: ast.Call) -> object:
        if any(isinstance(a, Unknown) for a in args):
            return next(a for a in args if isinstance(a, Unknown))
        if dotted in ("os.getenv", "os.environ.get") and args and isinstance(args[0], str):
            call_args: tuple[Subs, ...] = (literal(args[0]),)
            if len(args) > 1:
                default = _as_subs(args[1]) if isinstance(args[1], str | LazyStr) else None
                if default is None:
                    return self.unknown(node, "default is not text")
                call_args += (default,)
            return LazyStr((Call("env", call_args, self.segment(node)),))
        if not all(isinstance(a, str | LazyStr) for a in args) or not args:
            return self.unknown(node, "path of unknown values")
        if all(isinstance(a, str) for a in args):
            texts = [a for a in args if isinstance(a, str)]
            operations: dict[str, Callable[..., str]] = {
                "os.path.join": os.path.join, "os.path.dirname": os.path.dirname,
                "os.path.abspath": os.path.abspath, "os.path.realpath": os.path.abspath,
                "os.path.normpath": os.path.normpath, "pathlib.Path": os.path.join,
                "os.path.expanduser": lambda p: p,
            }
            return operations[dotted](*texts)
        parts = tuple(_as_subs(a) for a in args if isinstance(a, str | LazyStr))
        if dotted in ("os.path.join", "pathlib.Path"):
            return LazyStr((Call("path-join", parts, self.segment(node)),),
                           path=dotted == "pathlib.Path")
        if dotted in ("os.path.abspath", "os.path.realpath", "os.path.normpath",
                      "os.path.expanduser") and len(parts) == 1:
            return LazyStr(parts[0])
        return self.unknown(node, f"{dotted}() of a value known only at launch time")

    def ament(self, name: str, args: list[object], node: ast.Call) -> object:
        if len(args) != 1 or not isinstance(args[0], str | LazyStr):
            return self.unknown(node, f"{name}() of an unknown package")
        kind = {"get_package_share_directory": "find-pkg-share",
                "get_package_share_path": "find-pkg-share",
                "get_package_prefix": "find-pkg-prefix"}.get(name)
        if kind is None:
            return self.unknown(node, f"{name}() is not modelled")
        return LazyStr((Call(kind, (_as_subs(args[0]),), self.segment(node)),),
                       path=name.endswith("_path"))

    def arg(self, args: list[object], kwargs: dict[str, object], position: int, name: str
            ) -> object:
        if name in kwargs:
            return kwargs[name]
        return args[position] if position < len(args) else None

    def subs(self, value: object, node: ast.AST, what: str) -> Subs:
        """A value as launch's ``SomeSubstitutionsType``."""
        if isinstance(value, str):
            return literal(value)
        if isinstance(value, SubsVal | LazyStr):
            return value.subs
        if isinstance(value, Unknown):
            return (value.hole(),)
        if isinstance(value, list | tuple):
            parts: list[Sub] = []
            for item in value:
                parts.extend(self.subs(item, node, what))
            return tuple(parts)
        if isinstance(value, int | float) and not isinstance(value, bool):
            self.problem("roslaunch_error", node, f"{what} {value!r} is a number: launch "
                         f"only takes text or substitutions ('Failed to normalize given item "
                         f"of type {type(value).__name__}')")
            return literal(str(value))
        return (Opaque(self.segment(node), f"line {getattr(node, 'lineno', 1)}: {what} is "
                                           f"not text"),)

    def optional_subs(self, value: object, node: ast.AST, what: str) -> Subs | None:
        return None if value is None else self.subs(value, node, what)

    def condition(self, kwargs: dict[str, object], node: ast.Call) -> Predicate | None:
        value = kwargs.get("condition")
        if value is None:
            return None
        if isinstance(value, CondVal):
            return value.predicate
        unknown = value if isinstance(value, Unknown) else self.unknown(node, "unknown condition")
        return Predicate(True, (unknown.hole("python: "),))

    def actions(self, value: object, node: ast.AST) -> tuple[Action, ...]:
        """Launch entities given as a list (or one), flattened into actions."""
        found: list[Action] = []
        pending: list[object] = list(value) if isinstance(value, list | tuple) else [value]
        while pending:
            item = pending.pop(0)
            if isinstance(item, LaunchDescriptionVal):
                pending[:0] = item.items
            elif isinstance(item, list | tuple):
                pending[:0] = list(item)
            elif isinstance(item, Unknown):
                found.append(Unfollowed(Where(self.path, item.line, 1),
                                        f"launch entity not followed: {item.describe()}"))
            elif isinstance(item, Action):
                found.append(item)
        return tuple(found)

    def launch_LaunchDescription(self, args: list[object], kwargs: dict[str, object],
                                 node: ast.Call) -> object:
        initial = self.arg(args, kwargs, 0, "initial_entities")
        if initial is None:
            return LaunchDescriptionVal([])
        if isinstance(initial, list | tuple):
            return LaunchDescriptionVal([self.guard(item) for item in initial])
        return LaunchDescriptionVal([initial])

    def launch_Node(self, args: list[object], kwargs: dict[str, object], node: ast.Call
                    ) -> object:
        def pick(*names: str) -> object:
            return next((kwargs[n] for n in names if n in kwargs), None)

        arguments = pick("arguments")
        items: tuple[Subs, ...] | None
        unknown = ""
        if arguments is None:
            items = ()
        elif isinstance(arguments, list | tuple):
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
        legacy = [k for k in _LEGACY_NODE_KEYWORDS if k in kwargs]
        if legacy:
            # Kept as a note: evidence of a Foxy target, an error on later distributions
            # (the rule ros2_removed_keyword decides with the target distribution).
            self.problem("ros2_removed_keyword", node, ", ".join(
                f"{k}= (now {_LEGACY_NODE_KEYWORDS[k]}=)" for k in legacy))
        executable = pick("executable", "node_executable")
        return RunNode(
            where=self.where(node),
            condition=self.condition(kwargs, node),
            package=self.optional_subs(pick("package"), node, "package"),
            executable=self.optional_subs(executable, node, "executable"),
            name=self.optional_subs(pick("name", "node_name"), node, "name"),
            namespace=self.optional_subs(pick("namespace", "node_namespace"), node, "namespace"),
            arguments=items,
            args_written=self.segment(_keyword(node, "arguments") or node),
            unknown=unknown,
            parameters=self.parameters(pick("parameters"), node),
        )

    def launch_ExecuteProcess(self, args: list[object], kwargs: dict[str, object],
                              node: ast.Call) -> object:
        """``ExecuteProcess(cmd=['ros2', 'run', PKG, EXEC, ARGS...])`` starts that node;
        other processes are not transforms."""
        cmd = self.arg(args, kwargs, 0, "cmd")
        if not isinstance(cmd, list | tuple) or kwargs.get("shell") is True:
            return LaunchObject("ExecuteProcess")
        run = ros2_run([self.subs(item, node, "cmd item") for item in cmd])
        if run is None:
            return LaunchObject("ExecuteProcess")
        package, executable, arguments = run
        return RunNode(
            where=self.where(node), condition=self.condition(kwargs, node), package=package,
            executable=executable, name=None, namespace=None, arguments=arguments,
            args_written=self.segment(_keyword(node, "cmd") or node), pushed_namespace=False,
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
        if isinstance(launch_arguments, list | tuple):
            for pair in launch_arguments:
                if isinstance(pair, tuple | list) and len(pair) == 2:
                    pairs.append((self.subs(pair[0], node, "argument name"),
                                  self.subs(pair[1], node, "argument value")))
        elif launch_arguments is not None:
            self.problem("unresolved", node, "launch_arguments of this include are unknown")
        return Include(self.where(node), self.condition(kwargs, node), path, tuple(pairs))

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
        if not isinstance(function, FuncVal) or not isinstance(extra_args, list | tuple) or (
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
        notes = tuple(
            Unfollowed(Where(self.path, p.line, p.column),
                       f"in OpaqueFunction {name}(): {p.message}")
            for p in met
        )
        found = self.actions(result, node) if result is not None else ()
        if not found and not notes and _starts_actions(function.node):
            notes = (Unfollowed(where, f"line {node.lineno}: OpaqueFunction "
                                       f"{name}() builds launch actions but "
                                       f"returns none the linter can follow"),)
        return (*notes, *found)

    launch_LaunchConfiguration = _substitution("var", 2)
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
        if not isinstance(parts, list | tuple):
            return self.unknown(node, "PathJoinSubstitution of an unknown list")
        return SubsVal((Call("path-join", tuple(self.subs(p, node, "path part") for p in parts),
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
        variable = Call("var", (name,), self.segment(node))
        return CondVal(Predicate(True, (Call("equals", ((variable,), expected),
                                             self.segment(node)),)))

    def launch_LaunchConfigurationNotEquals(self, args: list[object],
                                            kwargs: dict[str, object], node: ast.Call
                                            ) -> object:
        condition = self.launch_LaunchConfigurationEquals(args, kwargs, node)
        assert isinstance(condition, CondVal)
        return CondVal(Predicate(False, condition.predicate.expression))

    def launch_ComposableNode(self, args: list[object], kwargs: dict[str, object],
                              node: ast.Call) -> object:
        return ComponentVal(Component(
            where=self.where(node),
            condition=self.condition(kwargs, node),
            package=self.optional_subs(kwargs.get("package"), node, "package"),
            plugin=self.optional_subs(kwargs.get("plugin"), node, "plugin"),
            name=self.optional_subs(kwargs.get("name"), node, "name"),
            namespace=self.optional_subs(kwargs.get("namespace"), node, "namespace"),
            parameters=self.parameters(kwargs.get("parameters"), node),
        ))

    def parameters(self, value: object, node: ast.Call) -> tuple[Params | ParamsUnknown, ...]:
        if value is None:
            return ()
        if not isinstance(value, list | tuple):
            return (ParamsUnknown(f"line {node.lineno}: parameters are not a list"),)
        out: list[Params | ParamsUnknown] = []
        for entry in value:
            if isinstance(entry, dict):
                items: list[tuple[str, Subs]] = []
                if not self.flatten(entry, "", items, node):
                    out.append(ParamsUnknown(f"line {node.lineno}: a parameter name or value "
                                             f"is unknown"))
                out.append(Params(tuple(items)))
            else:
                reason = entry.describe() if isinstance(entry, Unknown) else (
                    f"line {node.lineno}: parameters from a file")
                out.append(ParamsUnknown(reason))
        return tuple(out)

    def flatten(self, entry: dict[object, object], prefix: str,
                items: list[tuple[str, Subs]], node: ast.Call) -> bool:
        complete = True
        for key, value in entry.items():
            if not isinstance(key, str):
                complete = False
                continue
            if isinstance(value, dict):
                complete = self.flatten(value, f"{prefix}{key}.", items, node) and complete
            elif isinstance(value, bool):
                items.append((prefix + key, literal(str(value).lower())))
            elif isinstance(value, int | float):
                items.append((prefix + key, literal(repr(value))))
            elif isinstance(value, str | SubsVal | LazyStr | Unknown):
                items.append((prefix + key, self.subs(value, node, "parameter")))
        return complete

    def _container(self, args: list[object], kwargs: dict[str, object], node: ast.Call
                   ) -> object:
        descriptions = kwargs.get("composable_node_descriptions") or []
        if not isinstance(descriptions, list | tuple):
            return Unfollowed(self.where(node), f"line {node.lineno}: composable nodes of "
                                                f"{self.segment(node)} are unknown")
        components = tuple(d.component for d in descriptions if isinstance(d, ComponentVal))
        return LoadComponents(self.where(node), self.condition(kwargs, node), components)

    launch_ComposableNodeContainer = _container
    launch_LoadComposableNodes = _container


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


_SAFE_PERCENT = re.compile(r"%(?:[-+ #0]*\d{0,3}(?:\.\d{0,3})?[sdifgeEr]|%)")
"""``%`` conversions with small widths: wider ones could build huge strings."""


def _plain(value: object) -> bool:
    return isinstance(value, str | int | float | bool | list | tuple | dict) or value is None


def _performed(resolver: Callable[[Subs], Value], subs: Subs, node: ast.AST,
               interpreter: Interpreter) -> object:
    value = resolver(subs)
    text = resolved_text(value)
    if text is not None:
        return text
    return interpreter.unknown(node, "; ".join(f"{h.text}: {h.reason}" for h in holes(value)))


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


def _directive_comments(data: bytes) -> tuple[tuple[int, str], ...]:
    """The comments of a file that may hold a suppression directive, else none."""
    if DIRECTIVE_MARKER.encode() not in data:
        return ()
    found: list[tuple[int, str]] = []
    try:
        for token in tokenize.tokenize(BytesIO(data).readline):
            if token.type == tokenize.COMMENT:
                found.append((token.start[0], token.string[1:]))
    except (tokenize.TokenError, SyntaxError, UnicodeDecodeError):
        return tuple(found)
    return tuple(found)


def read_python(path: str, data: bytes, budget: Budget | None = None) -> FileRead:
    """Read a ROS 2 Python launch file (``path`` absolute, ``data`` its bytes)."""
    if len(data) > MAX_BYTES:
        message = f"file is {len(data)} bytes, larger than the {MAX_BYTES}-byte limit"
        return FileRead(FORMAT, None, problems=(Problem("parse_error", 1, 1, message),))
    try:
        # A byte order mark is allowed, as Python itself allows it.
        source = data.decode("utf-8-sig")
        tree = ast.parse(source, filename=path)
    except UnicodeDecodeError as exc:
        message = f"not UTF-8 text: {exc.reason}"
        return FileRead(FORMAT, None, problems=(Problem("parse_error", 1, 1, message),))
    except SyntaxError as exc:
        problem = Problem("parse_error", exc.lineno or 1, (exc.offset or 0) or 1,
                          f"not valid Python: {exc.msg}")
        return FileRead(FORMAT, None, _directive_comments(data), (), (problem,))
    except (RecursionError, MemoryError, ValueError) as exc:
        message = f"not readable Python: {type(exc).__name__}"
        return FileRead(FORMAT, None, problems=(Problem("parse_error", 1, 1, message),))
    comments = _directive_comments(data)
    # Statement lines only place directives: skipped (with the tokenizer) in the many files
    # that hold none.
    lines = (
        sorted({n.lineno for n in ast.walk(tree) if isinstance(n, ast.stmt | ast.Call)})
        if comments else ()
    )
    interpreter = Interpreter(path, source)
    actions = _launch_description(interpreter, tree)
    if budget is not None:
        # The interpreter's own step limit bounds one file; the root file's budget bounds
        # a file included many times.
        budget.step(interpreter.steps)
    return FileRead(FORMAT, actions, comments, tuple(lines), tuple(interpreter.problems))


ENTRY_POINTS = ("generate_launch_description", "generate_test_description")
"""What ``ros2 launch`` and ``launch_testing`` call; ``launch_pytest`` fixtures next."""


def _is_launch_pytest_fixture(decorator: ast.expr) -> bool:
    """``@launch_pytest.fixture``, ``@launch_pytest.fixture(...)`` or a bare ``@fixture``
    imported from it (checked by the caller)."""
    target = decorator.func if isinstance(decorator, ast.Call) else decorator
    return (
        isinstance(target, ast.Attribute) and target.attr == "fixture"
        and isinstance(target.value, ast.Name) and target.value.id == "launch_pytest"
    )


def _entry_point(tree: ast.Module, module: Env) -> tuple[str, FuncVal] | None:
    for name in ENTRY_POINTS:
        found, function = module.lookup(name)
        if found and isinstance(function, FuncVal):
            return name, function
    fixture_imported = any(
        isinstance(statement, ast.ImportFrom) and statement.module == "launch_pytest"
        and any(alias.name == "fixture" and alias.asname is None for alias in statement.names)
        for statement in tree.body
    )
    for statement in tree.body:
        if not isinstance(statement, ast.FunctionDef):
            continue
        for decorator in statement.decorator_list:
            bare = decorator.func if isinstance(decorator, ast.Call) else decorator
            if _is_launch_pytest_fixture(decorator) or (
                fixture_imported and isinstance(bare, ast.Name) and bare.id == "fixture"
            ):
                found, function = module.lookup(statement.name)
                if found and isinstance(function, FuncVal):
                    return statement.name, function
    return None


def _yield_as_return(function: FuncVal) -> FuncVal:
    """A fixture that ``yield``s its launch description (then cleans up) gives what it
    yields first: its body up to that statement, with the ``yield`` read as ``return``."""
    node = function.node
    if not isinstance(node, ast.FunctionDef):
        return function
    for index, statement in enumerate(node.body):
        if isinstance(statement, ast.Expr) and isinstance(statement.value, ast.Yield):
            returned = ast.copy_location(ast.Return(value=statement.value.value), statement)
            body = [*node.body[:index], returned]
            copy = ast.copy_location(ast.FunctionDef(
                name=node.name, args=node.args, body=body, decorator_list=[],
                returns=None, type_comment=None,
            ), node)
            return FuncVal(copy, function.closure, function.defaults)
    return function


def _served(interpreter: Interpreter, module: Env) -> LaunchDescriptionVal | None:
    """A script's launch description: what its module code, or else its ``main()``,
    gives ``LaunchService().include_launch_description``."""
    if not interpreter.served:
        found, main = module.lookup("main")
        if found and isinstance(main, FuncVal):
            interpreter.call_function(main, [], {}, main.node)
    if not interpreter.served:
        return None
    items: list[object] = []
    for description in interpreter.served:
        if isinstance(description, LaunchDescriptionVal):
            items.extend(description.items)
        else:
            items.append(description)
    return LaunchDescriptionVal(items)


def _fixture_arguments(interpreter: Interpreter, function: FuncVal, module: Env
                       ) -> dict[str, object]:
    """pytest passes a fixture's parameters from the fixtures of the same name: the
    module's own functions of those names are called (without arguments)."""
    values: dict[str, object] = {}
    for parameter in function.node.args.args:
        found, fixture = module.lookup(parameter.arg)
        if found and isinstance(fixture, FuncVal) and fixture is not function:
            values[parameter.arg] = interpreter.call_function(fixture, [], {}, fixture.node)
    return values


def _launch_description(interpreter: Interpreter, tree: ast.Module) -> tuple[Action, ...]:
    try:
        return _run_launch_description(interpreter, tree)
    finally:
        interpreter.forget_scopes()


def _run_launch_description(interpreter: Interpreter, tree: ast.Module) -> tuple[Action, ...]:
    module = interpreter.scope(None)
    top = Where(interpreter.path, 1, 1)
    try:
        interpreter.run_block(tree.body, module)
        entry = _entry_point(tree, module)
        if entry is None:
            served = _served(interpreter, module)
            if served is not None:
                return interpreter.actions(served.items, tree)
            interpreter.problems.append(Problem(
                "unresolved", 1, 1,
                "no generate_launch_description(), generate_test_description() or "
                "launch_pytest fixture: not a launch file ros2 launch can load; not read",
            ))
            return ()
        entry_name, function = entry
        node = function.node
        arguments = (_fixture_arguments(interpreter, function, module)
                     if entry_name not in ENTRY_POINTS else {})
        function = _yield_as_return(function)
        result = interpreter.call_function(function, [], arguments, node)
        if isinstance(result, (tuple, list)) and result and isinstance(
            result[0], LaunchDescriptionVal
        ):
            # launch_testing's (LaunchDescription, {name: process, ...}) form.
            result = result[0]
    except _OutOfSteps:
        return (Unfollowed(top, f"stopped interpreting after {MAX_STEPS} steps: the launch "
                                f"description is not followed"),)
    except RecursionError:
        return (Unfollowed(top, "expressions nested too deeply: the launch description is "
                                "not followed"),)
    except (_Return, _Break, _Continue):
        return (Unfollowed(top, "return, break or continue outside a function"),)
    if isinstance(result, LaunchDescriptionVal):
        return interpreter.actions(result.items, node)
    if isinstance(result, Unknown):
        return (Unfollowed(Where(interpreter.path, result.line, 1),
                           f"the launch description is unknown: {result.describe()}"),)
    return interpreter.actions(result, node)
