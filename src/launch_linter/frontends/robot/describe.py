"""From the ``robot_description`` a launch file gives to the URDF joints it publishes.

Front-ends record :class:`DescriptionSource`s (where, which file, which xacro args) and
:class:`NodeRecord`s; :func:`attach_robot` expands each description once per run (the
:class:`RobotCache` keys expansions by file, args and package roots) and adds its joints
to the tree, so rules see launch static transforms and URDF joints together.
"""

from __future__ import annotations

import os
import re
import typing
from collections.abc import Callable, Hashable, Sequence
from dataclasses import replace

from launch_linter.model.diagnostic import Problem
from launch_linter.model.launch import LaunchTree
from launch_linter.model.robot import DescriptionKind, DescriptionSource, NodeRecord, RobotJoint
from launch_linter.resolve import reads
from launch_linter.workspace.packages import PackageIndex

if typing.TYPE_CHECKING:
    from launch_linter.frontends.robot.xacro import Expansion

RSP_PACKAGE = "robot_state_publisher"
_XACRO_NAMED = re.compile(r"""(?:name\s*=\s*)?['"]xacro(?:\.py)?['"]""")
MAX_DESCRIPTIONS_PER_TREE = 50

# Aliases are evaluated at run time: typing's spelling keeps them working on Python 3.8.
Word = typing.Tuple[str, bool]
"""A command word and whether it is fully resolved."""


class RobotCache:
    """Expansions made in one run, keyed by (file, args, package roots)."""

    def __init__(self) -> None:
        self._expansions: dict[Hashable, tuple[Expansion, reads.ReadLog]] = {}

    def expansion(self, file: str, args: tuple[tuple[str, str | None], ...],
                  packages: PackageIndex, env: dict[str, str]) -> Expansion:
        key = (file, args, tuple(packages.roots), tuple(sorted(env.items())))

        def expand_file() -> Expansion:
            # Imported when a description is first expanded: xacro (with its interpreter
            # of ${} expressions) is a third of the start-up of a run that meets none.
            from launch_linter.frontends.robot.xacro import expand

            return expand(file, dict(args), packages.find, env)

        # Every launch file that uses the expansion depends on the files it read.
        return reads.remembered(self._expansions, key, expand_file)

    def __len__(self) -> int:
        return len(self._expansions)


XacroCall = typing.Tuple[
    typing.Optional[str], typing.Tuple[typing.Tuple[str, typing.Optional[str]], ...],
    typing.Optional[str],
]


def xacro_command(words: Sequence[Word]) -> XacroCall | None:
    """``(file, args, reason)`` when ``words`` run xacro (``xacro``, ``xacro.py``,
    ``$(find xacro)/xacro``, ``rosrun xacro xacro``, ``--inorder`` and other options
    skipped); None when the command is not xacro. ``file`` is None when unresolved."""
    start = None
    for index, (text, resolved) in enumerate(words[:4]):
        base = text.rstrip("/").rsplit("/", 1)[-1].strip("'\"")
        # An unresolved word that names xacro: FindExecutable(name='xacro') in ROS 2.
        named = not resolved and _XACRO_NAMED.search(text) is not None
        if base in ("xacro", "xacro.py") or named:
            start = index + 1
            if index + 1 < len(words) and words[index + 1][0] in ("xacro", "xacro.py"):
                start = index + 2
            break
    if start is None:
        return None
    file: str | None = None
    reason: str | None = None
    seen_file = False
    args: list[tuple[str, str | None]] = []
    skip = False
    for text, resolved in words[start:]:
        if skip:
            skip = False
            continue
        if text in ("-o", "--output"):
            skip = True
            continue
        if text.startswith("-"):
            continue
        if ":=" in text:
            name, _, value = text.partition(":=")
            args.append((name, value if resolved else None))
            continue
        if not seen_file:
            seen_file = True
            if resolved:
                file = text
            else:
                reason = f"the description file {text!r} is not resolved"
    if not seen_file:
        reason = "the xacro command names no file"
    return file, tuple(args), reason


def literal_kind(text: str) -> bool:
    """Whether a parameter value is a URDF written in place."""
    return "<robot" in text[:4096]


def attach_robot(tree: LaunchTree, packages: PackageIndex, cache: RobotCache | None,
                 display: Callable[[str], str], env: dict[str, str]) -> LaunchTree:
    """The tree with the joints of the descriptions that a robot_state_publisher of the
    tree publishes (in ROS 1 a ``robot_description`` parameter without one is not
    published by this tree), and an ``unresolved`` diagnostic per problem."""
    if not tree.descriptions:
        return tree
    publishes = any(node.package == RSP_PACKAGE for node in tree.nodes)
    if not publishes:
        return tree
    # Imported here, as xacro is in RobotCache: only trees that publish a robot need it.
    from launch_linter.frontends.robot.urdf import joints_of, literal_root

    cache = cache if cache is not None else RobotCache()
    joints: list[RobotJoint] = []
    problems_found: list[Problem] = []
    for source in tree.descriptions[:MAX_DESCRIPTIONS_PER_TREE]:
        if source.kind is DescriptionKind.LITERAL:
            root, problems = literal_root(source.text or "", source.path, source.line)
        elif source.file is None:
            problems_found.append(_unresolved(source, f"robot description not read: "
                                           f"{source.reason or 'unknown file'}"))
            continue
        else:
            args = source.args if source.kind is DescriptionKind.XACRO else ()
            expansion = cache.expansion(os.path.abspath(source.file), args, packages, env)
            root, problems = expansion.root, expansion.problems
        for problem in problems[:20]:
            where = display(problem.path)
            problems_found.append(Problem(
                "unresolved", source.path, source.line, source.column,
                f"robot description {where}:{problem.line}: {problem.message}"
                + ("; its joints are not read" if problem.fatal else ""),
            ))
        if root is not None:
            found = joints_of(root, source, display, source.condition)
            joints.extend(found)
            unknown = [j for j in found if j.reasons]
            for joint in unknown[:20]:
                problems_found.append(Problem(
                    "unresolved", joint.path, joint.line, joint.column,
                    f"URDF joint '{joint.name}' (robot_description at {source.path}:"
                    f"{source.line}): {', '.join(joint.unresolved)} not known: "
                    f"{'; '.join(joint.reasons)[:300]}",
                ))
    return replace(tree, joints=tuple(joints), problems=tree.problems + tuple(problems_found))


def _unresolved(source: DescriptionSource, message: str) -> Problem:
    return Problem("unresolved", source.path, source.line, source.column, message)


def robot_nodes(nodes: Sequence[NodeRecord]) -> list[NodeRecord]:
    return [n for n in nodes if n.package == RSP_PACKAGE]
