"""roslaunch (ROS 1) substitution args, resolved statically.

Mirrors ``roslaunch.substitution_args.resolve_args``: a whole-value ``$(eval …)`` is
evaluated (by our own interpreter); otherwise a first pass replaces ``env``, ``optenv``,
``dirname``, ``anon`` and ``arg`` (every identical occurrence at once) and a second pass
over the result replaces ``find``. What cannot be known becomes a :class:`Hole`; what
roslaunch itself refuses raises :class:`SubstitutionError`.
"""

from __future__ import annotations

import os
from collections.abc import Callable, Mapping
from dataclasses import dataclass

from launch_linter.resolve import safe_eval
from launch_linter.resolve.value import Hole, Part, Value, is_resolved, join, resolved_text

VALID_COMMANDS = ("find", "env", "optenv", "dirname", "anon", "arg")
FIRST_PASS = ("env", "optenv", "dirname", "anon", "arg")
_HOLE_MARK = "\x00"


class SubstitutionError(Exception):
    """roslaunch refuses this value; the message is close to roslaunch's own."""


@dataclass(frozen=True, slots=True)
class SubstitutionScope:
    """What a substitution can see at one place of a launch file."""

    args: Mapping[str, Value]
    env: Mapping[str, str]
    find: Callable[[str], str | None]
    anon: Callable[[str], str]
    filename: str


def collect_commands(text: str) -> list[str]:
    """The ``$(…)`` bodies of ``text`` in order, with roslaunch's lexer rules."""
    commands: list[str] = []
    buffer: list[str] = []
    state = "out"
    for char in text:
        if char == "$":
            if state == "out":
                state = "dollar"
            elif state != "dollar":
                raise SubstitutionError(
                    f"Dollar signs '$' cannot be inside of substitution args [{text}]"
                )
        elif char == "(":
            if state == "dollar":
                state = "lparen"
            elif state != "out":
                raise SubstitutionError(f"Invalid left parenthesis '(' in substitution args [{text}]")
        elif char == ")":
            if state == "in":
                commands.append("".join(buffer))
                buffer.clear()
            state = "out"
        elif state == "dollar":
            state = "out"
        elif state == "lparen":
            state = "in"
        if state == "in":
            buffer.append(char)
    return commands


def _replace_all(parts: list[Part], needle: str, replacement: Value) -> list[Part]:
    out: list[Part] = []
    for part in parts:
        if isinstance(part, Hole) or needle not in part:
            out.append(part)
            continue
        pieces = part.split(needle)
        for index, piece in enumerate(pieces):
            if index:
                out.extend(replacement)
            out.append(piece)
    return list(join(out))


def _first_pass_value(command: str, body: str, words: list[str], scope: SubstitutionScope) -> Value:
    written = f"$({body})"
    if command == "arg":
        if len(words) != 1:
            raise SubstitutionError(f"$(arg var) must specify exactly one arg [{body}]")
        if words[0] in scope.args:
            return scope.args[words[0]]
        return (Hole(written, f"arg '{words[0]}' is not set"),)
    if command == "env":
        if len(words) != 1:
            raise SubstitutionError(f"$(env var) command only accepts one argument [{body}]")
        if words[0] in scope.env:
            return (scope.env[words[0]],)
        return (Hole(written, f"environment variable '{words[0]}' not given (use --env)"),)
    if command == "optenv":
        if not words:
            raise SubstitutionError(f"$(optenv var) must specify an environment variable [{body}]")
        default = " ".join(words[1:])
        return (scope.env.get(words[0], default),)
    if command == "dirname":
        return (os.path.dirname(os.path.abspath(scope.filename)),)
    if len(words) != 1:
        raise SubstitutionError(f"$(anon var) must specify exactly one name [{body}]")
    return (scope.anon(words[0]),)


def _find_pass(parts: list[Part], scope: SubstitutionScope) -> list[Part]:
    flat = "".join(p if isinstance(p, str) else _HOLE_MARK for p in parts)
    for body in collect_commands(flat):
        words = [w for w in body.split(" ") if w]
        if not words or words[0] not in VALID_COMMANDS:
            raise SubstitutionError(
                f"Unknown substitution command [{body}]. Valid commands are {list(VALID_COMMANDS)}"
            )
        if words[0] != "find":
            continue
        if len(words) != 2:
            raise SubstitutionError(f"$(find pkg) command only accepts one argument [{body}]")
        parts = _replace_find(parts, f"$({body})", words[1], scope)
    return parts


def _replace_find(parts: list[Part], needle: str, package: str, scope: SubstitutionScope) -> list[Part]:
    for index, part in enumerate(parts):
        if isinstance(part, Hole) or needle not in part:
            continue
        before, _, after = part.partition(needle)
        cut = len(after)
        for position, char in enumerate(after):
            if char.isspace():
                cut = position
                break
        path, rest = after[:cut], after[cut:]
        location = scope.find(package)
        replacement: list[Part]
        if location is None:
            replacement = [Hole(needle, f"package '{package}' not found under the package path"), path]
        else:
            relative = path[1:] if path.startswith(("/", "\\")) else path
            replacement = [os.path.join(location, relative) if relative else location]
        return list(join([*parts[:index], before, *replacement, rest, *parts[index + 1 :]]))
    return parts


def _auto_text(value: Value) -> str | None:
    return resolved_text(value)


def _evaluate(expression: str, whole: str, scope: SubstitutionScope) -> Value:
    eval_scope = safe_eval.EvalScope(
        args={name: _auto_text(v) for name, v in scope.args.items()},
        env=scope.env,
        find=scope.find,
        anon=scope.anon,
        dirname=os.path.dirname(os.path.abspath(scope.filename)),
    )
    try:
        return (safe_eval.evaluate(expression, eval_scope),)
    except safe_eval.EvalUnresolved as exc:
        return (Hole(whole, f"$(eval) needs {exc.name}: {exc.reason}"),)
    except safe_eval.EvalError as exc:
        return (Hole(whole, f"$(eval) not evaluated: {exc.reason}"),)


def resolve(text: str, scope: SubstitutionScope) -> Value:
    """Resolve one attribute value; raise :class:`SubstitutionError` where roslaunch would."""
    if not text or "$" not in text:
        return (text,) if text else ()
    if text.startswith("$(eval ") and text.endswith(")"):
        return _evaluate(text[7:-1], text, scope)
    parts: list[Part] = [text]
    for body in collect_commands(text):
        words = [w for w in body.split(" ") if w]
        if not words or words[0] not in VALID_COMMANDS:
            raise SubstitutionError(
                f"Unknown substitution command [{body}]. Valid commands are {list(VALID_COMMANDS)}"
            )
        if words[0] in FIRST_PASS:
            replacement = _first_pass_value(words[0], body, words[1:], scope)
            parts = _replace_all(parts, f"$({body})", replacement)
    parts = _find_pass(parts, scope)
    return join(parts)


def to_bool(value: Value) -> bool | None:
    """roslaunch's if/unless truth rule; None when unresolved; ValueError when not a bool."""
    if not is_resolved(value):
        return None
    text = "".join(p for p in value if isinstance(p, str)).lower().strip()
    if text in ("true", "1"):
        return True
    if text in ("false", "0"):
        return False
    raise ValueError(f"{text} is not a 'bool' type")
