from __future__ import annotations

from typing import Callable, List, Tuple

from _urdf import link, lint_urdf, robot

RULE = "optical_rotated_twice"
OPTICAL_RPY = "-1.5707963 0 -1.5707963"
Lint = Callable[..., List[Tuple[str, int]]]


def joint(name: str, parent: str, child: str, rpy: str = "0 0 0", kind: str = "fixed") -> str:
    return (f'<joint name="{name}" type="{kind}"><parent link="{parent}"/>'
            f'<child link="{child}"/>\n<origin xyz="0 0 0" rpy="{rpy}"/></joint>')


def kinect(link: str = "camera_link", pose: str | None = None) -> str:
    """A Gazebo depth camera rendering from ``link`` (its sensor turned by ``pose``)."""
    turned = "" if pose is None else f"<pose>{pose}</pose>"
    return (f'<gazebo reference="{link}"><sensor type="depth" name="cam">{turned}'
            '<plugin name="kinect" filename="libgazebo_ros_openni_kinect.so">'
            '<frameName>camera_depth_frame</frameName></plugin></sensor></gazebo>')


def camera(depth_rpy: str, optical_rpy: str, kind: str = "fixed",
           sensor: str | None = kinect()) -> str:
    return robot("\n".join([
        link("camera_link"), link("camera_depth_frame"), link("camera_depth_optical_frame"),
        joint("depth_joint", "camera_link", "camera_depth_frame", depth_rpy, kind),
        joint("optical_joint", "camera_depth_frame", "camera_depth_optical_frame",
              optical_rpy),
        *([] if sensor is None else [sensor]),
    ]))


def found(text: str) -> list[tuple[int, str, tuple[int, ...]]]:
    return [(d.line, d.severity.value, tuple(r.line for r in d.related))
            for d in lint_urdf(text, RULE)]


def test_optical_joint_under_a_frame_already_turned_optical_is_found_at_its_origin() -> None:
    # Lines: 1 <robot>, 2-4 links, 5-6 depth_joint, 7-8 optical_joint. The simulated
    # camera renders along camera_link, above both rotations (create_autonomy#177).
    assert found(camera(OPTICAL_RPY, OPTICAL_RPY)) == [(8, "warning", (7, 5))]


def test_without_a_camera_rendering_above_both_rotations_it_is_info() -> None:
    # navigation2's nav2_system_tests/urdf/turtlebot3_waffle.urdf: no camera in the
    # description (the simulator's SDF model has it), nothing proves the view direction.
    no_camera = lint_urdf(camera(OPTICAL_RPY, OPTICAL_RPY, sensor=None), RULE)
    assert [(d.line, d.severity.value) for d in no_camera] == [(8, "info")]
    assert "may be the camera's mount" in no_camera[0].message
    # A sensor whose <pose> turns the view: the direction it renders along is not the
    # link's x axis.
    assert [level for _, level, _ in found(camera(
        OPTICAL_RPY, OPTICAL_RPY, sensor=kinect(pose="0 0 0 0 0.5 0")))] == ["info"]


def test_a_camera_mounted_looking_along_its_mounts_z_axis_is_info() -> None:
    # A tool camera (chenzixin-zn/my_robot_description's grinder): the camera body is
    # turned from the tool by the optical rotation (its x along the tool's z), and its
    # optical frame once more from the body, which the camera renders along: right.
    text = robot("\n".join([
        link("tool"), link("cam_link"), link("cam_optical_frame"),
        joint("mount", "tool", "cam_link", OPTICAL_RPY),
        joint("optical", "cam_link", "cam_optical_frame", OPTICAL_RPY),
        kinect("cam_link"),
    ]))
    assert [level for _, level, _ in found(text)] == ["info"]


def test_one_optical_rotation_is_silent() -> None:
    assert found(camera("0 0 0", OPTICAL_RPY)) == []
    assert found(camera(OPTICAL_RPY, "0 0 0")) == []


def test_the_first_rotation_split_over_identity_edges_is_still_seen() -> None:
    text = robot("\n".join([
        link("head"), link("cam"), link("cam_mount"), link("cam_optical_frame"),
        joint("a", "head", "cam", OPTICAL_RPY), joint("b", "cam", "cam_mount"),
        joint("c", "cam_mount", "cam_optical_frame", OPTICAL_RPY),
    ]))
    assert [line for line, _, _ in found(text)] == [11]


def test_a_movable_joint_on_the_way_leaves_it_unknown() -> None:
    assert found(camera(OPTICAL_RPY, OPTICAL_RPY, kind="revolute")) == []


def test_a_child_not_named_optical_is_info() -> None:
    text = robot("\n".join([
        link("a"), link("b"), link("c"),
        joint("ab", "a", "b", OPTICAL_RPY), joint("bc", "b", "c", OPTICAL_RPY),
    ]))
    assert [level for _, level, _ in found(text)] == ["info"]


def test_static_transform_with_the_optical_quaternion_under_an_optical_frame(
        lint: Lint) -> None:
    xml = ('<launch>\n'
           '<node pkg="tf2_ros" type="static_transform_publisher" name="a" args="0 0 0 '
           '-0.5 0.5 -0.5 0.5 camera_link camera_color_frame"/>\n'
           '<node pkg="tf2_ros" type="static_transform_publisher" name="b" args="0 0 0 '
           '-1.5707963 0 -1.5707963 camera_color_frame camera_color_optical_frame"/>\n'
           '</launch>')
    assert lint(xml, RULE) == [(RULE, 3)]
    once = xml.replace("-0.5 0.5 -0.5 0.5", "0 0 0 1")
    assert lint(once, RULE) == []


def test_a_chain_of_twenty_thousand_optical_joints_is_bounded() -> None:
    names = [f"f{i}" for i in range(20_000)]
    body = "\n".join([link(n) for n in names] + [
        joint(f"j{i}", names[i], names[i + 1], OPTICAL_RPY) for i in range(len(names) - 1)])
    assert len(lint_urdf(robot(body), RULE)) > 0
