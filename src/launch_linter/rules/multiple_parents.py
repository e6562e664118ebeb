"""A frame given two different parents in one launch tree.

## What it does
Follows includes and conditions through the whole launch tree and reports a static
transform whose child frame already has a different parent from an earlier static
transform (frame ids compared without one leading `/`). The diagnostic is on the later
transform and points at the earlier ones. When either transform is only launched under a
condition the linter cannot decide, the message says the frame *may* get two parents;
transforms under mutually exclusive conditions are never compared. When every parent places
the frame at the same pose relative to a frame above them (composed through fixed edges of
known values, each frame on the way with one parent; within 1 mm and about 1 mrad), the
finding is info: a redundant publisher, not a misplaced frame (a warning when every parent
is a joint of one description: the frame is right, the description is not a tree). URDF
joints a xacro macro made are shown at the macro's call; when one call made every parent's
joint, every call of the macro has the fault, and the finding is at the `<child>` the
macro writes, with the call and the other parents' `<child>` elements as related places.

## Why is this bad?
tf frames form a tree: each frame has exactly one parent (REP 105). With two static
parents tf2 keeps whichever transform arrived last, so the frame jumps between two places
depending on start-up order, and lookups through the other parent fail (one cache per
child frame: the last static transform received replaces the other, geometry2 noetic-devel
6df9e94 tf2/src/static_cache.cpp 48-52). Where both parents give the same pose, every
lookup gives the same answer whichever is kept. Typical causes: a
driver's launch file publishes `base_link -> laser` while the robot's own launch file
publishes `base_footprint -> laser`, or the two frames of one transform were swapped.

## Example
```xml
<launch>
  <node pkg="tf2_ros" type="static_transform_publisher" name="laser_tf"
        args="0 0 0.2 0 0 0 base_link laser"/>
  <node pkg="tf2_ros" type="static_transform_publisher" name="laser_mount_tf"
        args="0 0 0.3 0 0 0 base_footprint laser"/>
</launch>
```

## Use instead
```xml
<launch>
  <node pkg="tf2_ros" type="static_transform_publisher" name="base_tf"
        args="0 0 0.1 0 0 0 base_footprint base_link"/>
  <node pkg="tf2_ros" type="static_transform_publisher" name="laser_tf"
        args="0 0 0.2 0 0 0 base_link laser"/>
</launch>
```

## Known problems
URDF joints count when a `robot_state_publisher` of the same launch tree publishes the
description (`robot_description` from xacro, a URDF file or literal text); a parent given
by a node that publishes tf at run time (odometry, localization) is not seen. When the
tree's robot_state_publishers run in several namespaces (several robots), two robot
descriptions that give one frame name different parents are left to
`robot_frame_collision` (the robots share frame names; a prefix fixes it, not the URDF).
"""
from __future__ import annotations

import collections
import itertools
import typing
from collections.abc import Iterator

from launch_linter.model.diagnostic import Category, Location, Severity
from launch_linter.model.record import replace
from launch_linter.model.robot import DescriptionSource
from launch_linter.rules._api import (
    MAX_RELATED,
    Finding,
    RuleContext,
    summarised_lazily,
)
from launch_linter.rules._tree import (
    Edge,
    Quaternion,
    coexist,
    edges_of,
    finding_on,
    joints_only,
    place,
    same_rotation,
    written_edges,
)
from launch_linter.rules.camera_frame_not_optical import compose

ID = "multiple_parents"
CATEGORY = Category.TF
SEVERITY = Severity.ERROR

SAME_POSE_LEVEL = Severity.INFO
"""Every parent places the frame at one pose: tf2 keeps one parent per frame (the last
static transform received replaces the other: geometry2 noetic-devel 6df9e94
tf2/src/static_cache.cpp 48-52, one cache per child frame in buffer_core.cpp
``setTransform``), and either gives every lookup the same answer."""

SAME_POSE_JOINTS_LEVEL = Severity.WARNING
"""Every parent is a joint of one description and places the link at one pose: tf is
right, but the description is not the tree URDF requires (a link has one parent joint:
urdfdom's ``initTree`` sets the link's parent once per joint, the last one wins, and
KDL and MoveIt walk one of them), a defect its maintainers fix."""
SAME_DISTANCE = 1e-3
"""Metres."""
SAME_ROTATION = 1e-7
"""On ``1 - |q1.q2|``: about 1 mrad."""
MAX_DEPTH = 64
"""Frames followed up from a parent (a real tree is a few deep)."""
Pose = typing.Tuple[typing.Tuple[float, float, float], Quaternion]


class _Parents:
    """The parents given so far to one frame: for each parent (in order of first mention)
    its edges, the first of each condition only (a later edge under the same condition is
    never the first to coexist with anything), each with its position in the tree."""

    def __init__(self) -> None:
        self.edges: dict[str, list[tuple[int, Edge]]] = {}
        self.conditional_firsts = 0
        """Parents whose first edge has a condition."""

    def add(self, position: int, edge: Edge) -> None:
        known = self.edges.setdefault(edge.parent, [])
        if not known and not edge.condition.always:
            self.conditional_firsts += 1
        if all(other.condition != edge.condition or _robot(other) != _robot(edge)
               for _, other in known):
            known.append((position, edge))

    def rivals(self, edge: Edge, robots_apart: bool
               ) -> tuple[list[tuple[str, Edge]], int, bool]:
        """The first edge of each other parent that can coexist with ``edge`` (only the
        first ``MAX_RELATED`` of them: what a finding shows), in the order in which they
        come, how many there are, and whether any has a condition. With ``robots_apart``
        the joints of another robot description are not rivals (:func:`_other_robot`)."""
        parent = edge.parent
        if edge.condition.always and not robots_apart:
            # Every edge coexists with this one: each other parent's first edge is its
            # rival, in the order the parents came; no need to look at all of them.
            count = len(self.edges) - (parent in self.edges)
            firsts = ((p, known[0][1]) for p, known in self.edges.items() if p != parent)
            mine = self.edges.get(parent)
            own_conditional = mine is not None and not mine[0][1].condition.always
            conditional = self.conditional_firsts > (1 if own_conditional else 0)
            return list(itertools.islice(firsts, MAX_RELATED)), count, conditional
        found: list[tuple[int, str, Edge]] = []
        for other_parent, known in self.edges.items():
            if other_parent == parent:
                continue
            first = next(((i, e) for i, e in known if coexist(e, edge)
                          and not (robots_apart and _other_robot(e, edge))), None)
            if first is not None:
                found.append((first[0], other_parent, first[1]))
        found.sort(key=lambda item: item[0])
        conditional = any(not e.condition.always for _, _, e in found)
        return [(p, e) for _, p, e in found[:MAX_RELATED]], len(found), conditional


def _robot(edge: Edge) -> DescriptionSource | None:
    """The robot description an edge's URDF joint comes from (None: a launch transform)."""
    return None if edge.joint is None else edge.joint.source


def _other_robot(a: Edge, b: Edge) -> bool:
    """Two URDF joints of different robot descriptions."""
    return a.joint is not None and b.joint is not None and a.joint.source != b.joint.source


def _robots_apart(context: RuleContext) -> bool:
    """Whether the tree's robot_state_publishers run in more than one namespace (or in one
    the linter cannot resolve): then each publishes its own namespace's description, and
    a frame that two descriptions give different parents is a frame name two robots share,
    robot_frame_collision's finding (fixed by a prefix, not in either URDF), not a URDF
    frame with two parents."""
    publishers = [n for n in context.tree.nodes if n.package == "robot_state_publisher"]
    namespaces = {n.namespace for n in publishers}
    return len(publishers) > 1 and (len(namespaces) > 1 or None in namespaces)


def check(context: RuleContext) -> Iterator[Finding]:
    # Parents among URDF joints alone are the description's: found once, under the frames
    # as written; those with a launch transform or a node among them, under the prefixes
    # the tree's publishers put on the joints.
    robots_apart = _robots_apart(context)
    yield from _found(written_edges(context), context, robots_apart, joints=True)
    yield from _found(edges_of(context), context, robots_apart, joints=False)


def _found(edges: tuple[Edge, ...], context: RuleContext, robots_apart: bool,
           joints: bool) -> Iterator[Finding]:
    # Only a frame that is the child of two edges may have two parents (most are of one).
    counts = collections.Counter(edge.child for edge in edges)
    above: dict[str, list[Edge]] = {}
    for edge in edges:
        above.setdefault(edge.child, []).append(edge)
    by_child: dict[str, _Parents] = {}
    for position, edge in enumerate(edges):
        parent, child = edge.parent, edge.child
        if parent == child or counts[child] < 2:
            continue
        parents = by_child.setdefault(child, _Parents())
        rivals, count, conditional = parents.rivals(edge, robots_apart)
        parents.add(position, edge)
        if not count or joints != (count == len(rivals)
                                   and joints_only(edge, (t for _, t in rivals))):
            continue
        others = " and ".join(summarised_lazily(
            (f"'{p}' ({_where(t, edge)})" for p, t in rivals), count))
        gets = "may get" if conditional or not edge.condition.always else "gets"
        here = "here" if edge.joint is None else f"here (URDF joint '{edge.joint.name}')"
        keeps = (_kdl_keeps(edge, rivals, context)
                 or "tf2 keeps whichever transform arrives last")
        common = (_same_pose(edge, [t for _, t in rivals], above)
                  if count == len(rivals) else None)
        found = finding_on(
            edge,
            f"frame '{child}' {gets} {count + 1} parents: '{parent}' {here} and "
            f"{others}; a tf frame has exactly one parent, and " + keeps
            + ("" if common is None else
               f"; here every parent places it at the same pose relative to '{common}', "
               f"so each lookup gives the same answer whichever is kept: a redundant "
               f"publisher, not a misplaced frame"),
            tuple(t for _, t in rivals),
        )
        level = SAME_POSE_JOINTS_LEVEL if joints else SAME_POSE_LEVEL
        yield _in_macro(found if common is None else replace(found, severity=level),
                        edge, rivals, count)


def _same_pose(edge: Edge, rivals: list[Edge], above: dict[str, list[Edge]]) -> str | None:
    """The frame relative to which ``edge`` and every rival place their child at one pose
    (within 1 mm and about 1 mrad), through fixed edges of known values each of whose
    frames has one parent; None when they differ or cannot be composed."""
    mine = _up(edge, above)
    for rival in rivals:
        theirs = dict(_up(rival, above))
        common = next((frame for frame, _ in mine if frame in theirs), None)
        if common is None:
            return None
        here = dict(mine)[common]
        there = theirs[common]
        if (max(abs(a - b) for a, b in zip(here[0], there[0])) > SAME_DISTANCE
                or not same_rotation(here[1], there[1], SAME_ROTATION)):
            return None
    return common


def _up(edge: Edge, above: dict[str, list[Edge]]) -> list[tuple[str, Pose]]:
    """The pose of ``edge``'s child in its parent and in each frame above, while the way
    up is one fixed edge of known values per frame (at most ``MAX_DEPTH`` frames)."""
    pose = _pose_of(edge)
    if pose is None:
        return []
    out = [(edge.parent, pose)]
    frame, seen = edge.parent, {edge.child, edge.parent}
    for _ in range(MAX_DEPTH):
        ways = above.get(frame, [])
        if len({w.parent for w in ways}) != 1:
            break
        step = _pose_of(ways[0])
        if step is None or ways[0].parent in seen:
            break
        frame = ways[0].parent
        seen.add(frame)
        pose = (_moved(step, pose[0]), compose(step[1], pose[1]))
        out.append((frame, pose))
    return out


def _pose_of(edge: Edge) -> Pose | None:
    if edge.translation is None or edge.rotation is None or edge.dynamic:
        return None
    return edge.translation, edge.rotation


def _moved(step: Pose, point: tuple[float, float, float]) -> tuple[float, float, float]:
    """``point`` of the child frame of ``step`` in ``step``'s parent frame."""
    (tx, ty, tz), (x, y, z, w) = step
    px, py, pz = point
    # v + 2w(q x v) + 2 q x (q x v), q = (x, y, z)
    cx, cy, cz = y * pz - z * py, z * px - x * pz, x * py - y * px
    dx, dy, dz = y * cz - z * cy, z * cx - x * cz, x * cy - y * cx
    return (tx + px + 2 * (w * cx + dx), ty + py + 2 * (w * cy + dy),
            tz + pz + 2 * (w * cz + dz))


def _in_macro(found: Finding, edge: Edge, rivals: list[tuple[str, Edge]],
              count: int) -> Finding:
    """``found`` moved into the macro when one xacro macro call made every parent's joint:
    then every call of the macro gives the frame two parents, and the macro is what to
    fix; the finding is at the ``<child>`` the macro writes for ``edge``, with the call
    and the other parents' ``<child>`` elements as related places."""
    joint = edge.joint
    if joint is None or joint.child_at is None or count != len(rivals):
        return found
    call = (joint.path, joint.line, joint.column)
    others: list[Location] = []
    for _, rival in rivals:
        other = rival.joint
        if (other is None or other.child_at is None or other.source != joint.source
                or (other.path, other.line, other.column) != call):
            return found
        others.append(Location(*other.child_at))
    path, line, column = joint.child_at
    return replace(found, path=path, line=line, column=column,
                   related=(Location(*call), *others))


def _kdl_keeps(edge: Edge, rivals: list[tuple[str, Edge]], context: RuleContext) -> str | None:
    """What robot_state_publisher publishes when every parent comes from joints of one
    robot description: urdfdom keeps, as the link's parent joint, the joint whose name
    sorts last (its joints are a map by name), and KDL hangs the link under that joint's
    parent only (its other ``addSegment`` fails, unchecked)."""
    joint = edge.joint
    if joint is None or any(r.joint is None or r.joint.source != joint.source
                            for _, r in rivals):
        return None
    kept = max((j for j in context.tree.joints
                if j.source == joint.source and j.child == joint.child and j.parent is not None),
               key=lambda j: j.name, default=None)
    if kept is None:
        return None
    return (f"robot_state_publisher (urdfdom, then KDL) keeps one: '{joint.child}' under "
            f"'{kept.parent}' by joint '{kept.name}', the name that sorts last")


def _where(edge: Edge, seen_from: Edge) -> str:
    if edge.joint is None:
        return place(edge, seen_from)
    return f"URDF joint '{edge.joint.name}', {edge.location.path}:{edge.location.line}"
