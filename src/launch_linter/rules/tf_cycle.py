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
from __future__ import annotations

from collections.abc import Iterator

from launch_linter.model.diagnostic import Category, Severity
from launch_linter.model.transform import StaticTransform
from launch_linter.rules._api import Finding, RuleContext, can_coexist, finding_at, place

ID = "tf_cycle"
CATEGORY = Category.TF
SEVERITY = Severity.ERROR

MAX_LOOPS = 100
MAX_STEPS = 100_000


class _Search:
    """Simple loops, each found once from its earliest frame (Johnson's ordering trick)."""

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
        for start in self.order:
            self._walk(start, start, [], [])
        return self.loops

    def _walk(
        self, start: str, frame: str, frames: list[str], path: list[StaticTransform]
    ) -> None:
        for child, edge in self.edges.get(frame, ()):
            self.steps += 1
            if len(self.loops) >= MAX_LOOPS or self.steps > MAX_STEPS:
                return
            if not all(can_coexist(edge, other) for other in path):
                continue
            if child == start:
                self.loops.setdefault((*frames, frame), (*path, edge))
            elif self.order[child] > self.order[start] and child not in frames:
                self._walk(start, child, [*frames, frame], [*path, edge])


def check(context: RuleContext) -> Iterator[Finding]:
    position = {id(t): i for i, t in enumerate(context.tree.transforms)}
    for frames, edges in _Search(context.tree.transforms).run().items():
        closing = max(edges, key=lambda t: position[id(t)])
        others = [t for t in edges if t is not closing]
        loop = " -> ".join((*frames, frames[0]))
        conditional = any(not t.condition.always for t in edges)
        form = "may form" if conditional else "form"
        where = ", ".join(place(t, closing) for t in others)
        yield finding_at(closing,
            f"static transforms {form} a loop {loop} (with {where}): tf frames must form a "
            f"tree, and tf2 fails every lookup through the loop",
            others,
        )
