"""Expressions of ROS 2 Python launch files: names, literals, operators, f-strings,
comparisons, subscripts and comprehensions, over known values and bounded in size."""

from __future__ import annotations

import ast
import os
from collections.abc import Callable
from typing import Any

from launch_linter.frontends.ros2_python import moveit
from launch_linter.frontends.ros2_python.evaluator import Evaluator, _performed
from launch_linter.frontends.ros2_python.names import PYTHON_BUILTINS
from launch_linter.frontends.ros2_python.values import (
    _COMPARE,
    BUILTINS,
    BoundMethod,
    Builtin,
    ConfigsVal,
    ContextVal,
    Env,
    FuncVal,
    LaunchDescriptionVal,
    LaunchObject,
    LazyStr,
    LinedDict,
    ModuleVal,
    MoveItBuilderVal,
    MoveItConfigsVal,
    OpenFile,
    PartlyKnownList,
    SubsVal,
    Unknown,
    XacroDocVal,
    XacroParsedDoc,
    _as_subs,
    _OutOfSteps,
    _plain,
)
from launch_linter.resolve.bounded import PYTHON_MAX_FORMAT_FIELD, percent_refusal
from launch_linter.resolve.bounded import PYTHON_MAX_ITEMS as MAX_ITEMS
from launch_linter.resolve.bounded import PYTHON_MAX_STEPS as MAX_STEPS
from launch_linter.resolve.bounded import PYTHON_MAX_TEXT as MAX_TEXT
from launch_linter.resolve.ros2_substitution import Call, Sub, Text, literal
from launch_linter.resolve.safe_eval import subscript_index


def _why_unknown(value: object) -> str | None:
    """``WHAT: WHY`` for an operand the linter does not know as a plain value: an unknown
    value, or a string only known when the launch runs (an environment variable)."""
    if isinstance(value, Unknown):
        return f"{value.text}: {value.reason}"
    if isinstance(value, LazyStr):
        call = next((sub for sub in value.subs if isinstance(sub, Call)), None)
        if call is None:
            return None
        if call.name == "env" and len(call.args) == 1 and len(call.args[0]) == 1 and \
                isinstance(call.args[0][0], Text):
            # Python compares it before launch runs: --env does not reach this far.
            return (f"{call.written}: the environment variable '{call.args[0][0].text}' is "
                    "only known when the launch runs")
        return f"{call.written}: only known when the launch runs"
    return None


def _partly_known(left: object, right: object) -> Unknown:
    """``left + right`` where one side is unknown and the other a list (or unknown): the
    first unknown operand, keeping the parts in order for reading launch entities."""
    parts: list[object] = []
    for side in (left, right):
        if isinstance(side, PartlyKnownList):
            parts.extend(side.parts)
        else:
            parts.append(side)
    first = next(part for part in parts if isinstance(part, Unknown))
    assert isinstance(first, Unknown)
    if len(parts) > MAX_ITEMS:
        return first
    return PartlyKnownList(first.reason, first.text, first.line, tuple(parts))


class Expressions(Evaluator):
    """Expressions, over known values, bounded in sizes."""

    # -- expressions ---------------------------------------------------------------------
    def eval(self, node: ast.expr, env: Env) -> object:
        self.steps += 1
        if self.steps > MAX_STEPS:
            raise _OutOfSteps
        # Constants and names are most expressions: tested first, the rest looked up by
        # the expression's class.
        kind = type(node)
        if kind is ast.Constant:
            value = node.value  # type: ignore[attr-defined]
            if isinstance(value, (str, int, float, bool)) or value is None:
                return value
            return self.unknown(node, "unsupported constant")
        if kind is ast.Name:
            name: str = node.id  # type: ignore[attr-defined]
            found, value = env.lookup(name)
            if found:
                return value
            if name == "__file__":
                return (self.installed() if self.installed else None) or self.path
            if name == "__name__":
                return "__launch__"
            if name in BUILTINS:
                return Builtin(name)
            bound = (None if self.bound is None or self.branches or name in PYTHON_BUILTINS
                     else self.bound())
            if bound is not None and name not in bound:
                self.problem("py_name_error", node,
                             f"name '{name}' is bound nowhere in this file (no assignment, "
                             f"import, def or parameter) and is no builtin: Python raises "
                             f"\"NameError: name '{name}' is not defined\" here and ros2 "
                             f"launch stops")
            return self.unknown(node, f"name '{name}' is not known here")
        handler = _EXPRESSIONS.get(kind)
        if handler is None:
            return self.unknown(node, f"{kind.__name__} expressions are not interpreted")
        return handler(self, node, env)

    def _sequence_display(self, node: ast.List | ast.Tuple, env: Env) -> object:
        items = self.sequence(node.elts, env, node)
        if isinstance(items, Unknown):
            return items
        return items if isinstance(node, ast.List) else tuple(items)

    def _attribute(self, node: ast.Attribute, env: Env) -> object:
        return self.attribute(self.eval(node.value, env), node.attr, node)

    def _call(self, node: ast.Call, env: Env) -> object:
        return self.call(node, env)

    def _binary(self, node: ast.BinOp, env: Env) -> object:
        return self.binary(node.op, self.eval(node.left, env), self.eval(node.right, env), node)

    def _conditional(self, node: ast.IfExp, env: Env) -> object:
        tested = self.eval(node.test, env)
        self.text_tested(node.test, tested)
        test = self.truth(tested)
        if test is None:
            return self.unknown(node, "depends on a condition the linter cannot decide")
        return self.eval(node.body if test else node.orelse, env)

    def _subscript(self, node: ast.Subscript, env: Env) -> object:
        container = self.eval(node.value, env)
        return self.subscript(container, self.eval(subscript_index(node), env), node)

    def _lambda(self, node: ast.Lambda, env: Env) -> object:
        return FuncVal(node, env, self.defaults(node.args, env))

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
        result = LinedDict()
        for key_node, value_node in zip(node.keys, node.values):
            value = self.eval(value_node, env)
            if key_node is None:
                if not isinstance(value, dict):
                    return self.unknown(value_node, "cannot unpack this mapping")
                result.update(value)
                for key in value:
                    # An unpacked key keeps its own line where it has one, else this one.
                    result.places[key] = (value.places[key] if isinstance(value, LinedDict)
                                          and key in value.places else self.where(value_node))
                continue
            key = self.eval(key_node, env)
            if not isinstance(key, (str, int, float, bool)) and key is not None:
                return self.unknown(key_node, "dictionary key is not a known constant")
            result[key] = value
            result.places[key] = self.where(key_node)
        return result

    def truth(self, value: object) -> bool | None:
        if isinstance(value, (str, int, float, bool, list, tuple, dict)) or value is None:
            return bool(value)
        if isinstance(value, (Unknown, SubsVal, LazyStr)):
            return None
        return True

    def attribute(self, base: object, name: str, node: ast.Attribute) -> object:
        if isinstance(base, ModuleVal):
            return ModuleVal(f"{base.dotted}.{name}")
        if isinstance(base, Unknown):
            return base
        if isinstance(base, ContextVal) and name == "launch_configurations":
            return ConfigsVal(base.resolver)
        if isinstance(base, LazyStr) and base.path and name == "parent":
            # pathlib's parent of a path known as text (Path(__file__).parent.parent).
            if all(isinstance(sub, Text) for sub in base.subs):
                text = "".join(sub.text for sub in base.subs if isinstance(sub, Text))
                return LazyStr((Text(os.path.dirname(text.rstrip("/")) or "/"),), path=True)
            return self.unknown(node, "the parent of a path known only at launch time")
        if isinstance(base, MoveItConfigsVal):
            return moveit.configs_attribute(self, base, name, node)
        if isinstance(base, (list, dict, str, SubsVal, LazyStr, LaunchDescriptionVal, ConfigsVal,
                             OpenFile, MoveItBuilderVal, XacroDocVal, XacroParsedDoc)):
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
            elif isinstance(inner, (str, int, float, bool)):
                parts.append(Text(str(inner)))
            elif isinstance(inner, Unknown):
                return inner
            else:
                return self.unknown(value, "a launch object cannot be put into a string")
        return self.text_value(tuple(parts), node)

    def binary(self, op: ast.operator, left: object, right: object, node: ast.AST) -> object:
        if isinstance(op, ast.Add) and (isinstance(left, Unknown) or isinstance(
                right, Unknown)) and isinstance(left, (list, tuple, Unknown)) and isinstance(
                right, (list, tuple, Unknown)):
            return _partly_known(left, right)
        if isinstance(left, Unknown):
            return left
        if isinstance(right, Unknown):
            return right
        if isinstance(op, ast.Add):
            if isinstance(left, (LazyStr, str)) and isinstance(right, (LazyStr, str)):
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
            right, (str, LazyStr)
        ):
            return LazyStr((Call("path-join", (left.subs, _as_subs(right)),
                                 self.segment(node)),), path=True)
        if isinstance(op, ast.Div) and isinstance(left, SubsVal) and _is_path_join(left) and (
                isinstance(right, (str, LazyStr, SubsVal))):
            # PathSubstitution / 'urdf' / 'x.xacro' and PathJoinSubstitution / ...: launch's
            # __truediv__ makes a PathJoinSubstitution of both.
            right_subs = right.subs if isinstance(right, SubsVal) else _as_subs(right)
            joined = left.subs[0]
            assert isinstance(joined, Call)  # _is_path_join checked it
            return SubsVal((Call("path-join", (*joined.args, right_subs),
                                 self.segment(node)),))
        if isinstance(op, ast.Mod) and isinstance(left, str):
            args = right if isinstance(right, tuple) else (right,)
            if all(isinstance(a, (str, int, float, bool)) for a in args) and (
                percent_refusal(left, PYTHON_MAX_FORMAT_FIELD) is None
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
                item, (str, list, tuple)
            ):
                if len(item) * max(count, 0) > MAX_ITEMS * 10:
                    return self.unknown(node, "value too large")
                return item * count
        numbers = (int, float)
        if isinstance(left, numbers) and isinstance(right, numbers) and not isinstance(
            op, (ast.Pow, ast.LShift)
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

    def given(self, value: object) -> object:
        """``value``, or the text of the environment variable it reads when the run is
        told that variable (``os.environ['ROS_DISTRO']`` with ``--ros-distro humble``)."""
        if isinstance(value, LazyStr) and len(value.subs) == 1:
            call = value.subs[0]
            if isinstance(call, Call) and call.name == "env" and call.args and len(
                    call.args[0]) == 1 and isinstance(call.args[0][0], Text):
                return self.environ.get(call.args[0][0].text, value)
        return value

    def compare(self, node: ast.Compare, env: Env) -> object:
        left = self.given(self.eval(node.left, env))
        for op, right_node in zip(node.ops, node.comparators):
            right = self.given(self.eval(right_node, env))
            if not _plain(left) or not _plain(right):
                # Named after the operand that is unknown, so that a message can say what
                # really blocks the comparison (an environment variable, say).
                for operand in (left, right):
                    blocking = _why_unknown(operand)
                    if blocking is not None:
                        return self.unknown(node, blocking)
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
            self.text_tested(node.operand, operand)
            truth = self.truth(operand)
            return self.unknown(node, "depends on an unknown value") if truth is None else (
                not truth)
        if isinstance(operand, (int, float)) and not isinstance(operand, bool):
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
            if isinstance(base, (list, tuple, str)) and isinstance(key, int):
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

    # -- defined by a subclass, further on ---------------------------------------------------
    def call(self, node: ast.Call, env: Env) -> object:
        """Defined by :class:`.calls.Calls`."""
        raise NotImplementedError


_EXPRESSIONS: dict[type, Callable[[Expressions, Any, Env], object]] = {
    ast.List: Expressions._sequence_display,
    ast.Tuple: Expressions._sequence_display,
    ast.Dict: Expressions.mapping,
    ast.Attribute: Expressions._attribute,
    ast.Call: Expressions._call,
    ast.BinOp: Expressions._binary,
    ast.JoinedStr: Expressions.fstring,
    ast.Compare: Expressions.compare,
    ast.BoolOp: Expressions.boolean,
    ast.UnaryOp: Expressions.unary,
    ast.IfExp: Expressions._conditional,
    ast.Subscript: Expressions._subscript,
    ast.ListComp: Expressions.comprehension,
    ast.GeneratorExp: Expressions.comprehension,
    ast.Lambda: Expressions._lambda,
}
"""How each expression the evaluator models (other than constants and names) is worked
out, by its class."""


def _is_path_join(value: SubsVal) -> bool:
    return (len(value.subs) == 1 and isinstance(value.subs[0], Call)
            and value.subs[0].name == "path-join")
