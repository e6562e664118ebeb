"""From the ``robot_description`` a launch file gives to the URDF joints it publishes.

Front-ends record :class:`DescriptionSource`s (where, which file, which xacro args) and
:class:`NodeRecord`s; :func:`attach_robot` expands each description once per run (the
:class:`RobotCache` keys expansions by file, args and package roots) and adds its joints
to the tree, so rules see launch static transforms and URDF joints together.
"""

from __future__ import annotations

import os
from dataclasses import replace
from typing import Callable, Dict, List, Optional, Sequence, Tuple

from launch_linter.frontends.robot.urdf import joints_of, literal_root
from launch_linter.frontends.robot.xacro import Expansion, expand
from launch_linter.model.diagnostic import Category, Diagnostic, Severity
from launch_linter.model.launch import LaunchTree
from launch_linter.model.robot import DescriptionKind, DescriptionSource, NodeRecord, RobotJoint
from launch_linter.resolve.packages import PackageIndex

RSP_PACKAGE = "robot_state_publisher"
MAX_DESCRIPTIONS_PER_TREE = 50

Word = Tuple[str, bool]
"""A command word and whether it is fully resolved."""


class RobotCache:
    """Expansions made in one run, keyed by (file, args, package roots)."""

    def __init__(self) -> None:
        self._expansions: Dict[Tuple[object, ...], Expansion] = {}

    def expansion(self, file: str, args: Tuple[Tuple[str, Optional[str]], ...],
                  packages: PackageIndex, env: Dict[str, str]) -> Expansion:
        key = (file, args, tuple(packages.roots), tuple(sorted(env.items())))
        found = self._expansions.get(key)
        if found is None:
            found = self._expansions[key] = expand(file, dict(args), packages.find, env)
        return found

    def __len__(self) -> int:
        return len(self._expansions)


def xacro_command(words: Sequence[Word]) -> Optional[Tuple[Optional[str],
                                                           Tuple[Tuple[str, Optional[str]], ...],
                                                           Optional[str]]]:
    """``(file, args, reason)`` when ``words`` run xacro (``xacro``, ``xacro.py``,
    ``$(find xacro)/xacro``, ``rosrun xacro xacro``, ``--inorder`` and other options
    skipped); None when the command is not xacro. ``file`` is None when unresolved."""
    start = None
    for index, (text, _) in enumerate(words[:4]):
        base = text.rstrip("/").rsplit("/", 1)[-1].strip("'\"")
        if base in ("xacro", "xacro.py"):
            start = index + 1
            if index + 1 < len(words) and words[index + 1][0] in ("xacro", "xacro.py"):
                start = index + 2
            break
    if start is None:
        return None
    file: Optional[str] = None
    reason: Optional[str] = None
    seen_file = False
    args: List[Tuple[str, Optional[str]]] = []
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


def attach_robot(tree: LaunchTree, packages: PackageIndex, cache: Optional[RobotCache],
                 display: Callable[[str], str], env: Dict[str, str]) -> LaunchTree:
    """The tree with the joints of the descriptions that a robot_state_publisher of the
    tree publishes (in ROS 1 a ``robot_description`` parameter without one is not
    published by this tree), and an ``unresolved`` diagnostic per problem."""
    if not tree.descriptions:
        return tree
    publishes = any(node.package == RSP_PACKAGE for node in tree.nodes)
    if not publishes:
        return tree
    cache = cache if cache is not None else RobotCache()
    joints: List[RobotJoint] = []
    diagnostics: List[Diagnostic] = []
    for source in tree.descriptions[:MAX_DESCRIPTIONS_PER_TREE]:
        if source.kind is DescriptionKind.LITERAL:
            root, problems = literal_root(source.text or "", source.path, source.line)
        elif source.file is None:
            diagnostics.append(_unresolved(source, f"robot description not read: "
                                           f"{source.reason or 'unknown file'}"))
            continue
        else:
            args = source.args if source.kind is DescriptionKind.XACRO else ()
            expansion = cache.expansion(os.path.abspath(source.file), args, packages, env)
            root, problems = expansion.root, expansion.problems
        for problem in problems[:20]:
            where = display(problem.path)
            diagnostics.append(Diagnostic(
                "unresolved", Category.LAUNCH, Severity.INFO, source.path, source.line,
                source.column,
                f"robot description {where}:{problem.line}: {problem.message}"
                + ("; its joints are not read" if problem.fatal else ""),
            ))
        if root is not None:
            joints.extend(joints_of(root, source, display, source.condition))
    return replace(tree, joints=tuple(joints), diagnostics=tree.diagnostics + tuple(diagnostics))


def _unresolved(source: DescriptionSource, message: str) -> Diagnostic:
    return Diagnostic("unresolved", Category.LAUNCH, Severity.INFO, source.path, source.line,
                      source.column, message)


def robot_nodes(nodes: Sequence[NodeRecord]) -> List[NodeRecord]:
    return [n for n in nodes if n.package == RSP_PACKAGE]
