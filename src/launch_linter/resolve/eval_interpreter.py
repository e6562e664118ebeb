"""The interpreter of ``$(eval)`` expressions: a walk over the syntax tree that knows a
whitelist of node types and refuses everything else, with a work budget and size checks
before every expensive result (see :mod:`launch_linter.resolve.safe_eval`)."""

from __future__ import annotations

import ast
import builtins
import operator
from collections.abc import Sequence
from typing import Any, Callable, Final

from launch_linter.resolve.bounded import (
    EVAL_MAX_FORMAT_FIELD,
    STRING_METHODS,
    Refused,
    check_join,
    percent_refusal,
    string_method,
)
from launch_linter.resolve.bounded import EVAL_MAX_INT_BITS as MAX_INT_BITS
from launch_linter.resolve.bounded import EVAL_MAX_ITEMS as MAX_ITEMS
from launch_linter.resolve.bounded import EVAL_MAX_WORK as MAX_WORK
from launch_linter.resolve.eval_functions import _BUILTINS, _NAMES
from launch_linter.resolve.eval_values import (
    _BITS_PER_UNIT,
    _BULK_ITEMS_PER_UNIT,
    _EMPTY,
    _OPAQUE_SCALAR,
    _SCALAR,
    _TEXT_ITEMS_PER_UNIT,
    AttributeDict,
    EvalError,
    EvalScope,
    EvalUndefined,
    EvalUnresolved,
    _attempt,
    _auto_convert,
    _check_power,
    _clip,
    _Function,
    _is_singleton,
    _MapObject,
    _Meta,
    _truthy,
    _type_name,
    subscript_index,
)

# --- the interpreter -----------------------------------------------------------------

_BINARY: Final[dict[type[ast.operator], tuple[str, Callable[[object, object], object]]]] = {
    ast.Add: ("+", operator.add),
    ast.Sub: ("-", operator.sub),
    ast.Mult: ("*", operator.mul),
    ast.Div: ("/", operator.truediv),
    ast.FloorDiv: ("//", operator.floordiv),
    ast.Mod: ("%", operator.mod),
    ast.Pow: ("**", operator.pow),
}

# Any: typeshed types the ordering operators narrowly; values are checked at run time.
_ORDERING: Final[dict[type[ast.cmpop], Callable[[Any, Any], object]]] = {
    ast.Eq: operator.eq,
    ast.NotEq: operator.ne,
    ast.Lt: operator.lt,
    ast.LtE: operator.le,
    ast.Gt: operator.gt,
    ast.GtE: operator.ge,
}


_REFUSED: Final[dict[type[ast.AST], str]] = {
    ast.Attribute: "attribute access (x.y) is",
    ast.Lambda: "lambda expressions are",
    ast.ListComp: "comprehensions are",
    ast.SetComp: "comprehensions are",
    ast.DictComp: "comprehensions are",
    ast.GeneratorExp: "generator expressions are",
    ast.Starred: "starred expressions (*x) are",
    ast.JoinedStr: "f-strings are",
    ast.FormattedValue: "f-strings are",
    ast.NamedExpr: "assignment expressions (:=) are",
    ast.Set: "set displays are",
    ast.Slice: "a slice outside a subscript is",
    ast.Await: "await is",
    ast.Yield: "yield is",
    ast.YieldFrom: "yield is",
}



class _Interpreter:
    """Evaluates one expression tree; holds the per-evaluation work budget and size cache."""

    def __init__(self, scope: EvalScope) -> None:
        self.scope = scope
        self._work = 0
        # Keyed by id(); the value itself is kept so the id cannot be reused meanwhile.
        self._metas: dict[int, tuple[object, _Meta]] = {}

    # -- budget and sizes --

    @property
    def spent(self) -> int:
        """Work units spent so far."""
        return self._work

    def charge(self, units: int) -> None:
        """Spend work units: one per syntax node or function call, one per element walked
        in Python, and one per ``_BULK_ITEMS_PER_UNIT`` items handled by C code."""
        self._work += units
        if self._work > MAX_WORK:
            raise EvalError("expression needs too much work to evaluate")

    def bulk(self, items: int) -> None:
        self.charge(items // _BULK_ITEMS_PER_UNIT)

    def meta(self, value: object) -> _Meta:
        if isinstance(value, str):
            return _Meta(len(value), 1, False)
        if isinstance(value, (bool, float)) or value is None:
            return _SCALAR
        if isinstance(value, int):
            digits = max(1, value.bit_length() // 3)
            return _Meta(digits, digits, False)
        if isinstance(value, _Function):
            return _OPAQUE_SCALAR
        cached = self._metas.get(id(value))
        if cached is not None and cached[0] is value:
            return cached[1]
        if isinstance(value, _MapObject):
            inner = self.meta(value.items)
            return self.remember(value, inner._replace(opaque=True))
        elements: Sequence[object]
        if isinstance(value, (list, tuple)):
            elements = value
        elif isinstance(value, dict):
            elements = [*value.keys(), *value.values()]
        else:
            raise EvalError(f"values of type {type(value).__name__!r} are not supported")
        self.charge(len(elements))
        total = widest = 0
        opaque = False
        for element in elements:
            part = self.meta(element)
            size = max(1, part.weight)
            total += size
            widest = max(widest, size)
            opaque = opaque or part.opaque
        return self.remember(value, _Meta(total, widest, opaque))

    def remember(self, value: object, meta: _Meta) -> _Meta:
        self._metas[id(value)] = (value, meta)
        return meta

    def checked(self, value: object) -> object:
        """Apply the size bounds to a freshly produced value."""
        if isinstance(value, (bool, float, str, _Function)) or value is None:
            if isinstance(value, str) and len(value) > MAX_ITEMS:
                raise EvalError(f"text result would be longer than {MAX_ITEMS:,} characters")
            return value
        if isinstance(value, int):
            bits = value.bit_length()
            if bits > MAX_INT_BITS:
                raise EvalError(f"integer result would have more than {MAX_INT_BITS:,} bits")
            self.charge(bits // _BITS_PER_UNIT)
            return value
        if isinstance(value, complex):
            raise EvalError("complex numbers are not supported")
        if self.meta(value).weight > MAX_ITEMS:
            raise EvalError(f"result would have more than {MAX_ITEMS:,} items")
        return value

    def text(self, value: object) -> str:
        """``str(value)``, as roslaunch returns it, for values whose text is meaningful."""
        if isinstance(value, str):
            return value
        meta = self.meta(value)
        if isinstance(value, _Function):
            raise EvalError(f"{value.name} is a function, and has no value as text")
        if isinstance(value, _MapObject):
            raise EvalError("a map object has no value as text; use list(map(...))")
        if meta.opaque:
            raise EvalError("the value holds a function or map object, which has no text")
        self.charge(meta.weight // _TEXT_ITEMS_PER_UNIT)
        try:
            text = str(value)
        except ValueError as exc:
            # Python's limit on int-to-decimal conversion.
            raise EvalError(_clip(f"cannot convert to text: {exc}")) from None
        if len(text) > MAX_ITEMS:
            raise EvalError(f"text result would be longer than {MAX_ITEMS:,} characters")
        return text

    # -- expressions --

    def eval(self, node: ast.expr) -> object:
        self.charge(1)
        if isinstance(node, ast.Constant):
            return self._constant(node)
        if isinstance(node, ast.Name):
            return self.lookup(node.id)
        if isinstance(node, ast.UnaryOp):
            return self._unary(node)
        if isinstance(node, ast.BinOp):
            return self._binary(node)
        if isinstance(node, ast.BoolOp):
            return self._boolean(node)
        if isinstance(node, ast.Compare):
            return self._compare(node)
        if isinstance(node, ast.IfExp):
            chosen = node.body if _truthy(self.eval(node.test)) else node.orelse
            return self.eval(chosen)
        if isinstance(node, (ast.Tuple, ast.List)):
            return self._sequence(node)
        if isinstance(node, ast.Dict):
            return self._dict(node)
        if isinstance(node, ast.Subscript):
            return self._subscript(node)
        if isinstance(node, ast.Call):
            return self._call(node)
        if isinstance(node, ast.Attribute):
            return self._attribute(node)
        what = _REFUSED.get(type(node), f"{type(node).__name__} expressions are")
        raise EvalError(f"{what} not allowed in $(eval)")

    def _constant(self, node: ast.Constant) -> object:
        value = node.value
        if value is None or isinstance(value, (bool, int, float, str)):
            return self.checked(value)
        raise EvalError(f"{type(value).__name__} literals are not allowed in $(eval)")

    def lookup(self, name: str) -> object:
        if name in _NAMES:
            return _NAMES[name]
        args = self.scope.args
        if name in args:
            value = args[name]
            if value is None:
                raise EvalUnresolved(f"the value of arg '{name}' is not known", name)
            return self.checked(_auto_convert(value) if isinstance(value, str) else value)
        if name in _BUILTINS:
            return _BUILTINS[name]
        if name in vars(builtins):
            raise EvalError(f"the Python builtin '{name}' is not allowed in $(eval)")
        raise EvalUndefined(f"name '{name}' is not defined", name)

    def _unary(self, node: ast.UnaryOp) -> object:
        if isinstance(node.op, ast.Invert):
            raise EvalError("bitwise operators are not supported")
        operand = self.eval(node.operand)
        if isinstance(node.op, ast.Not):
            return not _truthy(operand)
        if isinstance(node.op, ast.USub):
            return self.checked(_attempt(None, operator.neg, operand))
        return self.checked(_attempt(None, operator.pos, operand))

    def _binary(self, node: ast.BinOp) -> object:
        entry = _BINARY.get(type(node.op))
        if entry is None:
            raise EvalError("bitwise and matrix operators are not supported")
        left = self.eval(node.left)
        right = self.eval(node.right)
        return self.binary(entry[0], entry[1], left, right)

    def binary(
        self, symbol: str, function: Callable[[object, object], object], left: object, right: object
    ) -> object:
        meta: _Meta | None = None
        if symbol == "+":
            meta = self._plan_add(left, right)
        elif symbol == "*":
            meta = self._plan_repeat(left, right)
        elif symbol == "**":
            _check_power(left, right)
        elif symbol == "%" and isinstance(left, str):
            return self._format(left, right)
        if isinstance(left, int) and isinstance(right, int):
            # Big-integer arithmetic is the one costly operation on small-looking values.
            self.charge((left.bit_length() + right.bit_length()) // _BITS_PER_UNIT)
        result = _attempt(None, function, left, right)
        if meta is not None and isinstance(result, (list, tuple)):
            self.remember(result, meta)
        return self.checked(result)

    def _plan_add(self, left: object, right: object) -> _Meta | None:
        """Refuse a concatenation whose result would be too big, before building it."""
        if isinstance(left, str) and isinstance(right, str):
            size = len(left) + len(right)
            if size > MAX_ITEMS:
                raise EvalError(f"text result would be longer than {MAX_ITEMS:,} characters")
            self.bulk(size)
            return None
        if (isinstance(left, list) and isinstance(right, list)) or (
            isinstance(left, tuple) and isinstance(right, tuple)
        ):
            a, b = self.meta(left), self.meta(right)
            meta = _Meta(a.weight + b.weight, max(a.widest, b.widest), a.opaque or b.opaque)
            if meta.weight > MAX_ITEMS:
                raise EvalError(f"result would have more than {MAX_ITEMS:,} items")
            self.bulk(len(left) + len(right))
            return meta
        # int + int is at most one bit longer than its operands; checked() catches that.
        return None

    def _plan_repeat(self, left: object, right: object) -> _Meta | None:
        """Refuse a repetition or product whose result would be too big, before building it."""
        sequence: object
        if isinstance(left, (str, list, tuple)) and isinstance(right, int):
            sequence, count = left, right
        elif isinstance(left, int) and isinstance(right, (str, list, tuple)):
            sequence, count = right, left
        elif isinstance(left, int) and isinstance(right, int):
            if left.bit_length() + right.bit_length() > MAX_INT_BITS + 1:
                raise EvalError(f"integer result would have more than {MAX_INT_BITS:,} bits")
            return None
        else:
            return None
        if count <= 0:
            return _EMPTY
        if isinstance(sequence, str):
            if len(sequence) * count > MAX_ITEMS:
                raise EvalError(f"text result would be longer than {MAX_ITEMS:,} characters")
            self.bulk(len(sequence) * count)
            return None
        assert isinstance(sequence, (list, tuple))
        inner = self.meta(sequence)
        if inner.weight * count > MAX_ITEMS:
            raise EvalError(f"result would have more than {MAX_ITEMS:,} items")
        self.bulk(len(sequence) * count)
        return inner._replace(weight=inner.weight * count)

    def _format(self, template: str, values: object) -> str:
        """``template % values``, refusing field sizes that would allocate without bound."""
        refusal = percent_refusal(template, EVAL_MAX_FORMAT_FIELD)
        if refusal is not None:
            raise EvalError(refusal)
        meta = self.meta(values)
        if meta.opaque:
            raise EvalError("cannot format a function or map object as text")
        self.charge((meta.weight + len(template)) // _TEXT_ITEMS_PER_UNIT)
        result = _attempt(None, operator.mod, template, values)
        assert isinstance(result, str)
        self.checked(result)
        return result

    def _boolean(self, node: ast.BoolOp) -> object:
        want = not isinstance(node.op, ast.And)
        # Like Python: the first operand that decides the outcome, else the last one.
        for operand in node.values[:-1]:
            value = self.eval(operand)
            if _truthy(value) == want:
                return value
        return self.eval(node.values[-1])

    def _compare(self, node: ast.Compare) -> object:
        left = self.eval(node.left)
        result: object = True
        for op, comparator in zip(node.ops, node.comparators):
            right = self.eval(comparator)
            result = self.compare(op, left, right)
            if not _truthy(result):
                return result
            left = right
        return result

    def compare(self, op: ast.cmpop, left: object, right: object) -> object:
        if isinstance(op, (ast.Is, ast.IsNot)):
            if not (_is_singleton(left) or _is_singleton(right)):
                raise EvalError("'is' is only supported against None, True or False")
            return (left is right) == isinstance(op, ast.Is)
        if isinstance(op, (ast.In, ast.NotIn)):
            if not isinstance(right, (str, list, tuple, dict, _MapObject)):
                raise EvalError(f"argument of type {_type_name(right)!r} is not iterable")
            self.bulk(self.meta(right).weight)
            found = _attempt(None, operator.contains, right, left)
            return bool(found) == isinstance(op, ast.In)
        function = _ORDERING[type(op)]
        self.bulk(min(self.meta(left).weight, self.meta(right).weight))
        return _attempt(None, function, left, right)

    def _sequence(self, node: ast.Tuple | ast.List) -> object:
        items = [self.eval(element) for element in node.elts]
        metas = [self.meta(item) for item in items]
        sizes = [max(1, meta.weight) for meta in metas]
        meta = _Meta(sum(sizes), max(sizes, default=0), any(m.opaque for m in metas))
        value: list[object] | tuple[object, ...] = (
            tuple(items) if isinstance(node, ast.Tuple) else items
        )
        self.remember(value, meta)
        return self.checked(value)

    def _dict(self, node: ast.Dict) -> object:
        result: dict[object, object] = {}
        for key_node, value_node in zip(node.keys, node.values):
            if key_node is None:
                raise EvalError("dict unpacking (**) is not allowed in $(eval)")
            key = self.eval(key_node)
            value = self.eval(value_node)
            _attempt(None, operator.setitem, result, key, value)
        return self.checked(result)

    def _subscript(self, node: ast.Subscript) -> object:
        container = self.eval(node.value)
        key = subscript_index(node)
        if isinstance(key, ast.Slice):
            bounds = [
                None if part is None else self.eval(part)
                for part in (key.lower, key.upper, key.step)
            ]
            return self.slice(container, bounds[0], bounds[1], bounds[2])
        index = self.eval(key)
        return self.index(container, index)

    def slice(self, container: object, lower: object, upper: object, step: object) -> object:
        if not isinstance(container, (str, list, tuple)):
            raise EvalError(f"{_type_name(container)!r} object cannot be sliced")
        for bound in (lower, upper, step):
            if bound is not None and not isinstance(bound, int):
                raise EvalError("slice indices must be integers or None")
        result = _attempt(None, operator.getitem, container, slice(lower, upper, step))
        if isinstance(result, (list, tuple)):
            outer = self.meta(container)
            weight = min(outer.weight, len(result) * outer.widest)
            self.remember(result, outer._replace(weight=weight))
            self.bulk(len(result))
        return self.checked(result)

    def index(self, container: object, index: object) -> object:
        if isinstance(container, (str, list, tuple)):
            if not isinstance(index, int):
                raise EvalError(
                    f"{_type_name(container)} indices must be integers or slices, "
                    f"not {_type_name(index)}"
                )
        elif not isinstance(container, dict):
            raise EvalError(f"{_type_name(container)!r} object is not subscriptable")
        return _attempt(None, operator.getitem, container, index)

    def _call(self, node: ast.Call) -> object:
        if node.keywords:
            raise EvalError("keyword arguments are not supported in $(eval)")
        if isinstance(node.func, ast.Attribute):
            receiver = self.eval(node.func.value)
            if not isinstance(receiver, AttributeDict):
                return self._string_method(receiver, node.func.attr, node.args)
            function = self.member(receiver, node.func.attr)
        else:
            function = self.eval(node.func)
        args = tuple(self.eval(arg) for arg in node.args)
        if not isinstance(function, _Function):
            raise EvalError(f"{_type_name(function)!r} object is not callable")
        return self.call(function, args)

    def _attribute(self, node: ast.Attribute) -> object:
        """``d.key`` on a dict the caller marked as attribute-readable (xacro's YAML data
        and include namespaces); every other attribute access stays refused."""
        return self.member(self.eval(node.value), node.attr)

    @staticmethod
    def member(receiver: object, name: str) -> object:
        if not isinstance(receiver, AttributeDict):
            raise EvalError(f"attribute access (x.{name}) is not allowed in $(eval)")
        if name not in receiver:
            raise EvalError(f"the dict has no key or attribute {name!r}")
        return receiver[name]

    def _string_method(self, receiver: object, name: str, arg_nodes: list[ast.expr]) -> object:
        """``text.method(...)`` for the few ``str`` methods launch files use on names.

        Attribute access stays refused everywhere else: only a call of a whitelisted
        method on a value that is already a ``str`` gets here, and every result is sized
        before it is built.
        """
        if not isinstance(receiver, str) or name not in STRING_METHODS:
            raise EvalError(f"attribute access (x.{name}) is not allowed in $(eval)")
        args = tuple(self.eval(arg) for arg in arg_nodes)
        self.charge(1 + len(receiver) // 64)
        if name != "join" and not all(
            isinstance(a, (str, int)) and not isinstance(a, bool) for a in args
        ):
            raise EvalError(f"str.{name}() takes only text or integer arguments here")
        if name == "join":
            if len(args) != 1:
                raise EvalError("str.join() takes exactly one argument")
            items = self.items(args[0], "str.join()")
            if not all(isinstance(i, str) for i in items):
                raise EvalError("str.join() needs a sequence of strings")
            try:
                check_join(receiver, [i for i in items if isinstance(i, str)], MAX_ITEMS)
            except Refused as refusal:
                raise EvalError(refusal.reason) from None
            return self.checked(receiver.join(i for i in items if isinstance(i, str)))
        try:
            result = string_method(receiver, name, args, MAX_ITEMS)
        except Refused as refusal:
            raise EvalError(_clip(refusal.reason)) from None
        return self.checked(result)

    def call(self, function: _Function, args: tuple[object, ...]) -> object:
        self.charge(1)
        return self.checked(function.impl(self, args))

    def items(self, value: object, caller: str) -> Sequence[object]:
        """The elements iterating ``value`` would give, for the iterable kinds of value."""
        if isinstance(value, (str, list, tuple)):
            return value
        if isinstance(value, dict):
            return list(value)
        if isinstance(value, _MapObject):
            return value.items
        raise EvalError(f"{caller}: {_type_name(value)!r} object is not iterable")
