"""The knowledge of accepted parameter values and of launch files that start known nodes:
every fact cites a commit, names distributions of its ROS version at most once per
parameter and program, and the format refuses what it does not know."""

from __future__ import annotations

import re
from typing import Any

import pytest

from launch_linter.knowledge import KnowledgeError
from launch_linter.knowledge.values import bundled, parse

COMMIT = re.compile(r"^[0-9a-f]{40}$")


def test_every_fact_cites_a_commit() -> None:
    facts = bundled()
    assert facts.values and facts.launch
    for cited in [f.sources for f in facts.values] + [f.sources for f in facts.launch]:
        assert cited
        for source in cited:
            assert COMMIT.match(source.commit) and source.file and source.lines


def test_one_fact_per_program_parameter_and_distribution() -> None:
    seen: set[tuple[object, ...]] = set()
    for fact in bundled().values:
        for distro in fact.distros:
            key = (fact.ros, fact.packages, fact.plugins, fact.controller, fact.parameter,
                   distro)
            assert key not in seen, fact.id
            seen.add(key)


def test_amcl_accepts_plugin_names_from_humble_and_plain_names_before() -> None:
    facts = bundled().facts_for(2, "nav2_amcl", "amcl", None, False)
    by_distro = {d: f for f in facts if f.parameter == "robot_model_type" for d in f.distros}
    assert by_distro["galactic"].refused("nav2_amcl::DifferentialMotionModel")
    assert not by_distro["galactic"].refused("differential")
    assert by_distro["humble"].refused("differential")
    assert not by_distro["humble"].refused("nav2_amcl::OmniMotionModel")
    # A plugin of another package may exist: not known to be refused.
    assert not by_distro["humble"].refused("my_pkg::MyMotionModel")


def test_a_costmap_layer_parameter_is_matched_by_its_pattern() -> None:
    fact = next(f for f in bundled().values if f.parameter == "*.plugin")
    assert fact.names("obstacle_layer.plugin")
    assert not fact.names("plugin") and not fact.names("a.b.plugin")


def _document(**changes: Any) -> dict[str, Any]:
    fact: dict[str, Any] = {
        "id": "x", "ros": 2, "match": {"package": "p", "executables": ["e"]},
        "parameter": "mode", "distros": ["humble"], "accepts": ["a"], "closed": True,
        "otherwise": "fails", "effect": "it stops",
        "sources": [{"repository": "o/r", "package": "p", "file": "f.cpp", "ref": "humble",
                     "commit": "0" * 40, "lines": "1"}]}
    fact.update(changes)
    return {"format": 1, "values": [fact]}


@pytest.mark.parametrize("changes", [
    {"distros": ["noetic"]}, {"otherwise": "maybe"}, {"sources": []},
    {"otherwise": "falls_back"}, {"match": {"package": "p"}}, {"accepts": "a"},
])
def test_the_format_refuses_a_bad_fact(changes: dict[str, Any]) -> None:
    with pytest.raises(KnowledgeError):
        parse(_document(**changes), "test")


def test_a_good_fact_parses() -> None:
    parsed = parse(_document(), "test")
    assert parsed.values[0].refused("b") and not parsed.values[0].refused("a")
