"""Our own interpreter for roslaunch's ``$(eval EXPR)`` substitution.

roslaunch (ROS 1) hands the text of ``$(eval EXPR)`` to Python's built-in ``eval``, with
the launch args, a few helper functions and the whole :mod:`math` module in scope. Its
only guard is refusing text that contains ``__``, which is well known not to be a
sandbox, and even harmless-looking arithmetic such as ``9**9**9`` would hang the process.
Launch files are untrusted input to the linter, so nothing here calls ``eval``, ``exec``
or ``compile`` on them, imports anything they name, or looks up attributes on any object.
The text is parsed with :func:`ast.parse` (which only builds a tree) and the tree is
walked by a small interpreter that knows a whitelist of node types, values and functions
and refuses everything else with :class:`EvalError`.

The language is the part of Python that legitimate launch files use, with roslaunch's
results (``str`` of the Python value):

* literals: ``int``, ``float``, ``str``, ``bool``, ``None``; tuple, list and dict displays;
* unary ``+ - not``; binary ``+ - * / // % **``; chained comparisons (including ``in``);
  short-circuit ``and``/``or`` returning an operand; ``a if c else b``;
* subscripts and slices of ``str``, ``list``, ``tuple`` (and subscripts of ``dict``);
* calls, with positional arguments only, to: roslaunch's ``arg env optenv find anon
  dirname``; every public function of :mod:`math`; the builtins roslaunch meant to offer,
  ``list dict map str float int``, plus the harmless ``len abs round min max bool``.
  (Real roslaunch leaks *all* builtins, ``open`` and ``__import__`` included; here every
  other builtin is refused.)

Names resolve as in roslaunch: first ``true false True False``, the helpers and every
public name of :mod:`math` (so an arg called ``e`` or ``pi`` is shadowed), then the
launch args (converted by roslaunch's "auto" rule), then the whitelisted builtins.

Deliberate differences from roslaunch, all on text no sane launch file contains:

* attribute access (so no methods such as ``'a'.upper()``), keyword arguments, ``*x``,
  lambdas, comprehensions, f-strings, ``:=``, set displays, bitwise operators and complex
  numbers are refused;
* ``is``/``is not`` are only allowed against ``None``, ``True`` or ``False`` (otherwise
  the answer depends on CPython's object caching);
* a function or ``map`` object cannot be turned into text (roslaunch would print a memory
  address); ``map`` is evaluated eagerly, and a ``map`` object can be iterated repeatedly;
* ``'...' % x`` refuses ``*`` and field widths or precisions above 10,000;
* ``anon()`` only takes a string id;
* where Python itself limits integer/text conversion (4,300 digits by default), so do we.

Like Python's run-time errors, a refusal happens when evaluation reaches the offending
node: ``True or x.y`` gives ``True``, as it does in roslaunch. Nothing is ever run for a
node that is not evaluated, so this costs no safety.

Bounds, so that hostile text cannot hang or exhaust the linter, are the ``MAX_*``
constants below: text length, syntax-tree size and depth, ``int ** int`` exponents (a
base of -1, 0 or 1 takes any exponent, its result being trivial), integer size, and the
size of strings and containers, each checked *before* an expensive result is built. A
work budget additionally caps the total effort of one evaluation, since 2,000 nodes of
individually bounded operations could otherwise still take minutes.
"""

from __future__ import annotations

import ast
import builtins
import math
import operator
import re
import warnings
from collections.abc import Callable, Iterator, Mapping, Sequence
from dataclasses import dataclass
from typing import Any, Final, NamedTuple, TypeAlias

from launch_linter.model.budget import Budget

__all__ = [
    "MAX_DEPTH",
    "MAX_INT_BITS",
    "MAX_ITEMS",
    "MAX_NODES",
    "MAX_POW_EXPONENT",
    "MAX_SOURCE_CHARS",
    "MAX_WORK",
    "EvalError",
    "EvalScope",
    "EvalUnresolved",
    "evaluate",
]

MAX_SOURCE_CHARS: Final = 10_000
"""Longest expression text accepted."""
MAX_NODES: Final = 2_000
"""Most syntax-tree nodes (operator and context markers not counted)."""
MAX_DEPTH: Final = 100
"""Deepest nesting of syntax-tree nodes."""
MAX_POW_EXPONENT: Final = 10_000
"""Largest integer exponent of ``int ** int`` (unless the base is -1, 0 or 1)."""
MAX_INT_BITS: Final = 100_000
"""Largest integer produced anywhere during evaluation, in bits."""
MAX_ITEMS: Final = 1_000_000
"""Largest string (characters) or container (items, counted recursively) produced."""
MAX_WORK: Final = 500_000
"""Budget of abstract work units for one evaluation; see ``_Interpreter.charge``."""

_MAX_FORMAT_FIELD: Final = 10_000
# Longer digit strings would make int() quadratic if Python's own digit limit is lifted.
_MAX_INT_TEXT: Final = 10_000
# C-level bulk operations cost roughly this many items per unit of work; making text of a
# container is slower per item, hence its own, smaller divisor.
_BULK_ITEMS_PER_UNIT: Final = 32
_TEXT_ITEMS_PER_UNIT: Final = 4
# Arithmetic on integers of about 100,000 bits takes milliseconds.
_BITS_PER_UNIT: Final = 32
_MAX_MESSAGE: Final = 200


class EvalError(Exception):
    """The expression cannot be evaluated statically. `.reason` is a short human message."""

    def __init__(self, reason: str) -> None:
        super().__init__(reason)
        self.reason = reason


class EvalUnresolved(EvalError):
    """The expression needs a value the linter does not know (e.g. an arg whose value is
    unresolved, an env var not given). `.name` says which."""

    def __init__(self, reason: str, name: str) -> None:
        super().__init__(reason)
        self.name = name


@dataclass(frozen=True)
class EvalScope:
    """What an expression can see."""

    args: Mapping[str, str | None]
    """Launch args visible here; ``None`` means known to exist but with an unresolved value."""
    env: Mapping[str, str]
    """Explicit environment; ``env('X')`` for a missing X raises :class:`EvalUnresolved`."""
    find: Callable[[str], str | None]
    """Package name to its path, ``None`` if not found."""
    anon: Callable[[str], str]
    """Anonymous id to the resolved anonymous name."""
    dirname: str | None
    """Directory of the current launch file, ``None`` if unknown."""
    budget: Budget | None = None
    """The root file's work budget: charged with this evaluation's work and result."""


def evaluate(source: str, scope: EvalScope) -> str:
    """Evaluate ``source`` like roslaunch's ``$(eval source)``, returning ``str`` of the value.

    Raises :class:`EvalUnresolved` when a needed value is unknown and :class:`EvalError`
    for anything roslaunch would reject, this interpreter refuses, or the bounds forbid.
    """
    tree = _parse(source)
    interpreter = _Interpreter(scope)
    try:
        result = interpreter.text(interpreter.eval(tree.body))
        if scope.budget is not None:
            scope.budget.produce(len(result))
        return result
    except EvalError:
        raise
    except RecursionError:
        raise EvalError("expression is nested too deeply") from None
    except MemoryError:
        raise EvalError("expression needs too much memory") from None
    except (ArithmeticError, LookupError, TypeError, ValueError) as exc:
        # Safety net: every operation converts its own errors, but a missed case must still
        # surface as a refusal rather than crash the linter.
        raise EvalError(_clip(f"{type(exc).__name__}: {exc}")) from None
    finally:
        # Each evaluation is bounded on its own; the root file's budget bounds their sum.
        if scope.budget is not None:
            scope.budget.step(1 + interpreter.spent)


# --- parsing -------------------------------------------------------------------------

# Markers that ast attaches to real nodes; counting them would only penalise operators.
_MARKERS: Final = (ast.expr_context, ast.boolop, ast.operator, ast.unaryop, ast.cmpop)


def _parse(source: str) -> ast.Expression:
    if len(source) > MAX_SOURCE_CHARS:
        raise EvalError(f"expression is longer than {MAX_SOURCE_CHARS:,} characters")
    if "__" in source:
        # Same rule and wording as roslaunch, which applies it to the raw text.
        raise EvalError("$(eval ...) may not contain double underscore expressions")
    # Python's eval() skips leading blanks of a string source; ast.parse does not.
    text = source.lstrip(" \t")
    try:
        with warnings.catch_warnings():
            # Literal-related SyntaxWarnings ("is" with a literal, bad escapes) are noise here.
            warnings.simplefilter("ignore")
            tree = ast.parse(text, mode="eval")
    except SyntaxError as exc:
        raise EvalError(_clip(f"invalid syntax: {exc.msg}")) from None
    except (RecursionError, MemoryError):
        # How the C parser reports running out of its own stack.
        raise EvalError("expression is nested too deeply to parse") from None
    except (ValueError, OverflowError) as exc:
        raise EvalError(_clip(f"cannot parse expression: {exc}")) from None
    _check_shape(tree)
    return tree


def _check_shape(tree: ast.Expression) -> None:
    # Iterative, so a pathological tree cannot exhaust the Python stack before we refuse it.
    count = 0
    stack: list[tuple[ast.AST, int]] = [(tree.body, 1)]
    while stack:
        node, depth = stack.pop()
        if isinstance(node, _MARKERS):
            continue
        count += 1
        if count > MAX_NODES:
            raise EvalError(f"expression has more than {MAX_NODES:,} syntax nodes")
        if depth > MAX_DEPTH:
            raise EvalError(f"expression is nested more than {MAX_DEPTH} levels deep")
        stack.extend((child, depth + 1) for child in ast.iter_child_nodes(node))


# --- values --------------------------------------------------------------------------
#
# Values are plain Python int, float, str, bool, None, list, tuple and dict objects
# (never mutated after creation), plus the two classes below. No other object is ever
# created, so Python's operators applied to values can only run CPython's own code.

_Impl: TypeAlias = Callable[["_Interpreter", tuple[object, ...]], object]


class _Function:
    """A callable of the expression language; only this module's implementations run."""

    __slots__ = ("impl", "name")

    def __init__(self, name: str, impl: _Impl) -> None:
        self.name = name
        self.impl = impl

    def __repr__(self) -> str:
        return f"<function {self.name}>"


class _MapObject:
    """Result of ``map()``: Python's is lazy; ours is computed eagerly and kept as a list."""

    __slots__ = ("items",)

    def __init__(self, items: list[object]) -> None:
        self.items = items

    def __iter__(self) -> Iterator[object]:
        return iter(self.items)


# Python's own error messages (unsupported operand types, not callable, ...) name the type
# of a value; these make them read as they would under roslaunch.
_Function.__name__ = "function"
_MapObject.__name__ = "map"

_OPAQUE: Final = (_Function, _MapObject)


class _Meta(NamedTuple):
    """Size facts about a value, kept so that bounds never need a full traversal."""

    weight: int
    """Characters of a str, estimated digits of an int, 1 for other scalars, and for a
    container the sum over its elements of ``max(1, element weight)``."""
    widest: int
    """Largest ``max(1, weight)`` of one element: bounds the weight of any slice."""
    opaque: bool
    """Holds a function or map object, whose text would be a memory address."""


_SCALAR: Final = _Meta(1, 1, False)
_OPAQUE_SCALAR: Final = _Meta(1, 1, True)
_EMPTY: Final = _Meta(0, 0, False)


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

# The str methods seen in launch files (joining and splitting names, case): none of them
# can grow its input by more than replace() or join() can, and those two are sized first.
_STRING_METHODS: Final = frozenset(
    {
        "join",
        "split",
        "rsplit",
        "replace",
        "strip",
        "lstrip",
        "rstrip",
        "lower",
        "upper",
        "startswith",
        "endswith",
        "find",
        "rfind",
        "count",
        "capitalize",
        "title",
    }
)

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

# printf-style conversion specifiers; "%%" first so it is consumed as a unit.
_FORMAT_SPEC: Final = re.compile(r"%%|%(?:\([^)]*\))?[#0\- +]*(\*|[0-9]+)?(?:\.(\*|[0-9]*))?")


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
        if isinstance(value, bool | float) or value is None:
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
        if isinstance(value, list | tuple):
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
        if isinstance(value, bool | float | str | _Function) or value is None:
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
        if isinstance(node, ast.Tuple | ast.List):
            return self._sequence(node)
        if isinstance(node, ast.Dict):
            return self._dict(node)
        if isinstance(node, ast.Subscript):
            return self._subscript(node)
        if isinstance(node, ast.Call):
            return self._call(node)
        what = _REFUSED.get(type(node), f"{type(node).__name__} expressions are")
        raise EvalError(f"{what} not allowed in $(eval)")

    def _constant(self, node: ast.Constant) -> object:
        value = node.value
        if value is None or isinstance(value, bool | int | float | str):
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
            return self.checked(_auto_convert(value))
        if name in _BUILTINS:
            return _BUILTINS[name]
        if name in vars(builtins):
            raise EvalError(f"the Python builtin '{name}' is not allowed in $(eval)")
        raise EvalError(f"name '{name}' is not defined")

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
        if meta is not None and isinstance(result, list | tuple):
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
        if isinstance(left, str | list | tuple) and isinstance(right, int):
            sequence, count = left, right
        elif isinstance(left, int) and isinstance(right, str | list | tuple):
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
        assert isinstance(sequence, list | tuple)
        inner = self.meta(sequence)
        if inner.weight * count > MAX_ITEMS:
            raise EvalError(f"result would have more than {MAX_ITEMS:,} items")
        self.bulk(len(sequence) * count)
        return inner._replace(weight=inner.weight * count)

    def _format(self, template: str, values: object) -> str:
        """``template % values``, refusing field sizes that would allocate without bound."""
        for match in _FORMAT_SPEC.finditer(template):
            for field in match.groups():
                if field == "*":
                    raise EvalError("'*' field widths in % formatting are not supported")
                if field and (len(field) > 6 or int(field) > _MAX_FORMAT_FIELD):
                    raise EvalError(
                        f"% format field width or precision above {_MAX_FORMAT_FIELD:,}"
                    )
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
        for op, comparator in zip(node.ops, node.comparators, strict=True):
            right = self.eval(comparator)
            result = self.compare(op, left, right)
            if not _truthy(result):
                return result
            left = right
        return result

    def compare(self, op: ast.cmpop, left: object, right: object) -> object:
        if isinstance(op, ast.Is | ast.IsNot):
            if not (_is_singleton(left) or _is_singleton(right)):
                raise EvalError("'is' is only supported against None, True or False")
            return (left is right) == isinstance(op, ast.Is)
        if isinstance(op, ast.In | ast.NotIn):
            if not isinstance(right, str | list | tuple | dict | _MapObject):
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
        for key_node, value_node in zip(node.keys, node.values, strict=True):
            if key_node is None:
                raise EvalError("dict unpacking (**) is not allowed in $(eval)")
            key = self.eval(key_node)
            value = self.eval(value_node)
            _attempt(None, operator.setitem, result, key, value)
        return self.checked(result)

    def _subscript(self, node: ast.Subscript) -> object:
        container = self.eval(node.value)
        if isinstance(node.slice, ast.Slice):
            bounds = [
                None if part is None else self.eval(part)
                for part in (node.slice.lower, node.slice.upper, node.slice.step)
            ]
            return self.slice(container, bounds[0], bounds[1], bounds[2])
        index = self.eval(node.slice)
        return self.index(container, index)

    def slice(self, container: object, lower: object, upper: object, step: object) -> object:
        if not isinstance(container, str | list | tuple):
            raise EvalError(f"{_type_name(container)!r} object cannot be sliced")
        for bound in (lower, upper, step):
            if bound is not None and not isinstance(bound, int):
                raise EvalError("slice indices must be integers or None")
        result = _attempt(None, operator.getitem, container, slice(lower, upper, step))
        if isinstance(result, list | tuple):
            outer = self.meta(container)
            weight = min(outer.weight, len(result) * outer.widest)
            self.remember(result, outer._replace(weight=weight))
            self.bulk(len(result))
        return self.checked(result)

    def index(self, container: object, index: object) -> object:
        if isinstance(container, str | list | tuple):
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
            return self._string_method(node.func, node.args)
        function = self.eval(node.func)
        args = tuple(self.eval(arg) for arg in node.args)
        if not isinstance(function, _Function):
            raise EvalError(f"{_type_name(function)!r} object is not callable")
        return self.call(function, args)

    def _string_method(self, attribute: ast.Attribute, arg_nodes: list[ast.expr]) -> object:
        """``text.method(...)`` for the few ``str`` methods launch files use on names.

        Attribute access stays refused everywhere else: only a call of a whitelisted
        method on a value that is already a ``str`` gets here, and every result is sized
        before it is built.
        """
        receiver = self.eval(attribute.value)
        name = attribute.attr
        if not isinstance(receiver, str) or name not in _STRING_METHODS:
            raise EvalError(f"attribute access (x.{name}) is not allowed in $(eval)")
        args = tuple(self.eval(arg) for arg in arg_nodes)
        self.charge(1 + len(receiver) // 64)
        if name != "join" and not all(
            isinstance(a, str | int) and not isinstance(a, bool) for a in args
        ):
            raise EvalError(f"str.{name}() takes only text or integer arguments here")
        if name == "join":
            if len(args) != 1:
                raise EvalError("str.join() takes exactly one argument")
            items = self.items(args[0], "str.join()")
            if not all(isinstance(i, str) for i in items):
                raise EvalError("str.join() needs a sequence of strings")
            size = sum(len(i) for i in items if isinstance(i, str))
            if size + len(receiver) * max(0, len(items) - 1) > MAX_ITEMS:
                raise EvalError(f"str.join() result longer than {MAX_ITEMS} characters")
            return self.checked(receiver.join(i for i in items if isinstance(i, str)))
        if name == "replace" and len(args) >= 2 and isinstance(args[0], str):
            grown = len(str(args[1])) - len(args[0])
            if grown > 0 and len(receiver) + receiver.count(args[0]) * grown > MAX_ITEMS:
                raise EvalError(f"str.replace() result longer than {MAX_ITEMS} characters")
        return self.checked(_attempt(f"str.{name}()", getattr(str, name), receiver, *args))

    def call(self, function: _Function, args: tuple[object, ...]) -> object:
        self.charge(1)
        return self.checked(function.impl(self, args))

    def items(self, value: object, caller: str) -> Sequence[object]:
        """The elements iterating ``value`` would give, for the iterable kinds of value."""
        if isinstance(value, str | list | tuple):
            return value
        if isinstance(value, dict):
            return list(value)
        if isinstance(value, _MapObject):
            return value.items
        raise EvalError(f"{caller}: {_type_name(value)!r} object is not iterable")


# --- helpers -------------------------------------------------------------------------


def _truthy(value: object) -> bool:
    if isinstance(value, _OPAQUE):
        return True
    return bool(value)


def _is_singleton(value: object) -> bool:
    return value is None or isinstance(value, bool)


def _type_name(value: object) -> str:
    return type(value).__name__


def _clip(message: str) -> str:
    # Python's messages may quote a whole (possibly huge) operand.
    if len(message) <= _MAX_MESSAGE:
        return message
    return message[: _MAX_MESSAGE - 3] + "..."


def _short_repr(value: object) -> str:
    if isinstance(value, int) and value.bit_length() > 256:
        # repr() of a huge int is slow or refused by Python's digit limit.
        return f"<int of {value.bit_length()} bits>"
    if isinstance(value, str) and len(value) > _MAX_MESSAGE:
        return repr(value[:_MAX_MESSAGE]) + "..."
    if isinstance(value, list | tuple | dict):
        return f"<{_type_name(value)} of {len(value)} items>"
    return repr(value)


def _attempt(what: str | None, function: Callable[..., object], *args: object) -> object:
    """Run one CPython operation on values, turning its errors into refusals."""
    prefix = f"{what}: " if what else ""
    try:
        return function(*args)
    except ZeroDivisionError as exc:
        raise EvalError(_clip(f"{prefix}{exc}")) from None
    except OverflowError as exc:
        # Float overflow carries (errno, text); keep only the text.
        detail = exc.args[-1] if exc.args else ""
        raise EvalError(_clip(f"{prefix}numeric overflow: {detail}")) from None
    except KeyError as exc:
        raise EvalError(_clip(f"{prefix}key {_short_repr(exc.args[0])} not found")) from None
    except (ArithmeticError, LookupError, TypeError, ValueError) as exc:
        raise EvalError(_clip(f"{prefix}{exc}")) from None


def _check_power(base: object, exponent: object) -> None:
    """Refuse ``int ** int`` whose result would be huge, before computing it."""
    if not (isinstance(base, int) and isinstance(exponent, int)):
        # Float powers overflow quickly and cheaply; _attempt reports it.
        return
    if exponent <= 0 or abs(base) <= 1:
        return
    if exponent > MAX_POW_EXPONENT:
        raise EvalError(f"integer exponent above {MAX_POW_EXPONENT:,}")
    if exponent * math.log2(abs(base)) > MAX_INT_BITS:
        raise EvalError(f"integer result would have more than {MAX_INT_BITS:,} bits")


def _auto_convert(value: str) -> object:
    """roslaunch's ``convert_value(value, 'auto')``, applied to every arg an expression reads."""
    if "." in value:
        try:
            return float(value)
        except ValueError:
            return value
    # Python 3 accepts "1_000" as an int; roslaunch keeps such values as text.
    if "_" not in value and len(value) <= _MAX_INT_TEXT:
        try:
            return int(value)
        except ValueError:
            pass
    lowered = value.lower()
    if lowered in ("true", "false"):
        return lowered == "true"
    return value


def _arity(name: str, args: tuple[object, ...], low: int, high: int | None) -> None:
    count = len(args)
    if low <= count and (high is None or count <= high):
        return
    if high is None:
        expected = f"at least {low} argument{'s' if low != 1 else ''}"
    elif low == high:
        expected = "no arguments" if low == 0 else f"exactly {low} argument{'s' * (low != 1)}"
    else:
        expected = f"from {low} to {high} arguments"
    raise EvalError(f"{name}() takes {expected} ({count} given)")


def _text_argument(name: str, value: object) -> str:
    if not isinstance(value, str):
        raise EvalError(f"{name}() expects a string, not {_type_name(value)!r}")
    return value


def _check_int_text(name: str, value: str) -> None:
    if len(value) > _MAX_INT_TEXT:
        raise EvalError(f"{name}: text longer than {_MAX_INT_TEXT:,} characters")


# --- roslaunch's functions -----------------------------------------------------------


def _fn_arg(it: _Interpreter, args: tuple[object, ...]) -> object:
    _arity("arg", args, 1, 1)
    name = _text_argument("arg", args[0])
    if name not in it.scope.args:
        raise EvalUnresolved(f"arg '{name}' is not set", name)
    value = it.scope.args[name]
    if value is None:
        raise EvalUnresolved(f"the value of arg '{name}' is not known", name)
    return _auto_convert(value)


def _fn_env(it: _Interpreter, args: tuple[object, ...]) -> object:
    _arity("env", args, 1, 1)
    name = _text_argument("env", args[0])
    if name not in it.scope.env:
        raise EvalUnresolved(f"environment variable '{name}' is not known", name)
    return it.scope.env[name]


def _fn_optenv(it: _Interpreter, args: tuple[object, ...]) -> object:
    _arity("optenv", args, 1, 2)
    name = _text_argument("optenv", args[0])
    if name in it.scope.env:
        return it.scope.env[name]
    return args[1] if len(args) == 2 else ""


def _fn_find(it: _Interpreter, args: tuple[object, ...]) -> object:
    _arity("find", args, 1, 1)
    package = _text_argument("find", args[0])
    path = it.scope.find(package)
    if path is None:
        raise EvalUnresolved(f"package '{package}' not found", package)
    return path


def _fn_anon(it: _Interpreter, args: tuple[object, ...]) -> object:
    _arity("anon", args, 1, 1)
    return it.scope.anon(_text_argument("anon", args[0]))


def _fn_dirname(it: _Interpreter, args: tuple[object, ...]) -> object:
    _arity("dirname", args, 0, 0)
    if it.scope.dirname is None:
        raise EvalUnresolved("the directory of the launch file is not known", "dirname")
    return it.scope.dirname


# --- builtins ------------------------------------------------------------------------


def _fn_list(it: _Interpreter, args: tuple[object, ...]) -> object:
    _arity("list", args, 0, 1)
    if not args:
        return []
    source = args[0]
    result = list(it.items(source, "list()"))
    it.bulk(len(result))
    if isinstance(source, str):
        it.remember(result, _Meta(len(result), 1, False))
    elif isinstance(source, list | tuple):
        it.remember(result, it.meta(source))
    elif isinstance(source, _MapObject):
        it.remember(result, it.meta(source.items))
    return result


def _fn_dict(it: _Interpreter, args: tuple[object, ...]) -> object:
    _arity("dict", args, 0, 1)
    if not args:
        return {}
    source = args[0]
    if isinstance(source, dict):
        it.bulk(len(source))
        return dict(source)
    pairs = it.items(source, "dict()")
    it.bulk(len(pairs))
    return _attempt("dict()", dict, pairs)


def _fn_map(it: _Interpreter, args: tuple[object, ...]) -> object:
    _arity("map", args, 2, None)
    function = args[0]
    if not isinstance(function, _Function):
        raise EvalError(f"{_type_name(function)!r} object is not callable")
    sources = [it.items(source, "map()") for source in args[1:]]
    # Charged up front so that an oversized map is refused before any call is made.
    it.charge(min(len(source) for source in sources))
    results = [it.call(function, group) for group in zip(*sources, strict=False)]
    it.meta(results)
    return _MapObject(results)


def _fn_str(it: _Interpreter, args: tuple[object, ...]) -> object:
    _arity("str", args, 0, 1)
    return it.text(args[0]) if args else ""


def _fn_int(it: _Interpreter, args: tuple[object, ...]) -> object:
    _arity("int", args, 0, 2)
    if not args:
        return 0
    value = args[0]
    if len(args) == 2:
        base = args[1]
        if not isinstance(value, str):
            raise EvalError("int() can't convert non-string with explicit base")
        if not isinstance(base, int):
            raise EvalError(f"int() base must be an integer, not {_type_name(base)!r}")
        _check_int_text("int()", value)
        return _attempt("int()", int, value, base)
    if isinstance(value, str):
        _check_int_text("int()", value)
    elif not isinstance(value, int | float):
        raise EvalError(
            f"int() argument must be a string or a real number, not {_type_name(value)!r}"
        )
    return _attempt("int()", int, value)


def _fn_float(it: _Interpreter, args: tuple[object, ...]) -> object:
    _arity("float", args, 0, 1)
    if not args:
        return 0.0
    value = args[0]
    if not isinstance(value, str | int | float):
        raise EvalError(
            f"float() argument must be a string or a real number, not {_type_name(value)!r}"
        )
    return _attempt("float()", float, value)


def _fn_bool(it: _Interpreter, args: tuple[object, ...]) -> object:
    _arity("bool", args, 0, 1)
    return _truthy(args[0]) if args else False


def _fn_len(it: _Interpreter, args: tuple[object, ...]) -> object:
    _arity("len", args, 1, 1)
    value = args[0]
    if not isinstance(value, str | list | tuple | dict):
        raise EvalError(f"object of type {_type_name(value)!r} has no len()")
    return len(value)


def _fn_abs(it: _Interpreter, args: tuple[object, ...]) -> object:
    _arity("abs", args, 1, 1)
    value = args[0]
    if not isinstance(value, int | float):
        raise EvalError(f"bad operand type for abs(): {_type_name(value)!r}")
    return abs(value)


def _fn_round(it: _Interpreter, args: tuple[object, ...]) -> object:
    _arity("round", args, 1, 2)
    value = args[0]
    digits = args[1] if len(args) == 2 else None
    if not isinstance(value, int | float):
        raise EvalError(f"type {_type_name(value)} doesn't define __round__ method")
    if digits is None:
        return _attempt("round()", round, value)
    if not isinstance(digits, int):
        raise EvalError(f"{_type_name(digits)!r} object cannot be interpreted as an integer")
    if isinstance(value, int) and digits < 0 and -digits > value.bit_length() // 3 + 2:
        # CPython would compute 10**-digits first; the answer is 0 whenever that power
        # exceeds twice |value|, which holds here.
        return 0
    return _attempt("round()", round, value, digits)


def _extremum(name: str, pick: Callable[..., object]) -> _Impl:
    def implementation(it: _Interpreter, args: tuple[object, ...]) -> object:
        if not args:
            raise EvalError(f"{name} expected at least 1 argument, got 0")
        candidates = it.items(args[0], f"{name}()") if len(args) == 1 else args
        it.bulk(len(candidates))
        return _attempt(f"{name}()", pick, candidates)

    return implementation


# --- math ----------------------------------------------------------------------------

_LN2: Final = math.log(2)
# Beyond this many factors a factorial-like result exceeds MAX_INT_BITS anyway, and
# lgamma() of larger floats is pointless.
_MAX_FACTORS: Final = 1_000_000


def _log2_factorial(n: int) -> float:
    return math.lgamma(n + 1) / _LN2


def _log2_perm(n: int, k: int) -> float:
    if k > _MAX_FACTORS:
        return math.inf
    if n >= 2**53:
        # n - k + 1 .. n are all about n.
        return k * math.log2(n)
    return _log2_factorial(n) - _log2_factorial(n - k)


def _math_result_bits(name: str, it: _Interpreter, args: tuple[object, ...]) -> float:
    """Estimated bits of the integer a math function would build, or 0 when it is small."""
    if name == "prod" and len(args) == 1:
        factors = it.items(args[0], "prod()")
        it.charge(len(factors))
        return float(sum(abs(f).bit_length() for f in factors if isinstance(f, int)))
    ints = [arg for arg in args if isinstance(arg, int)]
    if len(ints) != len(args):
        # Float arguments, or ones the function will reject by itself.
        return 0.0
    if name == "lcm":
        return float(sum(abs(n).bit_length() for n in ints))
    if name == "factorial" and len(ints) == 1:
        n = ints[0]
        return math.inf if n > _MAX_FACTORS else _log2_factorial(max(n, 0))
    if name in ("comb", "perm") and 1 <= len(ints) <= 2:
        n, k = ints[0], ints[-1]
        if n < 0 or k < 0 or k > n:
            return 0.0
        if name == "perm":
            return _log2_perm(n, k)
        k = min(k, n - k)
        return _log2_perm(n, k) - (0.0 if k > _MAX_FACTORS else _log2_factorial(k))
    return 0.0


def _math_function(name: str, function: Callable[..., object]) -> _Impl:
    def implementation(it: _Interpreter, args: tuple[object, ...]) -> object:
        for arg in args:
            if isinstance(arg, _Function):
                raise EvalError(f"{name}() cannot take a function as argument")
            if isinstance(arg, list | tuple | dict | _MapObject):
                it.bulk(it.meta(arg).weight)
        for arg in args:
            if isinstance(arg, int):
                it.charge(arg.bit_length() // _BITS_PER_UNIT)
        bits = _math_result_bits(name, it, args)
        if bits > MAX_INT_BITS:
            raise EvalError(f"{name}() result would have more than {MAX_INT_BITS:,} bits")
        # factorial(), comb() and friends multiply many big numbers to build their result.
        it.charge(int(bits) // (_BITS_PER_UNIT // 4))
        return _attempt(f"{name}()", function, *args)

    return implementation


# --- name tables ---------------------------------------------------------------------


def _build_names() -> dict[str, object]:
    names: dict[str, object] = {}
    # Every public name of math, like roslaunch's _eval_dict.update(math.__dict__).
    for name, value in vars(math).items():
        if name.startswith("_"):
            continue
        if isinstance(value, float):
            names[name] = value
        elif callable(value):
            names[name] = _Function(name, _math_function(name, value))
    names.update({"true": True, "false": False, "True": True, "False": False})
    roslaunch: dict[str, _Impl] = {
        "anon": _fn_anon,
        "arg": _fn_arg,
        "dirname": _fn_dirname,
        "env": _fn_env,
        "optenv": _fn_optenv,
        "find": _fn_find,
    }
    names.update({name: _Function(name, impl) for name, impl in roslaunch.items()})
    return names


_NAMES: Final[dict[str, object]] = _build_names()

_BUILTINS: Final[dict[str, object]] = {
    name: _Function(name, impl)
    for name, impl in {
        # What roslaunch meant to expose ...
        "list": _fn_list,
        "dict": _fn_dict,
        "map": _fn_map,
        "str": _fn_str,
        "float": _fn_float,
        "int": _fn_int,
        # ... and harmless builtins it exposes by accident, which launch files do use.
        "len": _fn_len,
        "abs": _fn_abs,
        "round": _fn_round,
        "min": _extremum("min", min),
        "max": _extremum("max", max),
        "bool": _fn_bool,
    }.items()
}
