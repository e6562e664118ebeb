"""Truth tests, in a Python launch file, of what a launch argument is not: its text, or
the substitution object that names it. Read from the syntax tree alone, never run.

``LaunchConfiguration('x').perform(context)`` and ``context.launch_configurations['x']``
give the argument's text, a ``str`` (launch's ``LaunchConfiguration.perform`` returns
``context.launch_configurations[name]``; every launch argument is text). Python takes
every non-empty string as true, so ``if x:`` holds for ``'false'`` as much as for
``'true'``. ``LaunchConfiguration('x')`` itself is a ``Substitution`` object, which
defines neither ``__bool__`` nor ``__len__`` (launch 3.4.3, launch/substitution.py and
substitutions/launch_configuration.py): always true, whatever the argument says.
"""

from __future__ import annotations

import ast
import re
from collections.abc import Iterator

from launch_linter.frontends.ros2_actions import Problem
from launch_linter.resolve.safe_eval import subscript_index

RULE = "py_string_as_bool"
BOOLEAN_WORDS = frozenset({"true", "false"})
"""What launch's own conditions read as booleans (``IfCondition`` takes ``true``/``false``,
and ``1``/``0``, in any case); only ``true``/``false`` mark an argument as a switch."""
_SCOPES = (ast.FunctionDef, ast.AsyncFunctionDef, ast.Lambda, ast.ClassDef)


def _callee(call: ast.Call) -> str | None:
    func = call.func
    if isinstance(func, ast.Name):
        return func.id
    if isinstance(func, ast.Attribute):
        return func.attr
    return None


def _text(node: ast.AST | None) -> str | None:
    if isinstance(node, ast.Constant) and isinstance(node.value, str):
        return node.value
    return None


def _keyword(call: ast.Call, name: str) -> ast.expr | None:
    for keyword in call.keywords:
        if keyword.arg == name:
            return keyword.value
    return None


def _switch_default(call: ast.Call) -> str | None:
    """The true/false default (or choices) of a ``DeclareLaunchArgument``, else None."""
    default = _text(_keyword(call, "default_value"))
    if default is not None:
        return default if default.lower() in BOOLEAN_WORDS else None
    choices = _keyword(call, "choices")
    if isinstance(choices, (ast.List, ast.Tuple)) and choices.elts:
        words = [_text(item) for item in choices.elts]
        if all(word is not None and word.lower() in BOOLEAN_WORDS for word in words):
            return "/".join(word for word in words if word is not None)
    return None


def _declared_switch(node: ast.AST) -> tuple[str, str] | None:
    """(name, default) of a ``DeclareLaunchArgument`` with a true/false default or
    choices, else None."""
    if not (isinstance(node, ast.Call) and _callee(node) == "DeclareLaunchArgument"):
        return None
    name = _text(node.args[0]) if node.args else _text(_keyword(node, "name"))
    default = _switch_default(node)
    return (name, default) if name is not None and default is not None else None


def _read_argument(node: ast.AST) -> tuple[str, str] | None:
    """(argument name, how it is read) when ``node`` gives an argument's text."""
    if isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute):
        owner = node.func.value
        if node.func.attr == "perform" and isinstance(owner, ast.Call) and (
            _callee(owner) == "LaunchConfiguration" and owner.args
        ):
            name = _text(owner.args[0])
            return (name, "LaunchConfiguration(...).perform(context)") if name else None
        if node.func.attr == "get" and isinstance(owner, ast.Attribute) and (
            owner.attr == "launch_configurations" and node.args
        ):
            name = _text(node.args[0])
            return (name, "context.launch_configurations.get(...)") if name else None
    if isinstance(node, ast.Subscript) and isinstance(node.value, ast.Attribute) and (
        node.value.attr == "launch_configurations"
    ):
        name = _text(subscript_index(node))
        return (name, "context.launch_configurations[...]") if name else None
    return None


def _scopes(tree: ast.Module) -> list[tuple[ast.AST, list[ast.AST]]]:
    """Each scope of ``tree`` (the module, each function, lambda and class body) with the
    nodes of its own body, not those of the scopes it defines: one walk of the tree."""
    scopes: list[tuple[ast.AST, list[ast.AST]]] = [(tree, [])]
    stack: list[tuple[ast.AST, int]] = [(child, 0) for child in ast.iter_child_nodes(tree)]
    while stack:
        node, index = stack.pop()
        scopes[index][1].append(node)
        if isinstance(node, _SCOPES):
            scopes.append((node, []))
            index = len(scopes) - 1
        stack.extend((child, index) for child in ast.iter_child_nodes(node))
    return scopes


def _bound_names(node: ast.AST) -> Iterator[str]:
    targets: list[ast.AST] = []
    if isinstance(node, ast.Assign):
        targets = list(node.targets)
    elif isinstance(node, (ast.AugAssign, ast.AnnAssign, ast.For, ast.AsyncFor)):
        targets = [node.target]
    elif isinstance(node, (ast.With, ast.AsyncWith)):
        targets = [item.optional_vars for item in node.items if item.optional_vars]
    elif isinstance(node, ast.NamedExpr):
        targets = [node.target]
    elif isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
        yield node.name
    for target in targets:
        for part in ast.walk(target):
            if isinstance(part, ast.Name):
                yield part.id


def _tested(test: ast.expr) -> Iterator[ast.expr]:
    """The operands whose truth a test takes: through ``not``, ``and``/``or`` and
    ``bool(...)``."""
    stack = [test]
    while stack:
        node = stack.pop()
        if isinstance(node, ast.UnaryOp) and isinstance(node.op, ast.Not):
            stack.append(node.operand)
        elif isinstance(node, ast.BoolOp):
            stack.extend(node.values)
        elif isinstance(node, ast.Call) and isinstance(node.func, ast.Name) and (
            node.func.id == "bool" and len(node.args) == 1 and not node.keywords
        ):
            stack.append(node.args[0])
        else:
            yield node


def _tests(nodes: list[ast.AST]) -> Iterator[ast.expr]:
    for node in nodes:
        if isinstance(node, (ast.If, ast.While, ast.IfExp, ast.Assert)):
            yield node.test
        elif isinstance(node, ast.comprehension):
            yield from node.ifs


def _substitution(node: ast.AST) -> str | None:
    """The argument a ``LaunchConfiguration('x')`` object names, else None."""
    if isinstance(node, ast.Call) and _callee(node) == "LaunchConfiguration" and node.args:
        return _text(node.args[0])
    return None


def _object_problem(operand: ast.expr, shown: str, name: str) -> Problem:
    return Problem(
        RULE, operand.lineno, operand.col_offset + 1,
        f"`{shown}` is tested for truth, but it is the substitution "
        f"LaunchConfiguration('{name}'), an object Python always takes as true: the test "
        f"never reads the argument's value; give the action IfCondition/UnlessCondition, "
        f"or read the value with .perform(context) in an OpaqueFunction and compare it",
    )


def _compared(compare: ast.Compare, objects: dict[str, str], bindings: dict[str, int]
              ) -> Iterator[Problem]:
    """``LaunchConfiguration('x') == 'true'``: a ``Substitution`` defines no ``__eq__``,
    so it equals nothing but itself, and ``!=`` holds for every text."""
    left, right = compare.left, compare.comparators[0]
    for side, other in ((left, right), (right, left)):
        if _text(other) is None:
            continue
        named = _substitution(side)
        if named is None and isinstance(side, ast.Name) and bindings.get(side.id) == 1:
            named = objects.get(side.id)
        if named is None:
            continue
        always = "False" if isinstance(compare.ops[0], ast.Eq) else "True"
        yield Problem(
            RULE, compare.lineno, compare.col_offset + 1,
            f"the substitution LaunchConfiguration('{named}') is compared with the text "
            f"{_text(other)!r}: an object equals no string, so the comparison is always "
            f"{always}, whatever the argument says; compare its value "
            f"(.perform(context) in an OpaqueFunction) or use "
            f"LaunchConfigurationEquals/EqualsSubstitution",
        )


def _scope_problems(scope: ast.AST, nodes: list[ast.AST], declared: dict[str, str]
                    ) -> Iterator[Problem]:
    reads: dict[str, tuple[str, str]] = {}
    objects: dict[str, str] = {}
    bindings: dict[str, int] = {}
    if isinstance(scope, (ast.FunctionDef, ast.AsyncFunctionDef, ast.Lambda)):
        for argument in (*scope.args.posonlyargs, *scope.args.args, *scope.args.kwonlyargs):
            bindings[argument.arg] = 2  # a parameter: whatever the caller gives
    for node in nodes:
        for name in _bound_names(node):
            bindings[name] = bindings.get(name, 0) + 1
        if isinstance(node, ast.Assign) and len(node.targets) == 1 and isinstance(
            node.targets[0], ast.Name
        ):
            read = _read_argument(node.value)
            if read is not None and read[0] in declared:
                reads[node.targets[0].id] = read
            named = _substitution(node.value)
            if named is not None:
                objects[node.targets[0].id] = named
    for node in nodes:
        if isinstance(node, ast.Compare) and len(node.ops) == 1 and isinstance(
            node.ops[0], (ast.Eq, ast.NotEq)
        ):
            yield from _compared(node, objects, bindings)
    for test in _tests(nodes):
        for operand in _tested(test):
            once = isinstance(operand, ast.Name) and bindings.get(operand.id) == 1
            named = objects.get(operand.id) if once and isinstance(operand, ast.Name) else (
                _substitution(operand))
            if named is not None:
                shown = operand.id if isinstance(operand, ast.Name) else (
                    f"LaunchConfiguration('{named}')")
                yield _object_problem(operand, shown, named)
                continue
            if isinstance(operand, ast.Name) and once:
                read = reads.get(operand.id)
                shown = operand.id
            else:
                read = _read_argument(operand)
                read = read if read is not None and read[0] in declared else None
                shown = "the value"
            if read is None:
                continue
            name, how = read
            yield Problem(
                RULE, operand.lineno, operand.col_offset + 1,
                f"`{shown}` is tested for truth, but it is the text of launch argument "
                f"'{name}' ({how}, declared {declared[name]!r}): every non-empty string is "
                f"true in Python, so 'false' passes the test as well as 'true'; compare "
                f"the text ({shown if shown != 'the value' else 'it'}.lower() == 'true') "
                f"or give the action IfCondition/UnlessCondition",
            )


_READS = ("LaunchConfiguration", "launch_configurations")
_ASSIGNED = re.compile(
    r"^[ \t]*(\w+)[ \t]*=(?!=)[^\n]*?(?:LaunchConfiguration|launch_configurations)", re.M)
_TEST_MARKS = ("if ", "if(", "while ", "assert ", "not ", " and ", " or ", "bool(", "==", "!=")
"""Text that every truth test or comparison holds (and much else: a cheap, wide sieve)."""


def may_test_arguments(source: str) -> bool:
    """Whether a line of ``source`` both reads an argument (or names a variable assigned
    from a read) and may test or compare something: substring checks that spare the walk
    of the syntax tree to the files (most) where no such test can be."""
    if not any(read in source for read in _READS):
        return False
    mentions = (*_READS, *{match.group(1) for match in _ASSIGNED.finditer(source)})
    return any(
        any(mention in line for mention in mentions) and any(mark in line for mark in _TEST_MARKS)
        for line in source.splitlines()
    )


def string_truth_problems(tree: ast.Module) -> tuple[Problem, ...]:
    """Every truth test in ``tree`` of a ``LaunchConfiguration`` object, and of the text
    of a launch argument the file declares as a true/false switch."""
    scopes = _scopes(tree)
    declared = dict(filter(None, (
        _declared_switch(node) for _, nodes in scopes for node in nodes)))
    problems: list[Problem] = []
    for scope, nodes in scopes:
        problems.extend(_scope_problems(scope, nodes, declared))
    return tuple(problems)
