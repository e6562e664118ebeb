"""camera_frame_not_optical: a Gazebo camera plugin stamping images with a body frame."""

from __future__ import annotations

from pathlib import Path

from launch_linter.engine import LintOptions, lint_paths

RULE = "camera_frame_not_optical"

ROBOT = """<robot name="r">
  <link name="base_link"/><link name="camera_link"/><link name="camera_link_optical"/>
  <joint name="camera_joint" type="fixed">
    <parent link="base_link"/><child link="camera_link"/>
    <origin xyz="0.1 0 0.2" rpy="0 0.3 0"/>
  </joint>
  <joint name="camera_optical_joint" type="fixed">
    <parent link="camera_link"/><child link="camera_link_optical"/>
    <origin xyz="0 0 0" rpy="{rpy}"/>
  </joint>
  <gazebo reference="camera_link">
    <sensor name="camera" type="depth">
      <plugin name="camera_controller" filename="{filename}">{body}</plugin>
    </sensor>
  </gazebo>
</robot>
"""


OPTICAL_RPY = "-1.5707963 0 -1.5707963"


def run(tmp_path: Path, text: str) -> list[tuple[int, str]]:
    path = tmp_path / "robot.urdf"
    path.write_text(text)
    options = LintOptions(package_paths=(), select=frozenset({RULE}))
    return [(d.line, d.message) for d in lint_paths([str(path)], options).diagnostics]


def test_ros2_camera_on_its_sensor_link_by_default(tmp_path: Path) -> None:
    fault = ROBOT.format(rpy=OPTICAL_RPY, filename="libgazebo_ros_camera.so", body="")
    (found,) = run(tmp_path, fault)
    assert found[0] == 13 and "'camera_link' (frame_name)" in found[1]
    fixed = ROBOT.format(rpy=OPTICAL_RPY, filename="libgazebo_ros_camera.so",
                         body="<frame_name>camera_link_optical</frame_name>")
    assert run(tmp_path, fixed) == []


def test_a_sensor_on_a_link_the_robot_lacks_is_never_made(tmp_path: Path) -> None:
    """unitree go1's <gazebo reference="depthCamera_link_left"> names no link of the
    robot: Gazebo attaches the block to no link and makes no camera."""
    fault = ROBOT.format(rpy=OPTICAL_RPY, filename="libgazebo_ros_camera.so", body="")
    assert len(run(tmp_path, fault)) == 1
    absent = fault.replace('<gazebo reference="camera_link">',
                           '<gazebo reference="camera_link_left">')
    assert run(tmp_path, absent) == []


def test_ros1_frame_name_that_lacks_the_optical_rotation(tmp_path: Path) -> None:
    body = "<frameName>camera_link_optical</frameName>"
    fault = ROBOT.format(rpy="0 0 0", filename="libgazebo_ros_openni_kinect.so", body=body)
    (found,) = run(tmp_path, fault)
    assert "not rotated from its sensor link 'camera_link'" in found[1]
    fixed = ROBOT.format(rpy=OPTICAL_RPY, filename="libgazebo_ros_openni_kinect.so",
                         body=body)
    assert run(tmp_path, fixed) == []
    # The same rotation written another way (a quaternion's other sign, yaw first) holds.
    assert run(tmp_path, fixed.replace(OPTICAL_RPY, "-1.5707963 0.0 4.712389")) == []


def test_unjoined_frames_are_judged_by_name_and_movable_paths_not_at_all(
        tmp_path: Path) -> None:
    named = ROBOT.format(rpy=OPTICAL_RPY, filename="libgazebo_ros_camera.so",
                         body="<frame_name>{}</frame_name>")
    assert len(run(tmp_path, named.format("kinect_frame"))) == 1
    (unpublished,) = run(tmp_path, named.format("kinect_optical_frame"))
    assert "nothing in this tree publishes" in unpublished[1]
    movable = ROBOT.format(rpy="0 0 0", filename="libgazebo_ros_camera.so",
                           body="<frame_name>camera_link_optical</frame_name>").replace(
        'name="camera_optical_joint" type="fixed"', 'name="camera_optical_joint" '
        'type="revolute"')
    assert run(tmp_path, movable) == []
    assert run(tmp_path, ROBOT.format(rpy="0 0 0", filename="libgazebo_ros_imu_sensor.so",
                                      body="")) == []


def test_a_sensor_pose_that_turns_the_camera_is_composed(tmp_path: Path) -> None:
    """Gazebo renders along the x axis of the sensor's <pose> (then its <camera>'s pose)
    in the link: a link stamped as the image frame is right when those poses turn the
    camera so that the link is its optical frame (baxter's hand cameras)."""
    posed = ROBOT.format(rpy=OPTICAL_RPY, filename="libgazebo_ros_camera.so",
                         body="<frame_name>camera_link</frame_name>")
    turned = posed.replace('type="depth">', 'type="depth"><pose>0 0 0 0 -1.5707963 '
                           '1.5707963</pose>')
    assert run(tmp_path, turned) == []
    in_camera = posed.replace('type="depth">', 'type="depth"><camera><pose>0 0 0 0 '
                              '-1.5707963 1.5707963</pose></camera>')
    assert run(tmp_path, in_camera) == []
    tilted = posed.replace('type="depth">', 'type="depth"><pose>0 0 0 0 -0.8 '
                           '-1.5707963</pose>')
    (found,) = run(tmp_path, tilted)
    assert "which the sensor's <pose> does not turn into the optical frame" in found[1]
    # A pose this reader cannot apply (SDF 1.7's relative_to) leaves the rotation unknown.
    unknown = posed.replace('type="depth">', 'type="depth"><pose relative_to="x">0 0 0 '
                            '0 0 0</pose>')
    (by_name,) = run(tmp_path, unknown)
    assert "whose name does not say optical" in by_name[1]


def test_a_multicamera_turns_as_its_cameras_when_they_agree(tmp_path: Path) -> None:
    posed = ROBOT.format(rpy=OPTICAL_RPY, filename="libgazebo_ros_multicamera.so",
                         body="<frameName>camera_link_optical</frameName>")
    pair = ('type="depth"><camera name="l"><pose>0 0.1 0 0 0 0</pose></camera>'
            '<camera name="r"><pose>0 -0.1 0 {} 0 0</pose></camera>')
    side_by_side = posed.replace('type="depth">', pair.format(0))
    (found,) = run(tmp_path, side_by_side.replace("camera_link_optical</frameName>",
                                                  "camera_link</frameName>"))
    assert "its sensor link itself" in found[1]
    assert run(tmp_path, side_by_side) == []
    turned_apart = posed.replace('type="depth">', pair.format(0.5)).replace(
        "camera_link_optical</frameName>", "camera_link</frameName>")
    (by_name,) = run(tmp_path, turned_apart)
    assert "whose name does not say optical" in by_name[1]


def test_a_proven_rotation_warns_and_a_name_alone_informs(tmp_path: Path) -> None:
    """The rotation over fixed joints is proof (warning); a frame that no fixed path joins
    to the sensor's link is judged by its name only, which a package publishing an optical
    frame under another name defeats (info)."""
    path = tmp_path / "robot.urdf"

    def levels(text: str) -> list[str]:
        path.write_text(text)
        options = LintOptions(package_paths=(), select=frozenset({RULE}))
        return [d.severity.value for d in lint_paths([str(path)], options).diagnostics]

    proven = ROBOT.format(rpy=OPTICAL_RPY, filename="libgazebo_ros_camera.so", body="")
    assert levels(proven) == ["warning"]
    # The study profile keeps the level the rule had when it was fixed.
    study = LintOptions(package_paths=(), select=frozenset({RULE}), profile="study")
    (kept,) = lint_paths([str(path)], study).diagnostics
    assert kept.severity.value == "info"
    named = ROBOT.format(rpy=OPTICAL_RPY, filename="libgazebo_ros_camera.so",
                         body="<frame_name>head_rgb_frame</frame_name>")
    assert levels(named) == ["info"]


GZ_SENSOR = """  <gazebo reference="camera_link">
    <sensor name="cam" type="{kind}">{body}
    </sensor>
  </gazebo>
</robot>
"""


def gz_robot(kind: str, body: str) -> str:
    head = ROBOT.format(rpy=OPTICAL_RPY, filename="x", body="")
    return head[:head.index("  <gazebo")] + GZ_SENSOR.format(kind=kind, body=body)


def test_a_gz_sim_camera_stamped_with_its_body_frame(tmp_path: Path) -> None:
    # yahboom_rosmaster e22470d: an rgbd_camera with <gz_frame_id> its body link.
    for kind, tag in (("rgbd_camera", "gz_frame_id"), ("camera", "ignition_frame_id")):
        fault = gz_robot(kind, f"<{tag}>camera_link</{tag}>")
        (found,) = run(tmp_path, fault)
        assert f"gz-sim {kind}" in found[1] and f"'camera_link' ({tag})" in found[1]
        assert run(tmp_path, fault.replace(">camera_link<", ">camera_link_optical<")) == []


def test_a_gz_sim_camera_whose_images_name_another_frame(tmp_path: Path) -> None:
    # A camera's <optical_frame_id> stamps its images, whatever the sensor's frame.
    optical = ("<gz_frame_id>camera_link</gz_frame_id>"
               "<camera><optical_frame_id>camera_link_optical</optical_frame_id></camera>")
    assert run(tmp_path, gz_robot("depth_camera", optical)) == []
    # No frame named (the sensor's scoped name), or a lidar: nothing to judge.
    assert run(tmp_path, gz_robot("rgbd_camera", "<topic>cam</topic>")) == []
    assert run(tmp_path, gz_robot("gpu_lidar", "<gz_frame_id>camera_link</gz_frame_id>")) == []


WITHOUT_OPTICAL = ROBOT.replace('<link name="camera_link_optical"/>', "").replace(
    """  <joint name="camera_optical_joint" type="fixed">
    <parent link="camera_link"/><child link="camera_link_optical"/>
    <origin xyz="0 0 0" rpy="{rpy}"/>
  </joint>
""", "")


def test_a_frame_no_link_of_the_description_and_nothing_publishes(tmp_path: Path) -> None:
    """vrx#140: the camera macro stamps images with ${name}_link_optical, a link the
    macro no longer defines: every tf lookup of the images fails."""
    body = "<frameName>camera_link_optical</frameName>"
    fault = WITHOUT_OPTICAL.format(filename="libgazebo_ros_camera.so", body=body)
    assert "camera_link_optical" not in fault.split("<gazebo")[0]
    (found,) = run(tmp_path, fault)
    assert "which is no link of the robot description and which nothing in this tree " \
           "publishes" in found[1] and "(frameName)" in found[1]
    fixed = ROBOT.format(rpy=OPTICAL_RPY, filename="libgazebo_ros_camera.so", body=body)
    assert run(tmp_path, fixed) == []
    # A namespace prefix on a link the description has is not read as another frame.
    prefixed = WITHOUT_OPTICAL.format(filename="libgazebo_ros_camera.so",
                                      body="<frameName>cam/camera_link_optical</frameName>")
    assert len(run(tmp_path, prefixed)) == 1
    on_link = prefixed.replace("cam/camera_link_optical", "cam/camera_link")
    assert all("nothing in this tree publishes" not in m for _, m in run(tmp_path, on_link))


def test_a_frame_a_static_transform_of_the_tree_publishes(tmp_path: Path) -> None:
    body = "<frameName>camera_link_optical</frameName>"
    (tmp_path / "robot.urdf").write_text(
        WITHOUT_OPTICAL.format(filename="libgazebo_ros_camera.so", body=body))
    static = ('<node pkg="tf2_ros" type="static_transform_publisher" name="optical" '
              'args="0 0 0 -1.5707963 0 -1.5707963 camera_link camera_link_optical"/>')
    launch = tmp_path / "sim.launch"
    launch.write_text(
        '<launch><param name="robot_description" textfile="$(dirname)/robot.urdf"/>'
        '<node pkg="robot_state_publisher" type="robot_state_publisher" name="rsp"/>'
        '<node pkg="gazebo_ros" type="spawn_model" name="spawn" '
        'args="-urdf -param robot_description -model r"/>' + "{}</launch>")
    options = LintOptions(package_paths=(), select=frozenset({RULE}))
    text = launch.read_text()
    launch.write_text(text.format(""))
    (found,) = lint_paths([str(launch)], options).diagnostics
    assert "nothing in this tree publishes" in found.message
    launch.write_text(text.format(static))
    assert lint_paths([str(launch)], options).diagnostics == ()


def test_an_incomplete_description_proves_no_frame_absent(tmp_path: Path) -> None:
    body = "<frameName>camera_link_optical</frameName>"
    text = WITHOUT_OPTICAL.format(filename="libgazebo_ros_camera.so", body=body).replace(
        '<robot name="r">', '<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">'
        '<xacro:include filename="$(find nowhere)/optical.xacro"/>')
    assert run(tmp_path, text) == []


def test_a_namespace_prefix_on_the_links_is_not_another_frame(tmp_path: Path) -> None:
    """uuv_simulator's camera links are ${namespace}/camera_link_optical and its plugin
    stamps camera_link_optical, which the ROS 1 plugin resolves with its tf_prefix."""
    text = ROBOT.format(rpy=OPTICAL_RPY, filename="libgazebo_ros_camera.so",
                        body="<frameName>camera_link_optical</frameName>")
    prefixed = text.replace('"camera_link', '"rov/camera_link').replace(
        ">camera_link_optical<", ">camera_link_optical<")
    assert all("nothing in this tree publishes" not in m for _, m in run(tmp_path, prefixed))



CAMERA_MODEL = """<robot name="camera">
  <link name="camera"/>
  <gazebo reference="camera">
    <sensor name="camera" type="camera">
      <plugin name="camera_controller" filename="libgazebo_ros_camera.so">
        <frameName>camera</frameName>
      </plugin>
    </sensor>
  </gazebo>
</robot>
"""

DIFF_DRIVE = """<gazebo>
    <plugin name="diff_drive" filename="libgazebo_ros_diff_drive.so">
      <odometryFrame>odom</odometryFrame><robotBaseFrame>camera</robotBaseFrame>
      <publishOdomTF>true</publishOdomTF>
    </plugin>
  </gazebo>
</robot>"""


def test_a_sensor_link_nothing_in_its_description_places_is_not_proven(
        tmp_path: Path) -> None:
    """autonomous_exploration_development_environment: a one-link camera model, spawned
    into Gazebo and moved by the simulator with the vehicle, while tf's 'camera' is a
    static transform (in another launch file) from the vehicle-aligned 'sensor' at the
    optical rotation. A root link is placed in tf by whatever publishes its parent, not
    by the description: how the Gazebo link stands against that tf frame is unknown, so
    the frame is judged by its name, at info."""
    (found,) = run(tmp_path, CAMERA_MODEL)
    assert "is not known" in found[1]
    (tmp_path / "robot.urdf").write_text(CAMERA_MODEL)
    options = LintOptions(package_paths=(), select=frozenset({RULE}))
    (diagnostic,) = lint_paths([str(tmp_path / "robot.urdf")], options).diagnostics
    assert diagnostic.severity.value == "info"


def test_a_root_sensor_link_a_known_plugin_tracks_is_still_proven(tmp_path: Path) -> None:
    """A root link that an odometry plugin of the description publishes (odom -> the
    link, the model's own pose) is the Gazebo link: stamped with it, still a warning."""
    (tmp_path / "robot.urdf").write_text(CAMERA_MODEL.replace("</robot>", DIFF_DRIVE))
    launch = tmp_path / "sim.launch"
    launch.write_text(
        '<launch><param name="robot_description" textfile="$(dirname)/robot.urdf"/>'
        '<node pkg="robot_state_publisher" type="robot_state_publisher" name="rsp"/>'
        '<node pkg="gazebo_ros" type="spawn_model" name="spawn" '
        'args="-urdf -param robot_description -model r"/></launch>')
    options = LintOptions(package_paths=(), select=frozenset({RULE}))
    (found,) = lint_paths([str(launch)], options).diagnostics
    assert found.severity.value == "warning" and "its sensor link itself" in found.message
    # Without the plugin nothing places the root link: its rotation is not known.
    (tmp_path / "robot.urdf").write_text(CAMERA_MODEL)
    (untracked,) = lint_paths([str(launch)], options).diagnostics
    assert untracked.severity.value == "info" and "is not known" in untracked.message


def _package(tmp_path: Path, build: str) -> Path:
    folder = tmp_path / build / "robot_description"
    folder.mkdir(parents=True)
    (folder / "package.xml").write_text(
        f'<package format="3"><name>robot_description</name><version>0.1.0</version>'
        f"<description>d</description><maintainer email='a@b.c'>a</maintainer>"
        f"<license>BSD</license><buildtool_depend>{build}</buildtool_depend>"
        f"<export><build_type>{build}</build_type></export></package>")
    return folder


def test_a_description_alone_runs_the_plugins_of_its_packages_ros(tmp_path: Path) -> None:
    """hamster_gazebo's ROS 1 (catkin) description names no frame for its
    libgazebo_ros_camera plugin: ROS 1's camera utilities then stamp /world (their
    <frameName> default), not the sensor's link as ROS 2's plugin does."""
    fault = ROBOT.format(rpy=OPTICAL_RPY, filename="libgazebo_ros_camera.so", body="")
    options = LintOptions(package_paths=(), select=frozenset({RULE}))
    for build, expected in (("ament_cmake", "'camera_link' (frame_name)"),
                            ("catkin", "'world' (frameName)")):
        path = _package(tmp_path, build) / "robot.urdf"
        path.write_text(fault)
        (found,) = lint_paths([str(path)], options).diagnostics
        assert expected in found.message
        assert (found.severity.value == "warning") == (build == "ament_cmake")
