"""The knowledge of installed executables and /clock sources (entries of format 2 in
``programs.json``): every fact names a known distribution and role and answers the
look-ups; a user's knowledge file adds and overrides them as it does tf entries; a file
of format 1 keeps loading, and a huge or malformed file is refused with its fault, in
bounded time, never with a traceback."""

from __future__ import annotations

import json
import time
from pathlib import Path

import pytest

from launch_linter.engine import LintOptions, lint_paths
from launch_linter.knowledge import (
    PROGRAMS_FILE,
    KnowledgeError,
    bundled,
    bundled_path,
    load,
    parse,
)
from launch_linter.knowledge.programs import CLOCK_ROLES, ClockFact, Installed, NodeNames
from launch_linter.model.distro import ROS1_DISTROS, ROS2_DISTROS
from launch_linter.workspace.config import load_knowledge_file

SOURCE = {"repository": "me/bot", "package": "bot", "file": "f", "ref": "r",
          "commit": "0" * 40, "lines": "1"}


def installed_entry(entry_id: str, package: str, distros: list[str], installs: list[str],
                    ros: int = 1) -> dict[str, object]:
    return {"id": entry_id, "kind": "installed", "ros": [ros], "match": {"package": package},
            "distros": distros, "installs": installs, "sources": [SOURCE]}


def clock_entry(entry_id: str, package: str, clock: str, **match: list[str]
                ) -> dict[str, object]:
    return {"id": entry_id, "kind": "clock", "ros": [2],
            "match": {"package": package, **match}, "clock": clock, "sources": [SOURCE]}


def user_file(tmp_path: Path, *entries: dict[str, object], file_format: int = 2) -> str:
    path = tmp_path / "knowledge.json"
    # Compact: twenty thousand entries stay under the size limit of a knowledge file.
    path.write_text(json.dumps({"format": file_format, "entries": list(entries)},
                               separators=(",", ":")))
    return str(path)


def test_every_node_names_entry_names_its_program_and_cites_its_source() -> None:
    facts = [f for f in load(str(bundled_path(PROGRAMS_FILE))).programs.facts
             if isinstance(f, NodeNames)]
    assert {(f.package, e) for f in facts for e in f.executables} >= {
        ("mavros", "mavros_node"), ("tf2_ros", "static_transform_publisher"),
        ("lio_sam", "lio_sam_imuPreintegration")}
    for fact in facts:
        assert fact.names and fact.executables and fact.ros == (2,), fact.id
        assert fact.sources, fact.id
        for source in fact.sources:
            assert len(source.commit) == 40 and source.file and source.lines, fact.id


def test_the_bundled_facts_name_known_distributions_once() -> None:
    facts = load(str(bundled_path(PROGRAMS_FILE))).programs.facts
    installed = [f for f in facts if isinstance(f, Installed)]
    assert installed
    seen: set[tuple[str, int, str]] = set()
    for fact in installed:
        assert fact.executables and len(fact.ros) == 1
        for distro in fact.distros:
            assert distro in (ROS1_DISTROS if fact.ros == (1,) else ROS2_DISTROS)
            assert (fact.package, fact.ros[0], distro) not in seen
            seen.add((fact.package, fact.ros[0], distro))


def test_the_bundled_clock_facts_have_a_role_and_one_kind_of_subject() -> None:
    clocks = [f for f in bundled().programs.facts if isinstance(f, ClockFact)]
    assert clocks
    for fact in clocks:
        assert fact.clock in CLOCK_ROLES
        assert bool(fact.executables) != bool(fact.launch_files)


def test_lookups() -> None:
    base = bundled()
    noetic = base.installed("robot_state_publisher", 1, "noetic")
    assert noetic is not None and "state_publisher" not in noetic.executables
    melodic = base.installed("robot_state_publisher", 1, "melodic")
    assert melodic is not None and "state_publisher" in melodic.executables
    assert base.installed("robot_state_publisher", 1, None) is None
    assert base.installed("robot_state_publisher", 2, "noetic") is None
    gz = base.clock_launch("ros_gz_sim", "launch/gz_sim.launch.py")
    assert gz is not None and gz.clock == "gz_sim"
    bridge = base.clock_program("ros_gz_bridge", "parameter_bridge")
    assert bridge is not None and bridge.clock == "may_bridge"
    assert base.clock_program("robot_state_publisher", "robot_state_publisher") is None
    assert base.clock_program("ros_gz_bridge", "parameter_bridge", ros=1) is None


# -- a user's file extends and overrides them ------------------------------------------------

LAUNCH = '<launch>\n<node name="d" pkg="{package}" type="{type}"/>\n</launch>\n'


def missing(tmp_path: Path, package: str, executable: str, knowledge: str | None,
            distro: str = "noetic") -> list[tuple[int, str]]:
    from launch_linter.commands.options import load_knowledge

    path = tmp_path / "robot.launch"
    path.write_text(LAUNCH.format(package=package, type=executable))
    options = LintOptions(package_paths=(), select=frozenset({"node_executable_missing"}),
                          ros_distro=distro,
                          knowledge=load_knowledge((knowledge,) if knowledge else ()))
    return [(d.line, d.severity.value) for d in lint_paths([str(path)], options).diagnostics]


def test_a_user_file_adds_a_package_s_executables(tmp_path: Path) -> None:
    mine = user_file(tmp_path, installed_entry("my_base_noetic", "my_base", ["noetic"],
                                               ["base_node"]))
    assert missing(tmp_path, "my_base", "old_base_node", None) == []
    assert missing(tmp_path, "my_base", "old_base_node", mine) == [(2, "error")]
    assert missing(tmp_path, "my_base", "base_node", mine) == []
    assert missing(tmp_path, "my_base", "old_base_node", mine, distro="melodic") == []


def test_a_user_file_overrides_a_bundled_fact(tmp_path: Path) -> None:
    # Its own build of robot_state_publisher for Noetic still installs state_publisher:
    # the user's entry comes first, and replaces a bundled one of its id.
    assert missing(tmp_path, "robot_state_publisher", "state_publisher", None) == [
        (2, "error")]
    mine = user_file(tmp_path, installed_entry(
        "robot_state_publisher_noetic", "robot_state_publisher", ["noetic"],
        ["robot_state_publisher", "state_publisher"]))
    assert missing(tmp_path, "robot_state_publisher", "state_publisher", mine) == []
    base = bundled().extended(load_knowledge_file(mine))
    assert [f.id for f in base.programs.facts].count("robot_state_publisher_noetic") == 1


SIM = ("from launch import LaunchDescription\n"
       "from launch_ros.actions import Node\n"
       "def generate_launch_description():\n"
       "    return LaunchDescription([\n"
       "        Node(package='ros_gz_sim', executable='create'),\n"
       "        Node(package='my_sim', executable='glue'),\n"
       "        Node(package='robot_state_publisher', executable='robot_state_publisher',\n"
       "             parameters=[{'use_sim_time': True}]),\n"
       "    ])\n")


def clock_findings(tmp_path: Path, *entries: dict[str, object]) -> list[str]:
    from launch_linter.commands.options import load_knowledge

    path = tmp_path / "sim.launch.py"
    path.write_text(SIM)
    files = (user_file(tmp_path, *entries),) if entries else ()
    options = LintOptions(package_paths=(), select=frozenset({"sim_clock_not_bridged"}),
                          knowledge=load_knowledge(files))
    return [d.message for d in lint_paths([str(path)], options).diagnostics]


def test_a_user_file_names_a_clock_bridge_or_a_program_without_a_clock(
        tmp_path: Path) -> None:
    (open_tree,) = clock_findings(tmp_path)
    assert "not decided" in open_tree and "my_sim/glue" in open_tree
    (found,) = clock_findings(tmp_path, clock_entry("my_glue", "my_sim", "none",
                                                    executables=["glue"]))
    assert "nothing in the launch tree bridges" in found and "robot_state_publisher" in found
    assert clock_findings(tmp_path, clock_entry("my_glue", "my_sim", "may_bridge",
                                                executables=["*"])) == []


def test_a_user_file_overrides_a_clock_fact(tmp_path: Path) -> None:
    # A fork whose create spawner also bridges the clock.
    fork = clock_entry("clock_ros_gz_sim_create", "ros_gz_sim", "may_bridge",
                       executables=["create"])
    assert clock_findings(tmp_path, fork, clock_entry("g", "my_sim", "none",
                                                      executables=["glue"])) == []


# -- the format: old files keep loading, new kinds need format 2 ----------------------------

def test_a_file_of_format_1_keeps_loading_without_the_new_kinds(tmp_path: Path) -> None:
    node: dict[str, object] = {"id": "my_node", "kind": "node", "ros": [1],
                               "match": {"package": "my_base", "executables": ["driver"]},
                               "sources": [SOURCE]}
    base = load_knowledge_file(user_file(tmp_path, node, file_format=1))
    assert [e.id for e in base.entries] == ["my_node"] and base.programs.facts == ()
    with pytest.raises(KnowledgeError, match="format 2 adds installed"):
        load_knowledge_file(user_file(
            tmp_path, installed_entry("x", "p", ["noetic"], ["a"]), file_format=1))
    with pytest.raises(KnowledgeError, match="format 1 or 2"):
        load_knowledge_file(user_file(tmp_path, node, file_format=3))


@pytest.mark.parametrize("entry, message", [
    (installed_entry("x", "p", ["humble"], ["a"]), "distros"),
    (installed_entry("x", "p", [], ["a"]), "distros"),
    (installed_entry("x", "p", ["noetic"], []), "installs"),
    (installed_entry("x", "p", ["noetic"], "a"), "installs"),  # type: ignore[arg-type]
    ({**installed_entry("x", "p", ["noetic"], ["a"]), "match": {}}, "match.package"),
    ({**installed_entry("x", "p", ["noetic"], ["a"]), "sources": []}, "sources"),
    (clock_entry("x", "p", "ticks", executables=["a"]), "clock must be one of"),
    (clock_entry("x", "p", "none"), "executables or launch_files"),
    (clock_entry("x", "p", "none", launch_files=[7]), "launch_files"),  # type: ignore[list-item]
    ({**clock_entry("x", "p", "none"), "kind": "node_names", "names": ["n"]},
     "match.executables and names"),
    ({**clock_entry("x", "p", "none", executables=["e"]), "kind": "node_names"},
     "match.executables and names"),
    ({**clock_entry("x", "p", "none", executables=["e"]), "kind": "node_names",
      "names": ["n", ""]}, r"names\[1\] must be a non-empty string"),
    ({**clock_entry("x", "p", "none", executables=["a"]), "ros": [3]}, "ros"),
])
def test_a_malformed_program_entry_is_refused_with_its_fault(entry: dict[str, object],
                                                             message: str) -> None:
    with pytest.raises(KnowledgeError, match=message):
        parse({"format": 2, "entries": [entry]}, "user.json")


# -- hostile files ---------------------------------------------------------------------------

MANY = 15_000
"""As many entries as the size limit of a knowledge file (4 MiB) lets through, compact."""
ITEMS = 20_000


def test_the_most_entries_a_file_holds_load_in_bounded_time(tmp_path: Path) -> None:
    entries = [installed_entry(f"e{i}", "my_base", ["noetic"], [f"n{i}"]) for i in range(MANY)]
    started = time.process_time()
    base = load_knowledge_file(user_file(tmp_path, *entries))
    assert len(base.programs.facts) == MANY
    for _ in range(100):  # looked up once per launched node
        assert base.installed("my_base", 1, "kinetic") is None
    assert time.process_time() - started < 30


def test_twenty_thousand_items_of_one_entry(tmp_path: Path) -> None:
    names = [f"node_{i}" for i in range(ITEMS)]
    base = load_knowledge_file(user_file(
        tmp_path, installed_entry("big", "my_base", ["noetic"], names),
        clock_entry("clock", "my_base", "none", executables=names)))
    fact = base.installed("my_base", 1, "noetic")
    assert fact is not None and len(fact.executables) == ITEMS
    distros = ["noetic"] * ITEMS + ["hydro"]
    with pytest.raises(KnowledgeError, match="distros"):
        load_knowledge_file(user_file(tmp_path, installed_entry("big", "b", distros, ["a"])))


def test_duplicated_ids_are_refused_quickly(tmp_path: Path) -> None:
    # Counting each id's uses in the list again was quadratic in the entries.
    entries = [clock_entry(f"e{i % 2}", "p", "none", executables=["a"]) for i in range(MANY)]
    started = time.process_time()
    with pytest.raises(KnowledgeError, match=r"used twice: e0, e1$"):
        load_knowledge_file(user_file(tmp_path, *entries))
    assert time.process_time() - started < 30


def test_a_huge_malformed_file_is_a_usage_error_not_a_traceback(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    from launch_linter.cli import main

    entries: list[object] = [clock_entry(f"e{i}", "p", "none", executables=["a"])
                             for i in range(MANY)]
    entries.append({"id": "last", "kind": "installed", "ros": [1], "match": []})
    user_file(tmp_path, *entries)  # type: ignore[arg-type]
    (tmp_path / ".launch-linter.toml").write_text('knowledge = "knowledge.json"\n')
    (tmp_path / "a.launch").write_text("<launch/>\n")
    code = main(["check", "--config", str(tmp_path / ".launch-linter.toml"),
                 str(tmp_path / "a.launch")])
    err = capsys.readouterr().err
    assert code == 2 and "Traceback" not in err
    assert f"entries[{MANY}] (last).match must be an object" in err


def test_nested_json_is_refused_with_a_message(tmp_path: Path) -> None:
    path = tmp_path / "knowledge.json"
    path.write_text('{"format": 2, "entries": ' + "[" * 100_000 + "]" * 100_000 + "}")
    with pytest.raises(KnowledgeError, match=r"not JSON|entries"):
        load_knowledge_file(str(path))


# -- distributions: a run of the release order, or a list ----------------------------------

def _bundled_distributions() -> dict[str, tuple[str, ...]]:
    from launch_linter.knowledge import VALUES_FILE

    programs = load(str(bundled_path(PROGRAMS_FILE)))
    values = load(str(bundled_path(VALUES_FILE)))
    return {**{f.id: f.distros for f in programs.programs.facts if isinstance(f, Installed)},
            **{f.id: f.distros for f in values.values.values}}


def test_a_distribution_added_to_the_order_needs_no_edit_of_open_entries(
        monkeypatch: pytest.MonkeyPatch) -> None:
    from launch_linter.model import distro

    before = _bundled_distributions()
    assert before["robot_state_publisher_ros2"] == ROS2_DISTROS[ROS2_DISTROS.index("foxy"):]
    newer = (*ROS2_DISTROS[:-1], "zenith", "rolling")
    monkeypatch.setattr(distro, "ROS2_DISTROS", newer)
    after = _bundled_distributions()
    # Every entry whose run is open at the end (the program is still shipped) covers it,
    # the others are unchanged.
    grown = {i for i in before if after[i] != before[i]}
    assert "robot_state_publisher_ros2" in grown
    assert "nav2_amcl.robot_model_type.plugins" in grown
    for entry_id in grown:
        assert after[entry_id] == (*before[entry_id][:-1], "zenith", "rolling"), entry_id
    assert after["nav2_amcl.robot_model_type.names"] == ("foxy", "galactic")
    assert after["robot_state_publisher_noetic"] == ("noetic",)


@pytest.mark.parametrize("changes, message", [
    ({"since": "hydro"}, "since must be a distribution of ROS 1"),
    ({"until": "humble"}, "until must be a distribution of ROS 1"),
    ({"since": "noetic", "until": "kinetic"}, "since comes after its until"),
    ({"since": "noetic", "distros": ["noetic"]}, "not both"),
    ({"distros": ["noetic", "foxy"]}, "distros names 'foxy', not a distribution of ROS 1"),
    ({"distros": []}, "distros must list distributions of ROS 1"),
    ({}, "needs distros, or since and/or until"),
    ({"since": "noetic", "ros": [1, 2]}, "one ROS version"),
])
def test_an_unknown_or_contradictory_distribution_is_a_fault(
        changes: dict[str, object], message: str) -> None:
    entry = installed_entry("x", "p", [], ["a"])
    del entry["distros"]
    entry.update(changes)
    with pytest.raises(KnowledgeError, match=message):
        parse({"format": 2, "entries": [entry]}, "user.json")


def test_a_run_of_the_order_from_a_users_file(tmp_path: Path) -> None:
    entry = installed_entry("mine", "my_base", [], ["driver"], ros=2)
    del entry["distros"]
    entry.update(since="humble", until="jazzy")
    base = load_knowledge_file(user_file(tmp_path, entry))
    assert [d for d in ROS2_DISTROS if base.installed("my_base", 2, d)] == [
        "humble", "iron", "jazzy"]
