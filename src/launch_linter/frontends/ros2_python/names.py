"""Which names a Python launch file binds, read from its syntax tree (never run).

A name that the file binds nowhere, that no import brings and that is no builtin raises
``NameError`` wherever Python evaluates it. What could bind a name unseen makes the set
unknown: a star import, ``exec``/``eval``, ``globals()``/``locals()``/``vars()``,
``setattr``/``__import__``/``__builtins__``, or a handler that catches ``NameError``
(or one of its bases) and so survives it.
"""

from __future__ import annotations

import ast
import builtins

PYTHON_BUILTINS = frozenset(dir(builtins)) | {"__file__", "__name__", "__doc__",
                                               "__spec__", "__loader__", "__package__"}
"""What Python finds without a binding in the module (``builtins``, module attributes)."""

_DYNAMIC = frozenset({"exec", "eval", "globals", "locals", "vars", "setattr", "__import__",
                      "__builtins__"})
_CATCHES_NAME_ERROR = frozenset({"NameError", "Exception", "BaseException"})


def bound_names(tree: ast.Module) -> frozenset[str] | None:
    """Every name ``tree`` binds in any scope; None when a name may be bound unseen."""
    bound: set[str] = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Name):
            if isinstance(node.ctx, ast.Store):
                bound.add(node.id)
            elif node.id in _DYNAMIC:
                return None
        elif isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
            bound.add(node.name)
        elif isinstance(node, ast.arg):
            bound.add(node.arg)
        elif isinstance(node, (ast.Import, ast.ImportFrom)):
            for alias in node.names:
                if alias.name == "*":
                    return None
                bound.add(alias.asname or alias.name.split(".", 1)[0])
        elif isinstance(node, ast.ExceptHandler):
            if node.name:
                bound.add(node.name)
            if _catches_name_error(node.type):
                return None
        elif isinstance(node, (ast.Global, ast.Nonlocal)):
            bound.update(node.names)
        else:
            # Pattern captures (``case Point(x=px)``, Python 3.10) and any other node that
            # carries a bound name in a ``name``/``rest`` field.
            for field in ("name", "rest"):
                value = getattr(node, field, None)
                if isinstance(value, str) and type(node).__name__.startswith("Match"):
                    bound.add(value)
    return frozenset(bound)


def _catches_name_error(kind: ast.expr | None) -> bool:
    if kind is None:
        return True  # a bare ``except:``
    names = kind.elts if isinstance(kind, ast.Tuple) else [kind]
    return any(isinstance(n, (ast.Name, ast.Attribute)) and
               (n.id if isinstance(n, ast.Name) else n.attr) in _CATCHES_NAME_ERROR
               for n in names)
