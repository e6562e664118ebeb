"""Where a node's transforms go when its knowledge entry sends them on a topic of its own.

Most tf publishers send on ``/tf``. steering_controllers_library's controllers and
mecanum_drive_controller send their odometry transform on the controller's own
``~/tf_odometry`` (knowledge ``tf_topic``): it joins the tree only when a remapping of the
controller's process brings it to ``/tf`` (the controller manager's ``remappings=``, a
simulator plugin's ``<ros><remapping>``, a spawner's ``--controller-ros-args``) or a relay
(topic_tools, or a node given the topic's name) republishes it. rcl applies the first
remapping rule whose source names the topic (``rcl_remap_topic_name``: ``~`` is the node's
full name, a relative name is under the node's namespace, ``node:`` limits a rule to one
node).
"""

from __future__ import annotations

from collections.abc import Callable, Sequence

from launch_linter.knowledge import TF_TOPIC, Entry
from launch_linter.model.robot import UNKNOWN_VALUE, NodeRecord

ROUTED = "routed"
LOST = "lost"
UNKNOWN = "unknown"
MAX_RULES = 1_000
"""Remapping rules read per record (as ``ros2_namespaces.MAX_REMAPPINGS``)."""
RELAY_PACKAGES = frozenset({"topic_tools"})
"""Packages whose nodes republish a topic on another (``relay``, ``mux``): with one in the
tree a node's own tf topic may reach ``/tf`` through it."""
OWN_TOPIC_MARK = "tf_odometry"
"""The last name of the controllers' own tf topic, as a relay's parameter would name it."""
NODE_OPTIONS_ARGS = "node_options_args"
"""A controller manager's ``<controller>.node_options_args``: arguments (remappings among
them) it gives that controller's node (ros2_control jazzy 9ffbf97
controller_manager.cpp 1373-1383)."""


def _expand(name: str, namespace: str, node_name: str | None) -> str | None:
    """A topic name as rcl expands it for the node ``node_name`` in ``namespace`` (None for
    a private name of a node whose name is not known)."""
    base = namespace.rstrip("/")
    if name.startswith("~"):
        return None if not node_name else f"{base}/{node_name}{name[1:]}"
    if name.startswith("/"):
        return name
    return f"{base}/{name}"


def own_topic(entry: Entry, node: NodeRecord) -> str | None:
    """The absolute topic a node sends its transforms on, None when its name or namespace
    is not known."""
    if not entry.tf_topic.startswith("~"):
        return entry.tf_topic
    if node.namespace is None or not node.name:
        return None
    return _expand(entry.tf_topic, node.namespace, node.name)


def remapped(topic: str, node: NodeRecord) -> str | None:
    """The absolute topic that ``topic`` (as the node names it: relative, ``~/`` or
    absolute) becomes under the remappings ``node`` is given: the first rule whose source
    names it decides; None when a rule, the node's name or its namespace is not known."""
    if node.remappings is None or node.namespace is None:
        return None
    expanded = _expand(topic, node.namespace, node.name)
    if expanded is None:
        return None
    for source, target in node.remappings[:MAX_RULES]:
        if source == UNKNOWN_VALUE:
            return None
        owner, colon, rest = source.partition(":")
        if colon and not owner.startswith(("~", "/")):
            if node.name is None:
                return None  # a rule for one node: which one this is is not known
            if owner != node.name:
                continue
            source = rest
        matched = _expand(source, node.namespace, node.name)
        if matched is None:
            return None
        if matched != expanded:
            continue
        return None if target == UNKNOWN_VALUE else _expand(target, node.namespace, node.name)
    return expanded


def route(topic: str, node: NodeRecord) -> str:
    """Whether the remappings ``node`` is given bring ``topic`` to a tf topic (``/tf``, or a
    namespaced ``…/tf`` as multi-robot trees use)."""
    moved = remapped(topic, node)
    if moved is None:
        return UNKNOWN
    return ROUTED if moved == TF_TOPIC or moved.endswith(TF_TOPIC) else LOST


def controller_routes(nodes: Sequence[NodeRecord],
                      entry_for: Callable[[NodeRecord], Entry | None]
                      ) -> dict[tuple[str | None, str | None], str]:
    """Where the transforms of each controller that sends them on a topic of its own go, by
    ``(name, namespace)``, from every record the tree has of it (its controller manager's
    file, a spawner, a simulator plugin: one process): routed when any record's
    remappings bring them to a tf topic; unknown when a rule is not read, a relay runs in
    the tree (topic_tools, a node given a ``tf_odometry`` name) or a manager gives the
    controller node arguments; else lost."""
    records: dict[tuple[str | None, str | None], list[tuple[NodeRecord, Entry]]] = {}
    relay = False
    with_arguments: set[str] = set()
    for node in nodes:
        relay = relay or node.package in RELAY_PACKAGES
        if node.kind != "controller":
            for name, value in node.params:
                if name.endswith("." + NODE_OPTIONS_ARGS):
                    with_arguments.add(name[:-len(NODE_OPTIONS_ARGS) - 1].rsplit(".", 1)[-1])
                # A node given such a topic's name (a relay's input) may republish it.
                relay = relay or OWN_TOPIC_MARK in value
            continue
        entry = entry_for(node)
        if entry is not None and entry.tf_topic != TF_TOPIC:
            records.setdefault((node.name, node.namespace), []).append((node, entry))
    out: dict[tuple[str | None, str | None], str] = {}
    for key, given in records.items():
        ways: set[str] = set()
        for node, entry in given:
            topic = own_topic(entry, node)
            ways.add(UNKNOWN if topic is None else route(topic, node))
        out[key] = (ROUTED if ROUTED in ways
                    else UNKNOWN if UNKNOWN in ways or relay or key[0] in with_arguments
                    else LOST)
    return out
