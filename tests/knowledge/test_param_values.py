"""The knowledge of accepted parameter values and of launch files that start known nodes:
every fact cites a commit, names distributions of its ROS version at most once per
parameter and program, and the format refuses what it does not know. A user's knowledge
file adds and overrides facts as it does tf entries: a bad fact is a usage error naming
its file and line, never a traceback, and a file of twenty thousand facts stays bounded."""

from __future__ import annotations

import json
import re
import time
from pathlib import Path
from typing import Any

import pytest

from launch_linter.engine import LintOptions, lint_paths
from launch_linter.knowledge import KnowledgeBase, KnowledgeError, parse
from launch_linter.knowledge import bundled as bundled_base
from launch_linter.knowledge.values import ValueKnowledge
from launch_linter.workspace.config import load_knowledge_file

COMMIT = re.compile(r"^[0-9a-f]{40}$")


def bundled() -> ValueKnowledge:
    return bundled_base().values


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
    return {"format": 2, "values": [fact]}


@pytest.mark.parametrize("changes", [
    {"distros": ["noetic"]}, {"otherwise": "maybe"}, {"sources": []},
    {"otherwise": "falls_back"}, {"match": {"package": "p"}}, {"accepts": "a"},
    # Without accepts, a closed fact would refuse every value: it must be written.
    {"accepts": None},
])
def test_the_format_refuses_a_bad_fact(changes: dict[str, Any]) -> None:
    with pytest.raises(KnowledgeError):
        parse(_document(**changes), "test")


def test_a_good_fact_parses() -> None:
    parsed = parse(_document(), "test").values
    assert parsed.values[0].refused("b") and not parsed.values[0].refused("a")


def test_optional_lists_read_null_as_absent_and_launch_paths_are_required() -> None:
    parsed = parse(_document(refuses=None), "test").values
    assert parsed.values[0].refuses == ()
    launch = {"id": "l", "ros": 2, "package": "p", "launch": ["a.launch.py"],
              "parameter_file_argument": "params_file",
              "nodes": [{"package": "p", "executable": "e", "name": "n"}],
              "sources": _document()["values"][0]["sources"]}
    assert parse({"format": 2, "launch_files": [launch]}, "t").values.launch_file(
        "p", "a.launch.py") is not None
    for paths in ([], None):
        with pytest.raises(KnowledgeError, match=r"launch_files\[0\] \(l\)\.launch must be"):
            parse({"format": 2, "launch_files": [{**launch, "launch": paths}]}, "t")


def test_values_need_format_2() -> None:
    with pytest.raises(KnowledgeError, match="'values' needs format 2"):
        parse({**_document(), "format": 1, "entries": []}, "test")


# -- a user's knowledge file -------------------------------------------------------------------

YAML_NODE = ("launch:\n"
             "  - node:\n"
             "      pkg: my_driver\n"
             "      exec: driver\n"
             "      name: driver\n"
             "      param:\n"
             "        - name: mode\n"
             "          value: {value}\n")


def _fact(**changes: Any) -> dict[str, Any]:
    fact: dict[str, Any] = _document(**{
        "id": "my_driver.mode", "match": {"package": "my_driver", "executables": ["driver"]},
        "distros": ["humble", "jazzy"], "accepts": ["fast", "slow"],
        "effect": "the driver stops"})["values"][0]
    fact.update(changes)
    return fact


def _user_file(tmp_path: Path, *values: dict[str, Any], compact: bool = False) -> str:
    path = tmp_path / "knowledge.json"
    document = {"format": 2, "values": list(values)}
    path.write_text(json.dumps(document, separators=(",", ":")) if compact
                    else json.dumps(document, indent=1))
    return str(path)


def _findings(tmp_path: Path, value: str, knowledge: KnowledgeBase | None
              ) -> list[tuple[int, str, str]]:
    launch = tmp_path / "a.launch.yaml"
    launch.write_text(YAML_NODE.format(value=value))
    options = LintOptions(package_paths=(), select=frozenset({"param_value_refused"}),
                          ros_distro="humble", knowledge=knowledge)
    return [(d.line, d.severity.value, d.message)
            for d in lint_paths([str(launch)], options).diagnostics]


def test_a_user_fact_adds_a_refused_value_that_reports(tmp_path: Path) -> None:
    base = bundled_base().extended(load_knowledge_file(_user_file(tmp_path, _fact())))
    assert _findings(tmp_path, "turbo", None) == []
    found = _findings(tmp_path, "turbo", base)
    assert [(line, level) for line, level, _ in found] == [(7, "error")]  # the param
    assert "does not accept mode 'turbo' (it accepts fast, slow)" in found[0][2]
    assert _findings(tmp_path, "fast", base) == []


def test_a_user_fact_overrides_a_bundled_one_by_id(tmp_path: Path) -> None:
    bundled_fact = next(f for f in bundled().values
                        if f.id == "nav2_amcl.robot_model_type.plugins")
    mine = _fact(id=bundled_fact.id, match={"package": "nav2_amcl", "executables": ["amcl"]},
                 parameter="robot_model_type", accepts=["differential"], distros=["humble"])
    base = bundled_base().extended(load_knowledge_file(_user_file(tmp_path, mine)))
    facts = base.values.facts_for(2, "nav2_amcl", "amcl", None, False)
    replaced = [f for f in facts if f.id == bundled_fact.id]
    assert len(replaced) == 1 and not replaced[0].refused("differential")
    assert len(base.values.values) == len(bundled().values)


def test_a_malformed_user_fact_is_a_usage_error_with_its_file_and_line(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    from launch_linter.cli import main

    path = _user_file(tmp_path, _fact(), _fact(id="bad", otherwise="maybe"))
    (tmp_path / ".launch-linter.toml").write_text('knowledge = "knowledge.json"\n')
    (tmp_path / "a.launch.yaml").write_text(YAML_NODE.format(value="fast"))
    code = main(["check", "--config", str(tmp_path / ".launch-linter.toml"),
                 str(tmp_path / "a.launch.yaml")])
    err = capsys.readouterr().err
    line = next(number for number, text in enumerate(Path(path).read_text().splitlines(), 1)
                if '"id": "bad"' in text) - 1  # the fact's opening brace
    assert code == 2 and "Traceback" not in err
    assert f"knowledge.json:{line}: values[1] (bad).otherwise must be one of" in err


ITEMS = 20_000
MANY = 14_000
"""As many facts as the size limit of a knowledge file (4 MiB) lets through, compact."""


def _facts(count: int) -> list[dict[str, Any]]:
    source = [{"repository": "o", "package": "p", "file": "f", "ref": "r",
               "commit": "0" * 40, "lines": "1"}]
    return [{"id": f"f{i}", "ros": 2, "match": {"package": f"p{i}", "executables": ["e"]},
             "parameter": "m", "distros": ["humble"], "accepts": [], "otherwise": "fails",
             "effect": "e", "sources": source} for i in range(count)]


def test_the_most_user_facts_a_file_holds_stay_bounded(tmp_path: Path) -> None:
    # Each launched node is matched against its own program's facts only.
    facts = _facts(MANY)
    started = time.process_time()
    base = load_knowledge_file(_user_file(tmp_path, *facts, compact=True))
    assert len(base.values.values) == MANY
    for i in range(0, MANY, 7):
        assert len(base.values.facts_for(2, f"p{i}", "e", None, False)) == 1
    with pytest.raises(KnowledgeError, match=r"used twice: f0$"):
        load_knowledge_file(_user_file(tmp_path, *facts, facts[0], compact=True))
    facts[-1] = {**facts[-1], "distros": ["hydro"]}
    with pytest.raises(KnowledgeError, match=rf":1: values\[{MANY - 1}\] \(f{MANY - 1}\)"):
        load_knowledge_file(_user_file(tmp_path, *facts, compact=True))
    with pytest.raises(KnowledgeError, match="larger than"):
        load_knowledge_file(_user_file(tmp_path, *_facts(ITEMS), compact=True))
    assert time.process_time() - started < 30


def test_twenty_thousand_items_of_one_user_fact(tmp_path: Path) -> None:
    values = [f"v{i}" for i in range(ITEMS)]
    fact = _fact(accepts=values, refuses=values, distros=["humble"] * ITEMS)
    started = time.process_time()
    base = load_knowledge_file(_user_file(tmp_path, fact, compact=True))
    assert not base.values.values[0].refused(values[-1])
    with pytest.raises(KnowledgeError, match="names 'hydro', not a distribution of ROS 2"):
        load_knowledge_file(_user_file(
            tmp_path, _fact(distros=["humble"] * ITEMS + ["hydro"]), compact=True))
    assert time.process_time() - started < 30
