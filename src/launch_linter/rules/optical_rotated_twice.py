"""An optical frame rotated by REP 103's optical rotation twice on its way from its body frame.

## What it does
Reports a fixed edge of the tf tree (a URDF joint or a static transform) that turns its
parent by REP 103's optical rotation (roll -π/2, pitch 0, yaw -π/2; the quaternion
(-0.5, 0.5, -0.5, 0.5), either sign, within 1e-3) when that parent is itself already
turned by exactly the optical rotation from a frame above it, over fixed edges whose
rotations are all known: the child ends up rotated twice, (0.5, -0.5, 0.5, 0.5) from
the body frame, which is no optical orientation. The finding is at the second rotation,
with the first as related place. It is a warning when the child's name says `optical` and
a simulated camera of the description renders from the frame the first rotation turns
(a Gazebo camera sensor whose `<gazebo reference>` link is that frame, or a frame fixed
to it without rotation, and whose `<pose>` does not turn it): the camera then looks
along that frame's x axis, and the optical frame is provably turned twice from it.
Otherwise it is info, saying so: a child whose name does not tell its role, or no camera
of the files renders from there. A camera mounted to look along its parent's z axis (a
wrist or tool camera) is turned from its mount by exactly the optical rotation, so two
such rotations in a row are not wrong by themselves.

## Why is this bad?
An optical frame (`*_optical_frame`, z forward, x right, y down) is the camera's body
frame (x forward, y left, z up) turned once by the optical rotation. A description that
already turns the camera's depth or colour frame into the optical orientation and then
adds the optical joint below it rotates the optical frame by 240°: its z axis points
to the camera's right instead of forward, so every image, depth cloud and detection
stamped with it lands sideways (create_autonomy#177: the Astra's depth joint and its
optical joint both carried the rotation).

## Example
```xml
<robot name="r">
  <link name="camera_link"/><link name="camera_depth_frame"/>
  <link name="camera_depth_optical_frame"/>
  <joint name="camera_depth_joint" type="fixed">
    <parent link="camera_link"/><child link="camera_depth_frame"/>
    <origin rpy="-1.5707963 0 -1.5707963"/>
  </joint>
  <joint name="camera_depth_optical_joint" type="fixed">
    <parent link="camera_depth_frame"/><child link="camera_depth_optical_frame"/>
    <origin rpy="-1.5707963 0 -1.5707963"/>
  </joint>
</robot>
```

## Use instead
```xml
<robot name="r">
  <link name="camera_link"/><link name="camera_depth_frame"/>
  <link name="camera_depth_optical_frame"/>
  <joint name="camera_depth_joint" type="fixed">
    <parent link="camera_link"/><child link="camera_depth_frame"/>
  </joint>
  <joint name="camera_depth_optical_joint" type="fixed">
    <parent link="camera_depth_frame"/><child link="camera_depth_optical_frame"/>
    <origin rpy="-1.5707963 0 -1.5707963"/>
  </joint>
</robot>
```

## Known problems
A rotation that is not known (an unresolved value, a movable joint on the way) stops the
walk up: nothing is said. The first rotation is found only when it is exactly the
optical rotation over the edges between (a camera mounted tilted and then turned to
the optical orientation in one joint is not recognised). A camera whose images are
stamped with a frame the optical rotation turned twice is also `camera_frame_not_optical`'s
when a simulator plugin stamps it. A real camera (a driver, not a simulated sensor) never
proves the rendering direction, so its description's double turn stays info. Judged in
docs/evaluation/camera_frames.md and docs/evaluation/samples-round7.md.
"""

from __future__ import annotations

from collections.abc import Iterator

from launch_linter.model.diagnostic import Category, Severity
from launch_linter.model.record import replace
from launch_linter.rules._api import Finding, RuleContext
from launch_linter.rules._tree import (
    Edge,
    Quaternion,
    coexist,
    finding_on,
    same_rotation,
    written_edges,
)
from launch_linter.rules.camera_frame_not_optical import (
    IDENTITY,
    OPTICAL,
    SENSOR_LINK,
    camera_in_link,
    compose,
    plugins_of,
)

ID = "optical_rotated_twice"
CATEGORY = Category.TF
SEVERITY = Severity.WARNING
EXAMPLE_PATH = "example.urdf"

MAX_DEPTH = 64
"""Edges walked up from one edge: a chain longer than any robot's, and a bound on the
work a hostile tree (a path of 20,000 frames) can ask per edge."""
UNNAMED_LEVEL = Severity.INFO
"""A child whose name does not say it is an optical frame, or a first rotation no
simulated camera is known to render along (it may be the camera's mount)."""


def _optical(edge: Edge) -> bool:
    return (not edge.dynamic and edge.rotation is not None
            and same_rotation(edge.rotation, OPTICAL, 1e-3))


def _first_rotation(edge: Edge, parents: dict[str, list[Edge]]) -> Edge | None:
    """The edge above ``edge`` at whose child the optical rotation, composed down to
    ``edge``'s parent over fixed edges of known rotation, is complete; None when the
    frames above do not give exactly the optical rotation."""
    rotation: Quaternion = IDENTITY
    frame = edge.parent
    seen = {edge.child}
    first: Edge | None = None
    for _ in range(MAX_DEPTH):
        if frame in seen:
            return None
        seen.add(frame)
        above = next((e for e in parents.get(frame, ()) if coexist(e, edge)), None)
        if above is None or above.dynamic or above.rotation is None:
            return None
        rotation = compose(above.rotation, rotation)
        if first is None and _optical(above):
            first = above
        if same_rotation(rotation, OPTICAL, 1e-3):
            return first or above
        frame = above.parent
    return None


def _rendering_links(context: RuleContext) -> frozenset[str]:
    """The links simulated cameras render along: each Gazebo camera plugin's sensor link
    (``<gazebo reference>``) whose sensor and camera ``<pose>`` leave the view along the
    link's x axis."""
    links = set()
    for plugin, _ in plugins_of(context):
        link = plugin.given(SENSOR_LINK)
        turn = camera_in_link(plugin)
        if link is not None and turn is not None and same_rotation(turn, IDENTITY, 1e-3):
            links.add(link.lstrip("/"))
    return frozenset(links)


def _renders_from(frame: str, rendering: frozenset[str], edge: Edge,
                  parents: dict[str, list[Edge]]) -> bool:
    """Whether a camera renders along ``frame``: its sensor link is ``frame`` or a frame
    above it joined by fixed edges without rotation."""
    seen: set[str] = set()
    for _ in range(MAX_DEPTH):
        if frame in rendering:
            return True
        if frame in seen:
            return False
        seen.add(frame)
        above = next((e for e in parents.get(frame, ()) if coexist(e, edge)), None)
        if (above is None or above.dynamic or above.rotation is None
                or not same_rotation(above.rotation, IDENTITY, 1e-3)):
            return False
        frame = above.parent
    return False


def _at_origin(edge: Edge, finding: Finding) -> Finding:
    """``finding`` at the joint's ``<origin>``, where the rotation is written (its
    ``<joint>`` line stays a related place)."""
    origin = None if edge.joint is None else edge.joint.origin_at
    if origin is None or edge.joint is None or edge.joint.defined is not None:
        return finding
    return replace(finding, path=origin[0], line=origin[1], column=origin[2],
                   related=(edge.location, *finding.related))


def check(context: RuleContext) -> Iterator[Finding]:
    if context.study:
        return
    edges = written_edges(context)
    parents: dict[str, list[Edge]] = {}
    for edge in edges:
        parents.setdefault(edge.child, []).append(edge)
    rendering: frozenset[str] | None = None
    for edge in edges:
        if not _optical(edge):
            continue
        first = _first_rotation(edge, parents)
        if first is None:
            continue
        finding = _at_origin(edge, finding_on(
            edge,
            f"'{edge.child}' is turned by REP 103's optical rotation (rpy -pi/2 0 -pi/2) "
            f"from '{edge.parent}', which is already turned by it from "
            f"'{first.parent}' ({first.describe()}): the rotation is applied twice, so "
            f"'{edge.child}' looks sideways (z to the camera's right), not along the "
            f"camera; give the optical rotation once between the camera's body frame and "
            f"its optical frame",
            related=(first,),
        ))
        if "optical" not in edge.child:
            yield replace(finding, severity=UNNAMED_LEVEL)
            continue
        rendering = _rendering_links(context) if rendering is None else rendering
        if _renders_from(first.parent, rendering, edge, parents):
            yield finding
        else:
            yield replace(finding, severity=UNNAMED_LEVEL, message=(
                f"{finding.message} (no simulated camera of the files is known to render "
                f"along '{first.parent}': the first rotation may be the camera's mount, "
                f"a camera looking along its mount's z axis is turned exactly so: info)"))
