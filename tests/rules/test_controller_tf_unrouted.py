"""controller_tf_unrouted: a controller that sends its odometry transform on its own
``~/tf_odometry`` with nothing bringing that topic to /tf (steering_controllers_library,
mecanum_drive_controller)."""

from __future__ import annotations

import time
from pathlib import Path

from launch_linter.engine import LintOptions, lint_paths
from launch_linter.frontends.params import controller_remappings
from launch_linter.knowledge import bundled
from launch_linter.model.robot import UNKNOWN_VALUE, NodeRecord
from launch_linter.rules._tf_topics import LOST, ROUTED, UNKNOWN, controller_routes, route

RULE = "controller_tf_unrouted"
ACKERMANN = "ackermann_steering_controller/AckermannSteeringController"
TOPIC = "/ackermann_steering_controller/tf_odometry"

CONTROLLERS = ("controller_manager:\n"
               "  ros__parameters:\n"
               "    {name}:\n"
               "      type: {kind}\n"
               "{name}:\n"
               "  ros__parameters:\n"
               "    enable_odom_tf: {enabled}\n")
LAUNCH = ("<launch>\n"
          "  <node pkg=\"controller_manager\" exec=\"ros2_control_node\">\n"
          "    <param from=\"$(dirname)/controllers.yaml\"/>\n"
          "{remaps}"
          "  </node>\n"
          "  <node pkg=\"controller_manager\" exec=\"spawner\" args=\"{name}\"/>\n"
          "{others}"
          "</launch>\n")


def run(tmp_path: Path, remaps: str = "", others: str = "",
        name: str = "ackermann_steering_controller", kind: str = ACKERMANN,
        enabled: str = "true", rules: frozenset[str] = frozenset({RULE})
        ) -> list[tuple[int, str, str]]:
    (tmp_path / "controllers.yaml").write_text(
        CONTROLLERS.format(name=name, kind=kind, enabled=enabled))
    path = tmp_path / "robot.launch.xml"
    path.write_text(LAUNCH.format(remaps=remaps, others=others, name=name))
    options = LintOptions(package_paths=(), select=rules)
    return [(d.line, d.severity.value, d.rule)
            for d in lint_paths([str(path)], options).diagnostics]


def remap(source: str, target: str = "/tf") -> str:
    return f"    <remap from=\"{source}\" to=\"{target}\"/>\n"


def test_a_steering_controller_whose_tf_topic_nobody_remaps(tmp_path: Path) -> None:
    assert run(tmp_path) == [(2, "warning", RULE)]


def test_mecanum_drive_controller_too(tmp_path: Path) -> None:
    found = run(tmp_path, name="mecanum_drive_controller",
                kind="mecanum_drive_controller/MecanumDriveController")
    assert found == [(2, "warning", RULE)]


def test_remapped_on_the_controller_manager_is_silent(tmp_path: Path) -> None:
    assert run(tmp_path, remaps=remap(TOPIC)) == []
    # The relative and private spellings name the same topic for the controller's node.
    assert run(tmp_path, remaps=remap("ackermann_steering_controller/tf_odometry")) == []
    assert run(tmp_path, remaps=remap("~/tf_odometry")) == []
    # A namespaced tf topic (multi-robot trees) is a tf topic too.
    assert run(tmp_path, remaps=remap(TOPIC, "/robot1/tf")) == []


def test_a_rule_for_another_topic_or_node_does_not_route_it(tmp_path: Path) -> None:
    assert run(tmp_path, remaps=remap("/cmd_vel", "/ackermann/reference")) == [
        (2, "warning", RULE)]
    assert run(tmp_path, remaps=remap(TOPIC, "/odom_tf")) == [(2, "warning", RULE)]
    assert run(tmp_path, remaps=remap("other_node:" + TOPIC)) == [(2, "warning", RULE)]
    assert run(tmp_path, remaps=remap("ackermann_steering_controller:" + TOPIC)) == []


def test_the_first_matching_rule_decides(tmp_path: Path) -> None:
    rules = remap(TOPIC, "/elsewhere") + remap(TOPIC)
    assert run(tmp_path, remaps=rules) == [(2, "warning", RULE)]


def test_an_unresolved_remapping_is_unknown_and_silent(tmp_path: Path) -> None:
    assert run(tmp_path, remaps=remap("$(var topic)")) == []


def test_diff_drive_controller_publishes_on_tf_itself(tmp_path: Path) -> None:
    assert run(tmp_path, name="diff_drive_controller",
               kind="diff_drive_controller/DiffDriveController") == []


def test_odometry_tf_switched_off_is_silent(tmp_path: Path) -> None:
    assert run(tmp_path, enabled="false") == []


def test_a_relay_in_the_tree_is_unknown(tmp_path: Path) -> None:
    relay = ("  <node pkg=\"topic_tools\" exec=\"relay\" "
             f"args=\"{TOPIC} /tf\"/>\n")
    assert run(tmp_path, others=relay) == []
    named = ("  <node pkg=\"my_tools\" exec=\"forward\">\n"
             f"    <param name=\"input_topic\" value=\"{TOPIC}\"/>\n  </node>\n")
    assert run(tmp_path, others=named) == []


def test_another_publisher_of_the_edge_makes_it_harmless(tmp_path: Path) -> None:
    ekf = ("  <node pkg=\"robot_localization\" exec=\"ekf_node\" name=\"ekf_filter_node\">\n"
           "    <param name=\"odom0\" value=\"/ackermann_steering_controller/odometry\"/>\n"
           "  </node>\n")
    assert run(tmp_path, others=ekf) == []


def test_the_lost_edge_is_no_second_publisher(tmp_path: Path) -> None:
    # Before: the controller's odom -> base_link counted as published on /tf, so an EKF
    # sending the same edge was reported as its second publisher.
    ekf = ("  <node pkg=\"robot_localization\" exec=\"ekf_node\" name=\"ekf_filter_node\">\n"
           "    <param name=\"odom0\" value=\"/ackermann_steering_controller/odometry\"/>\n"
           "  </node>\n")
    assert run(tmp_path, others=ekf, rules=frozenset({"duplicate_publisher"})) == []
    found = run(tmp_path, others=ekf, remaps=remap(TOPIC),
                rules=frozenset({"duplicate_publisher"}))
    assert [rule for _, _, rule in found] and {rule for _, _, rule in found} == {
        "duplicate_publisher"}


SPAWNER_LAUNCH = (
    "import os\n"
    "from launch import LaunchDescription\n"
    "from launch_ros.actions import Node\n"
    "def generate_launch_description():\n"
    "    here = os.path.dirname(__file__)\n"
    "    return LaunchDescription([\n"
    "        Node(package='controller_manager', executable='spawner',\n"
    "             arguments=['ackermann_steering_controller', '--param-file',\n"
    "                        os.path.join(here, 'controllers.yaml'){extra}]),\n"
    "    ])\n")


def run_spawner(tmp_path: Path, extra: str = "") -> list[tuple[int, str]]:
    (tmp_path / "controllers.yaml").write_text(
        CONTROLLERS.format(name="ackermann_steering_controller", kind=ACKERMANN,
                           enabled="true"))
    path = tmp_path / "spawn.launch.py"
    path.write_text(SPAWNER_LAUNCH.format(extra=extra))
    options = LintOptions(package_paths=(), select=frozenset({RULE}))
    return [(d.line, d.severity.value) for d in lint_paths([str(path)], options).diagnostics]


def test_a_spawner_controller_ros_args_remapping(tmp_path: Path) -> None:
    assert run_spawner(tmp_path) == [(7, "warning")]
    routed = f", '--controller-ros-args', '-r {TOPIC}:=/tf -r /a:=/b'"
    assert run_spawner(tmp_path, routed) == []
    # The spawner's own remappings are its process's, not the controller's.
    assert run_spawner(tmp_path, f", '--ros-args', '-r', '{TOPIC}:=/tf'") == [(7, "warning")]


URDF = ("<robot name=\"car\">\n"
        "  <link name=\"base_link\"/>\n"
        "  <gazebo>\n"
        "    <plugin filename=\"gz_ros2_control-system\" "
        "name=\"gz_ros2_control::GazeboSimROS2ControlPlugin\">\n"
        "      <parameters>{path}</parameters>\n"
        "{ros}"
        "    </plugin>\n"
        "  </gazebo>\n"
        "</robot>\n")
SIM_LAUNCH = ("<launch>\n"
              "  <node pkg=\"robot_state_publisher\" exec=\"robot_state_publisher\">\n"
              "    <param name=\"robot_description\" "
              "value=\"$(command 'xacro $(dirname)/car.urdf')\"/>\n"
              "  </node>\n"
              "  <node pkg=\"ros_gz_sim\" exec=\"create\" args=\"-topic robot_description\"/>\n"
              "{spawner}"
              "</launch>\n")
SPAWNER = "  <node pkg=\"controller_manager\" exec=\"spawner\" args=\"{name}\"/>\n"


def test_a_simulator_plugin_remapping(tmp_path: Path) -> None:
    (tmp_path / "controllers.yaml").write_text(
        CONTROLLERS.format(name="ackermann_steering_controller", kind=ACKERMANN,
                           enabled="true"))
    path = tmp_path / "sim.launch.xml"
    options = LintOptions(package_paths=(), select=frozenset({RULE}))

    def found(ros: str, spawner: str = "ackermann_steering_controller") -> list[str]:
        (tmp_path / "car.urdf").write_text(
            URDF.format(path=tmp_path / "controllers.yaml", ros=ros))
        path.write_text(SIM_LAUNCH.format(
            spawner=SPAWNER.format(name=spawner) if spawner else ""))
        return [Path(d.path).name for d in lint_paths([str(path)], options).diagnostics]

    assert found("") == ["car.urdf"]
    assert found(f"      <ros><remapping>{TOPIC}:=/tf</remapping></ros>\n") == []
    # Only named in the manager's file: no spawner of this tree starts it (a bringup split
    # over launch files that another one includes with the spawners and a relay).
    assert found("", spawner="") == []
    assert found("", spawner="other_controller") == []
    # A spawner whose words are not all resolved may start it: not judged.
    assert found("", spawner="$(var controller)") == []


def test_routing_of_one_node() -> None:
    def node(*rules: tuple[str, str]) -> NodeRecord:
        return NodeRecord("f", 1, 1, "", "", "ctrl", namespace="/robot", kind="controller",
                          remappings=rules)

    own = "/robot/ctrl/tf_odometry"
    assert route(own, node()) == LOST
    assert route(own, node(("~/tf_odometry", "tf"))) == ROUTED  # /robot/tf
    assert route(own, node(("ctrl/tf_odometry", "/tf"))) == ROUTED
    assert route(own, node(("/ctrl/tf_odometry", "/tf"))) == LOST  # another topic
    assert route(own, node((UNKNOWN_VALUE, "/tf"))) == UNKNOWN
    assert route(own, node(("~/tf_odometry", UNKNOWN_VALUE))) == UNKNOWN
    unknown = NodeRecord("f", 1, 1, "", "", "ctrl", kind="controller", remappings=None)
    assert route(own, unknown) == UNKNOWN


def test_controller_ros_args_words() -> None:
    words = ["c", "--controller-ros-args", "-r a:=b --remap ~/x:=/tf -p p:=1"]
    assert controller_remappings(words) == (("a", "b"), ("~/x", "/tf"))
    assert controller_remappings(["c", "--controller-ros-args", None]) is None
    assert controller_remappings(["c"]) == ()


def test_many_remappings_and_arguments_stay_fast(tmp_path: Path) -> None:
    # 20,000 remapping rules on the manager, none for the topic: every one looked at up to
    # the bound; 20,000 spawner words.
    rules = "".join(remap(f"/t{i}", f"/u{i}") for i in range(20_000))
    start = time.process_time()
    assert run(tmp_path, remaps=rules) == [(2, "warning", RULE)]
    # (The Python reader leaves a list of 40,000 literals unread, so the spawner's words
    # are given to the parser of its arguments directly.)
    words: list[str | None] = ["c"]
    for i in range(20_000):
        words += ["--controller-ros-args", f"-r /t{i}:=/u{i} " * 3]
    assert len(controller_remappings(words) or ()) == 60_000
    assert time.process_time() - start < 60


def test_many_controllers_stay_fast(tmp_path: Path) -> None:
    # 2,000 steering controllers in one manager's file (the file's parameters are bounded
    # at 5,000), each reported once at the manager.
    lines = ["controller_manager:", "  ros__parameters:"]
    for i in range(2_000):
        lines += [f"    c{i}:", f"      type: {ACKERMANN}"]
    (tmp_path / "controllers.yaml").write_text("\n".join(lines) + "\n")
    path = tmp_path / "many.launch.xml"
    names = " ".join(f"c{i}" for i in range(2_000))
    path.write_text("<launch>\n  <node pkg=\"controller_manager\" exec=\"ros2_control_node\">\n"
                    "    <param from=\"$(dirname)/controllers.yaml\"/>\n  </node>\n"
                    f"  <node pkg=\"controller_manager\" exec=\"spawner\" args=\"{names}\"/>\n"
                    "</launch>\n")
    options = LintOptions(package_paths=(), select=frozenset({RULE}))
    found = lint_paths([str(path)], options).diagnostics
    assert len(found) == 2_000 and {d.line for d in found} == {2}
    # 20,000 controller records and 20,000 nodes of 5 parameters each, routed in one pass.
    entry = bundled().plugin("controller", ACKERMANN, 2)
    nodes = [NodeRecord("f", i, 1, "", "", f"c{i}", kind="controller", plugin=ACKERMANN,
                        namespace="/", ros=2) for i in range(20_000)]
    nodes += [NodeRecord("f", i, 1, "p", "e", f"n{i}",
                         params=tuple((f"k{j}", "v") for j in range(5))) for i in range(20_000)]
    start = time.process_time()
    routes = controller_routes(nodes, lambda node: entry if node.kind == "controller" else None)
    assert time.process_time() - start < 60
    assert len(routes) == 20_000 and set(routes.values()) == {LOST}
