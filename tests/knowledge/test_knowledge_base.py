"""The bundled knowledge base: every entry well formed and citing its source; entries
evaluated against a node's parameters."""

from __future__ import annotations

import json
import os
from pathlib import Path

import pytest

from launch_linter.knowledge import (
    PROGRAMS_FILE,
    KnowledgeError,
    bundled,
    bundled_path,
    load,
    parse,
)
from launch_linter.knowledge.publish import published
from launch_linter.model.robot import UNKNOWN_VALUE, NodeRecord
from launch_linter.workspace.config import load_knowledge_file

REQUIRED = ("amcl", "nav2_amcl", "robot_localization_filter", "navsat_transform",
            "slam_toolbox", "gmapping", "cartographer", "hector_mapping", "rtabmap",
            "move_base", "nav2_costmap", "map_server", "nav2_map_server",
            "diff_drive_controller", "diff_drive_controller_ros1", "gazebo_ros_diff_drive",
            "gz_sim_diff_drive", "gazebo_ros_camera", "joint_state_publisher",
            "robot_state_publisher", "realsense2_camera", "openni2_camera",
            "freenect_camera", "mavros")


def test_every_bundled_entry_is_well_formed_and_cites_a_read_source() -> None:
    path = bundled_path()
    programs = bundled_path(PROGRAMS_FILE)
    assert path is not None and programs is not None
    base = load(path)
    ids = {entry.id for entry in base.entries}
    assert set(REQUIRED) <= ids
    facts = load(programs).programs.facts
    assert facts and not ids & {fact.id for fact in facts}
    for entry in (*base.entries, *facts):
        assert entry.sources, entry.id
        for source in entry.sources:
            assert len(source.commit) == 40 and source.file and source.repository, entry.id


@pytest.mark.parametrize("fault, message", [
    ({"sources": []}, "sources"),
    ({"sources": [{"repository": "a/b", "package": "p", "file": "f", "ref": "r",
                   "commit": "abc", "lines": "1"}]}, "commit"),
    ({"publishes": [{"parent": "{nope}", "child": "x", "role": "odometry"}]}, "nope"),
    ({"kind": "robot"}, "kind"),
    ({"ros1_tf2_from": "hydro"}, "ros1_tf2_from"),
    ({"header_frames": ["{nope}"]}, "nope"),
    ({"looks_up_listed": [{"list": "costmap/observation_sources"}]}, "looks_up_listed"),
    ({"looks_up_listed": "costmap/observation_sources"}, "looks_up_listed"),
])
def test_a_malformed_entry_is_refused_with_its_fault(fault: dict[str, object],
                                                      message: str) -> None:
    data = json.loads(Path(str(bundled_path())).read_text())
    entry = dict(data["entries"][0], **fault)
    with pytest.raises(KnowledgeError, match=message):
        parse({"format": 1, "entries": [entry]}, "user.json")


def test_header_frames_and_the_release_whose_frames_reach_tf2() -> None:
    """map_server stamps its frame_id on the map; costmap_2d reads frames in tf2 from
    Melodic on (both read in ros-planning/navigation and cited)."""
    base = bundled()
    map_server = base.node("map_server", "map_server", 1)
    move_base = base.node("move_base", "move_base", 1)
    assert map_server is not None and map_server.header_frames == ("{frame_id}",)
    assert move_base is not None and move_base.ros1_tf2_from == "melodic"
    gmapping = base.node("gmapping", "slam_gmapping", 1)
    assert gmapping is not None and gmapping.ros1_tf2_from is None


def test_robot_pose_ekf_always_broadcasts_its_output_frame() -> None:
    """robot_pose_ekf sends output_frame -> base_footprint_frame with no switch
    (gazebo_ros_pkgs#692: it and the Gazebo diff-drive plugin both sent odom ->
    base_footprint)."""
    assert edges(node("robot_pose_ekf", "robot_pose_ekf")) == [("odom_combined",
                                                                "base_footprint")]
    assert edges(node("robot_pose_ekf", "robot_pose_ekf", ("output_frame", "odom"))) == [
        ("odom", "base_footprint")]


def node(package: str, executable: str, *params: tuple[str, str], unread: tuple[str, ...] = (),
         ros: int = 1) -> NodeRecord:
    return NodeRecord("a.launch", 3, 1, package, executable, "n", params, unread=unread,
                      ros=ros)


def edges(record: NodeRecord) -> list[tuple[str | None, str | None]]:
    entry = bundled().node(record.package, record.executable, record.ros)
    assert entry is not None
    return [(e.parent, e.child) for e in published(entry, record)[0]]


def test_defaults_parameters_and_switches() -> None:
    assert edges(node("amcl", "amcl")) == [("map", "odom")]
    assert edges(node("amcl", "amcl", ("odom_frame_id", "odom_combined"))) == [
        ("map", "odom_combined")]
    assert edges(node("amcl", "amcl", ("tf_broadcast", "false"))) == []
    assert edges(node("gmapping", "slam_gmapping", ("transform_publish_period", "0"))) == []


def test_robot_localization_publishes_by_its_world_frame() -> None:
    assert edges(node("robot_localization", "ekf_localization_node",
                      ("odom0", "odom"))) == [("odom", "base_link")]
    assert edges(node("robot_localization", "ekf_localization_node",
                      ("world_frame", "map"), ("imu0", "imu"))) == [("map", "odom")]


def test_robot_localization_without_an_input_publishes_nothing() -> None:
    """The filter sends its transform only once a measurement initialized it, and it
    measures only the topics odom0, imu0... name: with every parameter read and none
    given, no edge; with its parameter file unread, the input may be there."""
    assert edges(node("robot_localization", "ekf_localization_node")) == []
    assert edges(node("robot_localization", "ekf_localization_node",
                      ("world_frame", "odom"), ("odom_topic", "odom"))) == []
    assert edges(node("robot_localization", "ekf_localization_node",
                      ("twist12", "cmd"))) == [("odom", "base_link")]
    record = node("robot_localization", "ekf_node", ("world_frame", "odom"),
                  unread=("file not read",), ros=2)
    entry = bundled().node("robot_localization", "ekf_node", 2)
    assert entry is not None
    assert [(e.parent, e.child) for e in published(entry, record, assume=True)[0]] == [
        ("odom", "base_link")]


def test_unread_parameters_leave_defaults_unknown() -> None:
    record = node("robot_localization", "ekf_node", unread=("file not read",), ros=2)
    entry = bundled().node("robot_localization", "ekf_node", 2)
    assert entry is not None
    sure, maybe = published(entry, record)
    assert sure == [] and len(maybe) == 2
    unknown = node("amcl", "amcl", ("odom_frame_id", UNKNOWN_VALUE))
    assert edges(unknown) == [("map", None)]


def test_a_controller_prefixes_its_frames_with_its_namespace() -> None:
    entry = bundled().plugin("controller", "diff_drive_controller/DiffDriveController", 2)
    assert entry is not None and entry.id == "diff_drive_controller"
    record = NodeRecord("a.py", 1, 1, "controller_manager", "", "ddc", (), kind="controller",
                        plugin="diff_drive_controller/DiffDriveController",
                        namespace="/robot1", ros=2)
    assert [(e.parent, e.child) for e in published(entry, record)[0]] == [
        ("robot1/odom", "robot1/base_link")]


def test_a_user_file_extends_and_overrides_the_bundled_base(tmp_path: Path) -> None:
    mine = {"format": 1, "entries": [{
        "id": "my_odometry", "kind": "node", "ros": [1],
        "match": {"package": "my_base", "executables": ["driver"]},
        "parameters": {"odom_frame": "odom"},
        "publishes": [{"parent": "{odom_frame}", "child": "base_link", "role": "odometry"}],
        "sources": [{"repository": "me/my_base", "package": "my_base", "file": "src/d.cpp",
                     "ref": "main", "commit": "0" * 40, "lines": "10"}]}]}
    path = tmp_path / "k.json"
    path.write_text(json.dumps(mine))
    base = bundled().extended(load_knowledge_file(str(path)))
    entry = base.node("my_base", "driver", 1)
    assert entry is not None and entry.origin == str(path)
    assert base.node("amcl", "amcl", 1) is not None


def test_the_configuration_names_knowledge_files(tmp_path: Path) -> None:
    from launch_linter.commands.common import UsageError
    from launch_linter.commands.options import load_knowledge
    from launch_linter.workspace.config import parse_config

    config = parse_config({"knowledge": "k.json"}, str(tmp_path / ".launch-linter.toml"))
    assert config.knowledge == (str(tmp_path / "k.json"),)
    (tmp_path / "k.json").write_text('{"format": 1, "entries": [{"id": "x"}]}')
    with pytest.raises(UsageError, match="kind"):
        load_knowledge(config.knowledge)


@pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="no FIFOs on this platform")
def test_a_configured_knowledge_file_that_is_a_fifo_is_refused_not_waited_on(
        tmp_path: Path) -> None:
    # open() of a FIFO blocks until a writer comes: a repository's configuration naming
    # one must not hang the run.
    from launch_linter.commands.common import UsageError
    from launch_linter.commands.options import load_knowledge

    os.mkfifo(str(tmp_path / "k.json"))
    with pytest.raises(UsageError, match="not a regular file"):
        load_knowledge((str(tmp_path / "k.json"),))


def test_a_configured_knowledge_file_past_the_limit_is_refused_unread(tmp_path: Path) -> None:
    from launch_linter.knowledge import MAX_KNOWLEDGE_BYTES

    path = tmp_path / "k.json"
    path.write_bytes(b" " * (MAX_KNOWLEDGE_BYTES + 1))
    with pytest.raises(KnowledgeError, match="larger than"):
        load_knowledge_file(str(path))


def test_a_ros1_controller_is_not_given_the_ros2_controller_s_own_tf_topic() -> None:
    # ros_controllers' AckermannSteeringController (ROS 1) sends odom -> base_link on /tf;
    # ros2_controllers' steering controllers of the same type name send it on
    # ~/tf_odometry. Falling back to the ROS 2 entry would drop a ROS 1 odometry edge.
    base = bundled()
    ros1 = base.plugin("controller", "ackermann_steering_controller/AckermannSteeringController", 1)
    ros2 = base.plugin("controller", "ackermann_steering_controller/AckermannSteeringController", 2)
    assert ros1 is not None and ros2 is not None
    assert ros1.id == "ackermann_steering_controller_ros1"
    assert ros1.tf_topic == "/tf"
    assert ros2.tf_topic == "~/tf_odometry"
