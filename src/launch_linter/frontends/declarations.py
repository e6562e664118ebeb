"""The parameters the tree's workspace nodes declare, attached to the tree once per run.

Only ROS 2 nodes given parameters are looked at, and only their packages found in source
(``workspace/node_declarations.py`` reads the executable's sources); each (package folder,
executable) is read once per run (the package index's life), and every tree that uses it
depends on what that read (``resolve.reads``).
"""

from __future__ import annotations

import functools
import os
import weakref

from launch_linter.model.launch import LaunchTree, NodeDeclarations
from launch_linter.model.record import replace
from launch_linter.resolve import reads
from launch_linter.workspace.node_declarations import declared_in_part, declared_parameters
from launch_linter.workspace.packages import PackageIndex, manifest_name

_STORES: weakref.WeakKeyDictionary[
    PackageIndex,
    dict[tuple[str, str], tuple[tuple[tuple[str, ...], str, bool] | None, reads.ReadLog]],
] = weakref.WeakKeyDictionary()


def attach_declarations(tree: LaunchTree, packages: PackageIndex) -> LaunchTree:
    """``tree`` with the declarations of its ROS 2 nodes that are given parameters."""
    store = _STORES.setdefault(packages, {})
    found: dict[tuple[str, str], NodeDeclarations] = {}
    for node in tree.nodes:
        if (node.kind != "node" or node.ros != 2 or node.plugin is not None
                or not node.params or not node.package or not node.executable):
            continue
        key = (node.package, node.executable)
        if key in found:
            continue
        root = packages.find(node.package) or _own_package(packages, node.path, node.package)
        if root is None:
            continue
        declared = reads.remembered(store, (root, node.executable),
                                    functools.partial(_declarations, root, node.executable))
        if declared is not None:
            found[key] = NodeDeclarations(node.package, node.executable, *declared)
    return replace(tree, declarations=tuple(found.values())) if found else tree


def _declarations(root: str, executable: str) -> tuple[tuple[str, ...], str, bool] | None:
    """(names, source, complete): every name the node declares, else those it surely
    declares (``declared_in_part``), else None."""
    complete = declared_parameters(root, executable)
    if complete is not None:
        return (*complete, True)
    part = declared_in_part(root, executable)
    return None if part is None else (*part, False)


def _own_package(packages: PackageIndex, path: str, package: str) -> str | None:
    """The folder of the package holding the launch file ``path`` when it is ``package``
    (a node of the launch file's own package, found without a package path)."""
    manifest = packages.package_xml_of(path)
    if manifest is None or manifest_name(manifest) != package:
        return None
    return os.path.dirname(manifest)
