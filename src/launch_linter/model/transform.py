"""The static transform record that every front-end produces and every rule reads."""

from __future__ import annotations

import functools
import math
from collections.abc import Iterable, Mapping
from enum import Enum

from launch_linter.model.equality import equality_test, exclusive, truth_test
from launch_linter.model.record import Record, _open, _seal, _set

TYPE_CHECKING = False  # typing is not imported at run time: start-up (docs/performance.md)
if TYPE_CHECKING:
    from launch_linter.model.equality import Test

NULL_TOLERANCE = 1e-9


class Field(str, Enum):
    """A field of the transform record that may be unresolved. The declaration order is
    the order in which output lists them."""

    NAME = "name"
    NAMESPACE = "namespace"
    PACKAGE = "package"
    EXECUTABLE = "executable"
    ARITY = "arity"
    TRANSLATION = "translation"
    ROTATION = "rotation"
    PARENT = "parent"
    CHILD = "child"
    PERIOD_MS = "period_ms"


FIELD_ORDER = {f: position for position, f in enumerate(Field)}
ROS2_FIELD_ORDER = {**FIELD_ORDER, Field.ARITY: len(FIELD_ORDER)}
"""The ROS 2 front-end has always listed ``arity`` after the fields it hides (the ROS 1
front-end before them); output keeps each order."""

DECODED_FIELDS = (Field.TRANSLATION, Field.ROTATION, Field.PARENT, Field.CHILD)
"""The fields the argument decoders give, in record order."""


def field_names(
    fields: Iterable[Field], order: Mapping[Field, int] = FIELD_ORDER
) -> tuple[str, ...]:
    """The fields' names in record order (how JSON, text and messages list them)."""
    return tuple(f.value for f in sorted(set(fields), key=order.__getitem__))


class ArgForm(str, Enum):
    """How the arguments were written, as the decoder read them."""

    YPR = "ypr"
    QUATERNION = "quaternion"
    INVALID = "invalid"
    """No layout the program accepts."""
    PARAM = "param"
    """ROS 1 ``tf2_ros`` given one argument: a parameter name."""
    UNKNOWN = "unknown"
    """A substitution hides how many words there are."""


class LaunchFormat(str, Enum):
    ROS1_XML = "ros1-xml"
    ROS2_XML = "ros2-xml"
    ROS2_YAML = "ros2-yaml"
    ROS2_PYTHON = "ros2-python"


class ArgIssueKind(str, Enum):
    """A ROS 2 argument mistake; each kind belongs to one rule, which words it."""

    POSITIONAL = "positional"
    """Deprecated old-style positional arguments (``ros2_positional_args``)."""
    UNKNOWN_FLAG = "unknown_flag"
    MIXED_STYLES = "mixed_styles"
    RPY_AND_QUATERNION = "rpy_and_quaternion"
    PARTIAL_QUATERNION = "partial_quaternion"
    MISSING_FRAME = "missing_frame"
    SINGLE_STRING = "single_string"
    """Several words in one argv item (``py_arguments_single_string``)."""
    DEFAULT_FRAMES = "default_frames"
    """A component left at ``/frame`` -> ``/child`` (``component_default_frames``)."""


class RotationKind(str, Enum):
    """How the rotation was written."""

    YPR = "ypr"
    QUATERNION = "quaternion"


class Rotation(Record):
    """A rotation as written: ``values`` is (yaw, pitch, roll) or (qx, qy, qz, qw)."""

    kind: RotationKind
    values: tuple[float, ...]

    __slots__ = ("kind", "values")

    def __init__(self, kind: RotationKind, values: tuple[float, ...]) -> None:
        _set(self, "kind", kind)
        _set(self, "values", values)

    @property
    def is_null(self) -> bool:
        """True for zero yaw/pitch/roll or a quaternion equal to ±(0, 0, 0, 1)."""
        if self.kind is RotationKind.YPR:
            return all(abs(v) <= NULL_TOLERANCE for v in self.values)
        qx, qy, qz, qw = self.values
        return (
            abs(qx) <= NULL_TOLERANCE
            and abs(qy) <= NULL_TOLERANCE
            and abs(qz) <= NULL_TOLERANCE
            and abs(abs(qw) - 1.0) <= NULL_TOLERANCE
        )


class ConditionLiteral(Record):
    """One unresolved ``if``/``unless`` test: the attribute text and whether it must be true."""

    text: str
    positive: bool

    __slots__ = ("text", "positive")

    def __init__(self, text: str, positive: bool) -> None:
        _set(self, "text", text)
        _set(self, "positive", positive)

    def negated(self) -> ConditionLiteral:
        return ConditionLiteral(self.text, not self.positive)


class Condition(Record):
    """A presence condition: the conjunction of unresolved literals (empty means always)."""

    literals: tuple[ConditionLiteral, ...]

    __slots__ = ("literals",)

    def __init__(self, literals: tuple[ConditionLiteral, ...] = ()) -> None:
        _set(self, "literals", literals)

    @property
    def always(self) -> bool:
        return not self.literals

    def __and__(self, other: Condition) -> Condition:
        merged = list(self.literals)
        merged.extend(lit for lit in other.literals if lit not in merged)
        return Condition(tuple(merged))

    def excludes(self, other: Condition) -> bool:
        """True when the two conditions can never hold together: one requires a test the
        other negates, or both compare one value with constants that cannot both hold
        (``== 'a'`` and ``== 'b'``; ``== 'a'`` and ``!= 'a'``), or one value's truth
        both ways (``IfCondition(x)`` and ``IfCondition(PythonExpression(['not ', x]))``)."""
        if any(lit.negated() in other.literals for lit in self.literals):
            return True
        tests = [t for t in map(_test, other.literals) if t is not None]
        return bool(tests) and any(
            exclusive(mine, theirs)
            for mine in map(_test, self.literals) if mine is not None
            for theirs in tests
        )

    def describe(self) -> str:
        if self.always:
            return "always"
        parts = [
            f"if={lit.text!r}" if lit.positive else f"unless={lit.text!r}" for lit in self.literals
        ]
        return " and ".join(parts)


ALWAYS = Condition()


@functools.lru_cache(maxsize=4096)
def _test(literal: ConditionLiteral) -> Test | None:
    """The comparison a literal requires (an ``unless`` negates it)."""
    found = equality_test(literal.text) or truth_test(literal.text)
    return None if found is None else (found[0], found[1], found[2] == literal.positive)


class NumberIssue(Record):
    """A numeric argument that the program does not read as written."""

    index: int
    written: str
    read_as: float | None

    __slots__ = ("index", "written", "read_as")

    def __init__(self, index: int, written: str, read_as: float | None) -> None:
        _set(self, "index", index)
        _set(self, "written", written)
        _set(self, "read_as", read_as)


class ArgIssue(Record):
    """A mistake in how a ROS 2 transform is written, beyond counts and numbers: the facts,
    which the rule of ``kind`` words.

    By kind, ``words`` holds: the positional words (``POSITIONAL``), the unknown flag, the
    flags beside positional arguments, the rpy flags, the missing quaternion flags, the
    missing frame flag, the argv item holding several words, the absent frame parameters.
    ``others`` holds: the flag each positional word stands for, the suggested flag (if
    any), the quaternion flags (``RPY_AND_QUATERNION``), the two frames a component
    publishes (``DEFAULT_FRAMES``), and for ``MISSING_FRAME`` how the frame is empty:
    nothing (the flag is absent), ``("empty",)`` (given empty), ``("positional", N)``
    (the Nth positional argument is empty) or ``("parameter",)`` (a component's
    ``frame_id``/``child_frame_id`` parameter, whose name is then in ``words``).
    ``values`` holds the completed quaternion (``PARTIAL_QUATERNION``). ``fatal`` is
    False for rpy flags beside positional arguments (the program silently replaces them).
    ``split`` is True for an unknown flag that is a flag name written with a space after
    ``--``.
    """

    kind: ArgIssueKind
    words: tuple[str, ...]
    others: tuple[str, ...]
    values: tuple[float, ...]
    fatal: bool
    split: bool

    __slots__ = ("kind", "words", "others", "values", "fatal", "split")

    def __init__(
        self,
        kind: ArgIssueKind,
        words: tuple[str, ...] = (),
        others: tuple[str, ...] = (),
        values: tuple[float, ...] = (),
        fatal: bool = True,
        split: bool = False,
    ) -> None:
        _set(self, "kind", kind)
        _set(self, "words", words)
        _set(self, "others", others)
        _set(self, "values", values)
        _set(self, "fatal", fatal)
        _set(self, "split", split)


class StaticTransform(Record):
    """One ``static_transform_publisher`` node, resolved as far as statically possible.

    ``parent``/``child`` and the numbers are the developer's intended reading of the
    arguments (the tf convention of the written form); ``arity_issue`` says when the
    package's program rejects or misreads that form.
    """

    path: str
    line: int
    column: int
    root: str
    included_from: tuple[str, int] | None
    name: str | None
    namespace: str
    package: str
    executable: str
    args_written: str
    args: str
    tokens: tuple[str, ...]
    parent_written: str | None
    child_written: str | None
    translation: tuple[float, float, float] | None
    rotation: Rotation | None
    period_ms: float | None
    form: ArgForm
    arity_issue: str | None
    number_issues: tuple[NumberIssue, ...]
    condition: Condition
    unresolved: frozenset[Field]
    unresolved_reasons: tuple[str, ...]
    ros_version: int
    launch_format: LaunchFormat
    arg_issues: tuple[ArgIssue, ...]

    __slots__ = (
        "path", "line", "column", "root", "included_from", "name", "namespace", "package",
        "executable", "args_written", "args", "tokens", "parent_written", "child_written",
        "translation", "rotation", "period_ms", "form", "arity_issue", "number_issues", "condition",
        "unresolved", "unresolved_reasons", "ros_version", "launch_format", "arg_issues",
        "_signature",
    )
    _private = ("_signature",)
    _signature: tuple[str, str] | None

    def __init__(
        self,
        path: str,
        line: int,
        column: int,
        root: str,
        included_from: tuple[str, int] | None,
        name: str | None,
        namespace: str,
        package: str,
        executable: str,
        args_written: str,
        args: str,
        tokens: tuple[str, ...],
        parent_written: str | None,
        child_written: str | None,
        translation: tuple[float, float, float] | None,
        rotation: Rotation | None,
        period_ms: float | None,
        form: ArgForm,
        arity_issue: str | None = None,
        number_issues: tuple[NumberIssue, ...] = (),
        condition: Condition | None = None,
        unresolved: frozenset[Field] = frozenset(),
        unresolved_reasons: tuple[str, ...] = (),
        ros_version: int = 1,
        launch_format: LaunchFormat = LaunchFormat.ROS1_XML,
        arg_issues: tuple[ArgIssue, ...] = (),
    ) -> None:
        _open(self)  # made for every static transform publisher: see _open
        self.path = path
        self.line = line
        self.column = column
        self.root = root
        self.included_from = included_from
        self.name = name
        self.namespace = namespace
        self.package = package
        self.executable = executable
        self.args_written = args_written
        self.args = args
        self.tokens = tokens
        self.parent_written = parent_written
        self.child_written = child_written
        self.translation = translation
        self.rotation = rotation
        self.period_ms = period_ms
        self.form = form
        self.arity_issue = arity_issue
        self.number_issues = number_issues
        self.condition = Condition() if condition is None else condition
        self.unresolved = unresolved
        self.unresolved_reasons = unresolved_reasons
        self.ros_version = ros_version
        self.launch_format = launch_format
        self.arg_issues = arg_issues
        _seal(self)

    def is_unresolved(self, *fields: Field) -> bool:
        """True when any of ``fields`` could not be resolved."""
        # Asked many times per transform by the rules; most transforms are fully resolved.
        return bool(self.unresolved) and not self.unresolved.isdisjoint(fields)

    def knows(self, *fields: Field) -> bool:
        """True when every one of ``fields`` is resolved."""
        return not self.unresolved or self.unresolved.isdisjoint(fields)

    @property
    def unresolved_names(self) -> tuple[str, ...]:
        """The unresolved fields' names in record order (as JSON and messages list them)."""
        return field_names(
            self.unresolved, ROS2_FIELD_ORDER if self.ros_version == 2 else FIELD_ORDER
        )

    @property
    def parent(self) -> str | None:
        return normalise_frame(self.parent_written)

    @property
    def child(self) -> str | None:
        return normalise_frame(self.child_written)

    @property
    def signature(self) -> tuple[str, str] | None:
        """(parent, child) without leading slashes; None unless both are resolved. Most
        rules ask, several times per transform: worked out once (kept in a slot that is
        not a field)."""
        try:
            return self._signature
        except AttributeError:
            pass
        parent, child = self.parent, self.child
        signature = None
        if parent is not None and child is not None and not self.is_unresolved(
                Field.PARENT, Field.CHILD):
            signature = (parent, child)
        _set(self, "_signature", signature)
        return signature

    @property
    def qualified_name(self) -> str | None:
        if self.name is None:
            return None
        ns = self.namespace if self.namespace.endswith("/") else self.namespace + "/"
        return ns + self.name

    @property
    def null_displacement(self) -> bool | None:
        if self.translation is None or self.is_unresolved(Field.TRANSLATION):
            return None
        return all(abs(v) <= NULL_TOLERANCE for v in self.translation)

    @property
    def null_rotation(self) -> bool | None:
        if self.rotation is None or self.is_unresolved(Field.ROTATION):
            return None
        return self.rotation.is_null

    @property
    def fully_resolved(self) -> bool:
        return not self.unresolved


def normalise_frame(frame: str | None) -> str | None:
    """Frame ids compare without one leading ``/`` (tf2 strips exactly one)."""
    if frame is None:
        return None
    return frame[1:] if frame.startswith("/") else frame


def is_finite(values: tuple[float, ...]) -> bool:
    return all(math.isfinite(v) for v in values)
