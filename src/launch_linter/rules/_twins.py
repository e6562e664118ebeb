"""One robot description published twice: two robot_state_publishers of one namespace
and one frame prefix sending the same URDF joints, and the place to report a publisher
that one launch line starts through two includes (``duplicate_publisher``'s)."""

from __future__ import annotations

from collections.abc import Iterator

from launch_linter.model.diagnostic import Location, Severity
from launch_linter.model.launch import LaunchTree
from launch_linter.model.robot import UNKNOWN_VALUE, DescriptionSource, NodeRecord
from launch_linter.rules._api import Finding, summarised_lazily
from launch_linter.rules._nodes import finding_at_node, twice_included

PUBLISHER = "robot_state_publisher"
PREFIX = "frame_prefix"
PROVEN = "both publishers known and their parameters read"
"""Said at the end of a proven finding (``duplicate_publisher``'s wording)."""


def unproven_runs(node: NodeRecord, other: NodeRecord) -> str | None:
    """Why two runs of one node line through two includes are not proven to run together
    (None when both run unconditionally): a condition the linter could not decide."""
    if twice_included(other, node) is None:
        return None
    undecided = [n.condition.describe() for n in (other, node) if not n.condition.always]
    if not undecided:
        return None
    return f"whether both includes run depends on {' and '.join(dict.fromkeys(undecided))}"


def at_second_run(node: NodeRecord, other: NodeRecord, message: str) -> Finding:
    """A finding at ``node``, the second publisher; when ``node`` and ``other`` are one
    launch line run through two includes, at the second of the includes that part, with
    the first and the line as related places (where the user drops one)."""
    split = twice_included(other, node)
    if split is None:
        return finding_at_node(node, message, (Location(other.path, other.line, other.column),))
    first, second = split
    # The message names neither include: one shared include file reached from several
    # roots is then one finding (the first include is the first related place).
    return Finding(path=second.path, line=second.line, column=second.column,
                   message=f"{message} (one launch line run twice: by this include and "
                           f"by another of the same launch, the first related place)",
                   node=node.name, related=(first, Location(node.path, node.line, node.column)))


def _place(record: DescriptionSource | NodeRecord) -> tuple[object, ...]:
    """A launch line and the includes it ran through: a ROS 2 robot_state_publisher and
    the ``robot_description`` parameter it is given share it."""
    return (record.path, record.line, record.column, record.included_at)


def _same_frames(node: NodeRecord, other: NodeRecord) -> bool:
    """Whether two robot_state_publishers name their frames alike: one namespace (known)
    and one ``frame_prefix`` (read: an unresolved prefix may differ)."""
    if node.namespace is None or node.namespace != other.namespace:
        # Other namespaces are robot_frame_collision's (robots told apart by namespace).
        return False
    prefix = node.given(PREFIX)
    return prefix != UNKNOWN_VALUE and prefix == other.given(PREFIX)


def twin_descriptions(tree: LaunchTree) -> Iterator[Finding]:
    """Two ROS 2 robot_state_publishers that run together (two launch elements, or one
    run through two different includes) in one namespace with one frame prefix, whose
    descriptions share joints: each of those edges has two publishers. One finding per
    later publisher, at it (or at its include), naming the edges. The descriptions of a
    tree are bounded (``MAX_DESCRIPTIONS_PER_TREE``), and so are the pairs compared."""
    publishers = [n for n in tree.nodes
                  if n.package == PUBLISHER and n.kind == "node" and n.ros == 2]
    if len(publishers) < 2:
        return
    by_place = {_place(n): n for n in publishers}
    described: list[tuple[NodeRecord, dict[tuple[str, str], None]]] = []
    edges: dict[tuple[str, str], None] = {}  # ordered and without repeats
    last: DescriptionSource | None = None
    for joint in tree.joints:
        if joint.source is not last:
            # Joints come per description entry, told apart by identity (one entry run
            # through two includes is two entries of equal value).
            last = joint.source
            node = by_place.get(_place(joint.source))
            edges = {}
            if node is not None:
                described.append((node, edges))
        if joint.parent is not None and joint.child is not None:
            edges[(joint.parent, joint.child)] = None
    for index, (node, mine) in enumerate(described):
        for other, theirs in described[:index]:
            if node is other or node.condition.excludes(other.condition):
                continue
            if ((node.path, node.line, node.column) == (other.path, other.line, other.column)
                    and twice_included(other, node) is None):
                continue  # one run read twice by the linter (a loop, a helper function)
            if not _same_frames(node, other):
                continue
            shared = [edge for edge in mine if edge in theirs]
            if shared:
                yield _twin_finding(node, other, shared)
                break


def _twin_finding(node: NodeRecord, other: NodeRecord, shared: list[tuple[str, str]]
                  ) -> Finding:
    listed = ", ".join(summarised_lazily((f"'{p}' -> '{c}'" for p, c in shared), len(shared)))
    namespace = node.namespace or "/"
    if twice_included(other, node) is not None:
        who = f"{PUBLISHER} ({node.path}:{node.line}) runs twice in namespace '{namespace}'"
    else:
        who = (f"{PUBLISHER} ({node.path}:{node.line}) and the one at "
               f"{other.path}:{other.line} run in namespace '{namespace}'")
    found = at_second_run(node, other, f"{who} with the same frames, both publishing the "
                          f"URDF joints {listed}; tf2 receives each of those edges from two "
                          f"publishers: start one robot_state_publisher per description")
    reasons = [f"{PUBLISHER} ({n.path}:{n.line}) may set {PREFIX} in {n.unread[0]}"
               for n in (other, node) if n.unread]
    runs = unproven_runs(node, other)
    if runs is None and any(not n.condition.always for n in (other, node)):
        runs = "whether both run depends on " + " and ".join(dict.fromkeys(
            n.condition.describe() for n in (other, node) if not n.condition.always))
    if runs is not None:
        reasons.append(runs)
    if not reasons:
        return Finding(path=found.path, line=found.line, column=found.column,
                       message=f"{found.message} ({PROVEN})", node=found.node,
                       related=found.related)
    return Finding(path=found.path, line=found.line, column=found.column,
                   message=f"{found.message} (not proven: {'; '.join(reasons)})",
                   node=found.node, related=found.related, severity=Severity.INFO)
