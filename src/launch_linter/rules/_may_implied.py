"""What the six ``may_implied`` rules share: looking up mined beliefs and citing them.

Implications are checked per file (transforms grouped by the file that declares them);
the null rules per transform. A value the linter could not resolve never counts: a file
with an unresolved signature (name) is not judged for a missing one, since the unresolved
transform may be the one that the belief asks for.
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import Callable, Optional, Tuple, Union

from launch_linter.model.diagnostic import Belief, Severity
from launch_linter.model.transform import Field, RotationKind, StaticTransform
from launch_linter.rules._api import Finding, RuleContext, finding_at, transforms_by_file

Key = Union[Tuple[str, ...], str]
KeyOf = Callable[[StaticTransform], Optional[Key]]


def signature_of(transform: StaticTransform) -> Key | None:
    return transform.signature


def signature_unresolved(transform: StaticTransform) -> bool:
    return transform.is_unresolved(Field.PARENT, Field.CHILD)


def name_of(transform: StaticTransform) -> Key | None:
    if transform.name and transform.knows(Field.NAME):
        return transform.name
    return None


def name_unresolved(transform: StaticTransform) -> bool:
    return transform.is_unresolved(Field.NAME)


def describe(key: Key | None) -> str:
    """``(parent → child)`` for a signature, ``'name'`` for a node name."""
    if isinstance(key, tuple):
        return f"({' → '.join(key)})"
    return repr(key)


def evidence(belief: Belief) -> str:
    """The belief's support; beliefs published without counts give only their z bound."""
    if belief.n == 0:
        return f"z ≥ {belief.z:g}, counts not published"
    return f"n={belief.n}, e={belief.e}, z={belief.z:.2f}"


STRONG_Z = 2.0
"""Below this z a belief is a hint: its findings are info (the study's profile: warning)."""


def level(context: RuleContext, belief: Belief) -> Severity | None:
    """Info for a weak belief; None (the rule's warning) otherwise."""
    return None if context.study or belief.z >= STRONG_Z else Severity.INFO


def implications(
    context: RuleContext,
    rule_id: str,
    key_of: KeyOf,
    unresolved: Callable[[StaticTransform], bool],
    what: str,
) -> Iterator[Finding]:
    """One diagnostic per file and violated belief ``A ⇒ B``: the file has A but not B,
    reported at the first transform with A."""
    index = context.beliefs.by_antecedent(rule_id)
    if not index:
        return
    for transforms in context.shared(transforms_by_file).values():
        if any(unresolved(t) for t in transforms):
            continue
        first: dict[Key, StaticTransform] = {}
        for transform in transforms:
            key = key_of(transform)
            if key is not None:
                first.setdefault(key, transform)
        for key, transform in first.items():
            for belief in index.get(key, ()):
                if belief.consequent not in first:
                    yield finding_at(
                        transform,
                        f"file has {what} {describe(key)} but not "
                        f"{describe(belief.consequent)}, which usually comes with it "
                        f"({evidence(belief)})",
                        belief=belief,
                        severity=level(context, belief),
                    )


def _numbers(values: tuple[float, ...]) -> str:
    return "(" + ", ".join(f"{v:g}" for v in values) + ")"


def _non_null(
    context: RuleContext,
    rule_id: str,
    key_of: KeyOf,
    what: str,
    quantity: str,
    values_of: Callable[[StaticTransform], str | None],
) -> Iterator[Finding]:
    """Transforms whose key usually has a zero ``quantity`` but whose own is not zero;
    ``values_of`` gives the written values, or None when they are unknown or zero."""
    index = context.beliefs.by_antecedent(rule_id)
    if not index:
        return
    for transform in context.tree.transforms:
        # The values are formatted only for a key that has beliefs (few have).
        key = key_of(transform)
        beliefs = index.get(key, ()) if key is not None else ()
        values = values_of(transform) if beliefs else None
        if values is None:
            continue
        if not context.study and quantity == "rotation" and _rotation_owned(transform):
            continue
        for belief in beliefs:
            yield finding_at(
                transform,
                f"{what} {describe(key)} usually has zero {quantity}, this one has "
                f"{values} ({evidence(belief)})",
                belief=belief,
                severity=level(context, belief),
            )


def _rotation_owned(transform: StaticTransform) -> bool:
    """True when another rule already reports this rotation's root cause: a quaternion tf2
    rejects (bad_quaternion) or an angle written in degrees (rot_degrees)."""
    from launch_linter.rules.bad_quaternion import TF2_TOLERANCE
    from launch_linter.rules.rot_degrees import looks_like_degrees

    rotation = transform.rotation
    if rotation is None:
        return False
    if rotation.kind is RotationKind.QUATERNION:
        return abs(sum(v * v for v in rotation.values) - 1.0) >= TF2_TOLERANCE
    return any(looks_like_degrees(v) for v in rotation.values)


def _displacement(transform: StaticTransform) -> str | None:
    if transform.translation is None or transform.null_displacement is not False:
        return None
    return _numbers(transform.translation)


def _rotation(transform: StaticTransform) -> str | None:
    if transform.rotation is None or transform.null_rotation is not False:
        return None
    return f"{transform.rotation.kind.value} {_numbers(transform.rotation.values)}"


def null_displacements(
    context: RuleContext, rule_id: str, key_of: KeyOf, what: str
) -> Iterator[Finding]:
    """A transform whose key usually has zero displacement, with a non-zero one."""
    return _non_null(context, rule_id, key_of, what, "displacement", _displacement)


def null_rotations(
    context: RuleContext, rule_id: str, key_of: KeyOf, what: str
) -> Iterator[Finding]:
    """A transform whose key usually has zero rotation, with a non-zero one."""
    return _non_null(context, rule_id, key_of, what, "rotation", _rotation)
