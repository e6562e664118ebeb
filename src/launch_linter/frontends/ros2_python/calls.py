"""Calls in ROS 2 Python launch files: the file's own functions, Python's builtins and
methods on known values, ``os.path``/``os.environ`` and ``ament_index_python``, and the
conversions of values into launch substitutions and actions that the launch API uses.
"""

from __future__ import annotations

import ast
import os
from collections.abc import Callable

from launch_linter.frontends.ros2_actions import (
    ACTION_TYPES,
    Action,
    Predicate,
    Unfollowed,
    Uses,
    Where,
)
from launch_linter.frontends.ros2_python import moveit
from launch_linter.frontends.ros2_python.evaluator import _performed
from launch_linter.frontends.ros2_python.expressions import Expressions
from launch_linter.frontends.ros2_python.values import (
    _PLAIN_BUILTINS,
    BoundMethod,
    Builtin,
    CondVal,
    ConfigsVal,
    ContextVal,
    Env,
    FuncVal,
    LaunchDescriptionVal,
    LaunchObject,
    LazyStr,
    ModuleVal,
    MoveItBuilderVal,
    OpenFile,
    PartlyKnownList,
    SubsVal,
    Unknown,
    XacroDocVal,
    XacroParsedDoc,
    _as_subs,
    _Break,
    _Continue,
)
from launch_linter.frontends.ros2_python.xacro_call import DOCUMENT_TEXT, document_text
from launch_linter.resolve.bounded import PYTHON_MAX_CALL_DEPTH as MAX_CALL_DEPTH
from launch_linter.resolve.bounded import PYTHON_MAX_ITEMS as MAX_ITEMS
from launch_linter.resolve.bounded import PYTHON_MAX_TEXT as MAX_TEXT
from launch_linter.resolve.bounded import STRING_METHODS, Refused, format_fields, string_method
from launch_linter.resolve.ros2_substitution import Call, Opaque, Sub, Subs, Text, literal
from launch_linter.resolve.value import holes, resolved_text

_UNSET_MARKER = "<unset launch configuration>"
"""The default ``context.launch_configurations.get(name)`` reads: launch gives None there."""


class Calls(Expressions):
    """Calls: the file's own functions, builtins, methods, ``os`` and ament."""

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
        if type(function) is ModuleVal:  # most calls: the launch library, os, ament
            return self.library(function, args, kwargs, node)
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
        return self.unknown(node, "calls something that is not a function")

    def call_function(self, function: FuncVal, args: list[object], kwargs: dict[str, object],
                      node: ast.AST) -> object:
        if self.depth >= MAX_CALL_DEPTH:
            return self.unknown(node, f"calls nested deeper than {MAX_CALL_DEPTH}")
        spec = function.node.args
        local = self.scope(function.closure)
        names = [a.arg for a in (*spec.posonlyargs, *spec.args)]
        for name, value in zip(names, args):
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
                # The Unknown (with its excerpt of the source) only for a missing argument.
                local.vars[name] = (function.defaults[name] if name in function.defaults
                                    else self.unknown(node, f"argument '{name}' is not given"))
        self.depth += 1
        try:
            if isinstance(function.node, ast.Lambda):
                return self.eval(function.node.body, local)
            return self.run_function_body(function.node.body, local)
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
            if isinstance(args[0], (str, int, float, bool)) or args[0] is None:
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
        if name == "len" and len(args) == 1 and isinstance(args[0], (list, tuple, str, dict)):
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
                return [tuple(group) for group in zip(*sequences)]
            if name == "sorted" and len(sequences) == 1 and all(
                isinstance(v, (str, int, float)) for v in sequences[0]
            ):
                try:
                    return sorted(sequences[0])  # type: ignore[type-var]
                except TypeError:
                    return self.unknown(node, "cannot sort these values")
        if name in ("int", "float", "bool", "abs", "round", "min", "max") and all(
            isinstance(a, (str, int, float, bool)) for a in args
        ) and args:
            try:
                return _PLAIN_BUILTINS[name](*args)
            except (TypeError, ValueError, OverflowError):
                return self.unknown(node, f"{name}() fails on these values")
        return self.unknown(node, f"{name}() on these values is not interpreted")

    def method(self, method: BoundMethod, args: list[object], kwargs: dict[str, object],
               node: ast.Call) -> object:
        target, name = method.target, method.name
        if isinstance(target, MoveItBuilderVal):
            return moveit.builder_method(self, target, name, args, kwargs, node)
        if isinstance(target, XacroDocVal) and name in DOCUMENT_TEXT:
            return target.text
        if isinstance(target, XacroParsedDoc) and name in DOCUMENT_TEXT:
            return document_text(self, target, node)
        if isinstance(target, OpenFile) and name == "read" and not args:
            return LazyStr((Call("file-content", (target.path,), self.segment(node)),))
        if isinstance(target, LazyStr) and target.path and not args:
            if name == "read_text":
                return LazyStr((Call("file-content", (target.subs,), self.segment(node)),))
            if name in ("resolve", "absolute", "expanduser"):
                return target
            if name == "as_posix":
                return LazyStr(target.subs)
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
        if isinstance(target, SubsVal) and name == "find" and len(args) == 1 and isinstance(
                args[0], (str, LazyStr)) and _single_call(target.subs, "find-pkg-share"):
            # FindPackageShare(p).find(name): the share folder of ``name``, as a string.
            return LazyStr((Call("find-pkg-share", (_as_subs(args[0]),), self.segment(node)),))
        if isinstance(target, (SubsVal, LazyStr)) and name == "perform":
            if len(args) == 1 and isinstance(args[0], ContextVal):
                return _performed(args[0].resolver, target.subs, node, self)
            return self.unknown(node, "perform() without the launch context")
        if isinstance(target, ConfigsVal) and name == "get" and 1 <= len(args) <= 2:
            key = args[0]
            if isinstance(key, str):
                default = args[1] if len(args) == 2 else None
                # dict.get gives the default for an unset configuration: never launch's
                # "does not exist" failure, so the read has a default of its own.
                unset = Opaque(_UNSET_MARKER, "unset")
                subs: Subs = (Call("var", (literal(key), (unset,)), self.segment(node)),)
                value = target.resolver(subs)
                text = resolved_text(value)
                if text is not None:
                    return text
                if all(h.text == _UNSET_MARKER for h in holes(value)):
                    return default
                return self.unknown(node, "; ".join(h.reason for h in holes(value)))
        return self.unknown(node, f"method '{name}' is not interpreted")

    def string_method(self, target: str, name: str, args: list[object], node: ast.Call
                      ) -> object:
        if name == "join" and len(args) == 1 and isinstance(args[0], (list, tuple)) and all(
            isinstance(item, (str, LazyStr)) for item in args[0]
        ):
            parts: list[Sub] = []
            for position, item in enumerate(args[0]):
                if position:
                    parts.extend(literal(target))
                parts.extend(_as_subs(item))
            return self.text_value(tuple(parts), node)
        if name == "format":
            return self.format(target, args, node)
        if not all(isinstance(a, (str, int)) for a in args):
            return self.unknown(node, f"str.{name}() on unknown values")
        if name not in STRING_METHODS or name == "join":
            return self.unknown(node, f"str.{name}() is not interpreted")
        try:
            return string_method(target, name, args, MAX_TEXT)
        except Refused as refusal:
            return self.unknown(node, refusal.reason)

    def format(self, template: str, args: list[object], node: ast.Call) -> object:
        """``str.format`` with plain ``{}``/``{0}`` fields only (no specs: they are
        unbounded in size)."""
        parts: list[Sub] = []
        try:
            for text, index in format_fields(template):
                parts.extend(literal(text))
                if index is None:
                    continue
                if index >= len(args):
                    return self.unknown(node, "str.format() is missing an argument")
                value = args[index]
                if isinstance(value, LazyStr):
                    parts.extend(value.subs)
                elif isinstance(value, (str, int, float, bool)):
                    parts.extend(literal(str(value)))
                else:
                    return self.unknown(node, "str.format() of an unknown value")
        except Refused as refusal:
            return self.unknown(node, refusal.reason)
        return self.text_value(tuple(parts), node)

    def os_call(self, dotted: str, args: list[object], node: ast.Call) -> object:
        if any(isinstance(a, Unknown) for a in args):
            return next(a for a in args if isinstance(a, Unknown))
        if dotted in ("os.getenv", "os.environ.get") and args and isinstance(args[0], str):
            call_args: tuple[Subs, ...] = (literal(args[0]),)
            if len(args) > 1:
                default = _as_subs(args[1]) if isinstance(args[1], (str, LazyStr)) else None
                if default is None:
                    return self.unknown(node, "default is not text")
                call_args += (default,)
            return LazyStr((Call("env", call_args, self.segment(node)),))
        if not all(isinstance(a, (str, LazyStr)) for a in args) or not args:
            return self.unknown(node, "path of unknown values")
        if all(isinstance(a, str) for a in args):
            texts = [a for a in args if isinstance(a, str)]
            operations: dict[str, Callable[..., str]] = {
                "os.path.join": os.path.join, "os.path.dirname": os.path.dirname,
                "os.path.abspath": os.path.abspath, "os.path.realpath": os.path.abspath,
                "os.path.normpath": os.path.normpath, "pathlib.Path": os.path.join,
                "os.path.expanduser": lambda p: p,
            }
            if dotted == "pathlib.Path":
                # Kept as a path: pathlib's ``/`` and ``.parent`` apply to it.
                return LazyStr((Text(os.path.join(*texts)),), path=True)
            return operations[dotted](*texts)
        parts = tuple(_as_subs(a) for a in args if isinstance(a, (str, LazyStr)))
        if dotted in ("os.path.join", "pathlib.Path"):
            return LazyStr((Call("path-join", parts, self.segment(node)),),
                           path=dotted == "pathlib.Path")
        if dotted in ("os.path.abspath", "os.path.realpath", "os.path.normpath",
                      "os.path.expanduser") and len(parts) == 1:
            return LazyStr(parts[0])
        return self.unknown(node, f"{dotted}() of a value known only at launch time")

    def ament(self, name: str, args: list[object], node: ast.Call) -> object:
        if len(args) != 1 or not isinstance(args[0], (str, LazyStr)):
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

    def subs(self, value: object, node: ast.AST, what: str, texts: bool = False) -> Subs:
        """A value as launch's ``SomeSubstitutionsType``; ``texts``: as the ``default`` of
        ``LaunchConfiguration``, whose items that are neither text nor a substitution launch
        turns into text with ``str()`` (launch/substitutions/launch_configuration.py), so a
        number or a bool there is its text, not the error it is elsewhere."""
        if texts and isinstance(value, (int, float)):
            return literal(str(value))
        if isinstance(value, str):
            return literal(value)
        if isinstance(value, (SubsVal, LazyStr)):
            return value.subs
        if isinstance(value, Unknown):
            return (value.hole(),)
        if isinstance(value, (list, tuple)):
            parts: list[Sub] = []
            for item in value:
                parts.extend(self.subs(item, node, what, texts))
            return tuple(parts)
        if isinstance(value, (int, float)) and not isinstance(value, bool):
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
        pending: list[object] = list(value) if isinstance(value, (list, tuple)) else [value]
        while pending:
            item = pending.pop(0)
            if isinstance(item, LaunchDescriptionVal):
                pending[:0] = item.items
            elif isinstance(item, (list, tuple)):
                pending[:0] = list(item)
            elif isinstance(item, PartlyKnownList):
                # Its known lists are flattened below; each unknown part is said once.
                pending[:0] = item.parts
            elif isinstance(item, Unknown):
                found.append(Unfollowed(Where(self.path, item.line, 1),
                                        f"launch entity not followed: {item.describe()}"))
            elif isinstance(item, ACTION_TYPES):
                found.append(item)
            elif isinstance(item, LaunchObject) and item.where is not None and (
                item.uses or item.condition is not None or item.parameter is not None
                or item.controls is not None
            ):
                found.append(Uses(item.where, item.condition, item.uses, item.parameter,
                                  item.controls))
        return tuple(found)

    # -- defined by a subclass, further on ---------------------------------------------------
    def library(self, module: ModuleVal, args: list[object], kwargs: dict[str, object],
                node: ast.Call) -> object:
        """Defined by :class:`.launch_api.Interpreter`."""
        raise NotImplementedError


def _single_call(subs: Subs, name: str) -> bool:
    return len(subs) == 1 and isinstance(subs[0], Call) and subs[0].name == name
