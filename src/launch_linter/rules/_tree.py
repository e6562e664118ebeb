"""The whole tf tree of one entry point, as the tree rules see it: launch static transforms
and URDF joints as one list of edges, each with its source."""

from __future__ import annotations

import math
import typing

from launch_linter.model.diagnostic import Diagnostic, Location
from launch_linter.model.launch import LaunchTree
from launch_linter.model.record import Record, _set, replace
from launch_linter.model.robot import RobotJoint
from launch_linter.model.transform import Condition, Field, RotationKind, StaticTransform
from launch_linter.rules._api import Finding, RuleContext
from launch_linter.rules._nodes import nodes_of
from launch_linter.rules._prefixes import description_prefixes, prefixed

Quaternion = typing.Tuple[float, float, float, float]
"""(x, y, z, w)."""


def quaternion_from_ypr(yaw: float, pitch: float, roll: float) -> Quaternion:
    """tf's yaw-pitch-roll (= URDF's fixed-axis roll-pitch-yaw) as a quaternion."""
    cy, sy = math.cos(yaw / 2), math.sin(yaw / 2)
    cp, sp = math.cos(pitch / 2), math.sin(pitch / 2)
    cr, sr = math.cos(roll / 2), math.sin(roll / 2)
    return (
        sr * cp * cy - cr * sp * sy,
        cr * sp * cy + sr * cp * sy,
        cr * cp * sy - sr * sp * cy,
        cr * cp * cy + sr * sp * sy,
    )


def normalised(q: Quaternion) -> Quaternion | None:
    norm = math.sqrt(sum(v * v for v in q))
    if not math.isfinite(norm) or norm < 1e-9:
        return None
    return (q[0] / norm, q[1] / norm, q[2] / norm, q[3] / norm)


def same_rotation(a: Quaternion, b: Quaternion, tolerance: float = 1e-4) -> bool:
    """Equal rotations (q and -q are the same rotation)."""
    dot = abs(a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3])
    return dot >= 1.0 - tolerance


class Edge(Record):
    """One parent -> child edge of the tf tree and where it comes from."""

    parent: str
    child: str
    translation: tuple[float, float, float] | None
    rotation: Quaternion | None
    condition: Condition
    location: Location
    transform: StaticTransform | None
    joint: RobotJoint | None

    __slots__ = (
        "parent", "child", "translation", "rotation", "condition", "location", "transform", "joint",
    )

    def __init__(
        self,
        parent: str,
        child: str,
        translation: tuple[float, float, float] | None,
        rotation: Quaternion | None,
        condition: Condition,
        location: Location,
        transform: StaticTransform | None = None,
        joint: RobotJoint | None = None,
    ) -> None:
        _set(self, "parent", parent)
        _set(self, "child", child)
        _set(self, "translation", translation)
        _set(self, "rotation", rotation)
        _set(self, "condition", condition)
        _set(self, "location", location)
        _set(self, "transform", transform)
        _set(self, "joint", joint)

    @property
    def kind(self) -> str:
        return "urdf" if self.joint is not None else "launch"

    @property
    def dynamic(self) -> bool:
        return self.joint is not None and self.joint.dynamic

    @property
    def node(self) -> str | None:
        return self.transform.name if self.transform is not None else None

    def describe(self) -> str:
        """How a message names this edge's source."""
        if self.joint is not None:
            via = self.joint.source
            return (f"URDF joint '{self.joint.name}' ({self.location.path}:{self.location.line}"
                    f", robot_description at {via.path}:{via.line})")
        name = self.transform.name if self.transform is not None else None
        shown = f"static transform '{name}'" if name else "static transform"
        return f"{shown} ({self.location.path}:{self.location.line})"

    def same_values(self, other: Edge) -> bool | None:
        """Whether the two edges carry the same transform; None when either is unknown."""
        if (self.translation is None or other.translation is None or self.rotation is None
                or other.rotation is None):
            return None
        mine, theirs = self.translation, other.translation
        close = all(abs(mine[i] - theirs[i]) <= 1e-6 for i in range(3))
        return close and same_rotation(self.rotation, other.rotation, 1e-9)


def _transform_edge(t: StaticTransform) -> Edge | None:
    signature = t.signature
    if signature is None:
        return None
    rotation: Quaternion | None = None
    if t.rotation is not None and not t.is_unresolved(Field.ROTATION):
        values = t.rotation.values
        if t.rotation.kind is RotationKind.YPR and len(values) == 3:
            rotation = quaternion_from_ypr(values[0], values[1], values[2])
        elif len(values) == 4:
            rotation = normalised((values[0], values[1], values[2], values[3]))
    translation = None if t.is_unresolved(Field.TRANSLATION) else t.translation
    return Edge(signature[0], signature[1], translation, rotation, t.condition,
                Location(t.path, t.line, t.column), transform=t)


def _joint_edge(j: RobotJoint, prefix: str = "", ros: int | None = None) -> Edge | None:
    if j.parent is None or j.child is None:
        return None
    rotation = None if j.rpy is None else quaternion_from_ypr(j.rpy[2], j.rpy[1], j.rpy[0])
    return Edge(prefixed(prefix, j.parent, ros), prefixed(prefix, j.child, ros),
                j.translation, rotation, j.condition, Location(j.path, j.line, j.column),
                joint=j)


def as_written(edge: Edge) -> Edge:
    """``edge`` with a URDF joint's frames as the description writes them (before the
    prefix its robot_state_publisher puts on them)."""
    joint = edge.joint
    if joint is None or joint.parent is None or joint.child is None:
        return edge
    return replace(edge, parent=joint.parent, child=joint.child)


def with_macro_definitions(tree: LaunchTree, found: list[Diagnostic]) -> list[Diagnostic]:
    """``found``, each diagnostic that points at the xacro macro call that made a joint
    (as its place or a related one) also pointing at the ``<joint>`` in the macro."""
    written = {Location(j.path, j.line, j.column): Location(*j.defined)
               for j in tree.joints if j.defined}
    if not written:
        return found
    out: list[Diagnostic] = []
    for diagnostic in found:
        places = (Location(diagnostic.path, diagnostic.line, diagnostic.column),
                  *diagnostic.related)
        given = set(places)
        # In order, without repeats and without the places already named: linear, since
        # a frame's rivals (multiple_parents' related places) are as many as the input.
        more = list(dict.fromkeys(written[p] for p in places
                                  if p in written and written[p] not in given))
        if more:
            diagnostic = replace(diagnostic, related=(*diagnostic.related, *more))
        out.append(diagnostic)
    return out


def tree_edges(tree: LaunchTree, distro: str | None = None) -> tuple[Edge, ...]:
    """URDF joints first (the robot's own structure), then launch static transforms in
    tree order, so that a finding lands on the launch file that adds to the robot. A
    joint's frames carry its robot_state_publisher's prefix (one edge per publisher of
    its description); a joint whose prefix is unknown is no edge (its frames are not
    known)."""
    edges: list[Edge] = []
    prefixes = description_prefixes(tree, distro)
    ros = next((n.ros for n in tree.nodes if n.ros is not None), None)
    for joint in tree.joints:
        for prefix in prefixes.get(id(joint.source), ("",)):
            edge = None if prefix is None else _joint_edge(joint, prefix, ros)
            if edge is not None:
                edges.append(edge)
    for transform in tree.transforms:
        edge = _transform_edge(transform)
        if edge is not None:
            edges.append(edge)
    return tuple(edges)


def _published_edges(context: RuleContext) -> tuple[Edge, ...]:
    edges = tree_edges(context.tree, context.distro)
    if nodes_of(context).joint_states:
        return edges
    # robot_state_publisher sends a movable joint only from /joint_states: with no known
    # publisher of them, the joint's edge is not in the tree.
    return tuple(edge for edge in edges if not edge.dynamic)


def edges_of(context: RuleContext) -> tuple[Edge, ...]:
    """The tree's edges (static transforms and the URDF joints robot_state_publisher
    sends), built once for all the tree rules run on one tree."""
    return context.derived(_published_edges)


def _written(context: RuleContext) -> tuple[Edge, ...]:
    seen: set[int] = set()
    out: list[Edge] = []
    for edge in edges_of(context):
        if edge.joint is not None:
            if id(edge.joint) in seen:
                continue
            seen.add(id(edge.joint))
            edge = as_written(edge)
        out.append(edge)
    return tuple(out)


def written_edges(context: RuleContext) -> tuple[Edge, ...]:
    """The tree's edges with each URDF joint once, under its frames as the description
    writes them: for the rules that judge a joint by its own values, or joints against
    each other (one defect of the description, however many publishers prefix it, and
    the same finding as on the description linted alone)."""
    return context.derived(_written)


def joints_only(edge: Edge, others: typing.Iterable[Edge]) -> bool:
    """Whether a finding on ``edge`` against ``others`` is among URDF joints alone (found
    on :func:`written_edges`, not again under each publisher's prefix)."""
    return edge.joint is not None and all(other.joint is not None for other in others)


def coexist(a: Edge, b: Edge) -> bool:
    return not a.condition.excludes(b.condition)


def place(edge: Edge, seen_from: Edge) -> str:
    if edge.location.path == seen_from.location.path:
        return f"line {edge.location.line}"
    return f"{edge.location.path}:{edge.location.line}"


def finding_on(edge: Edge, message: str, related: tuple[Edge, ...] = ()) -> Finding:
    """A finding at an edge (a launch node or a URDF joint)."""
    return Finding(
        path=edge.location.path, line=edge.location.line, column=edge.location.column,
        message=message, node=edge.node if edge.joint is None else edge.joint.name,
        related=tuple(r.location for r in related),
    )
