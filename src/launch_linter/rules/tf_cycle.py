"""Static transforms that form a loop.

## What it does
Follows includes and conditions through the whole launch tree, builds the graph of static
transforms (parent → child, frame ids compared without one leading `/`) and reports each
loop, such as `map -> odom` together with `odom -> map`. The diagnostic is on the transform
that closes the loop (the last one in the tree) and points at the others. When a transform
of the loop is only launched under a condition the linter cannot decide, the message says
the transforms *may* form a loop; transforms under mutually exclusive conditions never do.

## Why is this bad?
tf frames must form a tree. In a loop every frame has a parent, so there is no root:
tf2 fails every lookup that walks into the loop ("the tf tree is invalid because it
contains a loop"). A loop usually means one transform has its frames swapped, or the same
relation is declared in both directions.

## Example
```xml
<launch>
  <node pkg="tf2_ros" type="static_transform_publisher" name="map_to_odom"
        args="0 0 0 0 0 0 map odom"/>
  <node pkg="tf2_ros" type="static_transform_publisher" name="odom_to_map"
        args="0 0 0 0 0 0 odom map"/>
</launch>
```

## Use instead
```xml
<launch>
  <node pkg="tf2_ros" type="static_transform_publisher" name="map_to_odom"
        args="0 0 0 0 0 0 map odom"/>
</launch>
```

## Known problems
Only static transforms are seen. A very large, densely connected graph is searched for at
most a bounded number of loops.
"""

from collections.abc import Iterator

from launch_linter.model.diagnostic import Category, Severity
from launch_linter.model.transform import StaticTransform
from launch_linter.rules._api import (
    MAX_LISTED,
    MAX_RELATED,
    Finding,
    RuleContext,
    can_coexist,
    finding_at,
    place,
    summarised,
)

ID = "tf_cycle"
CATEGORY = Category.TF
SEVERITY = Severity.ERROR

MAX_LOOPS = 100
MAX_STEPS = 2_000_000
"""Edges followed plus transforms compared, for the whole search (a dense graph has very
many loops; the search stops there)."""


class _Search:
    """Simple loops, each found once from its earliest frame (Johnson's ordering trick).

    Both passes are iterative, so a chain of thousands of frames cannot exhaust Python's
    stack: strongly connected components first (only frames inside a component with more
    than one frame can be on a loop), then a depth-first search with an explicit stack,
    charged per edge and per transform compared.
    """

    def __init__(self, transforms: tuple[StaticTransform, ...]) -> None:
        self.order: dict[str, int] = {}
        self.edges: dict[str, list[tuple[str, StaticTransform]]] = {}
        for transform in transforms:
            signature = transform.signature
            if signature is None or signature[0] == signature[1]:
                continue
            parent, child = signature
            for frame in signature:
                self.order.setdefault(frame, len(self.order))
            self.edges.setdefault(parent, []).append((child, transform))
        self.loops: dict[tuple[str, ...], tuple[StaticTransform, ...]] = {}
        self.steps = 0

    def run(self) -> dict[tuple[str, ...], tuple[StaticTransform, ...]]:
        component = strongly_connected(self.order, self.edges)
        sizes: dict[int, int] = {}
        for number in component.values():
            sizes[number] = sizes.get(number, 0) + 1
        for start in self.order:
            if sizes[component[start]] > 1:
                self._search(start, component)
        return self.loops

    def _search(self, start: str, component: dict[str, int]) -> None:
        home = component[start]
        frames = [start]
        on_path = {start}
        path: list[StaticTransform] = []
        stack = [iter(self.edges.get(start, ()))]
        while stack:
            if len(self.loops) >= MAX_LOOPS or self.steps > MAX_STEPS:
                return
            step = next(stack[-1], None)
            if step is None:
                stack.pop()
                on_path.discard(frames.pop())
                if path:
                    path.pop()
                continue
            child, edge = step
            self.steps += 1
            if component[child] != home:
                continue
            if not edge.condition.always:
                # Only a conditional transform can exclude one already on the path.
                self.steps += len(path)
                if not all(can_coexist(edge, o) for o in path):
                    continue
            if child == start:
                self.loops.setdefault(tuple(frames), (*path, edge))
            elif self.order[child] > self.order[start] and child not in on_path:
                frames.append(child)
                on_path.add(child)
                path.append(edge)
                stack.append(iter(self.edges.get(child, ())))


def strongly_connected(
    order: dict[str, int], edges: dict[str, list[tuple[str, StaticTransform]]]
) -> dict[str, int]:
    """Frame -> number of its strongly connected component (Tarjan's algorithm, iterative)."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    component: dict[str, int] = {}
    stack: list[str] = []
    on_stack: set[str] = set()
    count = 0
    for root in order:
        if root in index:
            continue
        work = [(root, iter(edges.get(root, ())))]
        index[root] = low[root] = len(index)
        stack.append(root)
        on_stack.add(root)
        while work:
            frame, children = work[-1]
            step = next(children, None)
            if step is not None:
                child = step[0]
                if child not in index:
                    index[child] = low[child] = len(index)
                    stack.append(child)
                    on_stack.add(child)
                    work.append((child, iter(edges.get(child, ()))))
                elif child in on_stack:
                    low[frame] = min(low[frame], index[child])
                continue
            work.pop()
            if work:
                parent = work[-1][0]
                low[parent] = min(low[parent], low[frame])
            if low[frame] == index[frame]:
                while True:
                    member = stack.pop()
                    on_stack.discard(member)
                    component[member] = count
                    if member == frame:
                        break
                count += 1
    return component


def check(context: RuleContext) -> Iterator[Finding]:
    position = {id(t): i for i, t in enumerate(context.tree.transforms)}
    for frames, edges in _Search(context.tree.transforms).run().items():
        closing = max(edges, key=lambda t: position[id(t)])
        others = [t for t in edges if t is not closing]
        loop = " -> ".join(summarised([*frames, frames[0]], MAX_LISTED))
        conditional = any(not t.condition.always for t in edges)
        form = "may form" if conditional else "form"
        where = ", ".join(summarised([place(t, closing) for t in others], MAX_LISTED))
        yield finding_at(closing,
            f"static transforms {form} a loop {loop} (with {where}): tf frames must form a "
            f"tree, and tf2 fails every lookup through the loop",
            others[:MAX_RELATED],
        )
