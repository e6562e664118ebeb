"""ROS 2 launch substitutions, parsed and resolved statically.

ROS 2 launch (``launch.frontend``) parses an attribute into a list of substitutions:
literal text and ``$(name arg arg ...)`` calls whose arguments are separated by single
spaces, may be quoted (``'…'`` or ``"…"``) and may nest further calls. A backslash
escapes the next character. Unlike roslaunch, the text of a call's result is never
re-parsed, and a call may appear inside another call's arguments.

The Python front-end builds the same :class:`Call` values from ``LaunchConfiguration``,
``EnvironmentVariable``, ``FindPackageShare``, ``PathJoinSubstitution`` and friends, so
one resolver serves every format. What cannot be known statically becomes a
:class:`~launch_linter.resolve.value.Hole`; what launch itself refuses raises
:class:`SubstitutionError`.
"""

from __future__ import annotations

import os
import re
import shlex
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from typing import Tuple, Union

from launch_linter.model.budget import Budget
from launch_linter.resolve import safe_eval
from launch_linter.resolve.value import (
    Hole,
    Part,
    Value,
    holes,
    is_resolved,
    join,
    only_environment,
    resolved_text,
    text_of,
)

MAX_NESTING = 32
MAX_TEXT = 100_000
MAX_VALUE_CHARS = 4 * 1024 * 1024
"""Longest value one substitution may build."""


@dataclass(frozen=True)
class Text:
    """Literal text."""

    text: str

    def __init__(self, text: str) -> None:
        # Made for every literal piece of every substitution: put in the instance's dict,
        # cheaper than the frozen dataclass's ``object.__setattr__`` (assignment is still
        # refused).
        self.__dict__["text"] = text


@dataclass(frozen=True)
class Call:
    """A substitution call: ``name`` with its arguments; ``written`` is how it appeared."""

    name: str
    args: tuple[Subs, ...]
    written: str
    at: tuple[int, int] | None = field(default=None, compare=False)
    """(line, column) where the substitution is made, in the file of the action that
    performs it (a Python ``LaunchConfiguration(...)``); None: the action's own place."""

    def __init__(self, name: str, args: tuple[Subs, ...], written: str,
                 at: tuple[int, int] | None = None) -> None:
        self.__dict__.update(name=name, args=args, written=written, at=at)  # as Text's


@dataclass(frozen=True)
class Opaque:
    """A piece the linter cannot evaluate (a Python expression it does not model)."""

    text: str
    reason: str


Sub = Union[Text, Call, Opaque]
Subs = Tuple[Sub, ...]


class SubstitutionSyntaxError(Exception):
    """The text does not follow the substitution grammar; ``position`` is 0-based."""

    def __init__(self, message: str, position: int) -> None:
        super().__init__(message)
        self.position = position


class SubstitutionError(Exception):
    """ROS 2 launch refuses this substitution when it runs."""


@dataclass(frozen=True)
class Ros2Scope:
    """What a substitution can see at one place of a launch tree."""

    configs: Mapping[str, Value]
    env: Mapping[str, str]
    find: Callable[[str], str | None]
    anon: Callable[[str], str]
    filename: str
    budget: Budget | None = None
    """The root file's work budget, charged before a value is built."""
    missing: Callable[[str, tuple[int, int] | None], None] | None = None
    """Told the name (and the call's ``at``) of each launch configuration read without a
    default where none is set: launch's ``LaunchConfiguration.perform`` raises "launch
    configuration '…' does not exist" there (the loader decides whether anything could
    have set it)."""
    read: Callable[[str | None], None] | None = None
    """Told the name of every launch configuration read (None: a name not resolved), for
    the include arguments nothing uses (``frontends.ros2_include_args``)."""


def literal(text: str) -> Subs:
    return (Text(text),) if text else ()


def written(subs: Subs) -> str:
    """The substitutions as a launch file would write them."""
    out: list[str] = []
    for sub in subs:
        if isinstance(sub, Text):
            out.append(sub.text)
        elif isinstance(sub, Call):
            out.append(sub.written)
        else:
            out.append(sub.text)
    return "".join(out)


# -- parsing --------------------------------------------------------------------------

_TEMPLATE_SPECIAL = re.compile(r"\$\(|\\")
"""Where plain text stops in a template: a substitution or a backslash."""
_CALL_NAME = re.compile(r"[\w-]*")
"""A substitution's name: letters, digits (str.isalnum, as \\w), '_' and '-'."""
_ARGUMENT_SPECIAL = {
    None: re.compile(r"""[ )'"(\\$]"""),
    "'": re.compile(r"['\\]|\$\("),
    '"': re.compile(r'["\\]|\$\('),
}
"""Where plain text stops in a bare, single-quoted or double-quoted argument."""


class _Parser:
    def __init__(self, source: str) -> None:
        self.source = source
        self.pos = 0

    def error(self, message: str) -> SubstitutionSyntaxError:
        return SubstitutionSyntaxError(f"{message} at column {self.pos + 1}", self.pos)

    def template(self) -> Subs:
        parts: list[Sub] = []
        text: list[str] = []
        source, end = self.source, len(self.source)
        while self.pos < end:
            # Plain text up to the next substitution or backslash is taken whole.
            found = _TEMPLATE_SPECIAL.search(source, self.pos)
            stop = end if found is None else found.start()
            if stop > self.pos:
                text.append(source[self.pos : stop])
                self.pos = stop
                if found is None:
                    break
            if source.startswith("$(", self.pos):
                if text:
                    parts.append(Text("".join(text)))
                    text.clear()
                parts.append(self.call(0))
                continue
            # A backslash: it escapes the next character, except a newline (launch's
            # r'\\(.)' stops at one) and the end of the text, where it stays.
            if self.pos + 1 < end and source[self.pos + 1] != "\n":
                text.append(source[self.pos + 1])
                self.pos += 2
                continue
            text.append("\\")
            self.pos += 1
        if text:
            parts.append(Text("".join(text)))
        return tuple(parts)

    def call(self, depth: int) -> Call:
        if depth >= MAX_NESTING:
            raise self.error(f"substitutions nested deeper than {MAX_NESTING} levels")
        start = self.pos
        self.pos += 2
        name_start = self.pos
        found = _CALL_NAME.match(self.source, self.pos)  # always matches, maybe empty
        self.pos = found.end() if found is not None else self.pos
        name = self.source[name_start : self.pos]
        if not name or not name[0].isalpha():
            raise self.error("expected a substitution name after '$('")
        args: list[Subs] = []
        while True:
            if self.pos >= len(self.source):
                raise self.error(f"'$({name}' is not closed by ')'")
            char = self.source[self.pos]
            if char == ")":
                self.pos += 1
                break
            if char != " ":
                raise self.error(f"unexpected {char!r} in '$({name} ...)'")
            while self.source.startswith(" ", self.pos):
                self.pos += 1
            if self.source.startswith(")", self.pos):
                continue
            args.append(self.argument(depth))
        return Call(name, tuple(args), self.source[start : self.pos])

    def argument(self, depth: int) -> Subs:
        """One argument of a substitution: a quoted text, or a bare word that ends at a
        space or the closing parenthesis. Both may hold nested substitutions and ``\\``
        escapes."""
        source, end = self.source, len(self.source)
        quote = None
        if self.pos < end and source[self.pos] in "'\"":
            quote = source[self.pos]
            self.pos += 1
        special = _ARGUMENT_SPECIAL[quote]
        parts: list[Sub] = []
        text: list[str] = []
        while True:
            # Plain text up to the next character that matters is taken whole.
            found = special.search(source, self.pos)
            stop = end if found is None else found.start()
            if stop > self.pos:
                text.append(source[self.pos : stop])
                self.pos = stop
            if self.pos >= end:
                if quote is not None:
                    raise self.error(f"quoted argument is not closed by {quote}")
                break
            char = source[self.pos]
            if quote is None and char in " )":
                break
            if char == quote:
                self.pos += 1
                break
            if source.startswith("$(", self.pos):
                if text:
                    parts.append(Text("".join(text)))
                    text.clear()
                parts.append(self.call(depth + 1))
                continue
            if char == "\\" and self.pos + 1 < end and (
                source[self.pos + 1] != "\n"  # launch's r'\\(.)' stops at a newline
            ):
                text.append(source[self.pos + 1])
                self.pos += 2
                continue
            if quote is None and char in "'\"($":
                raise self.error(f"unexpected {char!r} in a substitution argument")
            text.append(char)
            self.pos += 1
        if text:
            parts.append(Text("".join(text)))
        return tuple(parts)


def parse(text: str) -> Subs:
    """Parse an attribute value; raise :class:`SubstitutionSyntaxError` if launch would."""
    if len(text) > MAX_TEXT:
        raise SubstitutionSyntaxError(f"value longer than {MAX_TEXT} characters", 0)
    if "$(" not in text and "\\" not in text:
        # Literal text, most attribute values: one piece, as the parser would give.
        return literal(text)
    return _Parser(text).template()


# -- resolution -----------------------------------------------------------------------

_ARITY: dict[str, tuple[int, int]] = {
    "var": (1, 2),
    "env": (1, 2),
    "find-pkg-share": (1, 1),
    "find-pkg-prefix": (1, 1),
    "find-exec": (1, 1),
    "exec-in-pkg": (2, 2),
    "eval": (1, 2),
    "anon": (1, 1),
    "dirname": (0, 0),
    "filename": (0, 0),
    "command": (1, 2),
    "file-content": (1, 1),
    "not": (1, 1),
    "and": (2, 2),
    "or": (2, 2),
    "any": (0, 64),
    "all": (0, 64),
    "equals": (2, 2),
    "not-equals": (2, 2),
    "if": (2, 3),
    "path-join": (0, 64),
    "param": (1, 2),
    "launch_log_dir": (0, 0),
    "log_dir": (0, 0),
}
"""Substitutions that ROS 2 launch (or our Python front-end) knows, with their arity."""

_RUNTIME_ONLY = {
    "find-pkg-prefix": "the install prefix of a package is only known in a built workspace",
    "find-exec": "the location of an executable is only known at run time",
    "exec-in-pkg": "the location of an executable is only known in a built workspace",
    "command": "$(command) runs a program, which the linter never does",
    "file-content": "the linter does not read files named by substitutions",
    # launch_ros (Humble+): a global parameter set by <set_parameter> or given at run time.
    "param": "a ROS parameter's value is only known when the launch runs",
    # launch: the folder of this run's logs, made when the launch starts.
    "launch_log_dir": "the launch log folder is only known when the launch runs",
    "log_dir": "the launch log folder is only known when the launch runs",
}

_TRUE_WORDS = ("true", "1", "yes", "on")
_FALSE_WORDS = ("false", "0", "no", "off")


def _refusal(call: Call) -> str | None:
    """Why launch refuses this one call (an unknown name, a wrong number of arguments),
    or None."""
    if call.name == "arg":
        return ("ROS 1's '$(arg)' in a ROS 2 launch file: launch stops with 'Unknown "
                "substitution: arg'; ROS 2 reads a launch argument with '$(var NAME)'")
    if call.name not in _ARITY:
        return f"unknown substitution '$({call.name})'"
    low, high = _ARITY[call.name]
    if not low <= len(call.args) <= high:
        expected = str(low) if low == high else f"{low} to {high}"
        return f"'$({call.name})' takes {expected} argument(s), not {len(call.args)}"
    return None


def first_refusal(subs: Subs) -> str | None:
    """Why launch refuses these substitutions when it parses them, nested ones included,
    or None: the frontend's parser instantiates every substitution of an attribute while
    it parses the file (``instantiate_substitution`` raises 'Unknown substitution', a
    substitution's ``parse`` a wrong argument count), before any action runs."""
    pending: list[Subs] = [subs]
    while pending:
        for sub in pending.pop():
            if isinstance(sub, Call):
                refusal = _refusal(sub)
                if refusal is not None:
                    return refusal
                pending.extend(sub.args)
    return None


def _hole(call: Call, reason: str) -> Value:
    return (Hole(call.written, reason),)


def _reasons(value: Value) -> str:
    return "; ".join(f"{h.text}: {h.reason}" for h in holes(value))


class _Resolver:
    def __init__(self, scope: Ros2Scope) -> None:
        self.scope = scope

    def value(self, subs: Subs) -> Value:
        parts: list[Part] = []
        for sub in subs:
            if isinstance(sub, Text):
                parts.append(sub.text)
            elif isinstance(sub, Opaque):
                parts.append(Hole(sub.text, sub.reason))
            else:
                parts.extend(self.call(sub))
        if len(parts) > 1:
            # Values that refer to each other double at each level: size before joining.
            size = sum(len(p) if isinstance(p, str) else len(p.text) for p in parts)
            if size > MAX_VALUE_CHARS:
                raise SubstitutionError(
                    f"value would be longer than {MAX_VALUE_CHARS:,} characters; not built")
            if self.scope.budget is not None:
                self.scope.budget.produce(size)
        return join(parts)

    def text(self, subs: Subs) -> str | Value:
        """The resolved text, or the unresolved value itself."""
        value = self.value(subs)
        text = resolved_text(value)
        return value if text is None else text

    def call(self, call: Call) -> Value:
        refusal = _refusal(call)
        if refusal is not None:
            raise SubstitutionError(refusal)
        if call.name in _RUNTIME_ONLY:
            return _hole(call, _RUNTIME_ONLY[call.name])
        handler = getattr(self, "_" + call.name.replace("-", "_"))
        result: Value = handler(call)
        return result

    def _var(self, call: Call) -> Value:
        name = self.text(call.args[0])
        if self.scope.read is not None:
            self.scope.read(name if isinstance(name, str) else None)
        if not isinstance(name, str):
            return _hole(call, f"the configuration name is unresolved: {_reasons(name)}")
        if name in self.scope.configs:
            value = self.scope.configs[name]
            return value if only_environment(value) else _hole(call, _reasons(value))
        if len(call.args) == 2:
            return self.value(call.args[1])
        if self.scope.missing is not None:
            self.scope.missing(name, call.at)
        return _hole(
            call,
            f"launch argument '{name}' is not set (give it with --arg {name}:=VALUE)",
        )

    def _env(self, call: Call) -> Value:
        name = self.text(call.args[0])
        if not isinstance(name, str):
            return _hole(call, f"the variable name is unresolved: {_reasons(name)}")
        if name in self.scope.env:
            return (self.scope.env[name],)
        if len(call.args) == 2:
            return self.value(call.args[1])
        return _hole(call, f"environment variable '{name}' not given (use --env)")

    def _find_pkg_share(self, call: Call) -> Value:
        package = self.text(call.args[0])
        if not isinstance(package, str):
            return _hole(call, f"the package name is unresolved: {_reasons(package)}")
        # The share folder holds what the package installs from its source folder
        # (launch/, config/, urdf/ ...), so the source folder stands in for it.
        location = self.scope.find(package)
        if location is None:
            return _hole(call, f"package '{package}' not found under the package path")
        return (location,)

    def _path_join(self, call: Call) -> Value:
        pieces: list[Value] = [self.value(arg) for arg in call.args]
        if all(is_resolved(piece) for piece in pieces):
            return (os.path.join(*(text_of(piece) for piece in pieces)),) if pieces else ()
        # A path whose unknowns are environment variables keeps its text around them
        # (``urdf/turtlebot3_`` + $TURTLEBOT3_MODEL + ``.urdf``): what it is for each
        # value of the variable is exact (a value that is itself an absolute path is
        # one of the values it does not name).
        if not all(only_environment(piece) for piece in pieces):
            return _hole(call, "; ".join(_reasons(p) for p in pieces if not is_resolved(p)))
        parts: list[Part] = []
        for piece in pieces:
            if piece and isinstance(piece[0], str) and piece[0].startswith("/"):
                parts = []
            elif parts and not (isinstance(parts[-1], str) and parts[-1].endswith("/")):
                parts.append("/")
            parts.extend(piece)
        return join(parts)

    def _eval(self, call: Call) -> Value:
        expression = self.text(call.args[0])
        if not isinstance(expression, str):
            return _hole(call, f"the expression is unresolved: {_reasons(expression)}")
        scope = safe_eval.EvalScope(
            # ROS 2 evaluates the text with the math module only: there is no arg().
            args={},
            env=self.scope.env,
            find=self.scope.find,
            anon=self.scope.anon,
            dirname=os.path.dirname(os.path.abspath(self.scope.filename)),
            budget=self.scope.budget,
        )
        try:
            return (safe_eval.evaluate(expression, scope),)
        except safe_eval.EvalUnresolved as exc:
            return _hole(call, f"$(eval) needs {exc.name}: {exc.reason}")
        except safe_eval.EvalError as exc:
            return _hole(call, f"$(eval) not evaluated: {exc.reason}")

    def _anon(self, call: Call) -> Value:
        name = self.text(call.args[0])
        if not isinstance(name, str):
            return _hole(call, f"the anonymous id is unresolved: {_reasons(name)}")
        return (self.scope.anon(name),)

    def _dirname(self, call: Call) -> Value:
        return (os.path.dirname(os.path.abspath(self.scope.filename)),)

    def _filename(self, call: Call) -> Value:
        return (os.path.abspath(self.scope.filename),)

    def _typed_bool(self, call: Call, subs: Subs) -> bool | Value:
        text = self.text(subs)
        if not isinstance(text, str):
            return text
        word = text.strip().lower()
        if word in _TRUE_WORDS:
            return True
        if word in _FALSE_WORDS:
            return False
        raise SubstitutionError(f"'$({call.name})' needs a boolean, not {text!r}")

    def _not(self, call: Call) -> Value:
        value = self._typed_bool(call, call.args[0])
        if isinstance(value, bool):
            return (str(not value).lower(),)
        return _hole(call, _reasons(value))

    def _combine(self, call: Call, short: bool) -> Value:
        # launch evaluates every operand; a known short-circuiting operand decides the
        # result whenever the unknown ones turn out to be booleans, as they must.
        unknown: list[Value] = []
        for arg in call.args:
            value = self._typed_bool(call, arg)
            if isinstance(value, bool):
                if value is short:
                    return (str(short).lower(),)
            else:
                unknown.append(value)
        if unknown:
            return _hole(call, "; ".join(_reasons(v) for v in unknown))
        return (str(not short).lower(),)

    def _and(self, call: Call) -> Value:
        return self._combine(call, False)

    def _or(self, call: Call) -> Value:
        return self._combine(call, True)

    def _all(self, call: Call) -> Value:
        return self._combine(call, False)

    def _any(self, call: Call) -> Value:
        return self._combine(call, True)

    def _equals(self, call: Call) -> Value:
        left = self.text(call.args[0])
        right = self.text(call.args[1])
        if not isinstance(left, str) or not isinstance(right, str):
            pending = [v for v in (left, right) if not isinstance(v, str)]
            return _hole(call, "; ".join(_reasons(v) for v in pending))
        return (str(_loosely_equal(left, right)).lower(),)

    def _not_equals(self, call: Call) -> Value:
        value = self._equals(call)
        if not is_resolved(value):
            return value
        return ("false" if text_of(value) == "true" else "true",)

    def _if(self, call: Call) -> Value:
        condition = self.value(call.args[0])
        try:
            truth = to_bool(condition)
        except ValueError as exc:
            raise SubstitutionError(f"'$(if)': {exc}") from None
        if truth is None:
            return _hole(call, _reasons(condition))
        if truth:
            return self.value(call.args[1])
        return self.value(call.args[2]) if len(call.args) == 3 else ()


def _loosely_equal(left: str, right: str) -> bool:
    """``$(equals)`` compares typed values: numbers and booleans by value, else text."""
    if left.lower() in ("true", "false") and right.lower() in ("true", "false"):
        return left.lower() == right.lower()
    try:
        return float(left) == float(right)
    except ValueError:
        return left == right


def resolve(subs: Subs, scope: Ros2Scope) -> Value:
    """Resolve substitutions; raise :class:`SubstitutionError` where launch would fail."""
    if not subs:
        return ()
    if len(subs) == 1 and type(subs[0]) is Text:
        # Literal text, most values: what the resolver would give, without one.
        text = subs[0].text
        return (text,) if text else ()
    return _Resolver(scope).value(subs)


def to_bool(value: Value) -> bool | None:
    """launch's ``if``/``unless`` rule (``strip().lower()`` is ``true``/``1`` or
    ``false``/``0``); None when unresolved; ValueError for any other text."""
    text = resolved_text(value)
    if text is None:
        return None
    word = text.strip().lower()
    if word in ("true", "1"):
        return True
    if word in ("false", "0"):
        return False
    raise ValueError(f"{text!r} is not a valid condition (true, false, 1 or 0)")


class CommandLineError(ValueError):
    """launch's ``shlex.split`` refuses a piece of literal text (an unclosed quote, a
    trailing backslash): the front-end raises and the whole file is refused."""


def split_command_line(subs: Subs) -> list[Subs]:
    """Split an ``args``/``cmd`` attribute into argv items exactly as launch's
    ``ExecuteProcess._parse_cmdline`` does.

    Each literal text is split with ``shlex.split``; a substitution's result is never
    split, and it joins the literal text it touches (``$(var a)_link``). Two of launch's
    artefacts are kept because the program sees them: a text of only whitespace closes
    the current item even when it is empty, so whitespace before a leading substitution
    (``args=" $(var a) b"``) and an empty attribute (``args=""``) give an empty argument.
    Raises :class:`CommandLineError` where ``shlex`` does (launch then refuses the file).
    """
    result: list[Subs] = []
    current: list[Sub] = []

    def close() -> None:
        # launch appends the item even when it is empty.
        result.append(tuple(current))
        current.clear()

    if not subs:
        # parse_substitution('') is one empty text, which shlex splits into nothing.
        return [()]
    for sub in subs:
        if not isinstance(sub, Text):
            current.append(sub)
            continue
        try:
            tokens = shlex.split(sub.text)
        except ValueError as exc:
            raise CommandLineError(f"{exc} in {sub.text!r}") from None
        if not tokens:
            close()
            continue
        if sub.text[0].isspace() and current:
            close()
        current.append(Text(tokens[0]))
        if len(tokens) > 1:
            close()
            current.append(Text(tokens[-1]))
        if len(tokens) > 2:
            result.extend((Text(token),) for token in tokens[1:-1])
        if sub.text[-1].isspace():
            close()
    if current:
        result.append(tuple(current))
    return result
