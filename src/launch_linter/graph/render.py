"""Graphviz DOT and Mermaid text for a :class:`TfGraph`.

Frame ids and node names come from untrusted launch files: vertices get generated ids
(``f0``, ``f1``, …) and every label is escaped for the target language.
"""

from __future__ import annotations

import json

from launch_linter.graph.model import TfGraph
from launch_linter.report.escape import printable

RED = "#c62828"
LEGEND = "red: errors or warnings at the transform; dashed: present only under a condition"
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
    caption = "".join(line + "\n" for line in (graph.title, LEGEND, *graph.notes))
    label = _dot_string(caption, LEFT)
    lines = [
        "digraph tf {",
        f"  graph [rankdir=TB, labelloc=t, labeljust=l, fontname=Helvetica, "
        f"fontsize=12, label={label}];",
        "  node [shape=ellipse, fontname=Helvetica, fontsize=11];",
        "  edge [fontname=Helvetica, fontsize=9];",
    ]
    for frame in graph.frames:
        attributes = [f"label={_dot_string(frame.label)}"]
        if not frame.resolved:
            attributes.append("style=dotted")
        if frame.flagged:
            attributes.append(f'color="{RED}", fontcolor="{RED}", penwidth=2')
        lines.append(f"  {ids[frame.key]} [{', '.join(attributes)}];")
    for edge in graph.edges:
        attributes = [f"label={_dot_string(NEWLINE.join(edge.label))}"]
        if edge.conditional:
            attributes.append("style=dashed")
        if edge.flagged:
            attributes.append(f'color="{RED}", fontcolor="{RED}", penwidth=2')
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
    for frame in graph.frames:
        lines.append(f"  {ids[frame.key]}([{_mermaid_text([frame.label])}])")
    red_links: list[int] = []
    for index, edge in enumerate(graph.edges):
        arrow = "-.->" if edge.conditional else "-->"
        lines.append(
            f"  {ids[edge.parent]} {arrow}|{_mermaid_text(edge.label)}| {ids[edge.child]}"
        )
        if edge.flagged:
            red_links.append(index)
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
    if red_links:
        lines.append(
            f"  linkStyle {','.join(map(str, red_links))} stroke:{RED},color:{RED},stroke-width:2px"
        )
    return "\n".join(lines) + "\n"
