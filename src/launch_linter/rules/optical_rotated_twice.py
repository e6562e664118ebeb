"""An optical frame rotated by REP 103's optical rotation twice on its way from its body frame.

## What it does
Reports a fixed edge of the tf tree (a URDF joint or a static transform) that turns its
parent by REP 103's optical rotation (roll -π/2, pitch 0, yaw -π/2; the quaternion
(-0.5, 0.5, -0.5, 0.5), either sign, within 1e-3) when that parent is itself already
turned by exactly the optical rotation from a frame above it, over fixed edges whose
rotations are all known: the child ends up rotated twice, (0.5, -0.5, 0.5, 0.5) from
the body frame, which is no optical orientation. The finding is at the second rotation,
with the first as related place. It is a warning when the child's name says `optical` and
a camera of the linted files stamps its data in a frame the rotation turned (the child,
or a frame between the two rotations): a Gazebo camera plugin of a description the tree
reads, or a camera driver the knowledge base lists with its frame parameters. Otherwise
it is info: a child whose name does not tell its role, or frames no camera of the linted
files is known to use (a description whose camera the simulator's own model or an
unknown driver stamps, a test asset), where the finding says so.

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
when a simulator plugin stamps it. Judged in docs/evaluation/camera_frames.md.
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
    camera_frames,
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
"""A child whose name does not say it is an optical frame, or twice-turned frames no
camera of the linted files is known to stamp its data in."""


def _optical(edge: Edge) -> bool:
    return (not edge.dynamic and edge.rotation is not None
            and same_rotation(edge.rotation, OPTICAL, 1e-3))


def _first_rotation(edge: Edge, parents: dict[str, list[Edge]]
                    ) -> tuple[Edge, list[str]] | None:
    """The edge above ``edge`` at whose child the optical rotation, composed down to
    ``edge``'s parent over fixed edges of known rotation, is complete, with the frames
    that rotation turned (``edge``'s child up to the first edge's child); None when the
    frames above do not give exactly the optical rotation."""
    rotation: Quaternion = IDENTITY
    frame = edge.parent
    seen = {edge.child}
    turned = [edge.child]
    first: Edge | None = None
    for _ in range(MAX_DEPTH):
        if frame in seen:
            return None
        seen.add(frame)
        turned.append(frame)
        above = next((e for e in parents.get(frame, ()) if coexist(e, edge)), None)
        if above is None or above.dynamic or above.rotation is None:
            return None
        rotation = compose(above.rotation, rotation)
        if first is None and _optical(above):
            first = above
        if same_rotation(rotation, OPTICAL, 1e-3):
            return first or above, turned
        frame = above.parent
    return None


def _stamped(context: RuleContext) -> frozenset[str]:
    """The frames the cameras of the linted files stamp their data with: the Gazebo camera
    plugins of the descriptions the tree reads and the known camera drivers it starts."""
    cameras = [plugin for plugin, _ in plugins_of(context)] + list(context.tree.nodes)
    return frozenset(frame.lstrip("/") for node in cameras
                     for frame, _ in camera_frames(context, node))


def _used(turned: list[str], stamped: frozenset[str]) -> bool:
    """Whether a camera stamps one of the ``turned`` frames; a ``prefix/`` on either side
    is not read as another frame (plugins resolve a ``tf_prefix``, descriptions prefix
    their links with a namespace)."""
    return any(frame == name or frame.endswith("/" + name) or name.endswith("/" + frame)
               for frame in stamped for name in (t.lstrip("/") for t in turned))


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
    stamped: frozenset[str] | None = None
    for edge in edges:
        if not _optical(edge):
            continue
        found = _first_rotation(edge, parents)
        if found is None:
            continue
        first, turned = found
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
        stamped = _stamped(context) if stamped is None else stamped
        if _used(turned, stamped):
            yield finding
        else:
            yield replace(finding, severity=UNNAMED_LEVEL, message=(
                f"{finding.message} (no camera of the linted files is known to stamp its "
                f"data in '{edge.child}' or the frames above it that the rotation turned: "
                f"info)"))
