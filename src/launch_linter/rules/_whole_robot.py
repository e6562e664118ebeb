"""Whether a closed tf tree is the whole running robot, for a node that looks up a frame.

A launch tree is often one of several started side by side: a navigation launch file
beside the robot's bringup, a camera launch beside both. A frame that such a tree gives
to no edge may then come from the others. A tree that brings up the robot's own tf
publishers leaves no such place: a robot_state_publisher of a description read
completely (every link the robot has), the odometry source that gives ``odom -> base``
with its frames read, and, for a global frame (the one a localization puts above
odometry), the localization; each running whenever the node that looks the frame up
does. Frames the running system may still give from outside such a tree are told apart
too: the frames of a movable joint while nothing is known to publish ``/joint_states``,
and the default frames of a sensor driver the knowledge base knows (for the tree's ROS
version) and the tree does not start.
"""

from __future__ import annotations

import itertools
import typing

from launch_linter.knowledge import Entry
from launch_linter.knowledge.publish import Parameters
from launch_linter.model.launch import LaunchTree
from launch_linter.model.robot import DescriptionKind, NodeRecord
from launch_linter.model.transform import Condition, ConditionLiteral
from launch_linter.rules._api import RuleContext
from launch_linter.rules._nodes import NodeEdge, entry_of, nodes_of, program_of
from launch_linter.rules._tree import tree_edges

T = typing.TypeVar("T")
MAX_SUBSET_LITERALS = 6
"""A node under more tests than this is matched only with publishers that run always or
under the very same tests (enumerating the subsets of its tests would cost 2^n): fewer
trees judged whole, never one more."""
GLOBAL_WORDS = ("global", "map", "world", "fixed")
"""Words of a frame parameter's name that make it a global frame (a costmap's
``global_frame``, a ``fixed_frame``, a ``map_frame``): a localization started on its own
would publish it, above the odometry frame."""


class FirstRunning(typing.Generic[T]):
    """Of some items, each running under a condition, the first that runs whenever a
    node under a given condition runs (its tests are among the node's): by the sets of
    tests, so a query costs the subsets of the node's tests, not a scan of the items."""

    def __init__(self, items: typing.Iterable[tuple[Condition, T]]) -> None:
        self._by_tests: dict[frozenset[ConditionLiteral], T] = {}
        for condition, item in items:
            self._by_tests.setdefault(frozenset(condition.literals), item)

    def find(self, condition: Condition) -> T | None:
        tests = list(dict.fromkeys(condition.literals))
        if len(tests) > MAX_SUBSET_LITERALS:
            always = self._by_tests.get(frozenset())
            return always if always is not None else self._by_tests.get(frozenset(tests))
        for size in range(len(tests) + 1):
            for chosen in itertools.combinations(tests, size):
                found = self._by_tests.get(frozenset(chosen))
                if found is not None:
                    return found
        return None


class RobotPublishers:
    """A tree's publishers of the robot, found once per tree (internal to the rules: not
    a contract record)."""

    describers: FirstRunning[NodeRecord]
    """robot_state_publishers (nodes whose entry publishes a description)."""
    description_read: bool
    """Every description the tree gives was read completely."""
    odometry: FirstRunning[NodeEdge]
    localization: FirstRunning[NodeEdge]
    dropped: frozenset[str]
    """Frames of movable joints, not sent while nothing publishes ``/joint_states``."""
    driver_frames: dict[str, str]
    """Default frames of sensor drivers the tree does not start: frame -> entry id."""

    __slots__ = ("describers", "description_read", "odometry", "localization", "dropped",
                 "driver_frames")

    def __init__(self, describers: FirstRunning[NodeRecord], description_read: bool,
                 odometry: FirstRunning[NodeEdge], localization: FirstRunning[NodeEdge],
                 dropped: frozenset[str], driver_frames: dict[str, str]) -> None:
        self.describers = describers
        self.description_read = description_read
        self.odometry = odometry
        self.localization = localization
        self.dropped = dropped
        self.driver_frames = driver_frames


def _describes(context: RuleContext, node: NodeRecord) -> bool:
    entry = entry_of(context, node)
    return entry is not None and entry.publishes_description


def _description_read(tree: LaunchTree) -> bool:
    if not tree.robots or not all(robot.complete for robot in tree.robots):
        return False
    return all(source.file is not None or source.kind is DescriptionKind.LITERAL
               for source in tree.descriptions)


def _driver_defaults(entry: Entry) -> list[str]:
    """The frames of ``entry``'s sensor edges under its defaults (a driver launched with
    no parameter), both ends known."""
    bare = Parameters(entry, NodeRecord("", 0, 0, "", ""))
    frames: list[str] = []
    for spec in entry.publishes:
        if spec.role != "sensor":
            continue
        parent, child = bare.fill(spec.parent), bare.fill(spec.child)
        if parent and child:
            frames.extend((parent.lstrip("/"), child.lstrip("/")))
    return frames


def _publishers(context: RuleContext) -> RobotPublishers:
    view = nodes_of(context)
    tree = context.tree
    describers = FirstRunning((n.condition, n) for n in tree.nodes
                              if n.kind == "node" and _describes(context, n))
    sure = [edge for edge in view.edges if not edge.assumed]
    dropped: set[str] = set()
    if not view.joint_states:
        for edge in tree_edges(tree, context.distro):
            if edge.dynamic:
                dropped.update((edge.parent, edge.child))
    running = {id(entry_of(context, n)) for n in tree.nodes}
    ros = next((n.ros for n in tree.nodes if n.ros is not None), None)
    driver_frames: dict[str, str] = {}
    for entry in context.knowledge.entries:
        if id(entry) not in running and (ros is None or ros in entry.ros):
            for frame in _driver_defaults(entry):
                driver_frames.setdefault(frame, entry.id)
    return RobotPublishers(
        describers, _description_read(tree),
        FirstRunning((e.node.condition, e) for e in sure if e.role == "odometry"),
        FirstRunning((e.node.condition, e) for e in sure if e.role == "localization"),
        frozenset(dropped), driver_frames)


def robot_publishers(context: RuleContext) -> RobotPublishers:
    """The tree's publishers of the robot, worked out once per tree."""
    return context.derived(_publishers)


def is_global(param: str) -> bool:
    """Whether a frame parameter names a global frame, by its last name's words."""
    name = param.rsplit("/", 1)[-1].lower()
    return any(word in name for word in GLOBAL_WORDS)


def outside_frame(context: RuleContext, frame: str) -> str | None:
    """Why ``frame``, given by no edge of the tree, may still be published by the running
    system: a movable joint's frame while nothing is known to publish ``/joint_states``,
    or a sensor driver's default frame; None when neither."""
    publishers = robot_publishers(context)
    frame = frame.lstrip("/")
    if frame in publishers.dropped:
        return ("the description names it under a movable joint, which "
                "robot_state_publisher sends only while something publishes /joint_states "
                "(no node of this tree is known to)")
    driver = publishers.driver_frames.get(frame)
    if driver is not None:
        return (f"it is a default frame of {driver} (knowledge base), a driver this tree "
                f"does not start")
    return None


def whole_robot(context: RuleContext, node: NodeRecord, global_frame: bool
                ) -> tuple[str | None, str]:
    """Whether the closed tree is the whole running robot for ``node`` (module
    docstring): (None, the robot's publishers as a message names them) when it is, else
    (why not, '')."""
    publishers = robot_publishers(context)
    describer = publishers.describers.find(node.condition)
    if describer is None:
        return "no robot_state_publisher of this tree runs with it", ""
    if not publishers.description_read:
        return "the robot's description is not read completely", ""
    odometry = publishers.odometry.find(node.condition)
    if odometry is None:
        return "no odometry source of this tree runs with it", ""
    named = [f"{program_of(describer)} ({describer.path}:{describer.line}) sends its "
             f"description, read completely", f"{odometry.describe()} its odometry"]
    if global_frame:
        localization = publishers.localization.find(node.condition)
        if localization is None:
            return ("nothing in this tree localizes: a localization started on its own "
                    "may give the global frame"), ""
        named.append(f"{localization.describe()} its localization")
    return None, "; ".join(named)
