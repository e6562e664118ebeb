"""The static transform record that every front-end produces and every rule reads."""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from enum import Enum

NULL_TOLERANCE = 1e-9


class RotationKind(str, Enum):
    """How the rotation was written."""

    YPR = "ypr"
    QUATERNION = "quaternion"


@dataclass(frozen=True)
class Rotation:
    """A rotation as written: ``values`` is (yaw, pitch, roll) or (qx, qy, qz, qw)."""

    kind: RotationKind
    values: tuple[float, ...]

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


@dataclass(frozen=True)
class ConditionLiteral:
    """One unresolved ``if``/``unless`` test: the attribute text and whether it must be true."""

    text: str
    positive: bool

    def negated(self) -> ConditionLiteral:
        return ConditionLiteral(self.text, not self.positive)


@dataclass(frozen=True)
class Condition:
    """A presence condition: the conjunction of unresolved literals (empty means always)."""

    literals: tuple[ConditionLiteral, ...] = ()

    @property
    def always(self) -> bool:
        return not self.literals

    def __and__(self, other: Condition) -> Condition:
        merged = list(self.literals)
        merged.extend(lit for lit in other.literals if lit not in merged)
        return Condition(tuple(merged))

    def excludes(self, other: Condition) -> bool:
        """True when the two conditions can never hold together."""
        return any(lit.negated() in other.literals for lit in self.literals)

    def describe(self) -> str:
        if self.always:
            return "always"
        parts = [
            f"if={lit.text!r}" if lit.positive else f"unless={lit.text!r}" for lit in self.literals
        ]
        return " and ".join(parts)


ALWAYS = Condition()


@dataclass(frozen=True)
class NumberIssue:
    """A numeric argument that the program does not read as written."""

    index: int
    written: str
    read_as: float | None


@dataclass(frozen=True)
class ArgIssue:
    """A mistake in how a ROS 2 transform is written, beyond counts and numbers.

    ``kind`` names it for the rule that reports it: ``positional`` (deprecated old-style
    arguments), ``unknown_flag``, ``mixed_styles``, ``rpy_and_quaternion``,
    ``partial_quaternion``, ``missing_frame``, ``single_string`` (several arguments in
    one argv item) or ``default_frames`` (a component left at ``/frame`` → ``/child``).
    """

    kind: str
    message: str


@dataclass(frozen=True)
class StaticTransform:
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
    form: str
    arity_issue: str | None = None
    number_issues: tuple[NumberIssue, ...] = ()
    condition: Condition = field(default_factory=Condition)
    unresolved: tuple[str, ...] = ()
    unresolved_reasons: tuple[str, ...] = ()
    ros_version: int = 1
    launch_format: str = "ros1-xml"
    arg_issues: tuple[ArgIssue, ...] = ()

    @property
    def parent(self) -> str | None:
        return normalise_frame(self.parent_written)

    @property
    def child(self) -> str | None:
        return normalise_frame(self.child_written)

    @property
    def signature(self) -> tuple[str, str] | None:
        """(parent, child) without leading slashes; None unless both are resolved."""
        if self.parent is None or self.child is None:
            return None
        if "parent" in self.unresolved or "child" in self.unresolved:
            return None
        return (self.parent, self.child)

    @property
    def qualified_name(self) -> str | None:
        if self.name is None:
            return None
        ns = self.namespace if self.namespace.endswith("/") else self.namespace + "/"
        return ns + self.name

    @property
    def null_displacement(self) -> bool | None:
        if self.translation is None or "translation" in self.unresolved:
            return None
        return all(abs(v) <= NULL_TOLERANCE for v in self.translation)

    @property
    def null_rotation(self) -> bool | None:
        if self.rotation is None or "rotation" in self.unresolved:
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
