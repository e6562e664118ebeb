"""Graphviz DOT and Mermaid text for a :class:`TfGraph`.

Frame ids and node names come from untrusted launch files: vertices get generated ids
(``f0``, ``f1``, …) and every label is escaped for the target language.
"""

from __future__ import annotations

import json

from launch_linter.graph.model import TfGraph
from launch_linter.report.escape import printable

RED = "#c62828"
BLUE = "#1565c0"
GREY = "#616161"
LEFT = "\\l"
NEWLINE = "\n"


def _dot_string(text: str, line_break: str = "\\n") -> str:
    """A quoted DOT string; ``line_break`` is ``\\n`` (centred) or ``\\l`` (left)."""
    # Control characters, NUL and lone surrogates become visible escapes first (Graphviz
    # stops at a NUL and cannot encode a surrogate); then backslashes, which DOT gives a
    # meaning (\N, \G, \l ...) inside labels.
    lines = (printable(line).replace("\\", "\\\\").replace('"', '\\"')
             for line in text.replace("\r", "").split("\n"))
    return '"' + line_break.join(lines) + '"'


def _ids(graph: TfGraph) -> dict[str, str]:
    return {frame.key: f"f{i}" for i, frame in enumerate(graph.frames)}


def to_dot(graph: TfGraph) -> str:
    """The graph in Graphviz DOT: dashed edges are conditional, red ones have findings."""
    ids = _ids(graph)
    legend = ("; ".join(graph.legend),) if graph.legend else ()
    caption = "".join(line + "\n" for line in (graph.title, *legend, *graph.notes))
    label = _dot_string(caption, LEFT)
    lines = [
        "digraph tf {",
        f"  graph [rankdir=TB, labelloc=t, labeljust=l, fontname=Helvetica, "
        f"fontsize=12, label={label}];",
        "  node [shape=ellipse, fontname=Helvetica, fontsize=11];",
        "  edge [fontname=Helvetica, fontsize=9];",
    ]
    clustered = len(graph.clusters) > 1
    for cluster in range(max(len(graph.clusters), 1)):
        indent = "  "
        if clustered:
            lines.append(f"  subgraph cluster_{cluster} {{")
            lines.append(f"    label={_dot_string(graph.clusters[cluster])}; style=rounded;")
            indent = "    "
        for frame in graph.frames:
            if frame.cluster != cluster and clustered:
                continue
            attributes = [f"label={_dot_string(frame.label)}"]
            if not frame.resolved:
                attributes.append("style=dotted")
            if frame.flagged:
                attributes.append(f'color="{RED}", fontcolor="{RED}", penwidth=2')
            lines.append(f"{indent}{ids[frame.key]} [{', '.join(attributes)}];")
        if clustered:
            lines.append("  }")
    for edge in graph.edges:
        attributes = [f"label={_dot_string(NEWLINE.join(edge.label))}"]
        if edge.conditional or edge.dynamic:
            attributes.append("style=dashed")
        if edge.flagged:
            attributes.append(f'color="{RED}", fontcolor="{RED}", penwidth=2')
        elif edge.source == "urdf":
            attributes.append(f'color="{BLUE}", fontcolor="{BLUE}"')
        else:
            attributes.append(f'fontcolor="{GREY}"')
        if edge.tooltip:
            attributes.append(f"tooltip={_dot_string(edge.tooltip)}")
        lines.append(f"  {ids[edge.parent]} -> {ids[edge.child]} [{', '.join(attributes)}];")
    lines.append("}")
    return "\n".join(lines) + "\n"


_MERMAID_ESCAPES = {
    '"': "#quot;",
    "#": "#35;",
    "&": "#38;",
    "<": "#lt;",
    ">": "#gt;",
    "|": "#124;",
    "`": "#96;",
}


def _mermaid_text(lines: tuple[str, ...] | list[str]) -> str:
    escaped = ["".join(_MERMAID_ESCAPES.get(c, c) for c in printable(line)) for line in lines]
    return '"' + "<br/>".join(escaped) + '"'


def to_mermaid(graph: TfGraph) -> str:
    """The graph as a Mermaid flowchart (renders in GitHub Markdown)."""
    ids = _ids(graph)
    # The front matter is YAML, where a JSON string is a valid double-quoted scalar.
    lines = ["---", f"title: {json.dumps(printable(graph.title))}", "---", "flowchart TD"]
    clustered = len(graph.clusters) > 1
    for cluster in range(max(len(graph.clusters), 1)):
        if clustered:
            lines.append(f"  subgraph c{cluster} [{_mermaid_text([graph.clusters[cluster]])}]")
        for frame in graph.frames:
            if clustered and frame.cluster != cluster:
                continue
            lines.append(f"  {ids[frame.key]}([{_mermaid_text([frame.label])}])")
        if clustered:
            lines.append("  end")
    red_links: list[int] = []
    blue_links: list[int] = []
    for index, edge in enumerate(graph.edges):
        arrow = "-.->" if edge.conditional or edge.dynamic else "-->"
        lines.append(
            f"  {ids[edge.parent]} {arrow}|{_mermaid_text(edge.label)}| {ids[edge.child]}"
        )
        if edge.flagged:
            red_links.append(index)
        elif edge.source == "urdf":
            blue_links.append(index)
    for note_index, note in enumerate(graph.notes):
        lines.append(f"  note{note_index}[{_mermaid_text([note])}]")
    lines.append(f"  classDef flagged stroke:{RED},color:{RED},stroke-width:2px")
    lines.append("  classDef unresolved stroke-dasharray:3 3")
    flagged = [ids[f.key] for f in graph.frames if f.flagged]
    if flagged:
        lines.append(f"  class {','.join(flagged)} flagged")
    unresolved = [ids[f.key] for f in graph.frames if not f.resolved]
    if unresolved:
        lines.append(f"  class {','.join(unresolved)} unresolved")
    if graph.notes:
        lines.append(f"  class {','.join(f'note{i}' for i in range(len(graph.notes)))} flagged")
    if blue_links:
        lines.append(f"  linkStyle {','.join(map(str, blue_links))} stroke:{BLUE},color:{BLUE}")
    if red_links:
        lines.append(
            f"  linkStyle {','.join(map(str, red_links))} stroke:{RED},color:{RED},stroke-width:2px"
        )
    return "\n".join(lines) + "\n"
