"""A simulated camera that stamps its images with a frame that is not an optical frame.

## What it does
Reports a Gazebo camera plugin read from the robot description (gazebo_ros
`libgazebo_ros_camera.so` in ROS 2, `frame_name`, by default the sensor's link; in ROS 1
the camera, depth-camera, multi-camera and openni-kinect plugins, `frameName`; a gz-sim
image sensor's `<gz_frame_id>`, see Known problems) whose image
frame is not REP 103's optical frame of the camera Gazebo renders: the rotation from the
link of the `<gazebo reference="...">` block, turned by the sensor's `<pose>` and its
`<camera>`'s `<pose>` as Gazebo composes them, to the image frame, over the description's
fixed joints and the launch files' static transforms, is not roll -π/2, pitch 0,
yaw -π/2 (z forward, x right, y down). The image frame being the sensor's link itself
(the ROS 2 default) is the commonest case. That rotation proven is a warning; a frame
that no fixed path joins to the sensor's link is reported by its name only, at info, when
the name does not say `optical`. A frame that is no link of the (complete) description,
under any `ns/` prefix, and at no end of an edge of the tree (static transform, URDF joint,
an edge a known node or plugin publishes) is reported at info: nothing in the tree
publishes it, so every tf lookup of the images fails unless another launch does (judged on
110 repositories with Gazebo cameras: 21 true of 29, docs/evaluation/camera_unpublished_frame.md;
the false ones are frames a stack publishes from another repository).

## Why is this bad?
Gazebo renders a camera looking along its link's x axis, and the plugin fills images,
depth images and point clouds in the optical convention (z forward). Stamped with a body
frame (x forward), the data is rotated by 90° twice for everything that transforms it:
point clouds stand on the wall or point into the floor, detections and markers land in
the wrong place.

## Example
```xml
<robot name="r">
  <link name="base_link"/><link name="camera_link"/>
  <joint name="camera_joint" type="fixed">
    <parent link="base_link"/><child link="camera_link"/>
  </joint>
  <gazebo reference="camera_link">
    <sensor name="camera" type="camera">
      <plugin name="camera_controller" filename="libgazebo_ros_camera.so"/>
    </sensor>
  </gazebo>
</robot>
```

## Use instead
```xml
<robot name="r">
  <link name="base_link"/><link name="camera_link"/><link name="camera_link_optical"/>
  <joint name="camera_joint" type="fixed">
    <parent link="base_link"/><child link="camera_link"/>
  </joint>
  <joint name="camera_optical_joint" type="fixed">
    <parent link="camera_link"/><child link="camera_link_optical"/>
    <origin xyz="0 0 0" rpy="-1.5707963 0 -1.5707963"/>
  </joint>
  <gazebo reference="camera_link">
    <sensor name="camera" type="camera">
      <plugin name="camera_controller" filename="libgazebo_ros_camera.so">
        <frame_name>camera_link_optical</frame_name>
      </plugin>
    </sensor>
  </gazebo>
</robot>
```

## Known problems
A gz-sim image sensor (no plugin; `camera`, `rgbd_camera`, `depth_camera`, ...) is read
when it names its images' frame: its camera's `<optical_frame_id>`, else the sensor's
`<gz_frame_id>` (before it `<ignition_frame_id>`), as gz-sensors stamps them; without one
its images carry the sensor's scoped name, no tf frame, and with the newest `<frame_id>`
it is not read. Drivers of real cameras (realsense, openni) publish
their own optical frames and are not checked. The rotation is proven only for a
sensor link whose tf frame is where Gazebo has the link: the child of a URDF joint, or of
an edge a known node or plugin publishes (odometry, the model's own pose). A root link
that a static transform places, or nothing does (a camera model spawned on its own and
moved by a simulator, a description linted alone), stands in tf where that transform
says and in Gazebo where the model is put: judged by the name only, at info
(autonomous_exploration_development_environment's camera model against its launch
files' static `sensor -> camera` at the optical rotation; precision-trial6.md). A
path through a movable joint (a
pan-tilt unit), a pose with attributes (`relative_to`, `degrees`) and a multicamera whose
cameras turn differently leave the rotation unknown: judged by the name only, at info.
A joint whose origin is an `<insert_block>` without the `xacro:` prefix has an unknown
origin unless `--ros-distro` says which xacro reads it (before 1.14, Melodic and older,
it inserts the block; later versions drop it).
Judged on 94 whole public repositories (robot descriptions with Gazebo cameras, simulation
stacks; docs/evaluation/tree_judged.jsonl): the proven-rotation findings are 20 true and 1
harmless of 21 (95%; with rotors_simulator's one judged before); 10 false ones before two
fixes (the sensor's and camera's `<pose>` not read: baxter's hand cameras; an Indigo xacro
macro's unprefixed `<insert_block>`: mastering_ros); 5 of the 21, all true, are from
repositories fetched after those fixes. The name-only findings are 9 true of 19 (with
rotors' 2; hsr_description's 8 name optical frames that its stack publishes elsewhere,
`*_rgb_frame`, `*_camera_frame`; tianracer's 2 name its optical frame without the
description's prefix): info. None on the corpus (it holds no descriptions).
"""

from __future__ import annotations

from collections.abc import Iterator

from launch_linter.knowledge.publish import frames_named
from launch_linter.model.diagnostic import Category, Severity
from launch_linter.model.record import replace
from launch_linter.model.robot import NodeRecord, pose_turn
from launch_linter.rules._api import Finding, RuleContext
from launch_linter.rules._nodes import entry_of, finding_at_node, nodes_of
from launch_linter.rules._tree import (
    Edge,
    Quaternion,
    as_written,
    edges_of,
    quaternion_from_ypr,
    same_rotation,
)

ID = "camera_frame_not_optical"
CATEGORY = Category.TF
SEVERITY = Severity.WARNING
EXAMPLE_PATH = "example.urdf"

SENSOR_LINK = "gazebo_reference"
"""The parameter the description reader gives a plugin: the link of its ``<gazebo>``."""
SENSOR_POSE = "gazebo_sensor_pose"
"""The parameter it gives a sensor's plugin: the poses that turn the camera in that link
(``frontends/robot/urdf.py``, ``SENSOR_POSE_PARAM``)."""
OPTICAL = quaternion_from_ypr(-1.5707963267948966, 0.0, -1.5707963267948966)
IDENTITY: Quaternion = (0.0, 0.0, 0.0, 1.0)
MAX_DEPTH = 64
UNPUBLISHED_LEVEL = Severity.INFO
"""A camera frame no link of a complete description and nothing in the tree publishes."""


def compose(a: Quaternion, b: Quaternion) -> Quaternion:
    """The Hamilton product: ``b`` expressed in the frame ``a`` turns to."""
    ax, ay, az, aw = a
    bx, by, bz, bw = b
    return (aw * bx + ax * bw + ay * bz - az * by,
            aw * by - ax * bz + ay * bw + az * bx,
            aw * bz + ax * by - ay * bx + az * bw,
            aw * bw - ax * bx - ay * by - az * bz)


def _inverse(q: Quaternion) -> Quaternion:
    return (-q[0], -q[1], -q[2], q[3])


def _ancestors(frame: str, parents: dict[str, Edge]) -> list[tuple[str, Edge | None]]:
    """``frame`` and its ancestors up to its root, each with the edge to its parent."""
    out: list[tuple[str, Edge | None]] = []
    seen: set[str] = set()
    while frame not in seen and len(out) < MAX_DEPTH:
        seen.add(frame)
        edge = parents.get(frame)
        out.append((frame, edge))
        if edge is None:
            break
        frame = edge.parent
    return out


def _down_to(chain: list[tuple[str, Edge | None]], ancestor: str) -> Quaternion | None:
    """The rotation of the chain's first frame in ``ancestor`` (None when an edge on the
    way is movable or its rotation unknown)."""
    rotation: Quaternion = IDENTITY
    for name, edge in chain:
        if name == ancestor:
            return rotation
        if edge is None or edge.rotation is None or (
                edge.joint is not None and edge.joint.dynamic):
            return None
        rotation = compose(edge.rotation, rotation)
    return None


def parents_of(edges: tuple[Edge, ...]) -> dict[str, Edge]:
    """Each frame's (first) edge to its parent."""
    parents: dict[str, Edge] = {}
    for edge in edges:
        parents.setdefault(edge.child, edge)
    return parents


def relative_rotation(body: str, frame: str, parents: dict[str, Edge]) -> Quaternion | None:
    """The rotation of ``frame`` in ``body`` over the tree's fixed edges (``parents``:
    :func:`parents_of`); None when no fixed, known path joins them."""
    if body == frame:
        return IDENTITY
    body_chain, frame_chain = _ancestors(body, parents), _ancestors(frame, parents)
    body_names = {name for name, _ in body_chain}
    common = next((name for name, _ in frame_chain if name in body_names), None)
    if common is None:
        return None
    body_rotation, frame_rotation = _down_to(body_chain, common), _down_to(frame_chain, common)
    if body_rotation is None or frame_rotation is None:
        return None
    return compose(_inverse(body_rotation), frame_rotation)


def camera_in_link(node: NodeRecord) -> Quaternion | None:
    """The rotation of the rendering camera in its sensor's link: the sensor's ``<pose>``
    then its camera's, as Gazebo composes them (identity without either); None when a pose
    is not six known numbers."""
    given = node.given(SENSOR_POSE)
    if given is None:
        return IDENTITY
    rotation: Quaternion = IDENTITY
    for pose in given.split(";"):
        turn = pose_turn(pose)
        if turn is None:
            return None
        roll, pitch, yaw = turn
        rotation = compose(rotation, quaternion_from_ypr(yaw, pitch, roll))
    return rotation


def _camera_frames(context: RuleContext, node: NodeRecord) -> list[tuple[str, str]]:
    entry = entry_of(context, node)
    if entry is None or not entry.camera_frames:
        return []
    return frames_named(entry, node, entry.camera_frames)


def plugins_of(context: RuleContext) -> list[tuple[NodeRecord, frozenset[str] | None]]:
    """The plugins of every description the tree reads (spawned or not: the fault is the
    description's), once each, in the tree's ROS version where the plugin does not say,
    each with the links of its description when that is complete (None otherwise); not a
    sensor's whose ``<gazebo reference>`` names no link of a complete description."""
    ros = next((n.ros for n in context.tree.nodes if n.ros is not None), None)
    seen: set[tuple[str, int]] = set()
    out: list[tuple[NodeRecord, frozenset[str] | None]] = []
    for robot in context.tree.robots:
        links = frozenset(e.name for e in robot.elements if e.kind == "link" and e.name)
        for plugin in robot.plugins:
            reference = plugin.given(SENSOR_LINK)
            if robot.complete and reference is not None and reference not in links:
                # Gazebo attaches a <gazebo reference> block to the link of that name: with
                # no such link (proven: the description is complete) no sensor is made.
                continue
            if (plugin.path, plugin.line) not in seen:
                seen.add((plugin.path, plugin.line))
                out.append((plugin if plugin.ros is not None or ros is None
                            else replace(plugin, ros=ros), links if robot.complete else None))
    return out


def _published(context: RuleContext) -> frozenset[str]:
    """Every frame at an end of an edge of the tree: static transforms, URDF joints (as
    published and as written) and the edges known nodes (Gazebo plugins included) publish."""
    edges = edges_of(context)
    frames = {end for edge in edges + tuple(as_written(e) for e in edges)
              for end in (edge.parent, edge.child)}
    frames.update(end for edge in nodes_of(context).edges for end in (edge.parent, edge.child))
    return frozenset(frame.lstrip("/") for frame in frames)


def _unpublished(frame: str, links: frozenset[str] | None,
                 published: frozenset[str]) -> bool:
    """Whether ``frame`` is proven to be no link of the plugin's complete description
    and no frame of the tree's edges. A ``prefix/`` on either side is not read as another
    frame: a ROS 1 plugin resolves its frame with the ``tf_prefix`` its namespace finds
    (gazebo_ros's camera utilities, ``tf::resolve``), and descriptions prefix their links
    with a namespace (``${namespace}/camera_link``)."""
    if links is None or frame in published or frame in links:
        return False
    ending = "/" + frame
    return frame.rpartition("/")[2] not in links and not any(
        link.endswith(ending) for link in links)


def _placed(context: RuleContext) -> frozenset[str]:
    """The links whose tf frame is where Gazebo has the link: the child of a URDF joint
    (robot_state_publisher sends the description's own placement) or of an edge a known
    node or plugin publishes (odometry: the model's pose). A root link placed by a static
    transform, or by nothing, stands in tf wherever that transform says, while Gazebo has
    it wherever the model is spawned or moved: no file ties the two together."""
    joints = {as_written(e).child for e in edges_of(context) if e.joint is not None}
    tracked = {e.child for e in nodes_of(context).edges}
    return frozenset(frame.lstrip("/") for frame in joints | tracked)


def check(context: RuleContext) -> Iterator[Finding]:
    plugins = plugins_of(context)
    if not plugins:
        return
    # The plugins name the description's links as written, before any publisher's prefix.
    parents = parents_of(tuple(as_written(e) for e in edges_of(context)))
    placed = _placed(context)
    published: frozenset[str] | None = None
    for node, links in plugins:
        body = node.given(SENSOR_LINK)
        if body is not None and body.lstrip("/") not in placed:
            # The rotation below is the image frame's in tf against the link in Gazebo:
            # unknown when nothing ties the link's tf frame to where Gazebo has it.
            body = None
        camera = camera_in_link(node)
        for frame, param in _camera_frames(context, node):
            frame = frame.lstrip("/")
            rotation = (None if body is None or camera is None
                        else relative_rotation(body, frame, parents))
            if rotation is not None and camera is not None:
                rotation = compose(_inverse(camera), rotation)
                if same_rotation(rotation, OPTICAL, 1e-3):
                    continue
                turned = "" if camera == IDENTITY else " (and the sensor's <pose>)"
                if frame == body:
                    what = "its sensor link itself" + (
                        ", which the sensor's <pose> does not turn into the optical frame"
                        if turned else "")
                else:
                    what = (f"not rotated from its sensor link '{body}'{turned} by the "
                            f"optical rotation")
                axis = "the sensor's" if turned else "the link's"
                base = f"the sensor's pose in '{body}'" if turned else f"'{body}'"
                yield finding_at_node(
                    node,
                    f"camera plugin {node.plugin} stamps its images with '{frame}' "
                    f"({param}), which is {what}: Gazebo renders along {axis} x axis "
                    f"and fills the data z forward (REP 103); stamp them with a child "
                    f"frame of {base} at rpy \"-pi/2 0 -pi/2\"",
                )
                continue
            if published is None:
                published = _published(context)
            if _unpublished(frame, links, published):
                yield replace(finding_at_node(
                    node,
                    f"camera plugin {node.plugin} stamps its images with '{frame}' "
                    f"({param}), which is no link of the robot description and which "
                    f"nothing in this tree publishes: every tf lookup of the images "
                    f"fails; add that frame to the description (a fixed joint from the "
                    f"sensor's link at rpy \"-pi/2 0 -pi/2\") or stamp them with one it has",
                ), severity=UNPUBLISHED_LEVEL)
            elif "optical" not in frame:
                # Only the name speaks here: a frame another package publishes may be an
                # optical frame named otherwise (hsr_description's *_rgb_frame).
                yield replace(finding_at_node(
                    node,
                    f"camera plugin {node.plugin} stamps its images with '{frame}' "
                    f"({param}), whose name does not say optical and whose rotation from "
                    f"the sensor's link is not known: camera data is in the optical "
                    f"convention (REP 103, z forward)",
                ), severity=Severity.INFO)
