"""The values of our ``$(eval)`` interpreter, its errors and scope, and helpers.

Values are plain Python int, float, str, bool, None, list, tuple and dict objects (never
mutated after creation), plus :class:`_Function` and :class:`_MapObject`. No other object
is ever created, so Python's operators applied to values can only run CPython's own code.
"""

from __future__ import annotations

import ast
import math
from collections.abc import Iterator, Mapping, Sequence
from dataclasses import dataclass
from typing import Any, Callable, Final, NamedTuple, Protocol, Tuple

from launch_linter.model.budget import Budget
from launch_linter.resolve.bounded import EVAL_MAX_INT_BITS as MAX_INT_BITS
from launch_linter.resolve.bounded import EVAL_MAX_INT_TEXT
from launch_linter.resolve.bounded import EVAL_MAX_POW_EXPONENT as MAX_POW_EXPONENT

# C-level bulk operations cost roughly this many items per unit of work; making text of a
# container is slower per item, hence its own, smaller divisor.
_BULK_ITEMS_PER_UNIT: Final = 32
_TEXT_ITEMS_PER_UNIT: Final = 4
# Arithmetic on integers of about 100,000 bits takes milliseconds.
_BITS_PER_UNIT: Final = 32
_MAX_MESSAGE: Final = 200


def subscript_index(node: ast.Subscript) -> ast.expr:
    """``node.slice`` as Python 3.9+ parses it: Python 3.8 wraps an index in ``ast.Index``
    and a tuple holding slices (``a[1:2, 3]``) in ``ast.ExtSlice``."""
    inner: Any = node.slice
    kind = type(inner).__name__
    if kind == "Index":
        index: ast.expr = inner.value
        return index
    if kind == "ExtSlice":
        return ast.copy_location(ast.Tuple(elts=list(inner.dims), ctx=ast.Load()), node)
    return node.slice


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


class EvalUndefined(EvalError):
    """The expression reads a name that nothing in scope defines (Python's
    ``NameError``). `.name` says which."""

    def __init__(self, reason: str, name: str) -> None:
        super().__init__(reason)
        self.name = name


@dataclass(frozen=True)
class EvalScope:
    """What an expression can see."""

    args: Mapping[str, object]
    """Launch args visible here; ``None`` means known to exist but with an unresolved value.
    Text is converted by roslaunch's "auto" rule; a caller may bind data values (dict,
    list, numbers) or values made by :func:`function`, which are used as they are."""
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


class Machine(Protocol):
    """What a function of the language uses of the interpreter running it."""

    scope: EvalScope

    def charge(self, units: int) -> None: ...

    def bulk(self, items: int) -> None: ...

    def meta(self, value: object) -> _Meta: ...

    def remember(self, value: object, meta: _Meta) -> _Meta: ...

    def items(self, value: object, caller: str) -> Sequence[object]: ...

    def call(self, function: _Function, args: tuple[object, ...]) -> object: ...

    def text(self, value: object) -> str: ...



# --- values --------------------------------------------------------------------------
#
# Values are plain Python int, float, str, bool, None, list, tuple and dict objects
# (never mutated after creation), plus the two classes below. No other object is ever
# created, so Python's operators applied to values can only run CPython's own code.

_Impl = Callable[[Machine, Tuple[object, ...]], object]


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


class AttributeDict(dict):  # type: ignore[type-arg]
    """A dict whose keys also read as attributes (``d.key``), as xacro's YAML dicts and
    include namespaces do. Only data supplied by the caller (never built by an
    expression) is of this kind, and reading an attribute only looks its key up."""

    __slots__ = ()


AttributeDict.__name__ = "dict"


def function(name: str, impl: _Impl) -> object:
    """A callable value of the language, for a caller that binds extra names (xacro's
    ``load_yaml``): ``impl`` receives the interpreter and the positional arguments."""
    return _Function(name, impl)


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
    if isinstance(value, (list, tuple, dict)):
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
    if "_" not in value and len(value) <= EVAL_MAX_INT_TEXT:
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
    if len(value) > EVAL_MAX_INT_TEXT:
        raise EvalError(f"{name}: text longer than {EVAL_MAX_INT_TEXT:,} characters")
