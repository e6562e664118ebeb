"""Reading a ROS 2 Python launch file: parse it, run its module code and its
``generate_launch_description()`` in the interpreter, and hand the actions over."""

from __future__ import annotations

import ast
import os
import sys
import tokenize
from collections.abc import Callable, Mapping
from io import BytesIO, StringIO

from launch_linter.frontends import python_trees
from launch_linter.frontends.ros2_actions import Action, FileRead, Problem, Unfollowed, Where
from launch_linter.frontends.ros2_python.launch_api import Interpreter
from launch_linter.frontends.ros2_python.names import bound_names
from launch_linter.frontends.ros2_python.string_truth import (
    may_test_arguments,
    string_truth_problems,
)
from launch_linter.frontends.ros2_python.values import (
    Env,
    FuncVal,
    LaunchDescriptionVal,
    Unknown,
    _Break,
    _Continue,
    _OutOfSteps,
    _Return,
)
from launch_linter.model.budget import Budget
from launch_linter.model.launch import DIRECTIVE_MARKER
from launch_linter.model.transform import LaunchFormat
from launch_linter.resolve.bounded import PYTHON_MAX_STEPS as MAX_STEPS
from launch_linter.resolve.xml_safe import MAX_BYTES

FORMAT = LaunchFormat.ROS2_PYTHON

MAX_SEPARATORS = 300_000
"""Operators and separators of one Python launch file: each makes a syntax node or two,
and ``ast.parse`` builds the whole tree in memory (a 4-million-item list literal took 15 s
and 3.8 GB). The most in the corpus's 709 Python launch files is 1,459."""
_SEPARATORS = b",;()[]{}.=+-*/%<>&|^~@:"


def _directive_comments(data: bytes) -> tuple[tuple[int, str], ...]:
    """The comments of a file that may hold a suppression directive, else none."""
    if DIRECTIVE_MARKER.encode() not in data:
        return ()
    found: list[tuple[int, str]] = []
    try:
        for token in tokenize.tokenize(BytesIO(data).readline):
            if token.type == tokenize.COMMENT:
                found.append((token.start[0], token.string[1:]))
    except (tokenize.TokenError, SyntaxError, UnicodeDecodeError):
        return tuple(found)
    return tuple(found)


def _unclosed_bracket(source: str) -> tuple[int, int, str] | None:
    """Where a bracket left open to the end of the file was opened, as the parser of the
    Python 3.10+ that ROS 2 runs launch files with reports it ("'(' was never closed" at
    the bracket); the parser of Python 3.8 and 3.9 names a later line instead. None when
    no bracket stays open (the host parser's own report stands)."""
    if sys.version_info >= (3, 10):
        return None  # the host parser reports the bracket itself
    openers: list[tuple[int, int, str]] = []
    closing = {")": "(", "]": "[", "}": "{"}
    try:
        for token in tokenize.generate_tokens(StringIO(source).readline):
            if token.type != tokenize.OP:
                continue
            if token.string in "([{":
                openers.append((token.start[0], token.start[1] + 1, token.string))
            elif token.string in closing:
                if not openers or openers[-1][2] != closing[token.string]:
                    return None  # a closer that does not match: another fault
                openers.pop()
    except tokenize.TokenError:  # the end of the file inside a bracket
        if openers:
            line, column, bracket = openers[-1]
            return line, column, f"'{bracket}' was never closed"
    except SyntaxError:
        pass
    return None


def _as_python_reads(data: bytes, path: str) -> tuple[str, ast.Module] | None:
    """The text and tree of a file that is not UTF-8 throughout but that Python compiles:
    ros2 launch runs ``SourceFileLoader``, which compiles the file's bytes, and CPython
    decodes them by their coding declaration (UTF-8 without one) and does not check the
    bytes of comments (3.8 to 3.12 alike: a GBK comment in guyuehome/originbot's
    camera_internal.launch.py loads). None when Python refuses the bytes too."""
    import io
    import tokenize

    try:
        tree = ast.parse(data, filename=path)
        encoding, _ = tokenize.detect_encoding(io.BytesIO(data).readline)
        # Only comments can hold what the encoding does not decode: replaced, unread.
        return data.decode(encoding, errors="replace"), tree
    except (SyntaxError, ValueError, LookupError, RecursionError, MemoryError):
        return None


def read_python(path: str, data: bytes, budget: Budget | None = None,
                environ: Mapping[str, str] | None = None,
                installed: Callable[[], str | None] | None = None) -> FileRead:
    """Read a ROS 2 Python launch file (``path`` absolute, ``data`` its bytes; ``environ``
    the environment variables the run is told of; ``installed`` tells, when asked, where
    the file is installed, which ``__file__`` names, if that differs from ``path``)."""
    if len(data) > MAX_BYTES:
        message = f"file is {len(data)} bytes, larger than the {MAX_BYTES}-byte limit"
        return FileRead(FORMAT, None, problems=(Problem("parse_error", 1, 1, message),))
    separators = len(data) - len(data.translate(None, _SEPARATORS))
    if separators > MAX_SEPARATORS:
        message = (f"{separators:,} operators and separators, more than the "
                   f"{MAX_SEPARATORS:,} a launch file is read with; not parsed")
        return FileRead(FORMAT, None, problems=(Problem("parse_error", 1, 1, message),))
    try:
        # A byte order mark is allowed, as Python itself allows it.
        source = data.decode("utf-8-sig")
        tree = ast.parse(source, filename=path)
    except UnicodeDecodeError as exc:
        read = _as_python_reads(data, path)
        if read is None:
            message = f"not UTF-8 text: {exc.reason}"
            return FileRead(FORMAT, None, problems=(Problem("parse_error", 1, 1, message),))
        source, tree = read
    except SyntaxError as exc:
        line, column, why = _unclosed_bracket(source) or (
            exc.lineno or 1, (exc.offset or 0) or 1, exc.msg)
        problem = Problem("parse_error", line, column, f"not valid Python: {why}")
        return FileRead(FORMAT, None, _directive_comments(data), (), (problem,))
    except (RecursionError, MemoryError, ValueError) as exc:
        message = f"not readable Python: {type(exc).__name__}"
        return FileRead(FORMAT, None, problems=(Problem("parse_error", 1, 1, message),))
    python_trees.note(path, data, tree)  # for locating fixes without parsing again
    comments = _directive_comments(data)
    # Statement lines only place directives: skipped (with the tokenizer) in the many files
    # that hold none.
    lines = (
        sorted({n.lineno for n in ast.walk(tree) if isinstance(n, (ast.stmt, ast.Call))})
        if comments else ()
    )
    interpreter = Interpreter(path, source, environ=dict(environ or {}),
                              installed=installed, bound=_once(bound_names, tree))
    truth = string_truth_problems(tree) if may_test_arguments(source) else ()
    interpreter.truth_told = frozenset(problem.line for problem in truth)
    actions = _launch_description(interpreter, tree)
    if budget is not None:
        # The interpreter's own step limit bounds one file; the root file's budget bounds
        # a file included many times.
        budget.step(interpreter.steps)
    problems = (*interpreter.problems, *truth)
    return FileRead(FORMAT, actions, comments, tuple(lines), problems,
                    interpreter.forget_deferred_scopes if interpreter.deferring else None)


ENTRY_POINTS = ("generate_launch_description", "generate_test_description")
"""What ``ros2 launch`` and ``launch_testing`` call; ``launch_pytest`` fixtures next."""


def _is_launch_pytest_fixture(decorator: ast.expr) -> bool:
    """``@launch_pytest.fixture``, ``@launch_pytest.fixture(...)`` or a bare ``@fixture``
    imported from it (checked by the caller)."""
    target = decorator.func if isinstance(decorator, ast.Call) else decorator
    return (
        isinstance(target, ast.Attribute) and target.attr == "fixture"
        and isinstance(target.value, ast.Name) and target.value.id == "launch_pytest"
    )


def _entry_point(tree: ast.Module, module: Env) -> tuple[str, FuncVal] | None:
    for name in ENTRY_POINTS:
        found, function = module.lookup(name)
        if found and isinstance(function, FuncVal):
            return name, function
    fixture_imported = any(
        isinstance(statement, ast.ImportFrom) and statement.module == "launch_pytest"
        and any(alias.name == "fixture" and alias.asname is None for alias in statement.names)
        for statement in tree.body
    )
    for statement in tree.body:
        if not isinstance(statement, ast.FunctionDef):
            continue
        for decorator in statement.decorator_list:
            bare = decorator.func if isinstance(decorator, ast.Call) else decorator
            if _is_launch_pytest_fixture(decorator) or (
                fixture_imported and isinstance(bare, ast.Name) and bare.id == "fixture"
            ):
                found, function = module.lookup(statement.name)
                if found and isinstance(function, FuncVal):
                    return statement.name, function
    return None


def _yield_as_return(function: FuncVal) -> FuncVal:
    """A fixture that ``yield``s its launch description (then cleans up) gives what it
    yields first: its body up to that statement, with the ``yield`` read as ``return``."""
    node = function.node
    if not isinstance(node, ast.FunctionDef):
        return function
    for index, statement in enumerate(node.body):
        if isinstance(statement, ast.Expr) and isinstance(statement.value, ast.Yield):
            returned = ast.copy_location(ast.Return(value=statement.value.value), statement)
            body = [*node.body[:index], returned]
            copy = ast.copy_location(ast.FunctionDef(
                name=node.name, args=node.args, body=body, decorator_list=[],
                returns=None, type_comment=None,
            ), node)
            return FuncVal(copy, function.closure, function.defaults)
    return function


def _served(interpreter: Interpreter, module: Env) -> LaunchDescriptionVal | None:
    """A script's launch description: what its module code, or else its ``main()``,
    gives ``LaunchService().include_launch_description``."""
    if not interpreter.served:
        found, main = module.lookup("main")
        if found and isinstance(main, FuncVal):
            interpreter.call_function(main, [], {}, main.node)
    if not interpreter.served:
        return None
    items: list[object] = []
    for description in interpreter.served:
        if isinstance(description, LaunchDescriptionVal):
            items.extend(description.items)
        else:
            items.append(description)
    return LaunchDescriptionVal(items)


def _fixture_arguments(interpreter: Interpreter, function: FuncVal, module: Env
                       ) -> dict[str, object]:
    """pytest passes a fixture's parameters from the fixtures of the same name: the
    module's own functions of those names are called (without arguments)."""
    values: dict[str, object] = {}
    for parameter in function.node.args.args:
        found, fixture = module.lookup(parameter.arg)
        if found and isinstance(fixture, FuncVal) and fixture is not function:
            values[parameter.arg] = interpreter.call_function(fixture, [], {}, fixture.node)
    return values


def _launch_description(interpreter: Interpreter, tree: ast.Module) -> tuple[Action, ...]:
    try:
        return _run_launch_description(interpreter, tree)
    finally:
        interpreter.forget_scopes()


def _run_launch_description(interpreter: Interpreter, tree: ast.Module) -> tuple[Action, ...]:
    module = interpreter.scope(None)
    top = Where(interpreter.path, 1, 1)
    try:
        interpreter.run_block(tree.body, module)
        entry = _entry_point(tree, module)
        if entry is None:
            served = _served(interpreter, module)
            if served is not None:
                return interpreter.actions(served.items, tree)
            if os.path.basename(interpreter.path).startswith("test_"):
                # A pytest module named like a launch test (test_*_launch.py) that starts
                # nothing itself: a test, not a launch file that failed to load.
                return ()
            interpreter.problems.append(Problem(
                "unresolved", 1, 1,
                "no generate_launch_description(), generate_test_description() or "
                "launch_pytest fixture: not a launch file ros2 launch can load; not read",
            ))
            return ()
        entry_name, function = entry
        node = function.node
        arguments = (_fixture_arguments(interpreter, function, module)
                     if entry_name not in ENTRY_POINTS else {})
        function = _yield_as_return(function)
        result = interpreter.call_function(function, [], arguments, node)
        if isinstance(result, (tuple, list)) and result and isinstance(
            result[0], LaunchDescriptionVal
        ):
            # launch_testing's (LaunchDescription, {name: process, ...}) form.
            result = result[0]
    except _OutOfSteps:
        return (Unfollowed(top, f"stopped interpreting after {MAX_STEPS} steps: the launch "
                                f"description is not followed"),)
    except RecursionError:
        return (Unfollowed(top, "expressions nested too deeply: the launch description is "
                                "not followed"),)
    except (_Return, _Break, _Continue):
        return (Unfollowed(top, "return, break or continue outside a function"),)
    if isinstance(result, LaunchDescriptionVal):
        return interpreter.actions(result.items, node)
    if isinstance(result, Unknown):
        return (Unfollowed(Where(interpreter.path, result.line, 1),
                           f"the launch description is unknown: {result.describe()}"),)
    return interpreter.actions(result, node)


def _once(function: Callable[[ast.Module], frozenset[str] | None],
          tree: ast.Module) -> Callable[[], frozenset[str] | None]:
    """``function(tree)``, computed on the first call and kept."""
    kept: list[frozenset[str] | None] = []

    def value() -> frozenset[str] | None:
        if not kept:
            kept.append(function(tree))
        return kept[0]

    return value
