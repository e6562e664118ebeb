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

from launch_linter.frontends.robot.xacro_values import _Refused, _Unknown

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
