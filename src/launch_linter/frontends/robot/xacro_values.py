"""The limits of the xacro expander, what it produces (the expanded tree, its problems),
and its tables of properties, macros and blocks with their scoping."""

from __future__ import annotations

import keyword
import re
import unicodedata
from collections.abc import Callable, Mapping

from launch_linter.model.record import MutableRecord, Record, _set
from launch_linter.model.robot import MALFORMED_XML
from launch_linter.resolve.xml_safe import Element

MAX_FILES = 200
"""Most distinct files one description may read."""
MAX_INCLUDE_DEPTH = 32
MAX_MACRO_DEPTH = 64
MAX_OUTPUT_ELEMENTS = 100_000
MAX_OUTPUT_CHARS = 16 * 1024 * 1024
"""Attribute text of one expansion: some 200 MB of Python strings and nodes at most."""
MAX_WORK = 1_000_000
"""Work units for one expansion: one per element visited and per substitution made."""
MAX_TEXT = 65_536
"""Longest attribute value an expansion may produce."""

_PREFIX = "xacro:"
# xacro's lexer: ``$${``/``$$(`` escapes, ``${expr}``, and ``$(...)`` whose words may hold
# ``${expr}`` (evaluated first, as xacro does).
_TOKEN = re.compile(r"\$\$[{(]|\$\{[^}]*\}|\$\((?:[^$)]|\$\{[^}]*\})*\)")
_MATH_PREFIX = re.compile(r"\bmath\.")
_GLOB = re.compile(r"[*?\[]")


def valid_name(name: str) -> bool:
    """Whether xacro takes ``name`` for a property: a Python identifier that parses as
    itself (no keyword, already in NFKC form), as xacro's ``is_valid_name`` checks (it
    refuses any other name, ``''`` included)."""
    return (name.isidentifier() and not keyword.iskeyword(name)
            and unicodedata.normalize("NFKC", name) == name)


_CLOSES = {")": "(", "]": "[", "}": "{"}


def _string_end(source: str, start: int, quote: str) -> int:
    """Where the string literal whose body starts at ``start`` ends (after its closing
    ``quote``); -1 when it is not closed (a one-quote string ends at a line's end)."""
    position = start
    while position < len(source):
        if source[position] == "\\":
            position += 2
        elif source.startswith(quote, position):
            return position + len(quote)
        elif source[position] == "\n" and len(quote) == 1:
            return -1
        else:
            position += 1
    return -1


def bracket_fault(source: str) -> str | None:
    """Why ``source`` is no Python expression in any Python xacro runs on (2 or 3): a
    bracket that closes none or not its own, a bracket or a string left open; None when
    its brackets and quotes pair up. xacro compiles each ``${...}`` it evaluates (its
    ``eval_text``/``safe_eval``), so such an expression stops it with a SyntaxError."""
    opened: list[str] = []
    position = 0
    while position < len(source):
        char = source[position]
        if char in "'\"":
            quote = char * 3 if source.startswith(char * 3, position) else char
            position = _string_end(source, position + len(quote), quote)
            if position < 0:
                return "a string is not closed"
            continue
        if char == "#":  # a comment, to the end of its line
            position = source.find("\n", position)
            if position < 0:
                break
        elif char in "([{":
            opened.append(char)
        elif char in _CLOSES:
            if not opened:
                return f"'{char}' closes no bracket"
            if opened.pop() != _CLOSES[char]:
                return f"'{char}' does not close its bracket"
        position += 1
    return f"'{opened[-1]}' is not closed" if opened else None


class _Abort(Exception):
    """A bound was reached, or the real xacro stops too (``kind`` ``REFUSED``): the
    expansion stops."""

    def __init__(self, message: str, path: str, line: int, kind: str | None = None) -> None:
        super().__init__(message)
        self.message = message
        self.path = path
        self.line = line
        self.kind = kind


class _Unknown(Exception):
    """A value the expander cannot know statically; ``reason`` says why."""

    def __init__(self, reason: str) -> None:
        super().__init__(reason)
        self.reason = reason


class _Refused(_Unknown):
    """What the real xacro stops on (an undefined macro, a missing parameter, an
    undeclared ``$(arg)``): unknown to the expander as well, and a fault of the source.
    ``arg`` names the undeclared arg of a refused ``$(arg)``."""

    def __init__(self, reason: str, arg: str | None = None) -> None:
        super().__init__(reason)
        self.arg = arg


class _Placed(_Refused):
    """A refusal whose fault is in another place than the element being expanded, said
    there as ``detail``: an included file that is not well-formed XML (xacro's minidom
    stops on it; no includer can make it well-formed), a property whose name xacro
    refuses to read (its definition)."""

    def __init__(self, reason: str, path: str, line: int, detail: str) -> None:
        super().__init__(reason)
        self.path = path
        self.line = line
        self.detail = detail


class _Mismatch(_Refused):
    """A macro call that does not match the macro's definition (a parameter missing or not
    declared, blocks that do not pair): xacro stops whatever else is defined, so it is a
    fault of its own when nothing was left unread (an include not found) between the
    definition and the call. ``seen`` is the number of problems before the definition."""

    def __init__(self, reason: str, seen: int) -> None:
        super().__init__(reason)
        self.seen = seen


def extension(body: str, args: Mapping[str, str | None],
              find: Callable[[str], str | None], env: Mapping[str, str],
              args_read: set[str], env_read: set[str],
              evaluate: Callable[[str], object]) -> str:
    """xacro's ``$(...)`` (``eval_extension``): ``$(arg)`` from ``args`` (None: given, value
    not known), ``$(find)``, ``$(env)``/``$(optenv)`` from ``env``, ``$(eval)`` through
    ``evaluate``; the args and variables read are added to ``args_read``/``env_read``.
    Raises :class:`_Unknown` for what cannot be known, :class:`_Refused` for an arg
    neither declared nor given."""
    words = body.split()
    if not words:
        raise _Unknown("empty $()")
    command, rest = words[0], words[1:]
    if command == "arg" and len(rest) == 1:
        name = rest[0]
        args_read.add(name)
        if name not in args:
            raise _Refused(f"$(arg {name}): the arg is not declared and not given", name)
        value = args[name]
        if value is None:
            raise _Unknown(f"$(arg {name}): its value is not known")
        return value
    if command == "find" and len(rest) == 1:
        found = find(rest[0])
        if found is None:
            raise _Unknown(f"$(find {rest[0]}): package not found under the package path")
        return found
    if command in ("env", "optenv") and rest:
        env_read.add(rest[0])
    if command == "env" and len(rest) == 1:
        if rest[0] not in env:
            raise _Unknown(f"$(env {rest[0]}): not given with --env")
        return env[rest[0]]
    if command == "optenv" and rest:
        return env.get(rest[0], " ".join(rest[1:]))
    if command == "eval":
        return str(evaluate(body[len("eval"):]))
    raise _Unknown(f"$({body}) is not supported")


UNKNOWN = "unknown"
"""A problem kind: something not followed; content may be missing from the expansion."""
KEPT = "kept"
"""A problem kind: an undecided ``xacro:if``/``xacro:unless``, its content kept."""
REFUSED = "refused"
"""A problem kind: the real xacro stops here (see :class:`_Refused`)."""
DROPPED = "dropped"
"""A problem kind: the real xacro silently drops content here (a block never inserted)."""
PARAM_AS_ARG = "param_as_arg"
"""A problem kind: a macro reads its own parameter as ``$(arg)``, which never sees it."""
UNEXPANDED = "unexpanded"
"""A problem kind: xacro goes on but leaves written xacro unexpanded or drops its text (a
macro call without the prefix, a ``${`` never closed: see ``xacro_unexpanded``)."""
FAULT_KINDS = (REFUSED, DROPPED, PARAM_AS_ARG, UNEXPANDED)
"""The kinds that are faults of the source itself."""
MALFORMED = MALFORMED_XML
"""What a refusal of a file that is not well-formed says: a fault of that file alone, which
nothing not followed before it can make well-formed."""


def expression_error(source: str, reason: str) -> _Unknown:
    """What an expression the evaluator could not read is: refused by xacro when it is
    no Python expression at all (:func:`bracket_fault`), else unknown (``reason``)."""
    fault = bracket_fault(source)
    if fault is not None:
        return _Refused(f"${{{source}}}: {fault}")
    return _Unknown(f"${{{source}}}: {reason}")


class XacroProblem(Record):
    """Something the expander could not follow, with where it was."""

    path: str
    line: int
    message: str
    fatal: bool
    """True when the expansion stopped (a bound was reached or the root is unreadable)."""
    kind: str
    """``UNKNOWN``, ``KEPT`` or one of the ``FAULT_KINDS``."""
    conditions: tuple[str, ...]
    """The undecided ``xacro:if``/``xacro:unless`` texts around it (see ExpandedNode)."""
    name: str | None
    """The arg of a refused ``$(arg)`` or of a ``PARAM_AS_ARG`` use; the macro of an
    ``UNEXPANDED`` call."""
    own: bool
    """A refusal that nothing left unread before it can explain: a call of a macro
    defined after the last thing not followed (:class:`_Mismatch`)."""

    __slots__ = ("path", "line", "message", "fatal", "kind", "conditions", "name", "own")

    def __init__(
        self,
        path: str,
        line: int,
        message: str,
        fatal: bool = False,
        kind: str = UNKNOWN,
        conditions: tuple[str, ...] = (),
        name: str | None = None,
        own: bool = False,
    ) -> None:
        _set(self, "path", path)
        _set(self, "line", line)
        _set(self, "message", message)
        _set(self, "fatal", fatal)
        _set(self, "kind", kind)
        _set(self, "conditions", conditions)
        _set(self, "name", name)
        _set(self, "own", own)


TF_PREFIX_PARAM = "tf_prefix"
"""The parameter a ROS 1 simulated plugin's record gives the ``tf_prefix`` it finds from its
robot namespace (set by the launch tree, not in the plugin block; ``describe``)."""
PLUGIN_TEXT_TAGS = frozenset({
    # gazebo_ros (ROS 1) plugin parameters that name frames or switch tf on and off.
    "robotNamespace", "publishOdomTF", "publishWheelTF", "publishTf", "odometryFrame",
    "robotBaseFrame", "frameName", "bodyName", "publishOdom", "broadcastTF",
    # kobuki_gazebo_plugins (ROS 1): Kobuki's simulated base.
    "publish_tf",
    # gazebo_ros (ROS 2): parameters, and <ros><namespace>/<remapping>.
    "namespace", "remapping", "publish_odom_tf", "publish_wheel_tf", "odometry_frame",
    "robot_base_frame", "frame_name", "body_name", "publish_odom",
    # gz-sim systems (diff drive, odometry publisher) and gz_ros2_control.
    "frame_id", "child_frame_id", "tf_topic", "odom_frame", "odom_publish_frequency",
    "parameters", "controller_manager_name",
    # A sensor's pose in its link (and its camera's in the sensor): where a camera looks.
    "pose",
    # gz-sim sensors: the frame of their data (gz-sensors Sensor.cc, CameraSensor.cc).
    "gz_frame_id", "ignition_frame_id", "optical_frame_id",
})
"""The elements whose text the expander keeps: the parameters of the Gazebo plugins the
knowledge base knows (tests/knowledge checks that every plugin entry's parameter is one)."""


class ExpandedNode:
    """An element of the expanded document, with where it was written."""

    __slots__ = ("attrib", "call", "children", "column", "conditions", "included", "line",
                 "path", "tag", "text", "unknown")

    def __init__(self, tag: str, path: str, line: int, column: int,
                 conditions: tuple[str, ...]) -> None:
        self.tag = tag
        self.path = path
        self.line = line
        self.column = column
        self.attrib: dict[str, str] = {}
        self.unknown: dict[str, str] = {}
        """Attribute name -> why its value is unknown."""
        self.children: list[ExpandedNode] = []
        self.text: str | None = ""
        """Character data inside (kept for :data:`PLUGIN_TEXT_TAGS` only); None when
        a ``${}`` in it cannot be known."""
        self.conditions = conditions
        """Texts of the enclosing ``xacro:if``/``unless`` whose values are unknown
        (``unless`` texts start with ``!``)."""
        self.call: tuple[str, int, int] | None = None
        """For an element a macro made: the outermost ``<xacro:macro_name .../>`` call
        that made it (file, line, column): what a user edits to change that instance."""
        self.included: tuple[str, int, int] | None = None
        """The ``xacro:include`` (file, line, column) that read the file this element, or
        its outermost macro call, is written in; None in the top file. A file included
        twice makes its elements twice, told apart by this."""


class Expansion(MutableRecord):
    """The result of expanding one description file with some args."""

    root: ExpandedNode | None
    problems: list[XacroProblem]
    files: list[str]
    defines_macros: bool
    """Whether a ``xacro:macro`` was defined (an empty robot made of a macros-only file)."""
    args_read: frozenset[str]
    """The xacro args the expansion looked up (given or not): the result depends on the
    given args only through these names, so a call differing elsewhere may reuse it."""
    env_read: frozenset[str]
    """The environment variables ``$(env)``/``$(optenv)`` looked up."""
    cut_by_budget: bool
    """Stopped by the work budget of the launch tree it was expanded for (not by a bound
    of its own): another tree, with budget left, must expand it again."""

    __slots__ = (
        "root", "problems", "files", "defines_macros", "args_read", "env_read", "cut_by_budget",
    )

    def __init__(
        self,
        root: ExpandedNode | None,
        problems: list[XacroProblem],
        files: list[str],
        defines_macros: bool = False,
        args_read: frozenset[str] = frozenset(),
        env_read: frozenset[str] = frozenset(),
        cut_by_budget: bool = False,
    ) -> None:
        self.root = root
        self.problems = problems
        self.files = files
        self.defines_macros = defines_macros
        self.args_read = args_read
        self.env_read = env_read
        self.cut_by_budget = cut_by_budget


class _Property(MutableRecord):
    text: str | None
    """Unevaluated text, or None once evaluated."""
    value: str | None
    """Evaluated text; None while unevaluated or when unknown."""
    reason: str | None
    block: tuple[Element, str] | None
    """For a block property: the ``xacro:property`` element and its file."""
    data: object
    """A value that is not text (a dict or list from ``load_yaml``); ``value`` is None."""
    namespace: _Table | None
    """For the name of an ``xacro:include ns=``: the table of the included file."""

    __slots__ = ("text", "value", "reason", "block", "data", "namespace")

    def __init__(
        self,
        text: str | None,
        value: str | None,
        reason: str | None = None,
        block: tuple[Element, str] | None = None,
        data: object = None,
        namespace: _Table | None = None,
    ) -> None:
        self.text = text
        self.value = value
        self.reason = reason
        self.block = block
        self.data = data
        self.namespace = namespace


class _Macro(MutableRecord):
    params: list[str]
    defaults: dict[str, tuple[str | None, str | None]]
    """param -> (forwarded name, default text)."""
    body: Element
    path: str
    scope: _Table | None
    """For a macro of a namespaced include: the include's table, where its body runs
    (xacro resolves ``ns.name`` to the namespace's own macros and properties)."""
    seen: int
    """The expander's problems before the definition (see :class:`_Mismatch`)."""

    __slots__ = ("params", "defaults", "body", "path", "scope", "seen")

    def __init__(
        self,
        params: list[str],
        defaults: dict[str, tuple[str | None, str | None]],
        body: Element,
        path: str,
        scope: _Table | None = None,
        seen: int = 0,
    ) -> None:
        self.seen = seen
        self.params = params
        self.defaults = defaults
        self.body = body
        self.path = path
        self.scope = scope


class _Block(MutableRecord):
    element: Element
    path: str
    content_only: bool
    scope: _Table

    __slots__ = ("element", "path", "content_only", "scope")

    def __init__(self, element: Element, path: str, content_only: bool, scope: _Table) -> None:
        self.element = element
        self.path = path
        self.content_only = content_only
        self.scope = scope


LEGACY_DISTROS = frozenset({"hydro", "indigo", "jade", "kinetic", "lunar", "melodic",
                            "dashing", "eloquent"})
"""Distributions whose xacro also reads xacro tags written without the ``xacro:`` prefix
(``allow_non_prefixed_tags`` true unless ``--xacro-ns``, with a deprecation warning):
ros/xacro melodic-devel e2ba976 and dashing-devel 5671b7d, ``src/xacro/__init__.py``
``check_deprecated_tag``, ``is_include``, ``handle_macro_call``. Noetic's (7045754) and
the ros2 branch's (9d05b0e) read only prefixed tags."""
LEGACY_DIRECTIVES = frozenset({"arg", "property", "macro", "if", "unless", "insert_block"})


def legacy_tags(env: Mapping[str, str]) -> bool:
    """Whether the target distribution (``--ros-distro``, else ``$ROS_DISTRO``) is one of
    the :data:`LEGACY_DISTROS`. Not known, tags are read as Noetic's and ROS 2's xacro
    reads them: a legacy xacro would also take any element named like a macro (a Gazebo
    ``<noise>`` beside a ``noise`` macro) for a call."""
    return env.get("ROS_DISTRO") in LEGACY_DISTROS


def legacy_tag(element: Element, table: _Table) -> bool:
    """Whether a legacy xacro reads the unprefixed ``element`` as a xacro tag: a
    directive, an ``<include>`` without element children (Gazebo's ``<include><uri>`` is
    not xacro's), or the call of a macro defined by then."""
    if element.tag == "include":
        return not element.children
    return element.tag in LEGACY_DIRECTIVES or table.find_macro(element.tag) is not None


class _Table:
    """A scope of properties (and, separately, macros) with a parent, like xacro's Table."""

    def __init__(self, parent: _Table | None = None) -> None:
        self.parent = parent
        self.properties: dict[str, _Property] = {}
        self.macros: dict[str, _Macro] = {}
        self.blocks: dict[str, _Block] = {}

    def find_property(self, name: str) -> tuple[_Table, _Property] | None:
        table: _Table | None = self
        while table is not None:
            found = table.properties.get(name)
            if found is not None:
                return table, found
            table = table.parent
        return None

    def find_macro(self, name: str) -> _Macro | None:
        table: _Table | None = self
        while table is not None:
            found = table.macros.get(name)
            if found is not None:
                return found
            table = table.parent
        return None

    def find_block(self, name: str) -> _Block | None:
        table: _Table | None = self
        while table is not None:
            found = table.blocks.get(name)
            if found is not None:
                return found
            table = table.parent
        return None


def _literal(text: str) -> str:
    """xacro's ``_eval_literal``, written as text that the evaluator's "auto" rule reads
    back as the same Python value (ints, floats with a dot, booleans, strings)."""
    if len(text) >= 2 and text[0] == "'" and text[-1] == "'":
        return text[1:-1]
    if "_" in text:
        return text
    try:
        return str(int(text))
    except ValueError:
        pass
    try:
        number = float(text)
    except ValueError:
        return text
    shown = repr(number)
    return shown if "." in shown else text


_WHOLE_EXPRESSION = re.compile(r"\$\{[^}]*\}\Z")
_PARAM = re.compile(
    r"""([^\s:=]+)(?:\s*(:?=)\s*(\^\|?)?"""
    r"""((?:\$\{[^}]*\}|\$\([^)]*\)|'[^']*'|"[^"]*"|[^\s'"])*))?""")
"""One macro parameter: name, then optionally ``:=``/``=``, ``^``/``^|`` and a default
that runs to the next space outside quotes, ``${}`` and ``$()`` (xacro's syntax)."""


def _unquoted(default: str) -> str:
    if len(default) >= 2 and default[0] == default[-1] and default[0] in "'\"":
        return default[1:-1]
    return default


def _boolean(value: str) -> bool | None:
    """xacro's ``get_boolean_value``; None when the text is not a boolean."""
    if value in ("true", "True"):
        return True
    if value in ("false", "False"):
        return False
    try:
        return bool(int(value))
    except ValueError:
        pass
    try:
        return bool(float(value))
    except ValueError:
        raise _Unknown(f"conditional value {value!r} is not a boolean") from None
