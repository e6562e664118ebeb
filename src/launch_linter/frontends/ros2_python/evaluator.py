"""The bounded evaluator of ROS 2 Python launch files: its state, and statements.

It interprets a small, safe part of Python over the syntax tree (never compiled, never
run); every step, loop, call depth and value size is bounded (``resolve/bounded.py``).
Expressions are :mod:`.expressions`'s, calls :mod:`.calls`'s, and calls of the launch
library :mod:`.launch_api`'s.
"""

from __future__ import annotations

import ast
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any

from launch_linter.frontends.ros2_actions import (
    ACTION_TYPES,
    Action,
    Group,
    Predicate,
    Problem,
    Where,
)
from launch_linter.frontends.ros2_python.values import (
    ACTION_NAMES,
    Env,
    FuncVal,
    LaunchDescriptionVal,
    LazyStr,
    LinedDict,
    ModuleVal,
    OpenFile,
    Unknown,
    _Break,
    _called_name,
    _Continue,
    _OutOfSteps,
    _Return,
)
from launch_linter.resolve.bounded import PYTHON_MAX_ITEMS as MAX_ITEMS
from launch_linter.resolve.bounded import PYTHON_MAX_STEPS as MAX_STEPS
from launch_linter.resolve.bounded import PYTHON_MAX_TEXT as MAX_TEXT
from launch_linter.resolve.ros2_substitution import Opaque, Subs, Text
from launch_linter.resolve.safe_eval import subscript_index
from launch_linter.resolve.value import Value, holes, resolved_text


@dataclass
class Evaluator:
    """The state of one file's interpretation, and its statements, bounded in steps."""

    path: str
    source: str
    problems: list[Problem] = field(default_factory=list)
    steps: int = 0
    depth: int = 0
    branches: list[Predicate] = field(default_factory=list)
    call_sites: list[ast.AST] = field(default_factory=list)
    """Calls of the file's own functions being run, outermost first."""
    lines: list[str] = field(default_factory=list)
    ascii: bool = False
    """Whether the source is ASCII: then a column is a character offset."""
    scopes: list[Env] = field(default_factory=list)
    """Every scope made, emptied at the end: a function and the scope it was defined in
    refer to each other, a cycle that would keep the file's syntax tree alive until the
    garbage collector finds it."""
    deferring: bool = False
    """Whether an ``OpaqueFunction`` will be run later, in its scopes (then they stay)."""
    served: list[object] = field(default_factory=list)
    """What a script gives ``LaunchService.include_launch_description``."""
    truth_told: frozenset[int] = frozenset()
    """Lines where the syntax scan (``string_truth``) reports a truth test already: its
    finding names the argument, so :meth:`text_tested` says nothing more there."""
    environ: Mapping[str, str] = field(default_factory=dict)
    """The environment the run is told of (``--env``, and ``ROS_DISTRO`` from
    ``--ros-distro``): a Python comparison of one of its variables is decided, so that a
    branch for another distribution is not taken."""
    bound: Callable[[], frozenset[str] | None] | None = None
    """Every name the module binds anywhere (assignment, import, def, parameter, ...);
    None when it may bind others unseen (a star import, ``exec``, ``globals()``). Asked
    only when a name is found nowhere in scope: walking the whole syntax tree costs more
    than parsing it, and most files never need it."""
    installed: Callable[[], str | None] | None = None
    """Where the file is installed (``share/<pkg>/launch/...``, spelled through the
    package's source folder), which ``__file__`` names; None: where it is read from.
    Asked only when ``__file__`` is read (the install rules are read for that file)."""

    # -- helpers -------------------------------------------------------------------------
    def scope(self, parent: Env | None) -> Env:
        env = Env(parent)
        self.scopes.append(env)
        return env

    def forget_scopes(self) -> None:
        if self.deferring:
            return
        self.forget_deferred_scopes()

    def forget_deferred_scopes(self) -> None:
        """Empties every scope, also those an ``OpaqueFunction`` would still run in: for
        when the launch tree is read and no function will run any more."""
        for env in self.scopes:
            env.vars.clear()
            env.parent = None
        self.scopes.clear()

    def step(self) -> None:
        self.steps += 1
        if self.steps > MAX_STEPS:
            raise _OutOfSteps

    def segment(self, node: ast.AST) -> str:
        """The first characters of the source text of ``node``, on one line."""
        if not self.lines:
            self.lines = self.source.splitlines(keepends=True)
            self.ascii = self.source.isascii()
        first = getattr(node, "lineno", 0) - 1
        last = getattr(node, "end_lineno", None)
        if not 0 <= first < len(self.lines) or last is None:
            return type(node).__name__
        # Columns are UTF-8 byte offsets (character offsets too in ASCII text, most
        # files); three lines are plenty for a short excerpt.
        text: str
        if self.ascii and last - 1 == first:
            # One line (most excerpts): what ``_one_line`` makes of it, without the list.
            line = self.lines[first][getattr(node, "col_offset", 0):
                                     getattr(node, "end_col_offset", None)]
            text = " ".join(line.split())
        elif self.ascii:
            lines = self.lines[first:min(last, first + 3)]
            if last - 1 < first + 3:
                lines[-1] = lines[-1][:getattr(node, "end_col_offset", None)]
            lines[0] = lines[0][getattr(node, "col_offset", 0):]
            text = _one_line(lines)
        else:
            chunk = [line.encode("utf-8") for line in self.lines[first:min(last, first + 3)]]
            if last - 1 < first + 3:
                chunk[-1] = chunk[-1][:getattr(node, "end_col_offset", None)]
            chunk[0] = chunk[0][getattr(node, "col_offset", 0):]
            text = _one_line(b"".join(chunk).decode("utf-8", "replace").splitlines())
        if last - 1 >= first + 3:  # cut after three lines: say so, as after 120 characters
            text += " ..."
        return text if len(text) <= 120 else text[:117] + "..."

    def text_value(self, subs: Subs, node: ast.AST) -> object:
        """Text when every part is known, else a lazy string; refused when too long."""
        if sum(len(sub.text) for sub in subs if isinstance(sub, Text)) > MAX_TEXT:
            return self.unknown(node, f"text longer than {MAX_TEXT} characters")
        if all(isinstance(sub, Text) for sub in subs):
            return "".join(sub.text for sub in subs if isinstance(sub, Text))
        return LazyStr(subs)

    def unknown(self, node: ast.AST, reason: str) -> Unknown:
        return Unknown(reason, self.segment(node), getattr(node, "lineno", 1))

    def where(self, node: ast.AST) -> Where:
        """Where an action is reported: inside a helper function of the file, at the call
        of that helper, so that each call is its own place (to point at and suppress)."""
        site = self.call_sites[0] if self.call_sites else node
        return Where(self.path, getattr(site, "lineno", 1), getattr(site, "col_offset", 0) + 1)

    def problem(self, rule: str, node: ast.AST, message: str) -> None:
        where = self.where(node)
        self.problems.append(Problem(rule, where.line, where.column, message))

    def guard(self, value: object) -> object:
        """An action added under an unknown Python ``if`` is present only under it."""
        if not self.branches or not isinstance(value, ACTION_TYPES):
            return value
        action: Action = value
        for predicate in reversed(self.branches):
            action = Group(action.where, predicate, (action,), scoped=False)
        return action

    # -- statements ------------------------------------------------------------------------
    def run_block(self, body: Sequence[ast.stmt], env: Env) -> None:
        for statement in body:
            self.run(statement, env)

    def run_function_body(self, body: Sequence[ast.stmt], env: Env) -> object:
        """What a function's body returns. A guard clause (``if <unknown>: ... return X``
        with no ``else``, at the body's top level) returns X under its condition only:
        Python runs the rest of the body when the condition is false, so the rest runs
        under the condition's negation and both returns are kept, each under its side
        (else the first return met would be taken as the function's only result)."""
        sides: list[tuple[ast.If, object]] = []
        depth = len(self.branches)
        value: object = None
        try:
            for statement in body:
                if not (isinstance(statement, ast.If) and not statement.orelse
                        and isinstance(statement.body[-1], ast.Return)):
                    self.run(statement, env)
                    continue
                guarded = self.guard_clause(statement, env)
                if guarded is _NOT_GUARDED:
                    continue
                if len(sides) >= MAX_GUARD_CLAUSES:
                    # Each side's actions sit under every condition before it.
                    raise _OutOfSteps
                sides.append((statement, guarded))
                self.branches.append(self.side(statement, False))
        except _Return as result:
            value = result.value
        finally:
            del self.branches[depth:]
        for statement, returned in reversed(sides):
            value = self.either(statement, returned, value)
        return value

    def guard_clause(self, node: ast.If, env: Env) -> object:
        """Runs ``if <test>: ... return X`` (no ``else``): X when the test is unknown (run
        under it, the variables it sets left to its side), else ``_NOT_GUARDED`` after
        running the statement as Python would (a true test returns, by ``_Return``)."""
        self.step()
        tested = self.eval(node.test, env)
        self.text_tested(node.test, tested)
        test = self.truth(tested)
        if test is True:
            self.run_block(node.body, env)
        if test is not None:
            return _NOT_GUARDED
        before = dict(env.vars)
        self.branches.append(self.side(node, True))
        try:
            self.run_block(node.body, env)
        except _Return as result:
            return result.value
        finally:
            self.branches.pop()
            env.vars = before
        return None

    def text_tested(self, node: ast.expr, value: object) -> None:
        """Notes a text that launch reads as a boolean (``'false'``, ``'True'``: launch's
        conditions, evaluate_condition_expression_impl.py) tested for truth by Python,
        whose truth of a text is its being non-empty: ``'false'`` is true, so the test
        takes the same side for every boolean value an argument is given."""
        if (isinstance(value, str) and value.lower() in BOOLEAN_WORDS
                and self.where(node).line not in self.truth_told):
            self.problem("py_string_as_bool", node, (
                f"Python tests the text {value!r} for truth: any non-empty text is true, "
                f"'false' as well, so every boolean value takes the same side; compare the "
                f"text (.lower() == 'true') or use IfCondition"))

    def side(self, node: ast.If, positive: bool, text: str | None = None) -> Predicate:
        """The condition a side of ``if <unknown>`` runs under (``text``: the test as
        written, when the caller has it already)."""
        reason = f"Python condition at line {node.lineno} depends on an unknown value"
        written = self.segment(node.test) if text is None else text
        return Predicate(positive, (Opaque(f"python: {written}", reason),))

    def either(self, node: ast.If, returned: object, rest: object) -> object:
        """One value for what a guard clause returns under its condition and what the
        rest of the body returns otherwise: launch actions of both, each under its side's
        condition, else unknown. Nothing returned is no action (an
        ``OpaqueFunction`` may return None)."""
        if returned is rest or (isinstance(returned, (str, int, float)) and
                                type(returned) is type(rest) and returned == rest):
            return rest
        both = [returned, rest]
        text = self.segment(node.test)
        items: list[object] = []
        for positive, value in zip((True, False), both):
            found = (value.items if isinstance(value, LaunchDescriptionVal)
                     else value if isinstance(value, (list, tuple))
                     else [] if value is None else None)
            if found is None or not all(isinstance(item, ACTION_TYPES) for item in found):
                return Unknown(f"returned under the condition {text!r}",
                               "the function's result", node.lineno)
            # A list written as a literal was not placed under its side's condition yet.
            items.extend(self.under(list(found), positive, text, node))
        if any(isinstance(value, LaunchDescriptionVal) for value in both):
            return LaunchDescriptionVal(items)
        return items

    def run(self, node: ast.stmt, env: Env) -> None:
        self.steps += 1
        if self.steps > MAX_STEPS:
            raise _OutOfSteps
        # One look-up by the statement's class instead of a chain of isinstance tests;
        # statements the evaluator does not model (pass, raise, global ...) do nothing.
        handler = _STATEMENTS.get(type(node))
        if handler is not None:
            handler(self, node, env)

    def _expression_statement(self, node: ast.Expr, env: Env) -> None:
        self.eval(node.value, env)

    def _assign_statement(self, node: ast.Assign, env: Env) -> None:
        value = self.eval(node.value, env)
        for target in node.targets:
            self.assign(target, value, env)

    def _annotated_assign(self, node: ast.AnnAssign, env: Env) -> None:
        if node.value is not None:
            self.assign(node.target, self.eval(node.value, env), env)

    def _return(self, node: ast.Return, env: Env) -> None:
        raise _Return(None if node.value is None else self.eval(node.value, env))

    def _function_definition(self, node: ast.FunctionDef | ast.AsyncFunctionDef, env: Env
                             ) -> None:
        defaults = self.defaults(node.args, env)
        env.vars[node.name] = FuncVal(node, env, defaults)

    def _import(self, node: ast.Import, env: Env) -> None:
        for alias in node.names:
            if alias.asname:
                env.vars[alias.asname] = ModuleVal(alias.name)
            else:
                top = alias.name.split(".")[0]
                env.vars[top] = ModuleVal(top)

    def _import_from(self, node: ast.ImportFrom, env: Env) -> None:
        module = node.module or ""
        for alias in node.names:
            if alias.name != "*":
                env.vars[alias.asname or alias.name] = ModuleVal(f"{module}.{alias.name}")

    def _try(self, node: ast.Try, env: Env) -> None:
        self.run_block(node.body, env)
        self.run_block(node.orelse, env)
        self.run_block(node.finalbody, env)

    def _with(self, node: ast.With, env: Env) -> None:
        for item in node.items:
            # ``with open(path) as f``: f.read() is the file's text, read by nobody.
            if isinstance(item.optional_vars, ast.Name):
                value = self.eval(item.context_expr, env)
                if isinstance(value, OpenFile):
                    env.vars[item.optional_vars.id] = value
        self.run_block(node.body, env)

    def _break(self, node: ast.Break, env: Env) -> None:
        raise _Break

    def _continue(self, node: ast.Continue, env: Env) -> None:
        raise _Continue

    def _class_definition(self, node: ast.ClassDef, env: Env) -> None:
        env.vars[node.name] = self.unknown(node, "classes are not interpreted")

    def _while(self, node: ast.While, env: Env) -> None:
        self.not_followed(node, "a while loop is not followed")

    def not_followed(self, node: ast.stmt, reason: str) -> None:
        """Report a statement skipped while it may start launch actions."""
        for inner in ast.walk(node):
            if isinstance(inner, ast.Call) and _called_name(inner.func) in ACTION_NAMES:
                self.problem("unresolved", node, f"{reason}: the launch actions in it "
                             f"(line {inner.lineno}) are not seen")
                return

    def defaults(self, arguments: ast.arguments, env: Env) -> dict[str, object]:
        values: dict[str, object] = {}
        positional = [*arguments.posonlyargs, *arguments.args]
        for arg, default in zip(positional[len(positional) - len(arguments.defaults):],
                                arguments.defaults):
            values[arg.arg] = self.eval(default, env)
        for arg, kw_default in zip(arguments.kwonlyargs, arguments.kw_defaults):
            if kw_default is not None:
                values[arg.arg] = self.eval(kw_default, env)
        return values

    def assign(self, target: ast.expr, value: object, env: Env) -> None:
        if isinstance(target, ast.Name):
            env.vars[target.id] = value
        elif isinstance(target, (ast.Tuple, ast.List)):
            names = target.elts
            if isinstance(value, (list, tuple)) and len(value) == len(names):
                for name, item in zip(names, value):
                    self.assign(name, item, env)
            else:
                reason = value if isinstance(value, Unknown) else self.unknown(
                    target, "cannot unpack this value")
                for name in names:
                    self.assign(name, reason, env)
        elif isinstance(target, ast.Subscript):
            container = self.eval(target.value, env)
            key = self.eval(subscript_index(target), env)
            if isinstance(container, dict) and isinstance(key, (str, int, float, bool)):
                container[key] = value
                if isinstance(container, LinedDict):
                    container.places[key] = self.where(target)

    def aug_assign(self, node: ast.AugAssign, env: Env) -> None:
        current = self.eval(node.target, env) if isinstance(node.target, ast.Name) else None
        value = self.eval(node.value, env)
        if isinstance(node.op, ast.Add) and isinstance(current, list) and isinstance(
            value, (list, tuple)
        ):
            self.extend(current, value)
            return
        if isinstance(node.target, ast.Name):
            env.vars[node.target.id] = self.binary(node.op, current, value, node)

    def extend(self, target: list[object], items: Sequence[object]) -> None:
        if len(target) + len(items) > MAX_ITEMS:
            raise _OutOfSteps
        target.extend(self.guard(item) for item in items)

    def run_if(self, node: ast.If, env: Env) -> None:
        tested = self.eval(node.test, env)
        self.text_tested(node.test, tested)
        test = self.truth(tested)
        if test is True:
            self.run_block(node.body, env)
            return
        if test is False:
            self.run_block(node.orelse, env)
            return
        text = self.segment(node.test)
        before = dict(env.vars)
        results: list[dict[str, object]] = []
        for positive, body in ((True, node.body), (False, node.orelse)):
            env.vars = dict(before)
            self.branches.append(self.side(node, positive, text))
            try:
                self.run_block(body, env)
            finally:
                self.branches.pop()
            results.append(env.vars)
        env.vars = self.merge(before, results[0], results[1], node, tested)

    def merge(self, before: dict[str, object], then: dict[str, object],
              otherwise: dict[str, object], node: ast.If, tested: object = None
              ) -> dict[str, object]:
        merged = dict(before)
        text = self.segment(node.test)
        # What makes the test unknown is what really blocks the variables it sets.
        cause = f" ({tested.reason})" if isinstance(tested, Unknown) else ""
        for name in set(then) | set(otherwise):
            a, b = then.get(name), otherwise.get(name)
            if a is b:
                merged[name] = a
            elif isinstance(a, list) and isinstance(b, list) and all(
                    isinstance(item, ACTION_TYPES) for item in (*a, *b)):
                # Lists of actions: each action runs under its branch. A list of values
                # (arguments, say) is one or the other, never both: unknown below.
                merged[name] = [
                    *self.under(a, True, text, node), *self.under(b, False, text, node)
                ]
            else:
                # Named by the variable (what the reader sees where it is used), not by
                # the condition's text.
                merged[name] = Unknown(f"set under the condition {text!r}{cause}", name,
                                       node.lineno)
        return merged

    def under(self, items: list[object], positive: bool, text: str, node: ast.If
              ) -> list[object]:
        self.branches.append(self.side(node, positive, text))
        try:
            return [self.guard(item) for item in items]
        finally:
            self.branches.pop()

    def iterate(self, value: object, node: ast.AST) -> list[object] | Unknown:
        if isinstance(value, (list, tuple)):
            return list(value)
        if isinstance(value, dict):
            return list(value)
        if isinstance(value, str):
            return list(value)
        if isinstance(value, Unknown):
            return value
        return self.unknown(node, "cannot iterate over this value")

    def run_for(self, node: ast.For, env: Env) -> None:
        items = self.iterate(self.eval(node.iter, env), node.iter)
        if isinstance(items, Unknown):
            self.not_followed(node, f"the loop over {items.text} ({items.reason})")
            return
        for item in items:
            self.assign(node.target, item, env)
            try:
                self.run_block(node.body, env)
            except _Break:
                return
            except _Continue:
                continue
        self.run_block(node.orelse, env)

    # -- defined by a subclass, further on ---------------------------------------------------
    def binary(self, op: ast.operator, left: object, right: object, node: ast.AST) -> object:
        """Defined by :class:`.expressions.Expressions`."""
        raise NotImplementedError

    def eval(self, node: ast.expr, env: Env) -> object:
        """Defined by :class:`.expressions.Expressions`."""
        raise NotImplementedError

    def truth(self, value: object) -> bool | None:
        """Defined by :class:`.expressions.Expressions`."""
        raise NotImplementedError


BOOLEAN_WORDS = frozenset({"true", "false"})
"""Texts launch's conditions read as booleans (ros2/launch launch/launch/conditions/
evaluate_condition_expression_impl.py, rolling 02595ba, lines 25-26, compared lowered;
its '1' and '0' are left out: a number's text may be tested on purpose)."""

MAX_GUARD_CLAUSES = 64
"""Guard clauses followed in one function body: an action after the n-th is under n
conditions, so the work grows with their square."""

_NOT_GUARDED = object()
"""``Evaluator.guard_clause``'s answer for a statement it ran as Python would."""

_STATEMENTS: dict[type, Callable[[Evaluator, Any, Env], None]] = {
    ast.Expr: Evaluator._expression_statement,
    ast.Assign: Evaluator._assign_statement,
    ast.AnnAssign: Evaluator._annotated_assign,
    ast.AugAssign: Evaluator.aug_assign,
    ast.Return: Evaluator._return,
    ast.If: Evaluator.run_if,
    ast.For: Evaluator.run_for,
    ast.FunctionDef: Evaluator._function_definition,
    ast.AsyncFunctionDef: Evaluator._function_definition,
    ast.Import: Evaluator._import,
    ast.ImportFrom: Evaluator._import_from,
    ast.Try: Evaluator._try,
    ast.With: Evaluator._with,
    ast.Break: Evaluator._break,
    ast.Continue: Evaluator._continue,
    ast.ClassDef: Evaluator._class_definition,
    ast.While: Evaluator._while,
}
"""What each statement the evaluator models does, by its class."""


def _performed(resolver: Callable[[Subs], Value], subs: Subs, node: ast.AST,
               interpreter: Evaluator) -> object:
    value = resolver(subs)
    text = resolved_text(value)
    if text is not None:
        return text
    return interpreter.unknown(node, "; ".join(f"{h.text}: {h.reason}" for h in holes(value)))


def _one_line(lines: list[str]) -> str:
    """Source lines as one line: blanks collapsed, and none where a line break followed an
    opening bracket or came before a closing one (``f( [a, b])`` read ``f([a, b])``)."""
    out = ""
    for line in lines:
        piece = " ".join(line.split())
        if not piece:
            continue
        if out and out[-1] not in "([{" and piece[0] not in ")]}":
            out += " "
        out += piece
    return out
