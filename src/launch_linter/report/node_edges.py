"""The node side of the tf tree in the ``transforms`` output: the edges launched nodes
publish at run time (by the knowledge base) and the frames they look up, in text and as
the additive JSON arrays ``node_edges`` and ``frame_consumers``."""

from __future__ import annotations

from collections.abc import Iterator
from typing import Any

from launch_linter.engine import LintResult
from launch_linter.knowledge import KnowledgeBase, bundled
from launch_linter.model.robot import NodeRecord
from launch_linter.report.escape import printable
from launch_linter.rules._nodes import Lookup, NodeEdge, NodeView, program_of, view_of


def views(result: LintResult, knowledge: KnowledgeBase | None, distro: str | None = None
          ) -> Iterator[tuple[str, NodeView]]:
    base = knowledge if knowledge is not None else bundled()
    for tree in result.trees:
        if tree.nodes:
            yield tree.root, view_of(tree, base, distro)


def _node_json(node: NodeRecord) -> dict[str, Any]:
    return {"path": node.path, "line": node.line, "column": node.column,
            "package": node.package, "executable": node.executable, "name": node.name,
            "kind": node.kind, "plugin": node.plugin,
            "condition": "always" if node.condition.always else "unknown"}


def edge_json(root: str, edge: NodeEdge) -> dict[str, Any]:
    return {**_node_json(edge.node), "root": root, "source": "node", "parent": edge.parent,
            "child": edge.child, "role": edge.role, "dynamic": True,
            "assumed_defaults": edge.assumed, "knowledge": edge.entry.id}


def lookup_json(root: str, lookup: Lookup) -> dict[str, Any]:
    return {**_node_json(lookup.node), "root": root, "frame": lookup.frame,
            "parameter": lookup.param, "knowledge": lookup.entry.id}


def document_part(result: LintResult, knowledge: KnowledgeBase | None,
                  distro: str | None = None) -> dict[str, Any]:
    """``node_edges`` and ``frame_consumers`` of every tree."""
    edges: list[dict[str, Any]] = []
    consumers: list[dict[str, Any]] = []
    for root, view in views(result, knowledge, distro):
        edges.extend(edge_json(root, e) for e in view.edges)
        consumers.extend(lookup_json(root, lookup) for lookup in view.lookups)
    return {"node_edges": edges, "frame_consumers": consumers}


def text_lines(result: LintResult, knowledge: KnowledgeBase | None,
               distro: str | None = None) -> Iterator[str]:
    """``FILE:LINE:COL: node PROGRAM PARENT -> CHILD [role ...]`` and
    ``FILE:LINE:COL: looks up FRAME (param NAME) PROGRAM``; each line through
    :func:`printable` (frames, parameters and programs are a launch file's words)."""
    for _, view in views(result, knowledge, distro):
        for edge in view.edges:
            node = edge.node
            extra = [edge.role]
            if edge.assumed:
                extra.append("defaults assumed: a parameter file is not read")
            if not node.condition.always:
                extra.append(f"when {node.condition.describe()}")
            yield printable(f"{node.path}:{node.line}:{node.column}: node {program_of(node)} "
                            f"{edge.parent} -> {edge.child}  [{'; '.join(extra)}]")
        for lookup in view.lookups:
            node = lookup.node
            yield printable(f"{node.path}:{node.line}:{node.column}: looks up {lookup.frame} "
                            f"(parameter {lookup.param}) {program_of(node)}")
