"""A ROS 2 namespace pushed twice, and the tf topic each node uses.

launch_ros pushes a relative namespace under the one already pushed
(``PushRosNamespace``, launch_ros/actions/push_ros_namespace.py: ``make_namespace_absolute
(prefix_namespace(previous, pushed))``), and a node's relative ``namespace=`` goes under
it too (launch_ros/actions/node.py). A file that pushes its ``namespace`` argument,
included from a group that already pushed the same namespace, so runs its nodes under
``/robot1/robot1``. tf2_ros publishes and listens on the absolute ``/tf`` and
``/tf_static``, which no namespace moves; a node remapped to the relative ``tf`` (the
multi-robot way) uses ``<namespace>/tf``: pushed twice, its transforms go to
``/robot1/robot1/tf``, a tree apart from the robot's on ``/robot1/tf``.
"""

from __future__ import annotations

from collections.abc import Sequence

from launch_linter.knowledge import TF_TOPIC
from launch_linter.model.diagnostic import Location
from launch_linter.model.launch import DoubledNamespace
from launch_linter.model.robot import UNKNOWN_VALUE, NodeRecord

MAX_REMAPPINGS = 1_000


def last_name(namespace: str) -> str:
    return namespace.rstrip("/").rsplit("/", 1)[-1]


def tf_topic(namespace: str, remappings: Sequence[tuple[str, str]] | None) -> str | None:
    """The topic a node under ``namespace`` (absolute) sends and reads tf on, with its
    remappings (rcl applies the first rule that matches; ``UNKNOWN_VALUE`` a name not
    resolved); None when not known."""
    if remappings is None:
        return None
    for source, target in remappings[:MAX_REMAPPINGS]:
        if source == UNKNOWN_VALUE:
            return None
        if source == TF_TOPIC or (source == TF_TOPIC[1:] and namespace == "/"):
            if target == UNKNOWN_VALUE or target.startswith("~"):
                return None
            if target.startswith("/"):
                return target
            return namespace.rstrip("/") + "/" + target
    return TF_TOPIC


class NamespaceWatch:
    """What one tree's pushes and nodes say of namespaces pushed twice."""

    def __init__(self) -> None:
        self.pushed_at: dict[str, Location] = {}
        """The first push that made each namespace."""
        self.doubled: dict[str, tuple[Location, Location]] = {}
        """Namespaces whose last name was pushed twice: the outer and inner push."""
        self.found: list[DoubledNamespace] = []
        self.topics: list[tuple[str, str]] = []
        """(namespace, tf topic) of every node whose tf topic is known."""

    def pushed(self, before: str | None, after: str | None, where: Location) -> None:
        """A push that turned the namespace ``before`` into ``after`` (None: unknown)."""
        if after is None or after == before:
            return
        self.pushed_at.setdefault(after, where)
        if before is not None and before != "/" and after == (
                before.rstrip("/") + "/" + last_name(before)):
            outer = self.pushed_at.get(before)
            if outer is not None:
                self.doubled.setdefault(after, (outer, where))

    def node(self, node: NodeRecord, base: str | None, own: str | None, program: str,
             topic: str | None) -> None:
        """A node launched under the pushed namespace ``base`` with its own ``namespace=``
        ``own`` (None when it gives none), now under ``node.namespace``."""
        namespace = node.namespace
        if namespace is None:
            return
        if topic is not None:
            self.topics.append((namespace, topic))
        pushes = self.doubled.get(namespace)
        if (pushes is None and base is not None and own is not None and base != "/"
                and not own.startswith("/") and own.strip("/") == last_name(base)):
            outer = self.pushed_at.get(base)
            if outer is not None:
                pushes = (outer, Location(node.path, node.line, node.column))
        if pushes is None:
            return
        self.found.append(DoubledNamespace(
            node.path, node.line, node.column, node.condition, node.name or "", program,
            namespace, pushes, topic))

    def records(self) -> tuple[DoubledNamespace, ...]:
        """The nodes under a doubled namespace, each with the tf topic the tree's nodes
        under the namespace pushed once use, when one is known."""
        out: list[DoubledNamespace] = []
        for found in self.found:
            once = found.namespace.rstrip("/").rsplit("/", 1)[0] or "/"
            tree = next((topic for namespace, topic in self.topics if namespace == once),
                        None)
            out.append(DoubledNamespace(
                found.path, found.line, found.column, found.condition, found.node,
                found.program, found.namespace, found.pushes, found.tf_topic, tree))
        return tuple(out)
