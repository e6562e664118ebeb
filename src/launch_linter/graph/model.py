"""The transform tree as a graph: frames are vertices, static transforms and the URDF joints
that a tree's robot_state_publisher publishes are edges.

A transform defines its child frame (each frame has one parent in tf), so a diagnostic at
a transform marks its edge and its child frame. Only errors and warnings mark; ``info``
diagnostics (what could not be resolved) show as ``?`` in the labels instead.

Linting a folder gives several launch trees. Each entry point (a root file that no other
root includes) becomes one cluster with its own frames: separate launch files usually
describe separate robots or configurations, where ``base_link`` is not one frame. A file
that is also included by another root is drawn inside that root's cluster only.
"""

from __future__ import annotations

import os
from collections.abc import Iterable
from dataclasses import dataclass

from launch_linter.engine import LintResult
from launch_linter.knowledge import KnowledgeBase, bundled
from launch_linter.model.diagnostic import Diagnostic, Severity
from launch_linter.model.robot import RobotJoint
from launch_linter.model.transform import Field, RotationKind, StaticTransform
from launch_linter.rules._nodes import view_of

MAX_NOTES = 12


@dataclass(frozen=True)
class Frame:
    key: str
    label: str
    resolved: bool
    flagged: bool
    cluster: int = 0


@dataclass(frozen=True)
class Edge:
    parent: str
    child: str
    label: tuple[str, ...]
    """Lines: node name, translation, rotation, condition, place, flagged rules."""
    conditional: bool
    flagged: bool
    tooltip: str
    cluster: int = 0
    source: str = "launch"
    """``launch`` (a static transform), ``urdf`` (a joint of a robot description) or
    ``node`` (published at run time by a launched node, by the knowledge base)."""
    dynamic: bool = False
    """A movable URDF joint (revolute, continuous, prismatic, floating, planar)."""


@dataclass(frozen=True)
class TfGraph:
    title: str
    frames: tuple[Frame, ...]
    edges: tuple[Edge, ...]
    notes: tuple[str, ...]
    """Diagnostics that are not at a transform (parse errors, roslaunch errors)."""
    clusters: tuple[str, ...] = ()
    """One title per entry point when there is more than one (``cluster`` indexes it)."""

    @property
    def legend(self) -> tuple[str, ...]:
        """The legend lines this picture needs: none for what it does not show."""
        lines = []
        if any(e.flagged for e in self.edges) or any(f.flagged for f in self.frames):
            lines.append("red: errors or warnings at the transform")
        if any(e.conditional for e in self.edges):
            lines.append("dashed: present only under a condition")
        if any(e.source == "urdf" for e in self.edges):
            lines.append("blue: a URDF joint (robot_state_publisher)")
        if any(e.dynamic for e in self.edges):
            lines.append("dashed blue: a movable URDF joint")
        if any(not f.resolved for f in self.frames):
            lines.append("dotted: a frame the linter could not resolve")
        return tuple(lines)


def _numbers(values: Iterable[float]) -> str:
    return " ".join(f"{v:g}" for v in values)


def _frame_key(
    transform: StaticTransform, which: str, index: int, cluster: int = 0
) -> tuple[str, str, bool]:
    """(key, label, resolved) of the parent or child frame of ``transform``."""
    normalised = transform.parent if which == "parent" else transform.child
    written = transform.parent_written if which == "parent" else transform.child_written
    prefix = f"{cluster}|" if cluster else ""
    if normalised is not None and transform.knows(Field(which)):
        return prefix + normalised, normalised, True
    # Unresolved frames are distinct vertices: two unknowns need not be the same frame.
    return f"{prefix}?{index}:{which}", written or "?", False


def _edge_label(
    transform: StaticTransform, rules: list[str], unnamed: int = 0
) -> tuple[str, ...]:
    # An unnamed node (ROS 2 allows it) is named by its executable and its position
    # among the unnamed nodes of its tree.
    name = transform.qualified_name or f"{transform.executable or 'node'} #{unnamed}"
    lines = [name]
    if transform.translation is None or transform.is_unresolved(Field.TRANSLATION):
        lines.append("xyz ?")
    else:
        lines.append(f"xyz {_numbers(transform.translation)}")
    rotation = transform.rotation
    if rotation is None or transform.is_unresolved(Field.ROTATION):
        lines.append("rotation ?")
    elif rotation.kind is RotationKind.YPR:
        lines.append(f"ypr {_numbers(rotation.values)}")
    else:
        lines.append(f"q {_numbers(rotation.values)}")
    if not transform.condition.always:
        lines.append(transform.condition.describe())
    lines.append(f"{os.path.basename(transform.path)}:{transform.line}")
    if rules:
        lines.append("! " + ", ".join(rules))
    return tuple(lines)


def entry_points(result: LintResult) -> list[int]:
    """Indices of the trees whose root no other tree includes."""
    included: set[str] = set()
    for tree in result.trees:
        included.update(f for f in tree.files if f != tree.root)
    return [i for i, tree in enumerate(result.trees) if tree.root not in included]


def _placed_transforms(result: LintResult) -> list[tuple[int, StaticTransform]]:
    """(cluster, transform) for each transform to draw; one cluster when one tree."""
    trees = result.trees
    if len(trees) <= 1:
        return [(0, t) for t in result.transforms]
    return [
        (cluster, transform)
        for cluster, index in enumerate(entry_points(result))
        for transform in trees[index].transforms
    ]


def _placed_joints(result: LintResult) -> list[tuple[int, RobotJoint]]:
    """(cluster, joint) for each URDF joint to draw, clustered like the transforms."""
    trees = result.trees
    if len(trees) <= 1:
        return [(0, j) for tree in trees for j in tree.joints]
    return [
        (cluster, joint)
        for cluster, index in enumerate(entry_points(result))
        for joint in trees[index].joints
    ]


def _joint_label(joint: RobotJoint, rules: list[str]) -> tuple[str, ...]:
    lines = [f"URDF {joint.joint_type} joint {joint.name}"]
    lines.append("xyz ?" if joint.translation is None else f"xyz {_numbers(joint.translation)}")
    lines.append("rpy ?" if joint.rpy is None else f"rpy {_numbers(joint.rpy)}")
    if not joint.condition.always:
        lines.append(joint.condition.describe())
    lines.append(f"{os.path.basename(joint.path)}:{joint.line}")
    if rules:
        lines.append("! " + ", ".join(rules))
    return tuple(lines)


def _node_edges(result: LintResult, frames: dict[str, Frame],
                knowledge: KnowledgeBase | None) -> list[Edge]:
    """The edges launched nodes publish at run time (dashed, labelled by the node)."""
    out: list[Edge] = []
    trees = result.trees
    placed = [(0, trees[0])] if len(trees) == 1 else [
        (cluster, trees[index]) for cluster, index in enumerate(entry_points(result))]
    base = knowledge if knowledge is not None else bundled()
    for cluster, tree in placed:
        if not tree.nodes:
            continue
        prefix = f"{cluster}|" if cluster else ""
        for edge in view_of(tree, base).edges:
            node = edge.node
            ends = []
            for frame in (edge.parent, edge.child):
                frames.setdefault(prefix + frame, Frame(prefix + frame, frame, True, False,
                                                        cluster))
                ends.append(prefix + frame)
            program = node.plugin or f"{node.package}/{node.executable}"
            out.append(Edge(
                parent=ends[0], child=ends[1],
                label=(f"node {program}", edge.role,
                       f"{os.path.basename(node.path)}:{node.line}"),
                conditional=not node.condition.always, flagged=False,
                tooltip=f"published at run time by {program} ({node.path}:{node.line})",
                cluster=cluster, source="node", dynamic=True,
            ))
    return out


def build_graph(result: LintResult, knowledge: KnowledgeBase | None = None) -> TfGraph:
    """The graph of every transform in ``result``, marked with its diagnostics."""
    at: dict[tuple[str, int, int], list[Diagnostic]] = {}
    for diagnostic in result.diagnostics:
        at.setdefault((diagnostic.path, diagnostic.line, diagnostic.column), []).append(diagnostic)
    frames: dict[str, Frame] = {}
    edges: list[Edge] = []
    placed: set[tuple[str, int, int]] = set()
    seen: set[tuple[object, ...]] = set()
    unnamed: dict[int, int] = {}
    for index, (cluster, transform) in enumerate(_placed_transforms(result)):
        identity = (cluster, transform.path, transform.line, transform.column, transform.args,
                    transform.condition)
        if identity in seen:
            continue  # one element reached twice with the same values draws one edge
        seen.add(identity)
        if transform.name is None:
            unnamed[cluster] = unnamed.get(cluster, 0) + 1
        where = (transform.path, transform.line, transform.column)
        placed.add(where)
        found = at.get(where, [])
        serious = [d for d in found if d.severity is not Severity.INFO]
        rules = sorted({d.rule for d in serious})
        parent = _frame_key(transform, "parent", index, cluster)
        child = _frame_key(transform, "child", index, cluster)
        for key, label, resolved in (parent, child):
            frames.setdefault(key, Frame(key, label, resolved, False, cluster))
        if serious:
            frames[child[0]] = Frame(child[0], child[1], child[2], True, cluster)
        edges.append(
            Edge(
                parent=parent[0],
                child=child[0],
                label=_edge_label(transform, rules, unnamed.get(cluster, 0)),
                conditional=not transform.condition.always,
                flagged=bool(serious),
                tooltip="\n".join(f"{d.severity.value}: {d.message} [{d.rule}]" for d in found),
                cluster=cluster,
            )
        )
    for cluster, joint in _placed_joints(result):
        drawn = (cluster, joint.path, joint.line, joint.column, joint.parent, joint.child,
                 joint.translation, joint.rpy, joint.condition)
        if drawn in seen:
            continue
        seen.add(drawn)
        where = (joint.path, joint.line, joint.column)
        placed.add(where)
        found = at.get(where, [])
        serious = [d for d in found if d.severity is not Severity.INFO]
        rules = sorted({d.rule for d in serious})
        prefix = f"{cluster}|" if cluster else ""
        ends = []
        for which, frame in (("parent", joint.parent), ("child", joint.child)):
            key = prefix + (frame if frame is not None else f"?urdf{len(edges)}:{which}")
            frames.setdefault(key, Frame(key, frame or "?", frame is not None, False, cluster))
            ends.append(key)
        if serious:
            frames[ends[1]] = Frame(ends[1], frames[ends[1]].label, frames[ends[1]].resolved,
                                    True, cluster)
        edges.append(Edge(
            parent=ends[0], child=ends[1], label=_joint_label(joint, rules),
            conditional=not joint.condition.always, flagged=bool(serious),
            tooltip="\n".join(f"{d.severity.value}: {d.message} [{d.rule}]" for d in found),
            cluster=cluster, source="urdf", dynamic=joint.dynamic,
        ))
    edges.extend(_node_edges(result, frames, knowledge))
    unplaced = [
        d for d in result.diagnostics
        if (d.path, d.line, d.column) not in placed and d.severity is not Severity.INFO
    ]
    notes = [f"{d.path}:{d.line}: {d.severity.value}: {d.message} [{d.rule}]"
             for d in unplaced[:MAX_NOTES]]
    if len(unplaced) > MAX_NOTES:
        notes.append(f"... and {len(unplaced) - MAX_NOTES} more")
    clusters: tuple[str, ...] = ()
    if len(result.trees) > 1:
        clusters = tuple(result.trees[i].root for i in entry_points(result))
    roots = ", ".join(f.path for f in result.files)
    if len(result.files) > 3:
        roots = f"{len(result.files)} launch files, {len(clusters)} entry point(s)"
    errors = sum(1 for d in result.diagnostics if d.severity is Severity.ERROR)
    warnings = sum(1 for d in result.diagnostics if d.severity is Severity.WARNING)
    urdf = sum(1 for e in edges if e.source == "urdf")
    static = sum(1 for e in edges if e.source == "launch")
    by_nodes = len(edges) - urdf - static
    title = (
        f"{roots}: {static} static transform(s), {urdf} URDF joint(s), "
        + (f"{by_nodes} node-published edge(s), " if by_nodes else "") +
        f"{len(frames)} frame(s), "
        f"{errors} error(s), {warnings} warning(s)"
    )
    return TfGraph(title, tuple(frames.values()), tuple(edges), tuple(notes), clusters)
