"""Two camera streams of sensors at different places (a stereo pair) stamped with one frame.

## What it does
Reports a node given one frame for two streams that its driver stamps separately because
they come from sensors at different places: the left and right camera of a stereo
driver (the knowledge base's `stream_frames` of the node's entry, each read from the
driver's source). The finding is at the parameter that repeats the other's frame, with
the other as related place; two values left at the driver's own defaults are never
reported (the driver gives them different defaults).
A node the knowledge base does not list is reported at info when two of its parameters
named alike but for `left` and `right` (`left_frame_id`/`right_frame_id`,
`left/frame_id`/`right/frame_id`) and naming a frame (`frame` in the name) are given
one value: the names alone say they are two cameras' frames. Two cameras that stamp one
frame are reported at info too: two known camera drivers, or two simulated camera
sensors (Gazebo camera plugins of the descriptions the tree reads) that do not render
from one place (another `<gazebo reference>` link or another sensor `<pose>`; a colour
and a depth sensor of one RGB-D camera at one place may share a frame), under conditions
that can hold together.

## Why is this bad?
A stereo pair's cameras sit a baseline apart. Stamped with one frame, the right camera's
images and camera_info say they were taken where the left camera is: every consumer
that transforms them (a point cloud from the right camera, a visual odometry that uses
both frames, rviz) puts the right camera's data at the left camera's pose, and a
calibration that ties each image to its own frame no longer holds (zed_cpu_ros#8: the
right camera's `right_frame_id` was given `left_frame`).

## Example
```xml
<launch>
  <node pkg="zed_cpu_ros" type="zed_cpu_ros" name="zed">
    <param name="left_frame_id" value="left_frame"/>
    <param name="right_frame_id" value="left_frame"/>
  </node>
</launch>
```

## Use instead
```xml
<launch>
  <node pkg="zed_cpu_ros" type="zed_cpu_ros" name="zed">
    <param name="left_frame_id" value="left_frame"/>
    <param name="right_frame_id" value="right_frame"/>
  </node>
</launch>
```

## Known problems
Only the drivers whose entries list `stream_frames` are known (a user adds others in the
configuration); a driver that stamps both cameras with one frame by design (Gazebo's
multicamera plugin, whose right camera_info carries the baseline) is not listed. Whether
two cameras sharing a frame sit apart is not computed from the tree (the links' poses
are not compared), so that finding stays at info. Judged in
docs/evaluation/camera_frames.md.
"""

from __future__ import annotations

import re
from collections.abc import Iterator

from launch_linter.knowledge.publish import frames_named
from launch_linter.model.diagnostic import Category, Location, Severity
from launch_linter.model.record import replace
from launch_linter.model.robot import UNKNOWN_VALUE, NodeRecord
from launch_linter.rules._api import Finding, RuleContext
from launch_linter.rules._nodes import entry_of, finding_at_param, twice_included
from launch_linter.rules.camera_frame_not_optical import SENSOR_LINK, SENSOR_POSE, plugins_of

ID = "camera_streams_one_frame"
CATEGORY = Category.TF
SEVERITY = Severity.WARNING
EXAMPLE_PATH = "example.launch"

BY_NAME_LEVEL = Severity.INFO
"""A pair found by its parameters' names alone, for a node the knowledge base does not
list: a heuristic (docs/severity.md); and two cameras sharing a frame, whose places are
not compared (no judged sample yet: docs/evaluation/camera_frames.md)."""
LEFT = re.compile(r"(?<![a-z])left(?![a-z])")
"""``left`` as a word of a parameter name (``left_frame_id``, ``left/frame_id``,
``frame_left``), not inside another word."""


def _place(node: NodeRecord, name: str) -> tuple[Location, ...]:
    """Where ``name`` is set, when that is not the node's element (already related)."""
    where = node.where_set(name)
    if where is None or where == (node.path, node.line, node.column):
        return ()
    return (Location(*where),)


def _message(node: NodeRecord, frame: str, first: str, second: str, why: str) -> str:
    return (f"'{second}' stamps a stream with '{frame}', the frame '{first}' gives the "
            f"other stream of node '{node.name or node.executable}': {why}, so one "
            f"camera's images and camera_info say they were taken where the other camera "
            f"is; give each its own frame")


def _known_pairs(node: NodeRecord, streams: list[tuple[str, str]]) -> Iterator[Finding]:
    first_of: dict[str, str] = {}
    for frame, param in streams:
        frame = frame.lstrip("/")
        first = first_of.setdefault(frame, param)
        if first == param or (node.given(param) is None and node.given(first) is None):
            continue
        # At the parameter the user wrote (the later one when both are given).
        at, other = (param, first) if node.given(param) is not None else (first, param)
        yield finding_at_param(
            node, at, _message(node, frame, other, at,
                               "the driver stamps these streams apart because its "
                               "sensors sit at different places"),
            related=_place(node, other))


def _named_pairs(node: NodeRecord) -> Iterator[Finding]:
    given = {name: value for name, value in node.params if value != UNKNOWN_VALUE}
    for name, value in given.items():
        if "frame" not in name or not LEFT.search(name) or not value.strip("/"):
            continue
        twin = LEFT.sub("right", name)
        if given.get(twin, "").lstrip("/") != value.lstrip("/"):
            continue
        yield replace(finding_at_param(
            node, twin, _message(node, value.lstrip("/"), name, twin,
                                 "the names say they are a left and a right camera"),
            related=_place(node, name)), severity=BY_NAME_LEVEL)


def _cameras(context: RuleContext) -> list[tuple[NodeRecord, str, str]]:
    """Every camera the tree runs with the frame it stamps and the parameter naming it:
    known camera drivers and the camera plugins of the descriptions it reads (once each;
    a plugin's alternative names for one frame count once)."""
    out: list[tuple[NodeRecord, str, str]] = []
    runs = [(node, None) for node in context.tree.nodes if node.kind == "node"]
    for node, _ in [*runs, *plugins_of(context)]:
        entry = entry_of(context, node)
        if entry is None or not entry.camera_frames:
            continue
        seen: set[str] = set()
        for frame, param in frames_named(entry, node, entry.camera_frames):
            frame = frame.lstrip("/")
            if frame and frame not in seen:
                seen.add(frame)
                out.append((node, frame, param))
    return out


def _same_place(a: NodeRecord, b: NodeRecord) -> bool:
    """Whether two simulated cameras render from one place: one ``<gazebo reference>``
    link and one sensor pose (a colour and a depth sensor of one RGB-D camera)."""
    return (a.kind == b.kind == "gazebo_plugin"
            and a.given(SENSOR_LINK) == b.given(SENSOR_LINK)
            and a.given(SENSOR_POSE) == b.given(SENSOR_POSE))


def _shared(context: RuleContext) -> Iterator[Finding]:
    """Two cameras (drivers or simulated sensors at different places) stamping one frame."""
    first_of: dict[str, tuple[NodeRecord, str]] = {}
    for node, frame, param in _cameras(context):
        first = first_of.setdefault(frame, (node, param))
        other, other_param = first
        if other is node or ((other.path, other.line, other.column) == (
                node.path, node.line, node.column) and twice_included(other, node) is None):
            continue
        if other.condition.excludes(node.condition) or _same_place(other, node):
            continue
        what = node.plugin if node.kind == "gazebo_plugin" else node.name or node.executable
        yield replace(finding_at_param(
            node, param,
            f"camera {what} stamps its images with '{frame}' ({param}), the frame the "
            f"camera at {other.path}:{other.line} ({other_param}) stamps its own with: two "
            f"cameras at different places cannot share one frame; give each its own",
            related=(Location(other.path, other.line, other.column),)),
            severity=BY_NAME_LEVEL)


def check(context: RuleContext) -> Iterator[Finding]:
    if context.study:
        return
    for node in context.tree.nodes:
        if node.kind != "node":
            continue
        entry = entry_of(context, node)
        if entry is not None and len(entry.stream_frames) > 1:
            yield from _known_pairs(node, frames_named(entry, node, entry.stream_frames))
        elif entry is None:
            yield from _named_pairs(node)
    yield from _shared(context)
