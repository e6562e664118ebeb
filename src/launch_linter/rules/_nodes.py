"""The tf tree's node side, as the knowledge base tells it: the edges each launched node
publishes (with the node and its launch line as source), the frames nodes look up, the
nodes the knowledge base does not know (which make the tree *open*), and whether anything
publishes ``/joint_states`` (without which robot_state_publisher sends no movable joint)."""

from __future__ import annotations

from launch_linter.knowledge import PLACEHOLDER, EdgeSpec, Entry, KnowledgeBase
from launch_linter.knowledge.publish import (
    PublishedEdge,
    frames_named,
    listed_parameters,
    lookup_templates,
    published,
)
from launch_linter.model.diagnostic import Location
from launch_linter.model.launch import LaunchTree
from launch_linter.model.record import Record, _set
from launch_linter.model.robot import NodeRecord
from launch_linter.rules._api import Finding, RuleContext
from launch_linter.rules._prefixes import publisher_prefix
from launch_linter.rules._tf_topics import LOST, controller_routes

STATIC_PUBLISHERS = frozenset({"tf", "tf2_ros"})
"""Packages whose static_transform_publisher the tree already reads as launch edges."""
JOINT_STATE_CONTROLLERS = ("joint_state_broadcaster/JointStateBroadcaster",
                           "joint_state_controller/JointStateController")
AUTHORITIES = ("localization", "odometry")
"""The roles whose edge REP 105 gives to one node alone (``frame_authority``'s)."""


def program_of(node: NodeRecord) -> str:
    """How a message names a launched node's program: its plugin, else package/executable."""
    return node.plugin or f"{node.package}/{node.executable}"


class NodeEdge(Record):
    """An edge a launched node publishes at run time."""

    parent: str
    child: str
    role: str
    node: NodeRecord
    entry: Entry
    assumed: bool
    """The edge rests on defaults that an unread parameter file of the node may change:
    enough for a warning measured on real files, never for an error."""
    spec: EdgeSpec | None
    """The knowledge base's edge it comes from (its switches and frame parameters)."""

    __slots__ = ("parent", "child", "role", "node", "entry", "assumed", "spec")

    def __init__(
        self,
        parent: str,
        child: str,
        role: str,
        node: NodeRecord,
        entry: Entry,
        assumed: bool = False,
        spec: EdgeSpec | None = None,
    ) -> None:
        _set(self, "parent", parent)
        _set(self, "child", child)
        _set(self, "role", role)
        _set(self, "node", node)
        _set(self, "entry", entry)
        _set(self, "assumed", assumed)
        _set(self, "spec", spec)

    @property
    def location(self) -> Location:
        return Location(self.node.path, self.node.line, self.node.column)

    def describe(self) -> str:
        what = "Gazebo plugin" if self.node.kind == "gazebo_plugin" else "node"
        return f"{what} {program_of(self.node)} ({self.node.path}:{self.node.line})"


class Lookup(Record):
    """A frame a node looks up by a parameter."""

    frame: str
    param: str
    node: NodeRecord
    entry: Entry

    __slots__ = ("frame", "param", "node", "entry")

    def __init__(self, frame: str, param: str, node: NodeRecord, entry: Entry) -> None:
        _set(self, "frame", frame)
        _set(self, "param", param)
        _set(self, "node", node)
        _set(self, "entry", entry)


class NodeView(Record):
    edges: tuple[NodeEdge, ...]
    lookups: tuple[Lookup, ...]
    unknown: tuple[NodeRecord, ...]
    """Nodes the knowledge base does not know: each may publish tf."""
    unsure: tuple[NodeRecord, ...]
    """Known nodes whose edges the linter cannot work out (parameters not read)."""
    joint_states: bool
    """Whether a node the knowledge base knows publishes ``/joint_states``."""

    __slots__ = ("edges", "lookups", "unknown", "unsure", "joint_states")

    def __init__(
        self,
        edges: tuple[NodeEdge, ...],
        lookups: tuple[Lookup, ...],
        unknown: tuple[NodeRecord, ...],
        unsure: tuple[NodeRecord, ...],
        joint_states: bool,
    ) -> None:
        _set(self, "edges", edges)
        _set(self, "lookups", lookups)
        _set(self, "unknown", unknown)
        _set(self, "unsure", unsure)
        _set(self, "joint_states", joint_states)

    @property
    def open_because(self) -> NodeRecord | None:
        """The first node that makes the tree open, None when it is closed."""
        return (self.unknown + self.unsure)[0] if self.unknown or self.unsure else None


def _lookup(base: KnowledgeBase, node: NodeRecord) -> Entry | None:
    if node.kind == "controller":
        return base.plugin("controller", node.plugin or "", node.ros)
    if node.plugin is not None:
        return base.plugin(node.kind, node.plugin, node.ros)
    return base.node(node.package, node.executable, node.ros)


def _entries(context: RuleContext) -> dict[tuple[str, str | None, str, str, int | None],
                                           Entry | None]:
    return {}


def entry_of(context: RuleContext, node: NodeRecord) -> Entry | None:
    """The knowledge base's entry of ``node``, looked up once per tree for all the rules
    (a plugin's lookup scans every entry)."""
    known = context.derived(_entries)
    key = (node.kind, node.plugin, node.package, node.executable, node.ros)
    if key not in known:
        known[key] = _lookup(context.knowledge, node)
    return known[key]


def _routes(context: RuleContext) -> dict[tuple[str | None, str | None], str]:
    return controller_routes(context.tree.nodes, lambda node: entry_of(context, node))


def routes_of(context: RuleContext) -> dict[tuple[str | None, str | None], str]:
    """Where each controller's own tf topic goes (``_tf_topics.controller_routes``), worked
    out once per tree for the node view and the rules."""
    return context.derived(_routes)


def _view(context: RuleContext) -> NodeView:
    edges: list[NodeEdge] = []
    lookups: list[Lookup] = []
    unknown: list[NodeRecord] = []
    unsure: list[NodeRecord] = []
    joint_states = False
    controllers: set[tuple[str | None, str | None]] = set()
    routes = routes_of(context)
    for node in context.tree.nodes:
        if node.package in STATIC_PUBLISHERS and node.kind == "node":
            continue
        if node.kind == "controller":
            # One controller given both in the manager's file and by a spawner's
            # --param-file is one controller.
            if (node.name, node.namespace) in controllers:
                continue
            controllers.add((node.name, node.namespace))
        if node.kind == "controller" and node.plugin in JOINT_STATE_CONTROLLERS:
            joint_states = True
            continue
        entry = entry_of(context, node)
        if entry is None:
            unknown.append(node)
            continue
        if node.kind == "controller" and routes.get((node.name, node.namespace)) == LOST:
            continue  # its transforms stay on a topic of its own (controller_tf_unrouted)
        joint_states = joint_states or entry.publishes_joint_states
        sure, maybe = published(entry, node, distro=context.distro)
        if (maybe or any(e.signature is None for e in sure)
                # A controller manager that could not read a parameter file: its
                # controllers, and the edges they send, are unknown.
                or (entry.loads_controllers and node.unread)
                or (entry.publishes_description and publisher_prefix(node, context.distro)
                    is None)):
            # Edges not worked out, or a description's frames under an unknown prefix.
            unsure.append(node)
        proven = {e.signature for e in sure if e.signature is not None}
        assumed = (published(entry, node, assume=True, distro=context.distro)[0]
                   if node.unread else sure)
        for edge in assumed:
            if edge.signature is not None:
                edges.append(NodeEdge(edge.signature[0], edge.signature[1], edge.role,
                                      node, entry, edge.signature not in proven, edge.spec))
        lookups.extend(Lookup(f, p, node, entry)
                       for f, p in frames_named(entry, node, lookup_templates(entry, node)))
    return NodeView(tuple(edges), tuple(lookups), tuple(unknown),
                    tuple(unsure), joint_states)


def nodes_of(context: RuleContext) -> NodeView:
    """The node side of the tree, worked out once for the rules run on one tree."""
    return context.derived(_view)


__all__ = ["NodeEdge", "NodeView", "PublishedEdge", "nodes_of", "view_of"]


def include_split(first: tuple[Location, ...], second: tuple[Location, ...]
                  ) -> tuple[Location, Location] | None:
    """Where two runs of one launch line part: the innermost include actions that differ
    between their include chains (``first``'s, ``second``'s), where a user can drop one;
    None when both came through the same includes (one run read twice by the linter: a
    loop or a helper function in Python, an include the reading repeats)."""
    for mine, theirs in zip(reversed(first), reversed(second)):
        if mine != theirs:
            return mine, theirs
    return None


def twice_included(a: NodeRecord, b: NodeRecord) -> tuple[Location, Location] | None:
    """Where one node line, run through two different includes into one namespace, parts
    (:func:`include_split`); None when ``a`` and ``b`` are not such a pair."""
    if (a.path, a.line, a.column) != (b.path, b.line, b.column):
        return None
    if a.namespace is None or a.namespace != b.namespace:
        # Other namespaces: robot_frame_collision's (robots told apart by namespace).
        return None
    return include_split(a.included_at, b.included_at)


def rivals(a: NodeEdge, b: NodeEdge) -> bool:
    """Whether two node edges come from two publishers that run together: two launch
    elements, or one element run through two different includes into one namespace (not
    one run the linter read twice), not under exclusive conditions (nav2's composed and
    separate amcl: ``IfCondition(x)`` and ``IfCondition(PythonExpression(['not ', x]))``)."""
    if a.node.condition.excludes(b.node.condition):
        return False
    return a.location != b.location or twice_included(a.node, b.node) is not None


def finding_at_node(node: NodeRecord, message: str,
                    related: tuple[Location, ...] = ()) -> Finding:
    """A finding at a launched node's element (or at the controller manager's, for a
    controller; at the Gazebo plugin's, for a plugin)."""
    return Finding(path=node.path, line=node.line, column=node.column, message=message,
                   node=node.name, related=related)


def finding_at_param(node: NodeRecord, name: str, message: str,
                     related: tuple[Location, ...] = ()) -> Finding:
    """A finding at the line that last sets the node's parameter ``name`` (a ``<param>``,
    a dictionary key in ``parameters=``, a parameter file's key), with the node's element
    as related; at the node's element when the front-end does not know where the value
    was written."""
    where = node.where_set(name)
    if where is None or where == (node.path, node.line, node.column):
        return finding_at_node(node, message, related)
    path, line, column = where
    return Finding(path=path, line=line, column=column, message=message, node=node.name,
                   related=(Location(node.path, node.line, node.column), *related))


def view_of(tree: LaunchTree, knowledge: KnowledgeBase, distro: str | None = None) -> NodeView:
    """The node side of one tree, outside a rule run (``transforms``, ``graph``), for the
    target distribution ``distro`` where a prefix depends on it."""
    return nodes_of(RuleContext(tree, knowledge=knowledge, distro=distro))


def frame_parameters(entry: Entry, node: NodeRecord | None = None) -> list[str]:
    """The parameters of ``entry`` that name frames: those in its published edges, its
    lookups, its camera frames and the frames it stamps on its data (a parameter used only
    as a switch is not one); with ``node``, also those its list parameters name."""
    names: dict[str, None] = {}  # ordered and without repeats
    templates = [t for spec in entry.publishes for t in (spec.parent, spec.child)]
    for template in (templates + list(entry.looks_up) + list(entry.camera_frames)
                     + list(entry.header_frames)):
        names.update(dict.fromkeys(PLACEHOLDER.findall(template)))
    if node is not None:
        names.update(dict.fromkeys(listed_parameters(entry, node)))
    return list(names)
