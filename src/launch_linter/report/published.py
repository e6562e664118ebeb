"""Each tf edge once, with the entry points that publish it.

Linting a folder gives one launch tree per root file, and a file several entry points
include (a robot's description launch file, say) gives the same edges to each of them.
``transforms`` lists such an edge once and ``graph`` draws entry points with the same edges
once; both group by :func:`edge_identity`: the element (file, line, column) and every value
read from it, so that one element included with different arguments stays two edges.

An entry point is a root file that no other root includes (:func:`entry_points`). An edge
found only in the tree of a file that others include (a file never launched alone in this
folder, or one whose includer gives other values) is published by that file itself.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Tuple, Union

from launch_linter.engine import LintResult
from launch_linter.model.launch import LaunchTree
from launch_linter.model.record import Record, _set, replace
from launch_linter.model.robot import RobotJoint
from launch_linter.model.transform import StaticTransform
from launch_linter.rules._prefixes import description_prefixes, prefixed

TfEdge = Union[StaticTransform, RobotJoint]
"""A static transform of a launch file, or a URDF joint a robot_state_publisher publishes."""
Identity = Tuple[object, ...]


def edge_identity(edge: TfEdge) -> Identity:
    """What makes two edges of two trees the same: the element and its values."""
    if isinstance(edge, RobotJoint):
        return ("urdf", edge.path, edge.line, edge.column, edge.name, edge.parent, edge.child,
                edge.translation, edge.rpy, edge.condition, edge.unresolved)
    return ("launch", edge.path, edge.line, edge.column, edge.namespace, edge.name, edge.args,
            edge.parent, edge.child, edge.condition)


def tree_edges(tree: LaunchTree, distro: str | None = None) -> list[TfEdge]:
    """The tree's static transforms, then its URDF joints, each identity once (an element
    reached twice with the same values is one edge)."""
    seen: set[Identity] = set()
    out: list[TfEdge] = []
    every: list[TfEdge] = [*tree.transforms, *published_joints(tree, distro)]
    for edge in every:
        identity = edge_identity(edge)
        if identity not in seen:
            seen.add(identity)
            out.append(edge)
    return out


def published_joints(tree: LaunchTree, distro: str | None = None) -> list[RobotJoint]:
    """The tree's URDF joints with the frames their robot_state_publisher sends: under its
    prefix (one joint per publisher of the description); a joint whose prefix is unknown
    as written."""
    prefixes = description_prefixes(tree, distro)
    if not prefixes:
        return list(tree.joints)
    ros = next((n.ros for n in tree.nodes if n.ros is not None), None)
    out: list[RobotJoint] = []
    for joint in tree.joints:
        for prefix in prefixes.get(id(joint.source), ("",)):
            if not prefix or joint.parent is None or joint.child is None:
                out.append(joint)
            else:
                out.append(replace(joint, parent=prefixed(prefix, joint.parent, ros),
                                   child=prefixed(prefix, joint.child, ros)))
    return out


def entry_points(result: LintResult) -> list[int]:
    """Indices of the trees whose root no other tree includes (every tree when each is
    included by another, as in a cycle)."""
    included: set[str] = set()
    for tree in result.trees:
        included.update(f for f in tree.files if f != tree.root)
    found = [i for i, tree in enumerate(result.trees) if tree.root not in included]
    return found or list(range(len(result.trees)))


class Published(Record):
    """An edge and the roots of the entry points whose trees have it."""

    edge: TfEdge
    entry_points: tuple[str, ...]

    __slots__ = ("edge", "entry_points")

    def __init__(self, edge: TfEdge, entry_points: tuple[str, ...]) -> None:
        _set(self, "edge", edge)
        _set(self, "entry_points", entry_points)


def published(result: LintResult, distro: str | None = None) -> list[Published]:
    """Every edge of ``result`` once, in the order first met (entry points first), with
    the entry points that publish it."""
    entries = entry_points(result)
    is_entry = set(entries)
    order = entries + [i for i in range(len(result.trees)) if i not in is_entry]
    found: dict[Identity, tuple[TfEdge, list[str]]] = {}
    for index in order:
        tree = result.trees[index]
        entry = index in is_entry
        for edge in tree_edges(tree, distro):
            identity = edge_identity(edge)
            if identity not in found:
                found[identity] = (edge, [tree.root])
            elif entry and tree.root not in found[identity][1]:
                found[identity][1].append(tree.root)
    return [Published(edge, tuple(roots)) for edge, roots in found.values()]


def named(roots: Sequence[str], limit: int) -> str:
    """``a.launch, b.launch and 3 more``: at most ``limit`` names."""
    shown = ", ".join(roots[:limit])
    return shown + (f" and {len(roots) - limit} more" if len(roots) > limit else "")


def nothing_published(result: LintResult) -> str:
    """What ``transforms`` says when no tree publishes an edge: how many files were read
    and how many robot descriptions gave no joint (``check`` says why for each)."""
    descriptions = sum(len(tree.descriptions) for tree in result.trees)
    read = sum(1 for tree in result.trees for robot in tree.robots if robot.joints)
    line = f"No transforms found in {len(result.files)} file(s)"
    if descriptions > read:
        line += (f"; {descriptions - read} robot description(s) gave no joint "
                 f"(`launch-linter check` says why)")
    return line + "."


__all__ = [
    "Published",
    "TfEdge",
    "edge_identity",
    "entry_points",
    "named",
    "nothing_published",
    "published",
    "tree_edges",
]
