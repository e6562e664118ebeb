"""URDF joints as tf edges, from a description expanded by :mod:`.xacro` (a plain URDF
file expands to itself)."""

from __future__ import annotations

import math
import typing

from launch_linter.frontends.robot.xacro import ExpandedNode, XacroProblem
from launch_linter.frontends.robot.xacro_values import PLUGIN_TEXT_TAGS
from launch_linter.model.robot import (
    UNKNOWN_VALUE,
    DescriptionSource,
    NodeRecord,
    RobotElement,
    RobotJoint,
    pose_turn,
)
from launch_linter.model.transform import Condition, ConditionLiteral
from launch_linter.resolve.xml_safe import Element, XmlError, parse_xml

Display = typing.Callable[[str], str]  # typing's Callable: a run-time alias (3.8)


def _vector(node: ExpandedNode | None, name: str) -> tuple[tuple[float, float, float] | None,
                                                            str | None]:
    """An origin's ``xyz``/``rpy`` (0 0 0 when absent), or None and why."""
    if node is None or name not in node.attrib:
        return (0.0, 0.0, 0.0), None
    if name in node.unknown:
        return None, node.unknown[name]
    words = node.attrib[name].split()
    if len(words) != 3:
        return None, f"origin {name}={node.attrib[name]!r} is not three numbers"
    try:
        values = tuple(float(w) for w in words)
    except ValueError:
        return None, f"origin {name}={node.attrib[name]!r} is not three numbers"
    if not all(math.isfinite(v) for v in values):
        return None, f"origin {name}={node.attrib[name]!r} is not finite"
    return (values[0], values[1], values[2]), None


def _first(node: ExpandedNode, tag: str) -> ExpandedNode | None:
    for child in node.children:
        if child.tag == tag:
            return child
    return None


def _condition(marks: tuple[str, ...]) -> Condition:
    literals = tuple(
        ConditionLiteral("xacro:" + mark[1:], False) if mark.startswith("!")
        else ConditionLiteral("xacro:" + mark, True)
        for mark in marks
    )
    return Condition(literals)


LEGACY_INSERT = "insert_block"
"""An ``insert_block`` written without the ``xacro:`` prefix, left as an element by an
expansion for an unknown distribution: xacro before 1.14 (ROS Melodic and older) inserts
the block, 1.14 and later keep the element as it is (xacro CHANGELOG 1.14.0, "Require all
xacro commands to be prefixed with 'xacro:'")."""
LEGACY_INSERT_REASON = ("the joint's <origin> is an <insert_block> without the xacro: "
                        "prefix: xacro before 1.14 (Melodic and older) inserts it, later "
                        "versions drop it (--ros-distro decides)")


def joints_of(root: ExpandedNode, source: DescriptionSource, display: Display,
              outer: Condition, distro_known: bool = False) -> list[RobotJoint]:
    """The joints directly under ``<robot>``, as edges of the tf tree. ``distro_known``:
    the target distribution is known, so the expansion read unprefixed xacro tags as its
    xacro does (``xacro_values.legacy_tags``); not known, such an origin is unknown."""
    out: list[RobotJoint] = []
    if root.tag != "robot":
        return out
    for joint in root.children:
        if joint.tag != "joint":
            continue
        unresolved: list[str] = []
        reasons: list[str] = []
        frames: dict[str, str | None] = {}
        child_at = None
        for end in ("parent", "child"):
            element = _first(joint, end)
            if end == "child" and element is not None and joint.call is not None:
                child_at = (display(element.path), element.line, element.column)
            if element is None or "link" not in element.attrib:
                frames[end] = None
                unresolved.append(end)
                reasons.append(f"joint has no <{end} link=...>")
            elif "link" in element.unknown:
                frames[end] = None
                unresolved.append(end)
                reasons.append(element.unknown["link"])
            else:
                frames[end] = element.attrib["link"]
        origin = _first(joint, "origin")
        xyz, why_xyz = _vector(origin, "xyz")
        rpy, why_rpy = _vector(origin, "rpy")
        if origin is None and not distro_known and _first(joint, LEGACY_INSERT) is not None:
            xyz = rpy = None
            unresolved.extend(("translation", "rotation"))
            reasons.append(LEGACY_INSERT_REASON)
        if why_xyz is not None:
            unresolved.append("translation")
            reasons.append(why_xyz)
        if why_rpy is not None:
            unresolved.append("rotation")
            reasons.append(why_rpy)
        # A joint a macro made is shown at the call (the instance a user edits), and
        # its <joint> in the macro as the place it is written.
        at = joint.call or (joint.path, joint.line, joint.column)
        placed = None if origin is None else (
            origin.call or (origin.path, origin.line, origin.column))
        out.append(RobotJoint(
            path=display(at[0]), line=at[1], column=at[2],
            defined=None if joint.call is None else (display(joint.path), joint.line,
                                                     joint.column),
            name=joint.attrib.get("name", ""), joint_type=joint.attrib.get("type", ""),
            parent=frames["parent"], child=frames["child"], translation=xyz, rpy=rpy,
            source=source, condition=outer & _condition(joint.conditions),
            unresolved=tuple(unresolved), reasons=tuple(reasons),
            origin_at=None if placed is None else (display(placed[0]), placed[1], placed[2]),
            child_at=child_at,
        ))
    return out


def elements_of(root: ExpandedNode, display: Display,
                outer: Condition) -> tuple[list[RobotElement], bool]:
    """The links, joints and materials directly under ``<robot>`` by name (as urdfdom
    reads them: a ``<material>`` inside a ``<visual>`` is the link's, not the model's),
    and whether every link name and joint end is known."""
    out: list[RobotElement] = []
    known = True
    if root.tag != "robot":
        return out, False
    for element in root.children:
        if element.tag in OUTSIDE_GAZEBO:
            if not _urdf_sensor(element):
                out.append(_outside_gazebo(element, display, outer))
            continue
        if element.tag == "gazebo" and "reference" in element.attrib:
            out.append(_gazebo_reference(element, display, outer))
            continue
        if element.tag not in ("link", "joint", "material"):
            continue
        # urdfdom keeps a top-level material without a name as '' (its parseMaterial
        # result is not checked), so two of them clash.
        name: str | None = element.attrib.get(
            "name", "" if element.tag == "material" else None)
        if "name" in element.unknown:
            name = None
            known = known and element.tag != "link"
        if element.tag == "joint":
            for end in ("parent", "child"):
                end_element = _first(element, end)
                if end_element is not None and "link" in end_element.unknown:
                    known = False
        at = element.call or (element.path, element.line, element.column)
        defined = (None if element.call is None
                   else (display(element.path), element.line, element.column))
        site = element.included
        included = None if site is None else (display(site[0]), site[1], site[2])
        out.append(RobotElement(element.tag, name, display(at[0]), at[1], at[2],
                                outer & _condition(element.conditions), defined, included))
        if element.tag in ("link", "joint"):
            out.extend(_ignored_origins(element, name, display, outer))
        if element.tag == "joint":
            out.extend(_mimic(element, display, outer))
    return out, known


FOLDED_PLUGIN_TAGS = frozenset(tag.lower() for tag in PLUGIN_TEXT_TAGS)
"""The known plugin parameters in lower case: a plugin element that matches one only so is
a misspelt parameter."""
OUTSIDE_GAZEBO = ("plugin", "sensor")
"""Gazebo's elements that do nothing straight under ``<robot>``: urdfdom skips elements it
does not know, and Gazebo's URDF reader (sdformat's parser_urdf.cc ``ParseSDFExtension``)
takes plugins and sensors only from ``<gazebo>`` elements."""


def _urdf_sensor(element: ExpandedNode) -> bool:
    """Whether a ``<sensor>`` is URDF's own sensor element (wiki.ros.org/urdf/XML/sensor:
    the ``<parent link>`` it is fixed to, an ``<origin>``, a ``<camera>`` or ``<ray>``
    with attributes), which describes the sensor and was never meant for Gazebo, not a
    Gazebo sensor written in the wrong place: SDFormat's ``<sensor>`` has no ``<parent>``
    (its link is the ``<gazebo reference>``)."""
    return element.tag == "sensor" and any(child.tag == "parent" for child in element.children)


def _outside_gazebo(element: ExpandedNode, display: Display,
                    outer: Condition) -> RobotElement:
    """A ``<plugin>`` or ``<sensor>`` straight under ``<robot>``, as an element of kind
    ``outside_gazebo`` named ``<tag> 'filename-or-name'`` (``<tag>`` when neither is
    known)."""
    label = "filename" if element.tag == "plugin" else "name"
    value = element.attrib.get(label)
    name = (f"<{element.tag}>" if value is None or label in element.unknown
            else f"<{element.tag}> '{value}'")
    at = element.call or (element.path, element.line, element.column)
    defined = (None if element.call is None
               else (display(element.path), element.line, element.column))
    return RobotElement("outside_gazebo", name, display(at[0]), at[1], at[2],
                        outer & _condition(element.conditions), defined)


def _gazebo_reference(element: ExpandedNode, display: Display,
                      outer: Condition) -> RobotElement:
    """A ``<gazebo reference="...">`` straight under ``<robot>``, as an element named by
    its reference (None when the name is not known), of kind ``gazebo_reference`` when it
    holds a ``<sensor>`` or a ``<plugin>``, ``gazebo_properties`` when it holds only the
    link's or joint's simulation properties (material, friction, damping)."""
    name = None if "reference" in element.unknown else element.attrib["reference"]
    at = element.call or (element.path, element.line, element.column)
    defined = (None if element.call is None
               else (display(element.path), element.line, element.column))
    kind = ("gazebo_reference" if any(c.tag in OUTSIDE_GAZEBO for c in element.children)
            else "gazebo_properties")
    return RobotElement(kind, name, display(at[0]), at[1], at[2],
                        outer & _condition(element.conditions), defined)


ORIGIN_OWNERS = ("visual", "collision", "inertial")
"""The elements of a ``<link>`` that urdfdom reads one ``<origin>`` of (the first)."""


def _ignored_origins(element: ExpandedNode, name: str | None, display: Display,
                     outer: Condition) -> list[RobotElement]:
    """The ``<origin>`` elements urdfdom ignores in a link's visuals, collisions and
    inertial, or in a joint: every one after the first (urdfdom's link.cpp and joint.cpp
    read ``FirstChildElement("origin")``), as elements of kind ``origin`` named after
    their owner (``<visual> of link 'x'``)."""
    what = f"link '{name}'" if element.tag == "link" else f"joint '{name}'"
    owners = ([(f"<{c.tag}> of {what}", c) for c in element.children
               if c.tag in ORIGIN_OWNERS] if element.tag == "link" else [(what, element)])
    out: list[RobotElement] = []
    for owner, node in owners:
        for origin in [c for c in node.children if c.tag == "origin"][1:]:
            at = origin.call or (origin.path, origin.line, origin.column)
            defined = (None if origin.call is None
                       else (display(origin.path), origin.line, origin.column))
            out.append(RobotElement("origin", owner, display(at[0]), at[1], at[2],
                                    outer & _condition(origin.conditions), defined))
    return out


def _mimic(joint: ExpandedNode, display: Display, outer: Condition) -> list[RobotElement]:
    """The joint's ``<mimic>`` as an element of kind ``mimic`` named after the joint it
    mimics (urdfdom's joint.cpp reads ``FirstChildElement("mimic")`` and its ``joint``
    attribute); none when the joint has no ``<mimic>`` or the name is unknown."""
    mimic = _first(joint, "mimic")
    if mimic is None or "joint" in mimic.unknown or "joint" not in mimic.attrib:
        return []
    at = mimic.call or (mimic.path, mimic.line, mimic.column)
    defined = None if mimic.call is None else (display(mimic.path), mimic.line, mimic.column)
    return [RobotElement("mimic", mimic.attrib["joint"], display(at[0]), at[1], at[2],
                         outer & _condition(mimic.conditions), defined)]


SIMULATOR_PACKAGE = "gazebo"
"""The package a Gazebo plugin's record names (it runs inside the simulator)."""
SENSOR_LINK_PARAM = "gazebo_reference"
"""The parameter a plugin's record gives the link of its ``<gazebo reference=...>``: a
sensor plugin's default frame (gazebo_ros's SensorFrameID) and the body its sensor looks
out of."""
SENSOR_POSE_PARAM = "gazebo_sensor_pose"
"""The parameter a sensor plugin's record gives the pose of the camera in its link: the
``<sensor><pose>`` and the ``<camera><pose>`` inside it, as Gazebo composes them
(sensor's then camera's: gazebo-classic gazebo/sensors/CameraSensor.cc and
DepthCameraSensor.cc, ``Init``, commit 00eaa74), each ``x y z roll pitch yaw``, joined
by ``;``."""
MAX_PLUGINS = 200

GZ_CAMERA_TYPES = frozenset({
    "camera", "depth", "depth_camera", "rgbd", "rgbd_camera", "thermal", "thermal_camera",
    "segmentation", "segmentation_camera", "boundingbox", "boundingbox_camera",
    "wideanglecamera", "wide_angle_camera"})
"""The ``<sensor type>`` names of SDFormat's image sensors (gazebosim/sdformat
``src/Sensor.cc`` ``Sensor::Load``, branch sdf14 8512585): gz-sim makes them without a
plugin. Their record is a ``gazebo_plugin`` named ``gz-sim TYPE`` (knowledge entry
``gz_sim_camera_sensor``)."""
GZ_FRAME_TAGS = ("gz_frame_id", "ignition_frame_id")
"""The sensor's frame as gz-sensors reads it (``src/Sensor.cc`` ``SensorPrivate::
PopulateFromSDF``: ``gz_frame_id``, before it ``ignition_frame_id``; gz-sensors7
4fcd8ed, gz-sensors8 c8159af), which a camera's ``<optical_frame_id>`` overrides for its
images (``src/CameraSensor.cc`` and ``RgbdCameraSensor.cc``, gz-sensors8)."""


ROS1_PLUGIN_TAGS = frozenset({"robotNamespace", "frameName", "publishOdomTF",
                              "odometryFrame", "robotBaseFrame", "bodyName", "broadcastTF"})
ROS2_PLUGIN_TAGS = frozenset({"ros", "frame_name", "publish_odom_tf", "odometry_frame",
                              "robot_base_frame", "body_name"})


def _ros_of(plugin: ExpandedNode) -> int | None:
    """The ROS version a gazebo_ros plugin is written for, by its parameters' spelling
    (ROS 1 camelCase, ROS 2 snake_case and ``<ros>``); None when they do not say."""
    tags = {child.tag for child in plugin.children}
    if tags & ROS2_PLUGIN_TAGS:
        return 2
    return 1 if tags & ROS1_PLUGIN_TAGS else None


def _plugin_elements(gazebo: ExpandedNode) -> list[tuple[ExpandedNode, ExpandedNode | None]]:
    """The plugins of a ``<gazebo>`` block, its own and its sensors', each with its
    sensor (None for the block's own)."""
    found: list[tuple[ExpandedNode, ExpandedNode | None]] = []
    for child in gazebo.children:
        if child.tag == "plugin":
            found.append((child, None))
        elif child.tag == "sensor":
            found.extend((p, child) for p in child.children if p.tag == "plugin")
    return found


def _pose_text(element: ExpandedNode) -> str:
    """An SDF ``<pose>`` as its six numbers' text; UNKNOWN_VALUE when its text is not
    known or it has attributes (``relative_to``, ``degrees``) this reader does not apply."""
    if element.text is None or element.attrib:
        return UNKNOWN_VALUE
    return element.text


def _sensor_pose(sensor: ExpandedNode) -> str | None:
    """The poses that place a sensor's camera in its link (:data:`SENSOR_POSE_PARAM`);
    None when the sensor gives none."""
    poses = [_pose_text(child) for child in sensor.children if child.tag == "pose"]
    turns = {pose_turn(_pose_text(pose)) for child in sensor.children if child.tag == "camera"
             for pose in child.children if pose.tag == "pose"}
    cameras = [child for child in sensor.children if child.tag == "camera"]
    if any(not any(c.tag == "pose" for c in camera.children) for camera in cameras):
        turns.add((0.0, 0.0, 0.0))
    if not poses and turns <= {(0.0, 0.0, 0.0)}:
        return None
    # A multicamera's cameras each have their own pose: their rotation is the camera's
    # when they all agree (a stereo pair side by side), unknown otherwise.
    turn = next(iter(turns), None) if len(turns) == 1 else None
    if UNKNOWN_VALUE in poses or (turns and turn is None):
        return UNKNOWN_VALUE
    if turn is not None:
        poses.append(f"0 0 0 {turn[0]} {turn[1]} {turn[2]}")
    return ";".join(poses)


def plugins_of(root: ExpandedNode, display: Display, outer: Condition,
               ros: int | None) -> list[NodeRecord]:
    """The ``<gazebo><plugin>`` blocks of a description, each as the record of a plugin
    (``filename``, its parameter elements as parameters, ``<ros><namespace>`` or
    ``<robotNamespace>`` as its namespace), at the plugin element; ``ros`` None leaves the
    ROS version to the plugin's own spelling."""
    out: list[NodeRecord] = []
    if root.tag != "robot":
        return out
    for gazebo in root.children:
        if gazebo.tag != "gazebo":
            continue
        reference = gazebo.attrib.get("reference")
        for plugin, sensor in _plugin_elements(gazebo):
            filename = plugin.attrib.get("filename")
            if not filename or "filename" in plugin.unknown:
                continue
            params: list[tuple[str, str]] = []
            if reference and "reference" not in gazebo.unknown:
                params.append((SENSOR_LINK_PARAM, reference))
            pose = None if sensor is None else _sensor_pose(sensor)
            if pose is not None:
                params.append((SENSOR_POSE_PARAM, pose))
            namespace: str | None = "/"
            lines: list[tuple[str, str, int, int]] = []
            for child in plugin.children:
                inner = child.children if child.tag == "ros" else [child]
                for element in inner:
                    if element.tag in ("namespace", "robotNamespace"):
                        namespace = (None if element.text is None
                                     else "/" + element.text.strip("/"))
                        if element.tag == "robotNamespace":
                            # Kept as a parameter too: a ROS 1 spawner writes its own
                            # namespace only into plugins that name none.
                            params.append((element.tag, UNKNOWN_VALUE if element.text is None
                                           else element.text))
                    elif element.tag in PLUGIN_TEXT_TAGS:
                        params.append((element.tag, UNKNOWN_VALUE if element.text is None
                                       else element.text))
                        lines.append((element.tag, display(element.path), element.line,
                                      element.column))
                    elif element.tag.lower() in FOLDED_PLUGIN_TAGS:
                        # Another spelling of a known parameter, which the plugin does
                        # not read (SDF's names are case-sensitive): kept by its name,
                        # with where it is, for plugin_param_case.
                        params.append((element.tag, UNKNOWN_VALUE))
                        lines.append((element.tag, display(element.path), element.line,
                                      element.column))
            out.append(NodeRecord(
                display(plugin.path), plugin.line, plugin.column, SIMULATOR_PACKAGE, "",
                plugin.attrib.get("name"), tuple(params),
                outer & _condition(plugin.conditions), kind="gazebo_plugin",
                plugin=filename, namespace=namespace,
                ros=ros if ros is not None else _ros_of(plugin), param_lines=tuple(lines),
                remappings=plugin_remappings(params)))
            if len(out) >= MAX_PLUGINS:
                return out
        out.extend(_gz_cameras(gazebo, display, outer, ros))
    return out[:MAX_PLUGINS]


def plugin_remappings(params: typing.Sequence[tuple[str, str]]) -> tuple[tuple[str, str], ...]:
    """A ROS 2 plugin's ``<ros><remapping>`` rules, ``from:=to`` each (``UNKNOWN_VALUE``
    for a rule not read): gazebo_ros plugins hand them to their node, and the ros2_control
    plugins to rcl with ``-r`` before they start the controller manager (gz_ros2_control
    rolling e19b0ef ``gz_ros2_control_plugin.cpp`` 336-346; gazebo_ros2_control the same)."""
    rules: list[tuple[str, str]] = []
    for key, value in params:
        if key != "remapping":
            continue
        source, colon, target = value.partition(":=")
        rules.append((source.strip(), target.strip()) if colon and value != UNKNOWN_VALUE
                     else (UNKNOWN_VALUE, UNKNOWN_VALUE))
    return tuple(rules)


def _gz_cameras(gazebo: ExpandedNode, display: Display, outer: Condition,
                ros: int | None) -> list[NodeRecord]:
    """The gz-sim image sensors of a ``<gazebo>`` block that name the frame of their
    images (a camera's ``<optical_frame_id>``, else the sensor's ``<gz_frame_id>`` or
    ``<ignition_frame_id>``), each as a record with that frame as a parameter. Without
    one the frame is the sensor's scoped name, no tf frame; with ``<frame_id>`` (read
    first by the newest gz-sensors) or a plugin inside (a gazebo_ros camera) none is
    made."""
    reference = gazebo.attrib.get("reference")
    out: list[NodeRecord] = []
    for sensor in gazebo.children:
        if sensor.tag != "sensor" or sensor.attrib.get("type") not in GZ_CAMERA_TYPES:
            continue
        tags = {child.tag: child for child in sensor.children}
        if "plugin" in tags or "frame_id" in tags:
            continue
        optical = [c for camera in sensor.children if camera.tag == "camera"
                   for c in camera.children if c.tag == "optical_frame_id"]
        named = optical[:1] or [tags[t] for t in GZ_FRAME_TAGS if t in tags][:1]
        if not named:
            continue
        params = [(named[0].tag, UNKNOWN_VALUE if named[0].text is None
                   else named[0].text)]
        if reference and "reference" not in gazebo.unknown:
            params.append((SENSOR_LINK_PARAM, reference))
        pose = _sensor_pose(sensor)
        if pose is not None:
            params.append((SENSOR_POSE_PARAM, pose))
        # At the element naming the frame: the word a fix changes.
        out.append(NodeRecord(
            display(named[0].path), named[0].line, named[0].column, SIMULATOR_PACKAGE, "",
            sensor.attrib.get("name"), tuple(params),
            outer & _condition(sensor.conditions), kind="gazebo_plugin",
            plugin=f"gz-sim {sensor.attrib['type']}", namespace="/", ros=ros))
    return out


def literal_root(text: str, path: str, line: int, own_lines: bool = False
                 ) -> tuple[ExpandedNode | None, list[XacroProblem]]:
    """A URDF written in a launch file, as an expanded tree (no xacro in it); with
    ``own_lines`` the text is the file ``path`` itself and keeps its lines."""
    try:
        document = parse_xml(text.encode("utf-8"), PLUGIN_TEXT_TAGS)
    except XmlError as exc:
        return None, [XacroProblem(path, line, f"literal robot description is not "
                                               f"well-formed XML: {exc.message}", True)]

    def convert(element: Element) -> ExpandedNode:
        node = (ExpandedNode(element.tag, path, element.line, element.column, ())
                if own_lines else ExpandedNode(element.tag, path, line, 1, ()))
        node.attrib = dict(element.attrib)
        node.text = element.text.strip()
        # Only joints, Gazebo plugins and the <origin>s of links' parts, with their
        # children, matter; the rest of the tree is not copied.
        if element.tag in ("robot", "joint", "gazebo", "sensor", "camera", "plugin", "ros",
                           "link", *ORIGIN_OWNERS):
            node.children = [convert(child) for child in element.children]
        return node

    return convert(document.root), []
