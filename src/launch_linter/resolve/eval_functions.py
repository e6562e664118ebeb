"""The functions an ``$(eval)`` expression may call: roslaunch's helpers (``arg``,
``env``, ``optenv``, ``find``, ``anon``, ``dirname``), the builtins roslaunch meant to
offer, and every public function of :mod:`math`, each result bounded before it is built.
"""

from __future__ import annotations

import math
from typing import Callable, Final

from launch_linter.resolve.bounded import EVAL_MAX_INT_BITS as MAX_INT_BITS
from launch_linter.resolve.eval_values import (
    _BITS_PER_UNIT,
    EvalError,
    EvalUnresolved,
    Machine,
    _arity,
    _attempt,
    _auto_convert,
    _check_int_text,
    _Function,
    _Impl,
    _MapObject,
    _Meta,
    _text_argument,
    _truthy,
    _type_name,
)

# --- roslaunch's functions -----------------------------------------------------------


def _fn_arg(it: Machine, args: tuple[object, ...]) -> object:
    _arity("arg", args, 1, 1)
    name = _text_argument("arg", args[0])
    if name not in it.scope.args:
        raise EvalUnresolved(f"arg '{name}' is not set", name)
    value = it.scope.args[name]
    if value is None:
        raise EvalUnresolved(f"the value of arg '{name}' is not known", name)
    return _auto_convert(value) if isinstance(value, str) else value


def _fn_env(it: Machine, args: tuple[object, ...]) -> object:
    _arity("env", args, 1, 1)
    name = _text_argument("env", args[0])
    if name not in it.scope.env:
        raise EvalUnresolved(f"environment variable '{name}' is not known", name)
    return it.scope.env[name]


def _fn_optenv(it: Machine, args: tuple[object, ...]) -> object:
    _arity("optenv", args, 1, 2)
    name = _text_argument("optenv", args[0])
    if name in it.scope.env:
        return it.scope.env[name]
    return args[1] if len(args) == 2 else ""


def _fn_find(it: Machine, args: tuple[object, ...]) -> object:
    _arity("find", args, 1, 1)
    package = _text_argument("find", args[0])
    path = it.scope.find(package)
    if path is None:
        raise EvalUnresolved(f"package '{package}' not found", package)
    return path


def _fn_anon(it: Machine, args: tuple[object, ...]) -> object:
    _arity("anon", args, 1, 1)
    return it.scope.anon(_text_argument("anon", args[0]))


def _fn_dirname(it: Machine, args: tuple[object, ...]) -> object:
    _arity("dirname", args, 0, 0)
    if it.scope.dirname is None:
        raise EvalUnresolved("the directory of the launch file is not known", "dirname")
    return it.scope.dirname


# --- builtins ------------------------------------------------------------------------


def _fn_list(it: Machine, args: tuple[object, ...]) -> object:
    _arity("list", args, 0, 1)
    if not args:
        return []
    source = args[0]
    result = list(it.items(source, "list()"))
    it.bulk(len(result))
    if isinstance(source, str):
        it.remember(result, _Meta(len(result), 1, False))
    elif isinstance(source, (list, tuple)):
        it.remember(result, it.meta(source))
    elif isinstance(source, _MapObject):
        it.remember(result, it.meta(source.items))
    return result


def _fn_dict(it: Machine, args: tuple[object, ...]) -> object:
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


def _fn_map(it: Machine, args: tuple[object, ...]) -> object:
    _arity("map", args, 2, None)
    function = args[0]
    if not isinstance(function, _Function):
        raise EvalError(f"{_type_name(function)!r} object is not callable")
    sources = [it.items(source, "map()") for source in args[1:]]
    # Charged up front so that an oversized map is refused before any call is made.
    it.charge(min(len(source) for source in sources))
    results = [it.call(function, group) for group in zip(*sources)]
    it.meta(results)
    return _MapObject(results)


def _fn_str(it: Machine, args: tuple[object, ...]) -> object:
    _arity("str", args, 0, 1)
    return it.text(args[0]) if args else ""


def _fn_int(it: Machine, args: tuple[object, ...]) -> object:
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
    elif not isinstance(value, (int, float)):
        raise EvalError(
            f"int() argument must be a string or a real number, not {_type_name(value)!r}"
        )
    return _attempt("int()", int, value)


def _fn_float(it: Machine, args: tuple[object, ...]) -> object:
    _arity("float", args, 0, 1)
    if not args:
        return 0.0
    value = args[0]
    if not isinstance(value, (str, int, float)):
        raise EvalError(
            f"float() argument must be a string or a real number, not {_type_name(value)!r}"
        )
    return _attempt("float()", float, value)


def _fn_bool(it: Machine, args: tuple[object, ...]) -> object:
    _arity("bool", args, 0, 1)
    return _truthy(args[0]) if args else False


def _fn_len(it: Machine, args: tuple[object, ...]) -> object:
    _arity("len", args, 1, 1)
    value = args[0]
    if not isinstance(value, (str, list, tuple, dict)):
        raise EvalError(f"object of type {_type_name(value)!r} has no len()")
    return len(value)


def _fn_abs(it: Machine, args: tuple[object, ...]) -> object:
    _arity("abs", args, 1, 1)
    value = args[0]
    if not isinstance(value, (int, float)):
        raise EvalError(f"bad operand type for abs(): {_type_name(value)!r}")
    return abs(value)


def _fn_round(it: Machine, args: tuple[object, ...]) -> object:
    _arity("round", args, 1, 2)
    value = args[0]
    digits = args[1] if len(args) == 2 else None
    if not isinstance(value, (int, float)):
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
    def implementation(it: Machine, args: tuple[object, ...]) -> object:
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


def _math_result_bits(name: str, it: Machine, args: tuple[object, ...]) -> float:
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
    def implementation(it: Machine, args: tuple[object, ...]) -> object:
        for arg in args:
            if isinstance(arg, _Function):
                raise EvalError(f"{name}() cannot take a function as argument")
            if isinstance(arg, (list, tuple, dict, _MapObject)):
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
