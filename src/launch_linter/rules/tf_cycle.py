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

import heapq
from collections.abc import Iterable, Iterator
from typing import Dict, List, Tuple

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
    summarised_lazily,
)

ID = "tf_cycle"
CATEGORY = Category.TF
SEVERITY = Severity.ERROR

MAX_LOOPS = 100
MAX_STEPS = 2_000_000
"""Edges followed plus transforms compared, for the whole search (a dense graph has very
many loops; the search stops there)."""

Edges = Dict[str, List[Tuple[str, StaticTransform]]]
"""Parent frame -> (child frame, transform), in tree order."""


class _Component:
    """The frames of a strongly connected component, in frame order, from ``next`` on
    still to be started from; ``inside`` holds those frames."""

    def __init__(self, frames: list[str], edges: Edges) -> None:
        self.frames = frames
        self.next = 0
        self.inside = set(frames)
        self.unconditional = all(
            t.condition.always for frame in frames for _, t in edges.get(frame, ())
        )

    def __lt__(self, other: _Component) -> bool:
        # Never two with one next frame in the queue (components are disjoint); defined
        # so that the queue's tuples always compare.
        return self.frames[self.next] < other.frames[other.next]


class _Search:
    """Simple loops, each found once from its earliest frame (Johnson's algorithm).

    Everything is iterative, so a chain of thousands of frames cannot exhaust Python's
    stack, and nothing is walked again for nothing: the loops through a frame are searched
    for only inside the strongly connected component it is the earliest frame of (frames
    taken in order, a component split again when its earliest frame closed no loop), and
    inside a component of unconditional transforms a frame that cannot lead back to the
    start is blocked until one it leads to can (Johnson's blocking). The whole search is
    charged per edge followed and per transform compared, and stops at ``MAX_STEPS``.
    """

    def __init__(self, transforms: tuple[StaticTransform, ...]) -> None:
        self.order: dict[str, int] = {}
        self.edges: Edges = {}
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

    def _done(self) -> bool:
        return len(self.loops) >= MAX_LOOPS or self.steps > MAX_STEPS

    def run(self) -> dict[tuple[str, ...], tuple[StaticTransform, ...]]:
        # Components by their next frame to start from, earliest first: the starts in
        # frame order.
        pending: list[tuple[int, _Component]] = []
        if len(self.edges) < 2:
            return self.loops  # a loop has two parents at least (most files have one)
        # Only a frame that is a parent and a child can be on a loop (leaves, roots and
        # the frames of independent pairs are never looked at again).
        children = {child for edges in self.edges.values() for child, _ in edges}
        inner = [f for f in self.order if f in children and f in self.edges]
        for part in self._components(inner):
            heapq.heappush(pending, (self.order[part.frames[0]], part))
        while pending and not self._done():
            _, part = heapq.heappop(pending)
            start = part.frames[part.next]
            found = len(self.loops)
            if part.unconditional:
                self._blocking_search(start, part.inside)
            else:
                self._search(start, part.inside)
            # A loop through a later frame avoids the start, so it lies in a component of
            # what remains. After a search that found loops the next frame is likely to
            # close some too: it searches the rest as it is; after a fruitless one the
            # rest is split first (the frames of a closed chain are each left alone).
            part.inside.discard(start)
            part.next += 1
            if len(part.frames) - part.next < 2:
                continue
            rest = [part] if len(self.loops) > found else self._components(
                part.frames[part.next:])
            for piece in rest:
                heapq.heappush(pending, (self.order[piece.frames[piece.next]], piece))
        return self.loops

    def _components(self, frames: list[str]) -> list[_Component]:
        """The strongly connected components of more than one frame among ``frames``
        (in frame order), each in frame order."""
        within = set(frames)
        number = strongly_connected(frames, self.edges, within)
        self.steps += len(frames) + sum(len(self.edges.get(f, ())) for f in frames)
        groups: dict[int, list[str]] = {}
        for frame in frames:
            groups.setdefault(number[frame], []).append(frame)
        return [_Component(group, self.edges) for group in groups.values() if len(group) > 1]

    def _search(self, start: str, inside: set[str]) -> None:
        """Every simple path from ``start`` inside its component, each transform checked
        against the conditions of the path (a conditional transform may exclude one)."""
        frames = [start]
        on_path = {start}
        path: list[StaticTransform] = []
        stack = [iter(self.edges.get(start, ()))]
        while stack:
            if self._done():
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
            if child not in inside:
                continue
            if not edge.condition.always:
                # Only a conditional transform can exclude one already on the path.
                self.steps += len(path)
                if not all(can_coexist(edge, o) for o in path):
                    continue
            if child == start:
                self.loops.setdefault(tuple(frames), (*path, edge))
            elif child not in on_path:
                frames.append(child)
                on_path.add(child)
                path.append(edge)
                stack.append(iter(self.edges.get(child, ())))

    def _blocking_search(self, start: str, inside: set[str]) -> None:
        """``_search`` for a component without conditions, where whether a frame leads back
        to the start does not depend on the path: a frame that did not stays blocked until
        a frame it leads to does (so each is walked once per loop found, not per path)."""
        blocked = {start}
        waiting: dict[str, set[str]] = {}
        """Frame -> the blocked frames to unblock when it is unblocked."""
        frames = [start]
        closed = [False]
        """Per frame of the path: whether a loop was found through it."""
        path: list[StaticTransform] = []
        stack = [iter(self.edges.get(start, ()))]
        while stack:
            if self._done():
                return
            step = next(stack[-1], None)
            if step is None:
                stack.pop()
                frame, found = frames.pop(), closed.pop()
                if path:
                    path.pop()
                if found:
                    _unblock(frame, blocked, waiting)
                    if closed:
                        closed[-1] = True
                else:
                    for child, _ in self.edges.get(frame, ()):
                        if child in inside:
                            waiting.setdefault(child, set()).add(frame)
                continue
            child, edge = step
            self.steps += 1
            if child not in inside:
                continue
            if child == start:
                self.loops.setdefault(tuple(frames), (*path, edge))
                closed[-1] = True
            elif child not in blocked:
                frames.append(child)
                blocked.add(child)
                closed.append(False)
                path.append(edge)
                stack.append(iter(self.edges.get(child, ())))


def _unblock(frame: str, blocked: set[str], waiting: dict[str, set[str]]) -> None:
    work = [frame]
    while work:
        current = work.pop()
        if current in blocked:
            blocked.discard(current)
            work.extend(waiting.pop(current, ()))


def strongly_connected(
    order: Iterable[str], edges: Edges, within: set[str] | None = None
) -> dict[str, int]:
    """Frame -> number of its strongly connected component (Tarjan's algorithm, iterative),
    for the frames of ``order``; with ``within``, only edges between frames of it count."""
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
                if within is not None and child not in within:
                    continue
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
        # Only the places shown are written out: a loop of 50,000 frames lists five.
        where = ", ".join(summarised_lazily((place(t, closing) for t in others), len(others)))
        yield finding_at(closing,
            f"static transforms {form} a loop {loop} (with {where}): tf frames must form a "
            f"tree, and tf2 fails every lookup through the loop",
            others[:MAX_RELATED],
        )
