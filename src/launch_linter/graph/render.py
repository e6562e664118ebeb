"""Graphviz DOT and Mermaid text for a :class:`TfGraph`.

Frame ids and node names come from untrusted launch files: vertices get generated ids
(``f0``, ``f1``, …) and every label is escaped for the target language.
"""

from __future__ import annotations

import json
import textwrap
from dataclasses import dataclass, field

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


CAPTION_COLUMNS = 120
"""Caption lines wrap here: a long message must not make the picture wider than a screen."""


def _wrapped(text: str) -> list[str]:
    """``text``'s lines wrapped at :data:`CAPTION_COLUMNS`, continued with an indent."""
    indent = text[: len(text) - len(text.lstrip(" "))] + "    "
    return [part for line in text.split("\n") for part in textwrap.wrap(
        line, CAPTION_COLUMNS, subsequent_indent=indent, drop_whitespace=True,
        break_on_hyphens=False) or [""]]


def _ids(graph: TfGraph) -> dict[str, str]:
    return {frame.key: f"f{i}" for i, frame in enumerate(graph.frames)}


WIDE_FAN = {"TB": 6, "LR": 14}
"""Children of one frame laid side by side (``TB``: about what a screen's width holds
with their labels) or one above the other (``LR``: a screen's height) before the leaves
wrap onto further ranks."""
MAX_WRAPPED_RANKS = 4


def rank_gaps(graph: TfGraph, direction: str) -> list[int]:
    """Per edge, how many ranks its child lies below its parent (Graphviz ``minlen``).
    A frame with more than ``WIDE_FAN[direction]`` leaf children would make one rank as
    long as all their labels: its leaves are dealt onto up to :data:`MAX_WRAPPED_RANKS`
    ranks instead (what Graphviz's ``unflatten -l`` does); a child with children of its
    own stays on the first rank, so that its subtree keeps its place."""
    parents = {edge.parent for edge in graph.edges}
    leaves: dict[str, list[int]] = {}
    for index, edge in enumerate(graph.edges):
        if edge.child not in parents:
            leaves.setdefault(edge.parent, []).append(index)
    gaps = [1] * len(graph.edges)
    fan = WIDE_FAN[direction]
    for indices in leaves.values():
        if len(indices) <= fan:
            continue
        ranks = min(MAX_WRAPPED_RANKS, -(-len(indices) // fan))
        for position, index in enumerate(indices):
            gaps[index] = 1 + position % ranks
    return gaps


SCREEN = (1920, 1080)
CELL = {"TB": (200, 110), "LR": (300, 70)}
"""About how many pixels a frame with its edge label takes across and along a rank: a
label's width when side by side (``TB``), its height when stacked (``LR``)."""


def _shape(graph: TfGraph) -> tuple[int, int]:
    """(depth, width): the most ranks of a cluster, and the frames on the widest rank of
    each cluster summed (clusters lie side by side across the ranks)."""
    children: dict[str, list[str]] = {}
    for edge in graph.edges:
        children.setdefault(edge.parent, []).append(edge.child)
    is_child = {edge.child for edge in graph.edges}
    cluster_of = {frame.key: frame.cluster for frame in graph.frames}
    widths: dict[int, dict[int, int]] = {}
    level = [key for key in children if key not in is_child]
    seen = set(level)
    depth = 0
    while level:  # breadth-first: the number of frames at each depth of each cluster
        for key in level:
            per_depth = widths.setdefault(cluster_of.get(key, 0), {})
            per_depth[depth] = per_depth.get(depth, 0) + 1
        depth += 1
        level = [c for key in level for c in children.get(key, ()) if c not in seen]
        seen.update(level)
    return depth, sum(max(per_depth.values()) for per_depth in widths.values())


@dataclass
class _Cluster:
    """What placing one cluster needs: its frames per rank, its roots, a deepest frame."""

    depth: int = 0
    width: int = 0
    roots: list[str] = field(default_factory=list)
    deepest: str = ""


def _clusters(graph: TfGraph) -> list[_Cluster]:
    """Each cluster's depth and widest rank (in frames), roots and a deepest frame."""
    shapes = [_Cluster() for _ in range(max(len(graph.clusters), 1))]
    children: dict[str, list[str]] = {}
    for edge in graph.edges:
        children.setdefault(edge.parent, []).append(edge.child)
    is_child = {edge.child for edge in graph.edges}
    for frame in graph.frames:
        if frame.key not in is_child and frame.cluster < len(shapes):
            shapes[frame.cluster].roots.append(frame.key)
    for shape in shapes:
        level, seen = list(shape.roots), set(shape.roots)
        while level:  # breadth-first, as in _shape
            shape.depth += 1
            shape.width = max(shape.width, len(level))
            shape.deepest = level[0]
            level = [c for key in level for c in children.get(key, ()) if c not in seen]
            seen.update(level)
    return shapes


def _grid(shapes: list[_Cluster], direction: str) -> tuple[float, list[list[int]]]:
    """The clusters dealt into rows (``TB``; columns for ``LR``), the deepest together, the
    number per row the one that needs the picture shrunk least to fit a screen; with that
    shrink factor."""
    across, along = CELL[direction]
    screen_across, screen_along = SCREEN if direction == "TB" else SCREEN[::-1]
    # The deepest together: a row is as long as its deepest cluster.
    order = sorted(range(len(shapes)), key=lambda i: -shapes[i].depth)
    best: tuple[float, list[list[int]]] = (float("inf"), [order])
    for per_row in range(1, len(shapes) + 1):
        rows = [order[start:start + per_row] for start in range(0, len(shapes), per_row)]
        wide = max(sum(shapes[i].width for i in row) for row in rows) * across
        long = sum(max(shapes[i].depth for i in row) for row in rows) * along
        scale = max(wide / screen_across, long / screen_along)
        if scale < best[0]:
            best = (scale, rows)
    return best


def cluster_rows(graph: TfGraph, direction: str) -> list[list[int]]:
    """The clusters in rows so that the picture is as close to a screen's shape as it can
    be: side by side, ten arms of a manipulator with many variants made a picture 9,675
    pixels wide."""
    return _grid(_clusters(graph), direction)[1]


def _row_links(graph: TfGraph, direction: str, ids: dict[str, str]) -> list[str]:
    """Invisible edges from the deepest frame of each row of clusters to the roots of the
    next row: Graphviz then lays the rows one after the other."""
    shapes = _clusters(graph)
    rows = cluster_rows(graph, direction)
    lines: list[str] = []
    for above, below in zip(rows, rows[1:]):
        deepest = max(above, key=lambda i: shapes[i].depth)
        for index in below:
            lines.extend(f"  {ids[shapes[deepest].deepest]} -> {ids[root]} [style=invis, weight=0];"
                         for root in shapes[index].roots if shapes[deepest].deepest)
    return lines


def rankdir(graph: TfGraph) -> str:
    """``TB`` or ``LR``, whichever needs the picture shrunk least to fit a screen:
    ``LR`` for a tree wider than deep, as robot descriptions are (a base with a dozen
    parts, then one above the other), ``TB`` for deep narrow ones (arms, chains). Several
    trees are dealt into rows (:func:`cluster_rows`) either way."""
    if len(graph.clusters) > 1:
        shapes = _clusters(graph)
        return "LR" if _grid(shapes, "LR")[0] < _grid(shapes, "TB")[0] else "TB"
    depth, width = _shape(graph)

    def scale(direction: str) -> float:
        across, along = CELL[direction]
        if direction == "TB":
            return max(width * across / SCREEN[0], depth * along / SCREEN[1])
        return max(depth * across / SCREEN[0], width * along / SCREEN[1])

    return "LR" if scale("LR") < scale("TB") else "TB"


def to_dot(graph: TfGraph) -> str:
    """The graph in Graphviz DOT: dashed edges are conditional, red ones have findings."""
    ids = _ids(graph)
    direction = rankdir(graph)
    legend = ("; ".join(graph.legend),) if graph.legend else ()
    caption = "".join(line + "\n" for text in (graph.title, *legend, *graph.notes)
                      for line in _wrapped(text))
    label = _dot_string(caption, LEFT)
    lines = [
        "digraph tf {",
        f"  graph [rankdir={direction}, labelloc=t, labeljust=l, fontname=Helvetica, "
        f"fontsize=12, label={label}];",
        "  node [shape=ellipse, fontname=Helvetica, fontsize=11];",
        "  edge [fontname=Helvetica, fontsize=9];",
    ]
    clustered = len(graph.clusters) > 1
    for cluster in range(max(len(graph.clusters), 1)):
        indent = "  "
        if clustered:
            lines.append(f"  subgraph cluster_{cluster} {{")
            title = _dot_string("\n".join(_wrapped(graph.clusters[cluster])) + "\n", LEFT)
            lines.append(f"    label={title}; labeljust=l; style=rounded;")
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
    for edge, gap in zip(graph.edges, rank_gaps(graph, direction)):
        attributes = [f"label={_dot_string(NEWLINE.join(edge.label))}"]
        if gap > 1:
            attributes.append(f"minlen={gap}")
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
    if clustered:
        lines.extend(_row_links(graph, direction, ids))
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
    direction = rankdir(graph)
    lines = ["---", f"title: {json.dumps(printable(graph.title))}", "---",
             f"flowchart {'TD' if direction == 'TB' else 'LR'}"]
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
    for index, (edge, gap) in enumerate(zip(graph.edges, rank_gaps(graph, direction))):
        # A longer arrow spans more ranks (Mermaid's form of minlen).
        dashed = edge.conditional or edge.dynamic
        arrow = "-" + "." * gap + "->" if dashed else "-" * (gap + 1) + ">"
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
