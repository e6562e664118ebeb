"""joint_states_two_publishers: joint_state_publisher beside a spawned joint_state_broadcaster
(or another known joint-states publisher) on one joint_states topic."""

from __future__ import annotations

import time
from pathlib import Path

from launch_linter.engine import LintOptions, lint_paths

RULE = "joint_states_two_publishers"
CONTROLLERS = ("controller_manager:\n"
               "  ros__parameters:\n"
               "    joint_state_broadcaster:\n"
               "      type: joint_state_broadcaster/JointStateBroadcaster\n"
               "{extra}")
LAUNCH = ("<launch>\n"
          "  <node pkg=\"joint_state_publisher\" exec=\"joint_state_publisher\"{jsp_attrs}>\n"
          "{jsp}"
          "  </node>\n"
          "  <node pkg=\"controller_manager\" exec=\"ros2_control_node\">\n"
          "    <param from=\"$(dirname)/controllers.yaml\"/>\n"
          "{manager}"
          "  </node>\n"
          "  <node pkg=\"controller_manager\" exec=\"spawner\" args=\"{spawned}\"/>\n"
          "</launch>\n")


def run(tmp_path: Path, jsp: str = "", manager: str = "", jsp_attrs: str = "",
        spawned: str = "joint_state_broadcaster", extra: str = "") -> list[tuple[int, str]]:
    (tmp_path / "controllers.yaml").write_text(CONTROLLERS.format(extra=extra))
    path = tmp_path / "robot.launch.xml"
    path.write_text(LAUNCH.format(jsp=jsp, manager=manager, jsp_attrs=jsp_attrs,
                                  spawned=spawned))
    options = LintOptions(package_paths=(), select=frozenset({RULE}))
    return [(d.line, d.severity.value) for d in lint_paths([str(path)], options).diagnostics]


def test_joint_state_publisher_beside_the_broadcaster(tmp_path: Path) -> None:
    assert run(tmp_path) == [(2, "info")]


def test_the_gui_too(tmp_path: Path) -> None:
    (tmp_path / "controllers.yaml").write_text(CONTROLLERS.format(extra=""))
    path = tmp_path / "gui.launch.xml"
    path.write_text(LAUNCH.format(jsp="", manager="", jsp_attrs="", spawned=(
        "joint_state_broadcaster")).replace(
        "pkg=\"joint_state_publisher\" exec=\"joint_state_publisher\"",
        "pkg=\"joint_state_publisher_gui\" exec=\"joint_state_publisher_gui\""))
    options = LintOptions(package_paths=(), select=frozenset({RULE}))
    assert [d.line for d in lint_paths([str(path)], options).diagnostics] == [2]


def test_a_broadcaster_no_spawner_starts_is_silent(tmp_path: Path) -> None:
    assert run(tmp_path, spawned="other_controller") == []
    assert run(tmp_path, spawned="$(var controllers)") == []


def test_merging_a_source_list_is_not_judged(tmp_path: Path) -> None:
    merged = "    <param name=\"source_list\" value=\"['/broadcaster/joint_states']\"/>\n"
    assert run(tmp_path, jsp=merged) == []


def test_different_topics_are_silent(tmp_path: Path) -> None:
    # joint_state_publisher remapped away, or in another namespace.
    assert run(tmp_path, jsp="    <remap from=\"joint_states\" to=\"jsp_states\"/>\n") == []
    assert run(tmp_path, jsp_attrs=" namespace=\"gui\"") == []
    # The broadcaster on its own topic: remapped on the manager, or use_local_topics.
    assert run(tmp_path, manager="    <remap from=\"/joint_states\" to=\"/cm_states\"/>\n") == []
    local = ("joint_state_broadcaster:\n  ros__parameters:\n    use_local_topics: true\n")
    assert run(tmp_path, extra=local) == []
    # A remapping bringing them back together.
    together = "    <remap from=\"joint_states\" to=\"/joint_states\"/>\n"
    assert run(tmp_path, jsp=together) == [(2, "info")]


def test_an_unresolved_remapping_is_silent(tmp_path: Path) -> None:
    assert run(tmp_path, jsp="    <remap from=\"$(var topic)\" to=\"x\"/>\n") == []


def test_exclusive_conditions_are_silent(tmp_path: Path) -> None:
    (tmp_path / "controllers.yaml").write_text(CONTROLLERS.format(extra=""))
    path = tmp_path / "cond.launch.xml"
    path.write_text(
        "<launch>\n  <arg name=\"sim\" default=\"true\"/>\n"
        "  <node pkg=\"joint_state_publisher\" exec=\"joint_state_publisher\" "
        "unless=\"$(var sim)\"/>\n"
        "  <node pkg=\"controller_manager\" exec=\"ros2_control_node\" if=\"$(var sim)\">\n"
        "    <param from=\"$(dirname)/controllers.yaml\"/>\n  </node>\n"
        "  <node pkg=\"controller_manager\" exec=\"spawner\" args=\"joint_state_broadcaster\" "
        "if=\"$(var sim)\"/>\n</launch>\n")
    options = LintOptions(package_paths=(), select=frozenset({RULE}))
    assert list(lint_paths([str(path)], options).diagnostics) == []


def test_many_publishers_and_remappings_stay_fast(tmp_path: Path) -> None:
    # 20,000 remapping rules on joint_state_publisher (the first 1,000 read), and 2,000
    # broadcasters spawned beside it (a manager's file is bounded at 5,000 parameters).
    rules = "".join(f"    <remap from=\"/t{i}\" to=\"/u{i}\"/>\n" for i in range(20_000))
    extra = "".join(f"    b{i}:\n      type: joint_state_broadcaster/JointStateBroadcaster\n"
                    for i in range(2_000))
    (tmp_path / "controllers.yaml").write_text(CONTROLLERS.format(extra="").replace(
        "controller_manager:\n  ros__parameters:\n",
        "controller_manager:\n  ros__parameters:\n" + extra))
    path = tmp_path / "many.launch.xml"
    names = " ".join(f"b{i}" for i in range(2_000))
    path.write_text(LAUNCH.format(jsp=rules, manager="", jsp_attrs="", spawned=names))
    options = LintOptions(package_paths=(), select=frozenset({RULE}))
    start = time.process_time()
    found = lint_paths([str(path)], options).diagnostics
    assert time.process_time() - start < 60
    assert [d.line for d in found] == [2]
