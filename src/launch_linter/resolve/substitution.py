"""roslaunch (ROS 1) substitution args, resolved statically.

Mirrors ``roslaunch.substitution_args.resolve_args``: a whole-value ``$(eval …)`` is
evaluated (by our own interpreter); otherwise a first pass replaces ``env``, ``optenv``,
``dirname``, ``anon`` and ``arg`` (every identical occurrence at once) and a second pass
over the result replaces ``find``. What cannot be known becomes a :class:`Hole`; what
roslaunch itself refuses raises :class:`SubstitutionError`.
"""

from __future__ import annotations

import os
import re
from collections.abc import Callable, Iterator, Mapping
from typing import Optional, Tuple

from launch_linter.model.budget import Budget
from launch_linter.model.record import MutableRecord
from launch_linter.resolve.value import Hole, Part, Value, is_resolved, join, resolved_text

VALID_COMMANDS = ("find", "env", "optenv", "dirname", "anon", "arg")
FIRST_PASS = ("env", "optenv", "dirname", "anon", "arg")
_HOLE_MARK = "\x00"
MAX_VALUE_CHARS = 4 * 1024 * 1024
"""Longest value one substitution may build (arguments that double each other grow fast)."""


class SubstitutionError(Exception):
    """roslaunch refuses this value; the message is close to roslaunch's own."""


class SubstitutionScope(MutableRecord):
    """What a substitution can see at one place of a launch file (treat as read-only).

    ``missing_arg`` is called with the name of an arg that is not set at all and returns
    the reason for the hole (it may raise :class:`SubstitutionError` to refuse the value).
    """

    args: Mapping[str, Value]
    env: Mapping[str, str]
    find: Callable[[str], str | None]
    anon: Callable[[str], str]
    filename: str
    missing_arg: Callable[[str], str] | None
    budget: Budget | None
    """The root file's work budget, charged before a value is built."""

    __slots__ = ("args", "env", "find", "anon", "filename", "missing_arg", "budget")

    def __init__(
        self,
        args: Mapping[str, Value],
        env: Mapping[str, str],
        find: Callable[[str], str | None],
        anon: Callable[[str], str],
        filename: str,
        missing_arg: Callable[[str], str] | None = None,
        budget: Budget | None = None,
    ) -> None:
        self.args = args
        self.env = env
        self.find = find
        self.anon = anon
        self.filename = filename
        self.missing_arg = missing_arg
        self.budget = budget


_SPECIAL = re.compile(r"[$()]")


def collect_commands(text: str) -> list[str]:
    """The ``$(…)`` bodies of ``text`` in order, with roslaunch's lexer rules.

    ``$(`` opens and the next ``)`` closes; there are no escapes and no nesting: a ``$``
    or ``(`` inside a body is an error, as is a ``$`` or ``(`` right after ``$(``.
    This is roslaunch's character-by-character state machine, stepping from one special
    character to the next (the other characters never change its state).
    """
    commands: list[str] = []
    end = len(text)
    dollar = text.find("$")
    while dollar >= 0:
        paren = dollar + 1
        while paren < end and text[paren] == "$":
            paren += 1
        if paren >= end or text[paren] != "(":
            dollar = text.find("$", paren)
            continue
        start = paren + 1
        if start >= end:
            break
        first = text[start]
        if first == ")":
            dollar = text.find("$", start + 1)
            continue
        special = first if first in "$(" else None
        close = start
        if special is None:
            match = _SPECIAL.search(text, start)
            if match is None:
                break
            special, close = match.group(), match.start()
        if special == "$":
            raise SubstitutionError(
                f"Dollar signs '$' cannot be inside of substitution args [{text}]"
            )
        if special == "(":
            raise SubstitutionError(f"Invalid left parenthesis '(' in substitution args [{text}]")
        commands.append(text[start:close])
        dollar = text.find("$", close + 1)
    return commands


def _grown_size(text: str, needle: str, replacement_size: int) -> int:
    """Length of ``text`` once every ``needle`` is replaced by that many characters."""
    if replacement_size <= len(needle):
        return len(text)
    return len(text) + text.count(needle) * (replacement_size - len(needle))


def _charge(scope: SubstitutionScope, size: int) -> None:
    """Refuse a value longer than MAX_VALUE_CHARS; charge the root file's budget."""
    if size > MAX_VALUE_CHARS:
        raise SubstitutionError(
            f"value would be longer than {MAX_VALUE_CHARS:,} characters; not built")
    if scope.budget is not None:
        scope.budget.produce(size)


def _replace_all(parts: list[Part], needle: str, replacement: Value,
                 scope: SubstitutionScope) -> list[Part]:
    # A hole counts as its written text, so that values full of holes are bounded too.
    size = sum(len(p) if isinstance(p, str) else len(p.text) for p in replacement)
    _charge(scope, sum(_grown_size(p, needle, size) if isinstance(p, str) else len(p.text)
                       for p in parts))
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


def _words(body: str) -> list[str]:
    """roslaunch splits a command on single spaces and drops the empty pieces."""
    if "  " not in body and body[:1] != " " and body[-1:] != " ":
        return body.split(" ")
    return [w for w in body.split(" ") if w]


Command = Tuple[str, str, Optional[Tuple[str, ...]]]
"""A ``$(…)`` of a text: its body, the text it replaces (``$(body)``) and its words, or
None when roslaunch refuses the command (:func:`_check_command` says why)."""

_LEXED: dict[str, tuple[Command, ...]] = {}
_LEXED_SIZE = 4096


def _commands(text: str) -> tuple[Command, ...]:
    """:func:`collect_commands` with each command split into words, remembered by text:
    the same attribute values come back element after element and file after file."""
    known = _LEXED.get(text)
    if known is None:
        commands = []
        for body in collect_commands(text):
            words = _words(body)
            valid = bool(words) and words[0] in VALID_COMMANDS
            commands.append((body, f"$({body})", tuple(words) if valid else None))
        if len(_LEXED) >= _LEXED_SIZE:
            _LEXED.clear()
        known = _LEXED[text] = tuple(commands)
    return known


_WHOLE_ARG: dict[str, str] = {}
"""Text -> NAME when the text is exactly ``$(arg NAME)``, else ""."""


def _whole_arg(text: str) -> str:
    name = ""
    if text.startswith("$(arg ") and text.endswith(")"):
        inner = text[6:-1].strip(" ")
        if inner and not any(mark in inner for mark in " $()"):
            name = inner
    if len(_WHOLE_ARG) >= _LEXED_SIZE:
        _WHOLE_ARG.clear()
    _WHOLE_ARG[text] = name
    return name


def _first_pass_value(command: str, body: str, words: tuple[str, ...],
                      scope: SubstitutionScope) -> Value:
    """The value of ``$(body)``; ``words`` are the words after the command's name."""
    if command == "arg":
        if not words:
            raise SubstitutionError(f"$(arg var) must specify a variable name [{body}]")
        if len(words) > 1:
            raise SubstitutionError(f"$(arg var) may only specify one arg [{body}]")
        value = scope.args.get(words[0])
        if value is not None:
            return value
        reason = (
            scope.missing_arg(words[0]) if scope.missing_arg else f"arg '{words[0]}' is not set"
        )
        return (Hole(f"$({body})", reason),)
    if command == "env":
        if len(words) != 1:
            raise SubstitutionError(f"$(env var) command only accepts one argument [{body}]")
        if words[0] in scope.env:
            return (scope.env[words[0]],)
        reason = f"environment variable '{words[0]}' is not given (use --env)"
        return (Hole(f"$({body})", reason),)
    if command == "optenv":
        if not words:
            raise SubstitutionError(f"$(optenv var) must specify an environment variable [{body}]")
        return (scope.env.get(words[0], " ".join(words[1:])),)
    if command == "dirname":
        return (os.path.dirname(os.path.abspath(scope.filename)),)
    if not words:
        raise SubstitutionError(f"$(anon var) must specify a name [{body}]")
    if len(words) > 1:
        raise SubstitutionError(f"$(anon var) may only specify one name [{body}]")
    return (scope.anon(words[0]),)


def _check_command(body: str) -> list[str]:
    words = _words(body)
    if not words or words[0] not in VALID_COMMANDS:
        raise SubstitutionError(
            f"Unknown substitution command [{body}]. Valid commands are {list(VALID_COMMANDS)}"
        )
    return words


def _find_pass(parts: list[Part], scope: SubstitutionScope) -> list[Part]:
    flat = "".join(p if isinstance(p, str) else _HOLE_MARK for p in parts)
    if "$" not in flat:
        return parts
    return _find_commands(parts, _commands(flat), scope)


def _find_commands(parts: list[Part], commands: tuple[Command, ...], scope: SubstitutionScope
                   ) -> list[Part]:
    for body, needle, words in commands:
        if words is None:
            _check_command(body)
            continue
        if words[0] != "find":
            continue
        if len(words) != 2:
            raise SubstitutionError(f"$(find pkg) command only accepts one argument [{body}]")
        parts = _replace_find(parts, needle, words[1], scope)
    return parts


def _replace_find(
    parts: list[Part], needle: str, package: str, scope: SubstitutionScope
) -> list[Part]:
    """Replace the first ``needle`` and the path that follows it, as roslaunch's ``_find``:
    the path runs to the next space, one leading slash is dropped, and it is joined to
    the package folder with ``os.path.join``."""
    for index, part in enumerate(parts):
        if isinstance(part, Hole) or needle not in part:
            continue
        before, _, after = part.partition(needle)
        cut = after.find(" ")
        path, rest = (after, "") if cut < 0 else (after[:cut], after[cut:])
        # The path may go on into an unresolved part: then only its start is known.
        runs_on = cut < 0 and index + 1 < len(parts)
        location = scope.find(package)
        replacement: list[Part]
        if location is None:
            missing = Hole(needle, f"package '{package}' not found under the package path")
            replacement = [missing, path]
        else:
            relative = path.replace("\\", "/")
            relative = relative[1:] if relative.startswith("/") else relative
            if relative:
                replacement = [os.path.join(location, relative)]
            elif runs_on:
                replacement = [location + "/"]
            else:
                replacement = [location]
        return list(join([*parts[:index], before, *replacement, rest, *parts[index + 1 :]]))
    return parts


class _ArgTexts(Mapping):  # type: ignore[type-arg]  # not subscripted: Python 3.8
    """The args as ``$(eval)`` sees them: each value's text, None where it has a hole.

    Worked out for the names an expression reads, not for every arg in scope at every
    ``$(eval)`` (a file with a hundred args and a hundred evals read each arg a hundred
    times)."""

    __slots__ = ("_values",)

    def __init__(self, values: Mapping[str, Value]) -> None:
        self._values = values

    def __contains__(self, name: object) -> bool:
        return name in self._values

    def __getitem__(self, name: str) -> str | None:
        return resolved_text(self._values[name])

    def __iter__(self) -> Iterator[str]:
        return iter(self._values)

    def __len__(self) -> int:
        return len(self._values)


def _evaluate(expression: str, whole: str, scope: SubstitutionScope) -> Value:
    if "__" in expression:
        raise SubstitutionError("$(eval ...) may not contain double underscore expressions")
    # Imported here: the interpreter (and ``ast``) is needed only by the few files with an
    # $(eval), and most runs start up without it.
    from launch_linter.resolve import safe_eval

    eval_scope = safe_eval.EvalScope(
        args=_ArgTexts(scope.args),
        env=scope.env,
        find=scope.find,
        anon=scope.anon,
        dirname=os.path.dirname(os.path.abspath(scope.filename)),
        budget=scope.budget,
    )
    try:
        return (safe_eval.evaluate(expression, eval_scope),)
    except safe_eval.EvalUnresolved as exc:
        return (Hole(whole, f"$(eval) needs {exc.name}: {exc.reason}"),)
    except safe_eval.EvalError as exc:
        return (Hole(whole, f"$(eval) not evaluated: {exc.reason}"),)


def resolve(text: str, scope: SubstitutionScope) -> Value:
    """Resolve one attribute value; raise :class:`SubstitutionError` where roslaunch would."""
    if "$" not in text:
        return (text,) if text else ()
    # A whole-value $(arg NAME) is half of all substitutions: the general path gives the
    # same result when the value is plain text.
    name = _WHOLE_ARG.get(text)
    if name is None:
        name = _whole_arg(text)
    if name:
        value = scope.args.get(name)
        if value is not None and (
            not value or (len(value) == 1 and type(value[0]) is str and "$" not in value[0])
        ):
            return value
    elif text.startswith("$(eval ") and text.endswith(")"):
        return _evaluate(text[7:-1], text, scope)
    # ``current`` holds the text while every replacement so far was plain text; ``parts``
    # takes over once a hole appears.
    current = text
    parts: list[Part] | None = None
    commands = _commands(text)
    # A needle replaced everywhere by text without "$(" cannot come back: the same
    # command again (200,000 $(arg a) in one value) is skipped, not searched for again.
    gone: set[str] = set()
    for body, needle, words in commands:
        if needle in gone:
            continue
        if words is None:
            _check_command(body)
            continue
        command = words[0]
        if command == "find":
            continue
        replacement = _first_pass_value(command, body, words[1:], scope)
        if parts is None:
            if scope.budget is not None:
                scope.budget.step(1 + len(current) // 4096)  # each replace reads the text
            if not replacement:
                current = current.replace(needle, "")
                gone.add(needle)
                continue
            if len(replacement) == 1 and type(replacement[0]) is str:
                if len(replacement[0]) > len(needle):
                    _charge(scope, _grown_size(current, needle, len(replacement[0])))
                current = current.replace(needle, replacement[0])
                if "$(" not in replacement[0]:
                    gone.add(needle)
                continue
            parts = [current]
        parts = _replace_all(parts, needle, replacement, scope)
    # Every list of parts here is already joined (one non-empty text, or the output of
    # ``join``), so the result is that list as a tuple.
    if parts is None:
        if "$" not in current:
            return (current,) if current else ()
        if current is text:
            # Only $(find) in the text: the second pass sees the same commands.
            return tuple(_find_commands([text], commands, scope))
        parts = [current]
    return tuple(_find_pass(parts, scope))


def to_bool(value: Value) -> bool | None:
    """roslaunch's if/unless truth rule; None when unresolved; ValueError when not a bool."""
    if len(value) == 1 and type(value[0]) is str:
        text = value[0].lower().strip()
    elif is_resolved(value):
        text = "".join(p for p in value if isinstance(p, str)).lower().strip()
    else:
        return None
    if text in ("true", "1"):
        return True
    if text in ("false", "0"):
        return False
    raise ValueError(f"{text} is not a 'bool' type")
