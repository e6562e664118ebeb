"""The knowledge of installed executables and /clock sources: every fact cites a source
with a commit, names a known distribution and role, and answers the look-ups."""

from __future__ import annotations

import re

from launch_linter.knowledge.programs import (
    CLOCK,
    CLOCK_ROLES,
    DISTROS,
    INSTALLED,
    clock_launch,
    clock_program,
    installed,
)

COMMIT = re.compile(r"^[0-9a-f]{40}$")


def test_every_fact_cites_a_commit() -> None:
    sources = [fact.sources for fact in INSTALLED] + [fact.sources for fact in CLOCK]
    for cited in sources:
        assert cited
        for source in cited:
            assert COMMIT.match(source.commit) and source.file and source.repository


def test_installed_facts_name_known_distributions_once() -> None:
    seen: set[tuple[str, int, str]] = set()
    for fact in INSTALLED:
        assert fact.executables and fact.ros in (1, 2)
        for distro in fact.distros:
            assert distro in DISTROS
            assert (fact.package, fact.ros, distro) not in seen
            seen.add((fact.package, fact.ros, distro))


def test_clock_facts_have_a_role_and_one_subject() -> None:
    for fact in CLOCK:
        assert fact.does in CLOCK_ROLES
        assert (fact.executable is None) != (fact.launch is None)


def test_lookups() -> None:
    noetic = installed("robot_state_publisher", 1, "noetic")
    assert noetic is not None and "state_publisher" not in noetic.executables
    melodic = installed("robot_state_publisher", 1, "melodic")
    assert melodic is not None and "state_publisher" in melodic.executables
    assert installed("robot_state_publisher", 1, None) is None
    gz = clock_launch("ros_gz_sim", "launch/gz_sim.launch.py")
    assert gz is not None and gz.does == "gz_sim"
    bridge = clock_program("ros_gz_bridge", "parameter_bridge")
    assert bridge is not None and bridge.does == "may_bridge"
    assert clock_program("robot_state_publisher", "robot_state_publisher") is None
