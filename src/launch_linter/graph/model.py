"""The transform tree as a graph: frames are vertices, static transforms and the URDF joints
that a tree's robot_state_publisher publishes are edges.

A transform defines its child frame (each frame has one parent in tf), so a diagnostic at
a transform marks its edge and its child frame. Only errors and warnings mark; ``info``
diagnostics (what could not be resolved) show as ``?`` in the labels instead.

Linting a folder gives several launch trees. Entry points (root files that no other root
includes) with the same edges (:mod:`launch_linter.report.published`: the same elements
with the same values) describe one robot: it is drawn once, as one cluster titled with
those entry points. Separate robots or configurations are separate clusters, with their
own frames (``base_link`` of two robots is not one frame). Entry points that publish no
edge are not drawn: a note says why (the description that was not read, the first value
that could not be resolved). A picture of more than :data:`MAX_DRAWN_EDGES` edges would be
unreadable and slow to lay out: the first edges from the roots are drawn, and a note says
how many are left out.
"""

from __future__ import annotations

import collections
import os
from collections.abc import Iterable
from dataclasses import dataclass

from launch_linter.engine import LintResult
from launch_linter.knowledge import KnowledgeBase, bundled
from launch_linter.model.diagnostic import Diagnostic, Severity
from launch_linter.model.included import cause
from launch_linter.model.launch import LaunchTree
from launch_linter.model.robot import RobotJoint
from launch_linter.model.transform import Field, RotationKind, StaticTransform
from launch_linter.report.published import (
    TfEdge,
    edge_identity,
    entry_points,
    named,
    tree_edges,
)
from launch_linter.rules._nodes import NodeEdge, view_of

MAX_NOTES = 12
MAX_TITLE_NAMES = 8
"""Entry points named in a cluster's title (then "... and N more")."""
MAX_LINE_NAMES = 3
"""Entry points named on one line of the caption."""
MAX_REASON = 320
"""Characters of a reason why an entry point publishes nothing (at most four lines)."""
MAX_REASONS = 6
"""Distinct reasons listed in the caption (then "... and N more reasons")."""
MAX_DRAWN_EDGES = 300
"""Edges given to Graphviz: more is no longer readable at screen size, and its layout of
labelled edges grows faster than linearly (a 30,000-joint chain took 111 s)."""


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
    """One title per distinct tree when there is more than one (``cluster`` indexes it)."""
    left_out: int = 0
    """Edges not drawn: the picture would be too large (see :data:`MAX_DRAWN_EDGES`)."""

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


def _joint_label(joint: RobotJoint, rules: list[str]) -> tuple[str, ...]:
    """The joint, its type and origin (a zero rotation left out: most joints have one),
    and its place; the blue colour says it is a URDF joint."""
    lines = [f"{joint.name} ({joint.joint_type})"]
    lines.append("xyz ?" if joint.translation is None else f"xyz {_numbers(joint.translation)}")
    if joint.rpy is None:
        lines.append("rpy ?")
    elif any(joint.rpy):
        lines.append(f"rpy {_numbers(joint.rpy)}")
    if not joint.condition.always:
        lines.append(joint.condition.describe())
    lines.append(f"{os.path.basename(joint.path)}:{joint.line}")
    if rules:
        lines.append("! " + ", ".join(rules))
    return tuple(lines)


def _diagnostics_at(result: LintResult) -> dict[tuple[str, int, int], list[Diagnostic]]:
    at: dict[tuple[str, int, int], list[Diagnostic]] = {}
    for diagnostic in result.diagnostics:
        at.setdefault((diagnostic.path, diagnostic.line, diagnostic.column), []).append(diagnostic)
    return at


class _Builder:
    """Frames and edges of the picture, cluster by cluster."""

    def __init__(self, at: dict[tuple[str, int, int], list[Diagnostic]]) -> None:
        self.at = at
        self.frames: dict[str, Frame] = {}
        self.edges: list[Edge] = []
        self.placed: set[tuple[str, int, int]] = set()
        self.unnamed: dict[int, int] = {}

    def _found(self, path: str, line: int, column: int) -> tuple[list[Diagnostic], list[str]]:
        where = (path, line, column)
        self.placed.add(where)
        found = self.at.get(where, [])
        serious = [d for d in found if d.severity is not Severity.INFO]
        return found, sorted({d.rule for d in serious})

    def _mark(self, key: str) -> None:
        frame = self.frames[key]
        self.frames[key] = Frame(frame.key, frame.label, frame.resolved, True, frame.cluster)

    def add(self, cluster: int, edge: TfEdge) -> None:
        if isinstance(edge, RobotJoint):
            self.add_joint(cluster, edge)
        else:
            self.add_transform(cluster, edge)

    def add_transform(self, cluster: int, transform: StaticTransform) -> None:
        if transform.name is None:
            self.unnamed[cluster] = self.unnamed.get(cluster, 0) + 1
        found, rules = self._found(transform.path, transform.line, transform.column)
        index = len(self.edges)
        parent = _frame_key(transform, "parent", index, cluster)
        child = _frame_key(transform, "child", index, cluster)
        for key, label, resolved in (parent, child):
            self.frames.setdefault(key, Frame(key, label, resolved, False, cluster))
        if rules:
            self._mark(child[0])
        self.edges.append(Edge(
            parent=parent[0], child=child[0],
            label=_edge_label(transform, rules, self.unnamed.get(cluster, 0)),
            conditional=not transform.condition.always, flagged=bool(rules),
            tooltip=_tooltip(found), cluster=cluster,
        ))

    def add_node_edge(self, edge: NodeEdge) -> None:
        """An edge a launched node publishes at run time: dashed, labelled by the node."""
        node = edge.node
        for frame in (edge.parent, edge.child):
            self.frames.setdefault(frame, Frame(frame, frame, True, False, 0))
        program = node.plugin or f"{node.package}/{node.executable}"
        self.edges.append(Edge(
            parent=edge.parent, child=edge.child,
            label=(f"node {program}", edge.role, f"{os.path.basename(node.path)}:{node.line}"),
            conditional=not node.condition.always, flagged=False,
            tooltip=f"published at run time by {program} ({node.path}:{node.line})",
            source="node", dynamic=True,
        ))

    def add_joint(self, cluster: int, joint: RobotJoint) -> None:
        found, rules = self._found(joint.path, joint.line, joint.column)
        prefix = f"{cluster}|" if cluster else ""
        ends = []
        for which, frame in (("parent", joint.parent), ("child", joint.child)):
            key = prefix + (frame if frame is not None else f"?urdf{len(self.edges)}:{which}")
            self.frames.setdefault(key, Frame(key, frame or "?", frame is not None, False,
                                              cluster))
            ends.append(key)
        if rules:
            self._mark(ends[1])
        self.edges.append(Edge(
            parent=ends[0], child=ends[1], label=_joint_label(joint, rules),
            conditional=not joint.condition.always, flagged=bool(rules),
            tooltip=_tooltip(found), cluster=cluster, source="urdf", dynamic=joint.dynamic,
        ))


def _tooltip(found: list[Diagnostic]) -> str:
    return "\n".join(f"{d.severity.value}: {d.message} [{d.rule}]" for d in found)


def why_nothing(tree: LaunchTree, result: LintResult) -> str:
    """Why ``tree`` publishes no edge: the descriptions that were not read (and why), or
    the first value that could not be resolved in its files."""
    reasons: list[str] = []
    for source in tree.descriptions:
        where = f"robot_description at {source.path}:{source.line}"
        if source.file is None:
            reasons.append(f"{where} not read: {source.reason or 'its file is not known'}")
            continue
        failed = [_description_cause(d) for d in result.diagnostics if d.rule == "unresolved"
                  and (d.path, d.line) == (source.path, source.line)]
        reasons.append(f"{where} gave no joint" + (f": {failed[0]}" if failed else
                                                   " (no robot_state_publisher publishes it)"))
    if reasons:
        # The first in full (a cause cut short says nothing), the others counted.
        return reasons[0] + (f"; and {len(reasons) - 1} more" if len(reasons) > 1 else "")
    files = set(tree.files)
    unresolved = [d for d in result.diagnostics if d.rule == "unresolved" and d.path in files]
    tail = (f"; {len(unresolved)} value(s) unresolved, first {unresolved[0].path}:"
            f"{unresolved[0].line}: {unresolved[0].message}" if unresolved else "")
    return "no static_transform_publisher and no robot_description" + tail


_DESCRIPTION_PREFIX = "robot description "
_NOT_READ_SUFFIX = "; its joints are not read"


def _description_cause(diagnostic: Diagnostic) -> str:
    """A description's unresolved message as a reason: the place and the cause, without
    the words the reason already says (which description, that joints are not read, the
    include the caption's entry points name)."""
    text = cause(diagnostic.message, diagnostic.related)
    if text.startswith(_DESCRIPTION_PREFIX):
        text = text[len(_DESCRIPTION_PREFIX):]
    if text.endswith(_NOT_READ_SUFFIX):
        text = text[: -len(_NOT_READ_SUFFIX)]
    return text


def _why_nothing_notes(trees: list[LaunchTree], result: LintResult) -> list[str]:
    """One line per reason, naming the entry points it holds for (a few of them)."""
    by_reason: dict[str, list[str]] = {}
    for tree in trees:
        by_reason.setdefault(_shortened(why_nothing(tree, result)), []).append(tree.root)
    lines = [f"  {named(roots, MAX_LINE_NAMES)}: {reason}"
             for reason, roots in list(by_reason.items())[:MAX_REASONS]]
    if len(by_reason) > MAX_REASONS:
        lines.append(f"  ... and {len(by_reason) - MAX_REASONS} more reasons")
    return lines


def _shortened(text: str) -> str:
    return text if len(text) <= MAX_REASON else text[: MAX_REASON - 1] + "…"


def _groups(result: LintResult) -> tuple[list[tuple[list[str], list[TfEdge]]], list[int]]:
    """The entry points with the same edges grouped (first met first), each group with its
    edges; and the indices of the entry points with no edge."""
    groups: dict[frozenset[object], tuple[list[str], list[TfEdge]]] = {}
    empty: list[int] = []
    for index in entry_points(result):
        tree = result.trees[index]
        edges = tree_edges(tree)
        if not edges:
            empty.append(index)
            continue
        signature = frozenset(edge_identity(e) for e in edges)
        groups.setdefault(signature, ([], edges))[0].append(tree.root)
    return list(groups.values()), empty


def _capped(edges: list[Edge]) -> list[Edge]:
    """At most :data:`MAX_DRAWN_EDGES` edges: breadth-first from the frames that are no
    edge's child, so that the picture shows the top of each tree."""
    if len(edges) <= MAX_DRAWN_EDGES:
        return edges
    children: dict[str, list[int]] = {}
    for index, edge in enumerate(edges):
        children.setdefault(edge.parent, []).append(index)
    is_child = {edge.child for edge in edges}
    queue = collections.deque(i for i, e in enumerate(edges) if e.parent not in is_child)
    chosen: list[int] = []
    taken: set[int] = set()
    while queue and len(chosen) < MAX_DRAWN_EDGES:
        index = queue.popleft()
        if index in taken:
            continue
        taken.add(index)
        chosen.append(index)
        queue.extend(children.get(edges[index].child, ()))
    for index in range(len(edges)):  # cycles: no root reaches them
        if len(chosen) >= MAX_DRAWN_EDGES:
            break
        if index not in taken:
            chosen.append(index)
    return [edges[i] for i in sorted(chosen)]


def build_graph(result: LintResult, knowledge: KnowledgeBase | None = None) -> TfGraph:
    """The graph of every transform in ``result``, marked with its diagnostics."""
    builder = _Builder(_diagnostics_at(result))
    notes: list[str] = []
    clusters: tuple[str, ...] = ()
    several = len(result.trees) > 1
    if several:
        groups, empty = _groups(result)
        titles = []
        for cluster, (roots, tf_edges) in enumerate(groups):
            for tf_edge in tf_edges:
                builder.add(cluster if len(groups) > 1 else 0, tf_edge)
            titles.append(_cluster_title(roots, tf_edges))
        clusters = tuple(titles) if len(groups) > 1 else ()
        if len(groups) == 1 and len(groups[0][0]) > 1:
            notes.append(titles[0])
        if empty:
            notes.append(f"{len(empty)} entry point(s) publish no transform:")
            notes.extend(_why_nothing_notes([result.trees[i] for i in empty], result))
    else:
        base = knowledge if knowledge is not None else bundled()
        for tree in result.trees:
            for tf_edge in tree_edges(tree):
                builder.add(0, tf_edge)
            # One tree: the edges its nodes publish too (several trees: left out for now).
            for node_edge in view_of(tree, base).edges if tree.nodes else ():
                builder.add_node_edge(node_edge)
        if not builder.edges:
            notes.extend(f"{tree.root}: {why_nothing(tree, result)}" for tree in result.trees)
    edges = _capped(builder.edges)
    if len(edges) < len(builder.edges):
        notes.append(
            f"too large for a readable picture: {len(edges)} of {len(builder.edges)} edges "
            f"drawn (breadth-first from the roots); `launch-linter transforms` lists them all"
        )
    drawn = {key for edge in edges for key in (edge.parent, edge.child)}
    frames = [frame for key, frame in builder.frames.items() if key in drawn]
    unplaced = [
        d for d in result.diagnostics
        if (d.path, d.line, d.column) not in builder.placed and d.severity is not Severity.INFO
    ]
    notes.extend(f"{d.path}:{d.line}: {d.severity.value}: {d.message} [{d.rule}]"
                 for d in unplaced[:MAX_NOTES])
    if len(unplaced) > MAX_NOTES:
        notes.append(f"... and {len(unplaced) - MAX_NOTES} more")
    return TfGraph(_title(result, builder.edges, len(builder.frames)), tuple(frames),
                   tuple(edges), tuple(notes), clusters, len(builder.edges) - len(edges))


def _cluster_title(roots: list[str], edges: list[TfEdge]) -> str:
    joints = sum(1 for e in edges if isinstance(e, RobotJoint))
    counts = f"{len(edges) - joints} static transform(s), {joints} URDF joint(s)"
    if len(roots) == 1:
        return f"{roots[0]}: {counts}"
    return f"{len(roots)} entry points with this tree ({counts}):\n" + "\n".join(
        roots[:MAX_TITLE_NAMES]) + (f"\n... and {len(roots) - MAX_TITLE_NAMES} more"
                                    if len(roots) > MAX_TITLE_NAMES else "")


def _title(result: LintResult, edges: list[Edge], frames: int) -> str:
    roots = ", ".join(f.path for f in result.files)
    if len(result.files) > 3:
        roots = f"{len(result.files)} file(s), {len(entry_points(result))} entry point(s)"
    errors = sum(1 for d in result.diagnostics if d.severity is Severity.ERROR)
    warnings = sum(1 for d in result.diagnostics if d.severity is Severity.WARNING)
    urdf = sum(1 for e in edges if e.source == "urdf")
    by_nodes = sum(1 for e in edges if e.source == "node")
    return (
        f"{roots}: {len(edges) - urdf - by_nodes} static transform(s), {urdf} URDF joint(s), "
        + (f"{by_nodes} node-published edge(s), " if by_nodes else "")
        + f"{frames} frame(s), {errors} error(s), {warnings} warning(s)"
    )
