"""Which names a Python launch file binds, read from its syntax tree (never run).

A name that the file binds nowhere, that no import brings and that is no builtin raises
``NameError`` wherever Python evaluates it. What could bind a name unseen makes the set
unknown: a star import, ``exec``/``eval``, ``globals()``/``locals()``/``vars()``,
``setattr``/``__import__``/``__builtins__``, or a handler that catches ``NameError``
(or one of its bases) and so survives it.
"""

from __future__ import annotations

import ast

# ``dir(builtins)`` of every Python ROS 2 runs on (3.8, Foxy, to 3.13), not of the Python
# running the linter: under 3.8 a launch file calling ``anext`` (3.10) or raising
# ``ExceptionGroup`` (3.11) is fine on the robot. Written out because no one interpreter
# has them all; 3.10 added aiter, anext, EncodingWarning; 3.11 BaseExceptionGroup,
# ExceptionGroup; 3.13 PythonFinalizationError, _IncompleteInputError; none was removed.
_BUILTINS_3_8_TO_3_13 = (
    'ArithmeticError', 'AssertionError', 'AttributeError', 'BaseException',
    'BaseExceptionGroup', 'BlockingIOError', 'BrokenPipeError', 'BufferError',
    'BytesWarning', 'ChildProcessError', 'ConnectionAbortedError', 'ConnectionError',
    'ConnectionRefusedError', 'ConnectionResetError', 'DeprecationWarning', 'EOFError',
    'Ellipsis', 'EncodingWarning', 'EnvironmentError', 'Exception', 'ExceptionGroup',
    'False', 'FileExistsError', 'FileNotFoundError', 'FloatingPointError',
    'FutureWarning', 'GeneratorExit', 'IOError', 'ImportError', 'ImportWarning',
    'IndentationError', 'IndexError', 'InterruptedError', 'IsADirectoryError', 'KeyError',
    'KeyboardInterrupt', 'LookupError', 'MemoryError', 'ModuleNotFoundError', 'NameError',
    'None', 'NotADirectoryError', 'NotImplemented', 'NotImplementedError', 'OSError',
    'OverflowError', 'PendingDeprecationWarning', 'PermissionError', 'ProcessLookupError',
    'PythonFinalizationError', 'RecursionError', 'ReferenceError', 'ResourceWarning',
    'RuntimeError', 'RuntimeWarning', 'StopAsyncIteration', 'StopIteration',
    'SyntaxError', 'SyntaxWarning', 'SystemError', 'SystemExit', 'TabError',
    'TimeoutError', 'True', 'TypeError', 'UnboundLocalError', 'UnicodeDecodeError',
    'UnicodeEncodeError', 'UnicodeError', 'UnicodeTranslateError', 'UnicodeWarning',
    'UserWarning', 'ValueError', 'Warning', 'ZeroDivisionError', '_IncompleteInputError',
    '__build_class__', '__debug__', '__doc__', '__import__', '__loader__', '__name__',
    '__package__', '__spec__', 'abs', 'aiter', 'all', 'anext', 'any', 'ascii', 'bin',
    'bool', 'breakpoint', 'bytearray', 'bytes', 'callable', 'chr', 'classmethod',
    'compile', 'complex', 'copyright', 'credits', 'delattr', 'dict', 'dir', 'divmod',
    'enumerate', 'eval', 'exec', 'exit', 'filter', 'float', 'format', 'frozenset',
    'getattr', 'globals', 'hasattr', 'hash', 'help', 'hex', 'id', 'input', 'int',
    'isinstance', 'issubclass', 'iter', 'len', 'license', 'list', 'locals', 'map', 'max',
    'memoryview', 'min', 'next', 'object', 'oct', 'open', 'ord', 'pow', 'print',
    'property', 'quit', 'range', 'repr', 'reversed', 'round', 'set', 'setattr', 'slice',
    'sorted', 'staticmethod', 'str', 'sum', 'super', 'tuple', 'type', 'vars', 'zip',
)

PYTHON_BUILTINS = frozenset(_BUILTINS_3_8_TO_3_13) | {"__file__", "__name__", "__doc__",
                                                      "__spec__", "__loader__", "__package__"}
"""What Python finds without a binding in the module (``builtins``, module attributes)."""

_DYNAMIC = frozenset({"exec", "eval", "globals", "locals", "vars", "setattr", "__import__",
                      "__builtins__"})
_CATCHES_NAME_ERROR = frozenset({"NameError", "Exception", "BaseException"})


_DEFINITIONS = (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)
_IMPORTS = (ast.Import, ast.ImportFrom)
_DECLARATIONS = (ast.Global, ast.Nonlocal)
_CAPTURES = tuple(kind for kind in vars(ast).values() if isinstance(kind, type)
                  and issubclass(kind, ast.AST) and kind.__name__.startswith("Match"))
"""The pattern node types of this Python (3.10+): some carry a bound name in a ``name``
or ``rest`` field (``case Point(x=px)``, ``case {**rest}``)."""


def bound_names(tree: ast.Module) -> frozenset[str] | None:
    """Every name ``tree`` binds in any scope; None when a name may be bound unseen."""
    bound: set[str] = set()
    # One stack over the tree's nodes (order does not matter here), not ``ast.walk``,
    # whose three generators per node cost more than the tests below.
    pending: list[ast.AST] = [tree]
    push = pending.append
    while pending:
        node = pending.pop()
        for field in node._fields:
            child = getattr(node, field, None)
            if isinstance(child, ast.AST):
                push(child)
            elif isinstance(child, list):
                for item in child:
                    if isinstance(item, ast.AST):
                        push(item)
        if isinstance(node, ast.Name):
            if isinstance(node.ctx, ast.Store):
                bound.add(node.id)
            elif node.id in _DYNAMIC:
                return None
        elif isinstance(node, _DEFINITIONS):
            bound.add(node.name)
        elif isinstance(node, ast.arg):
            bound.add(node.arg)
        elif isinstance(node, _IMPORTS):
            for alias in node.names:
                if alias.name == "*":
                    return None
                bound.add(alias.asname or alias.name.split(".", 1)[0])
        elif isinstance(node, ast.ExceptHandler):
            if node.name:
                bound.add(node.name)
            if _catches_name_error(node.type):
                return None
        elif isinstance(node, _DECLARATIONS):
            bound.update(node.names)
        elif isinstance(node, _CAPTURES):
            for field in ("name", "rest"):
                value = getattr(node, field, None)
                if isinstance(value, str):
                    bound.add(value)
    return frozenset(bound)


def _catches_name_error(kind: ast.expr | None) -> bool:
    if kind is None:
        return True  # a bare ``except:``
    names = kind.elts if isinstance(kind, ast.Tuple) else [kind]
    return any(isinstance(n, (ast.Name, ast.Attribute)) and
               (n.id if isinstance(n, ast.Name) else n.attr) in _CATCHES_NAME_ERROR
               for n in names)
