"""The prefix robot_state_publisher puts before the URDF frames it sends, per description.

ROS 1: the ``tf_prefix`` that ``searchParam`` finds from the node's private namespace up
(the front-end gives the node those set inside it and in the namespaces around it), put
before each frame as tf 1 did: a frame written with a leading ``/`` is sent without it and
unprefixed, a prefix loses its leading ``/`` and gains a trailing one (robot_state_publisher
melodic-devel cd1c43c ``src/robot_state_publisher.cpp`` 94-95, 119-120 through
``tf::resolve``; noetic-devel 9afecc8 lines 94-120, ``prefix_frame``, and
``src/joint_state_listener.cpp`` 93-104). Noetic's 1.15.0 and 1.15.1 sent no prefix;
1.15.2 (bd2a7c6) restored it, and the linter follows the current release.
ROS 2: ``frame_prefix`` as written (rolling e0f77e6 ``src/robot_state_publisher.cpp``
81-127), from 2.5.0; dashing and eloquent have none.

A publisher reads the description by its parameter: ROS 2 its own ``robot_description``,
ROS 1 the one ``searchParam`` finds from its namespace up.
"""

from __future__ import annotations

from launch_linter.model.launch import LaunchTree
from launch_linter.model.robot import UNKNOWN_VALUE, DescriptionSource, NodeRecord

PUBLISHER = "robot_state_publisher"
NO_FRAME_PREFIX = ("dashing", "eloquent")
"""ROS 2 distributions whose robot_state_publisher has no ``frame_prefix`` (added in 2.5.0,
ros/robot_state_publisher#159, backported to foxy in 2.4.5, August 2021)."""
MAX_PREFIXES = 64
"""Prefixed copies of one description kept per tree (bounded work: one description
published by thousands of robot_state_publishers gives the first 64 robots' frames)."""
PREFIX_PARAMS = {1: "tf_prefix", 2: "frame_prefix"}
"""The parameter that prefixes robot_state_publisher's frames, by ROS version; each
version ignores the other's (ros/robot_state_publisher#192)."""


def publisher_prefix(node: NodeRecord, distro: str | None = None) -> str | None:
    """What ``node`` (a robot_state_publisher) puts before its frames: '' for nothing,
    None when unknown (a value the linter could not resolve, or an unknown ROS version
    where one of the two parameters is given)."""
    if node.ros == 2 and distro in NO_FRAME_PREFIX:
        return ""
    names = ((PREFIX_PARAMS[node.ros],) if node.ros in PREFIX_PARAMS
             else tuple(PREFIX_PARAMS.values()))
    values = [node.given(name) for name in names]
    if any(v == UNKNOWN_VALUE for v in values):
        return None
    given = [v for v in values if v]
    if not given:
        return ""
    return given[0] if len(given) == 1 and node.ros in PREFIX_PARAMS else None


def prefixed(prefix: str, frame: str, ros: int | None) -> str:
    """``frame`` as a publisher with ``prefix`` sends it (the module's rules)."""
    if not prefix:
        return frame
    if ros == 2:
        return prefix + frame
    if frame.startswith("/"):
        return frame[1:]
    return (prefix[1:] if prefix.startswith("/") else prefix) + "/" + frame


def publishers(tree: LaunchTree) -> list[NodeRecord]:
    return [n for n in tree.nodes if n.package == PUBLISHER and n.kind == "node"]


def _inside(namespace: str, outer: str) -> bool:
    return not outer or namespace == outer or namespace.startswith(outer + "/")


def source_read_by(node: NodeRecord, sources: list[DescriptionSource]
                   ) -> DescriptionSource | None:
    """The description robot_state_publisher ``node`` publishes: the one given to it by
    name, else (ROS 1) the one ``searchParam`` finds first from its namespace up (the
    closest namespace around it); None when the linter cannot tell."""
    named = next((s for s in sources if s.node is not None and s.node == node.name), None)
    if named is not None or node.namespace is None:
        return named
    here = node.namespace.strip("/")
    best: DescriptionSource | None = None
    for source in sources:
        if source.node is not None or source.namespace is None:
            continue
        mine = source.namespace.strip("/")
        if _inside(here, mine) and (best is None or len(mine) > len(
                (best.namespace or "").strip("/"))):
            best = source
    return best


def description_prefixes(tree: LaunchTree, distro: str | None = None
                         ) -> dict[int, tuple[str | None, ...]]:
    """For each description of ``tree`` (by ``id`` of its source), the prefixes its
    publishers put before its frames (one per publisher; None: unknown). Empty when no
    publisher of the tree prefixes anything (the common case: frames as written)."""
    nodes = publishers(tree)
    prefixes = [publisher_prefix(n, distro) for n in nodes]
    if all(p == "" for p in prefixes):
        return {}
    by_node = {id(n): p for n, p in zip(nodes, prefixes)}
    sources: list[DescriptionSource] = []
    for joint in tree.joints:
        if not sources or sources[-1] is not joint.source:
            sources.append(joint.source)
    # Each publisher once against each description (both bounded: descriptions by the
    # tree's limit), not each description against every pair.
    found: dict[int, dict[str | None, None]] = {}
    for node in nodes:
        source = source_read_by(node, sources)
        if source is not None:
            found.setdefault(id(source), {})[by_node[id(node)]] = None
    alike = len(set(prefixes)) == 1
    out: dict[int, tuple[str | None, ...]] = {}
    for source in sources:
        mine = found.get(id(source))
        out[id(source)] = (tuple(mine)[:MAX_PREFIXES] if mine else (prefixes[0],) if alike
                           else (None,))
    return out
