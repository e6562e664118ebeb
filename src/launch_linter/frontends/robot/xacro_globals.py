"""The names xacro's expressions see without any property: its global symbols, as data.

xacro evaluates ``${...}`` with Python's ``eval`` over its table of properties whose root
is ``create_global_symbols()`` (builtins are disabled: ``globals.update(__builtins__={})``
in ``safe_eval``). Any other name stops xacro with "name 'x' is not defined". The lists
below were read from ``src/xacro/__init__.py`` ``create_global_symbols`` of ros/xacro
noetic-devel 7045754 (2024-03-10) and ``xacro/__init__.py`` of the ros2 branch 9d05b0e
(2024-03-21); both expose the same names, and the later xacro 2.1.1 (PyPI, the ros2
line) adds ``bool`` beside them:

* ``list dict map len str float int bool True False min max round`` directly;
* ``sorted range`` directly (deprecated) and in the ``python`` namespace, which also holds
  ``abs all any complex divmod enumerate filter frozenset hash isinstance issubclass ord
  repr reversed slice set sum tuple type zip``;
* every public name of :mod:`math`, directly and as ``math.x``;
* ``load_yaml abs_filename dotify`` directly (deprecated) and in the ``xacro`` namespace
  (with ``arg message warning error print_location fatal tokenize``).

The math names are those of the target's Python, not the linter's: the list holds every
public name of :mod:`math` up to Python 3.13 (``cbrt exp2`` 3.11, ``sumprod`` 3.12,
``fma`` 3.13), so that a name some target's xacro defines is never said undefined.
Older xacro releases exposed fewer names (a subset), so the union is the safe side.
"""

from __future__ import annotations

import ast
import warnings
from collections.abc import Mapping

from launch_linter.frontends.robot.xacro_values import _Placed, _Refused, _Unknown
from launch_linter.model.robot import INVALID_NAMES

XACRO_BUILTINS = frozenset({
    "list", "dict", "map", "len", "str", "float", "int", "True", "False", "min", "max",
    "round", "sorted", "range", "bool",
})
"""Python builtins xacro binds directly (noetic-devel 7045754, ros2 9d05b0e; ``bool``
from xacro 2.1.1)."""

XACRO_NAMESPACES = frozenset({"python", "math", "xacro"})
"""xacro's namespaces of symbols (``python.abs``, ``math.pi``, ``xacro.load_yaml``)."""

XACRO_FUNCTIONS = frozenset({"load_yaml", "abs_filename", "dotify"})
"""xacro's own functions bound directly as well as in its ``xacro`` namespace."""

MATH_NAMES = frozenset({
    "acos", "acosh", "asin", "asinh", "atan", "atan2", "atanh", "cbrt", "ceil", "comb",
    "copysign", "cos", "cosh", "degrees", "dist", "e", "erf", "erfc", "exp", "exp2",
    "expm1", "fabs", "factorial", "floor", "fma", "fmod", "frexp", "fsum", "gamma", "gcd",
    "hypot", "inf", "isclose", "isfinite", "isinf", "isnan", "isqrt", "lcm", "ldexp",
    "lgamma", "log", "log10", "log1p", "log2", "modf", "nan", "nextafter", "perm", "pi",
    "pow", "prod", "radians", "remainder", "sin", "sinh", "sqrt", "sumprod", "tan", "tanh",
    "tau", "trunc", "ulp",
})
"""Every public name of Python's :mod:`math` up to 3.13 (xacro exposes them all)."""

XACRO_GLOBAL_NAMES = XACRO_BUILTINS | XACRO_NAMESPACES | XACRO_FUNCTIONS | MATH_NAMES


def xacro_defines(name: str) -> bool:
    """Whether some xacro of Noetic or ROS 2 defines ``name`` without a property. A name
    with ``__`` is refused by xacro with another message: left to the unknown side."""
    return name in XACRO_GLOBAL_NAMES or name.startswith("__")


def undefined_name(reason: str, name: str, open_tables: bool) -> _Unknown:
    """What reading ``name``, defined by no property, is: xacro's refusal when it is no
    global symbol of xacro and nothing left unknown (``open_tables``: an include not
    followed, a property or conditional not decided, a legacy xacro that is not in-order)
    could have defined it; unknown otherwise."""
    if open_tables or xacro_defines(name):
        return _Unknown(f"{reason} (it may be defined where the linter did not look)")
    return _Refused(f"{reason} (no property by then, and no symbol of xacro)")


DUNDER_ALLOWED_DISTROS = frozenset({"hydro", "indigo", "jade", "kinetic", "lunar", "dashing",
                                    "eloquent"})
"""Distributions whose last xacro predates ``safe_eval`` (ros/xacro 9941961, 2021-09-03,
``src/xacro/__init__.py``: ``invalid_names = [n for n in code.co_names if
n.startswith("__")]`` then "Use of invalid name(s)"), first released in 1.13.13 (Melodic),
1.14.9 (Noetic) and 2.0.7 (the ros2 branch, released to the ROS 2 distributions supported
then, Foxy and Galactic, and every later one), 2021-09-04; kinetic-devel never had it."""

_SCOPES = (ast.Lambda, ast.ListComp, ast.SetComp, ast.DictComp, ast.GeneratorExp)
"""Nodes whose names Python compiles into a code object of their own (before Python 3.12
a comprehension too): xacro checks only the expression's own ``co_names``."""


def dunder_refusal(source: str, distro: str | None,
                   defined: Mapping[str, tuple[str, int]]) -> _Refused | None:
    """xacro's refusal of ``${source}`` for reading a name that begins with ``__`` (a
    property ``__limits``, an attribute ``x.__class__``), where the target's xacro has
    ``safe_eval`` (``distro`` not known: as the current xacro of every supported
    distribution). Only the names compiled into the expression's own ``co_names`` (the
    names it reads and the attributes it takes, outside a lambda or comprehension) are
    checked, as xacro does; None when there is none or the text is no expression. A
    property so named (``defined``: its file and line) is the fault: its name, placed
    at its definition (one finding however often it is read)."""
    if "__" not in source or distro in DUNDER_ALLOWED_DISTROS:
        return None
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            tree = ast.parse(source.strip(), mode="eval")
    except (SyntaxError, ValueError, RecursionError, MemoryError, OverflowError):
        return None  # what xacro makes of it is said elsewhere (or unknown)
    found: list[tuple[int, str]] = []  # (offset in the text, name)
    stack: list[ast.AST] = [tree.body]
    while stack:  # iterative: as many nodes as the text (bounded by the caller's charge)
        node = stack.pop()
        if isinstance(node, _SCOPES):
            continue
        if isinstance(node, ast.Name) and node.id.startswith("__"):
            found.append((node.col_offset, node.id))
        elif isinstance(node, ast.Attribute) and node.attr.startswith("__"):
            found.append((node.col_offset, node.attr))
        stack.extend(ast.iter_child_nodes(node))
    if not found:
        return None
    names = [name for _, name in sorted(found)]
    since = "xacro 1.13.13, 1.14.9 and 2.0.7 on: safe_eval"
    read = f"${{{source}}}: {INVALID_NAMES}: {', '.join(sorted(set(names))[:5])}"
    place = defined.get(names[0])
    if place is None:
        return _Refused(f"{read} (names beginning with '__' are refused, {since})")
    return _Placed(read, place[0], place[1],
                   f"{INVALID_NAMES}: property '{names[0]}' is refused by every expression "
                   f"that reads it (names beginning with '__', {since}); rename it")
