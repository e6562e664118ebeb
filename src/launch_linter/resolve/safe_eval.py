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

* attribute access (except a few ``str`` methods and the keys of a dict the caller
  binds as attribute-readable, :class:`AttributeDict`), keyword arguments, ``*x``,
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
import warnings
from typing import Final

from launch_linter.resolve.bounded import EVAL_MAX_DEPTH as MAX_DEPTH
from launch_linter.resolve.bounded import EVAL_MAX_INT_BITS as MAX_INT_BITS
from launch_linter.resolve.bounded import EVAL_MAX_ITEMS as MAX_ITEMS
from launch_linter.resolve.bounded import EVAL_MAX_NODES as MAX_NODES
from launch_linter.resolve.bounded import EVAL_MAX_POW_EXPONENT as MAX_POW_EXPONENT
from launch_linter.resolve.bounded import EVAL_MAX_SOURCE_CHARS as MAX_SOURCE_CHARS
from launch_linter.resolve.bounded import EVAL_MAX_WORK as MAX_WORK
from launch_linter.resolve.eval_interpreter import _Interpreter
from launch_linter.resolve.eval_values import (
    EvalError,
    EvalScope,
    EvalUndefined,
    EvalUnresolved,
    _clip,
    subscript_index,
)

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
    "EvalUndefined",
    "EvalUnresolved",
    "evaluate",
    "evaluate_value",
    "subscript_index",
]


def evaluate(source: str, scope: EvalScope) -> str:
    """Evaluate ``source`` like roslaunch's ``$(eval source)``, returning ``str`` of the value.

    Raises :class:`EvalUnresolved` when a needed value is unknown and :class:`EvalError`
    for anything roslaunch would reject, this interpreter refuses, or the bounds forbid.
    """
    result = _run(source, scope, True)
    assert isinstance(result, str)
    return result


def evaluate_value(source: str, scope: EvalScope) -> object:
    """Like :func:`evaluate`, but the value itself (a dict, list, number or text; xacro
    keeps the value of a text that is one ``${...}``), bounded in size like any result."""
    return _run(source, scope, False)


def _run(source: str, scope: EvalScope, as_text: bool) -> object:
    tree = _parse(source)
    interpreter = _Interpreter(scope)
    try:
        value = interpreter.eval(tree.body)
        result = interpreter.text(value) if as_text else value
        if scope.budget is not None:
            scope.budget.produce(len(result) if isinstance(result, str) else 1)
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


# The same few expressions come back in file after file (``$(eval arg('x') == 'true')``):
# each text's checked tree (the interpreter only reads it) or refusal, kept for short texts,
# the whole memo dropped when full.
_PARSED: dict[str, ast.Expression | str] = {}
_PARSED_MAX_ENTRIES: Final = 1024
_PARSED_MAX_CHARS: Final = 400


def _parse(source: str) -> ast.Expression:
    if len(source) > _PARSED_MAX_CHARS:
        return _parse_uncached(source)
    known = _PARSED.get(source)
    if known is None:
        try:
            known = _parse_uncached(source)
        except EvalError as exc:
            known = exc.reason
        if len(_PARSED) >= _PARSED_MAX_ENTRIES:
            _PARSED.clear()
        _PARSED[source] = known
    if isinstance(known, str):
        raise EvalError(known)
    return known


def _parse_uncached(source: str) -> ast.Expression:
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
