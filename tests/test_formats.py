"""The SARIF and GitHub output formats.

The official SARIF schema carries no licence statement, so it is not copied here; the
schema below is our own description of the subset we emit, with the official property
names and constraints. ``scripts/validate_sarif.py`` checks output against the official
schema where a copy is available.
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import jsonschema
import pytest

from launch_linter import LintOptions, lint_paths, lint_text
from launch_linter.cli import main
from launch_linter.engine import LintResult
from launch_linter.model import Belief, Category, Diagnostic, Location, Severity
from launch_linter.model.beliefs import BeliefSet
from launch_linter.report.formats import (
    artifact_uri,
    doc_section,
    escape_data,
    escape_property,
    github_command,
    render,
)
from launch_linter.rules import RULES

MESSAGE = {"type": "object", "required": ["text"], "properties": {"text": {"type": "string"}}}
PHYSICAL = {
    "type": "object",
    "additionalProperties": False,
    "required": ["artifactLocation", "region"],
    "properties": {
        "artifactLocation": {
            "type": "object",
            "additionalProperties": False,
            "required": ["uri"],
            "properties": {"uri": {"type": "string", "minLength": 1}},
        },
        "region": {
            "type": "object",
            "additionalProperties": False,
            "required": ["startLine", "startColumn"],
            "properties": {
                "startLine": {"type": "integer", "minimum": 1},
                "startColumn": {"type": "integer", "minimum": 1},
            },
        },
    },
}
LEVEL = {"enum": ["none", "note", "warning", "error"]}
# SARIF 2.1.0 ``fix``: a description and at least one artifact change, each with at least
# one replacement of a region (here in bytes) by inserted content.
FIXES: dict[str, Any] = {
    "type": "array",
    "items": {
        "type": "object",
        "additionalProperties": False,
        "required": ["artifactChanges"],
        "properties": {
            "description": MESSAGE,
            "artifactChanges": {
                "type": "array",
                "minItems": 1,
                "items": {
                    "type": "object",
                    "additionalProperties": False,
                    "required": ["artifactLocation", "replacements"],
                    "properties": {
                        "artifactLocation": {"type": "object", "required": ["uri"]},
                        "replacements": {
                            "type": "array",
                            "minItems": 1,
                            "items": {
                                "type": "object",
                                "additionalProperties": False,
                                "required": ["deletedRegion"],
                                "properties": {
                                    "deletedRegion": {
                                        "type": "object",
                                        "required": ["byteOffset", "byteLength"],
                                        "properties": {
                                            "byteOffset": {"type": "integer", "minimum": 0},
                                            "byteLength": {"type": "integer", "minimum": 0},
                                        },
                                    },
                                    "insertedContent": {
                                        "type": "object",
                                        "required": ["text"],
                                    },
                                },
                            },
                        },
                    },
                },
            },
        },
    },
}

SARIF_SUBSET: dict[str, Any] = {
    "type": "object",
    "additionalProperties": False,
    "required": ["version", "runs"],
    "properties": {
        "$schema": {"type": "string"},
        "version": {"const": "2.1.0"},
        "runs": {
            "type": "array",
            "minItems": 1,
            "maxItems": 1,
            "items": {
                "type": "object",
                "additionalProperties": False,
                "required": ["tool", "results"],
                "properties": {
                    "tool": {
                        "type": "object",
                        "required": ["driver"],
                        "properties": {
                            "driver": {
                                "type": "object",
                                "required": ["name", "rules"],
                                "properties": {
                                    "name": {"type": "string"},
                                    "version": {"type": "string"},
                                    "semanticVersion": {"type": "string"},
                                    "rules": {
                                        "type": "array",
                                        "items": {
                                            "type": "object",
                                            "required": ["id", "shortDescription", "help"],
                                            "properties": {
                                                "id": {"type": "string"},
                                                "name": {"type": "string"},
                                                "shortDescription": MESSAGE,
                                                "fullDescription": MESSAGE,
                                                "help": {
                                                    "type": "object",
                                                    "required": ["text", "markdown"],
                                                },
                                                "defaultConfiguration": {
                                                    "type": "object",
                                                    "required": ["level"],
                                                    "properties": {"level": LEVEL},
                                                },
                                                "properties": {"type": "object"},
                                            },
                                            "additionalProperties": False,
                                        },
                                    },
                                },
                                "additionalProperties": False,
                            }
                        },
                    },
                    "columnKind": {"enum": ["utf16CodeUnits", "unicodeCodePoints"]},
                    "results": {
                        "type": "array",
                        "items": {
                            "type": "object",
                            "additionalProperties": False,
                            "required": ["ruleId", "level", "message", "locations"],
                            "properties": {
                                "ruleId": {"type": "string"},
                                "ruleIndex": {"type": "integer", "minimum": 0},
                                "fixes": FIXES,
                                "level": LEVEL,
                                "message": MESSAGE,
                                "locations": {
                                    "type": "array",
                                    "minItems": 1,
                                    "items": {
                                        "type": "object",
                                        "additionalProperties": False,
                                        "properties": {"physicalLocation": PHYSICAL},
                                    },
                                },
                                "relatedLocations": {
                                    "type": "array",
                                    "items": {
                                        "type": "object",
                                        "additionalProperties": False,
                                        "required": ["id", "physicalLocation"],
                                        "properties": {
                                            "id": {"type": "integer", "minimum": 0},
                                            "physicalLocation": PHYSICAL,
                                            "message": MESSAGE,
                                        },
                                    },
                                },
                                "properties": {"type": "object"},
                            },
                        },
                    },
                    "properties": {"type": "object"},
                },
            },
        },
    },
}

NODE = '<node pkg="tf2_ros" type="static_transform_publisher" name="{name}" args="{args}"/>'
XML = "\n".join([
    "<launch>",
    "  " + NODE.format(name="a", args="0 0 0 0 0 0 base_link laser"),
    "  " + NODE.format(name="b", args="0 0 1 0 0 0 base_link laser"),
    "  " + NODE.format(name="c", args="0 0 0 0 0 0 map /odom"),
    "</launch>",
])


def sarif_of(result: LintResult) -> dict[str, Any]:
    document: dict[str, Any] = json.loads(render("sarif", result, BeliefSet.empty(), "9.9"))
    return document


@pytest.fixture
def result() -> LintResult:
    return lint_text(XML, "launch/robot.launch", LintOptions(package_paths=()))


def test_sarif_is_valid(result: LintResult) -> None:
    document = sarif_of(result)
    jsonschema.Draft7Validator(SARIF_SUBSET).validate(document)
    assert document["version"] == "2.1.0"


def test_subset_schema_rejects_what_sarif_rejects(result: LintResult) -> None:
    document = sarif_of(result)
    document["runs"][0]["results"][0]["locations"][0]["physicalLocation"]["region"][
        "startLine"
    ] = 0
    with pytest.raises(jsonschema.ValidationError):
        jsonschema.Draft7Validator(SARIF_SUBSET).validate(document)


def test_every_rule_is_described_with_its_documentation(result: LintResult) -> None:
    driver = sarif_of(result)["runs"][0]["tool"]["driver"]
    assert driver["name"] == "launch-linter" and driver["version"] == "9.9"
    assert [r["id"] for r in driver["rules"]] == [r.id for r in RULES]
    for descriptor, rule in zip(driver["rules"], RULES):
        assert descriptor["help"]["markdown"] == rule.doc
        assert descriptor["shortDescription"]["text"] == rule.summary
        level = {"error": "error", "warning": "warning", "info": "note"}[rule.severity.value]
        assert descriptor["defaultConfiguration"]["level"] == level


def test_one_result_per_diagnostic_with_region_and_related(result: LintResult) -> None:
    run = sarif_of(result)["runs"][0]
    results = run["results"]
    assert [(r["ruleId"], r["locations"][0]["physicalLocation"]["region"]["startLine"])
            for r in results] == [(d.rule, d.line) for d in result.diagnostics]
    dup = next(r for r in results if r["ruleId"] == "dup_sig")
    assert dup["level"] == "error"
    assert dup["locations"][0]["physicalLocation"] == {
        "artifactLocation": {"uri": "launch/robot.launch"},
        "region": {"startLine": 3, "startColumn": 3},
    }
    assert dup["relatedLocations"][0]["physicalLocation"]["region"] == {
        "startLine": 2, "startColumn": 3
    }
    assert run["tool"]["driver"]["rules"][dup["ruleIndex"]]["id"] == "dup_sig"
    assert dup["properties"]["node"] == "b"


def test_info_is_a_note_and_belief_is_kept() -> None:
    belief = Belief("name_null_rot", "map_to_odom", None, 30, 29, 1.9)
    diagnostic = Diagnostic(
        "name_null_rot", Category.MAY_IMPLIED, Severity.INFO, "a.launch", 1, 1, "m", None,
        (Location("b.launch", 2, 4),), belief,
    )
    document = sarif_of(LintResult((), (), (diagnostic,)))
    jsonschema.Draft7Validator(SARIF_SUBSET).validate(document)
    (item,) = document["runs"][0]["results"]
    assert item["level"] == "note"
    assert item["properties"]["belief"]["z"] == 1.9
    assert item["relatedLocations"][0]["physicalLocation"]["artifactLocation"]["uri"] == (
        "b.launch"
    )


def test_uris() -> None:
    assert artifact_uri("./launch/a b.launch") == "launch/a%20b.launch"
    assert artifact_uri("/ws/src/robot.launch") == "file:///ws/src/robot.launch"
    assert artifact_uri("robot#1.launch") == "robot%231.launch"


def test_doc_section() -> None:
    doc = "Summary.\n\n## What it does\nFinds\nthings.\n\n## Why is this bad?\nBecause."
    assert doc_section(doc, "What it does") == "Finds things."
    assert doc_section(doc, "Example") == ""


def test_github_escaping() -> None:
    assert escape_data("50% done\r\nnext") == "50%25 done%0D%0Anext"
    assert escape_property("a:b,c%\n") == "a%3Ab%2Cc%25%0A"


def test_github_command() -> None:
    diagnostic = Diagnostic(
        "dup_sig", Category.MUST, Severity.ERROR, "dir,x/a:b.launch", 12, 3,
        "pair 'a' -> 'b' twice:\nsee line 9 (100%)",
    )
    assert github_command(diagnostic) == (
        "::error file=dir%2Cx/a%3Ab.launch,line=12,col=3,title=launch-linter dup_sig"
        "::pair 'a' -> 'b' twice:%0Asee line 9 (100%25)"
    )
    warning = Diagnostic("leading_slash", Category.TF, Severity.WARNING, "a.launch", 1, 1, "m")
    info = Diagnostic("unresolved", Category.LAUNCH, Severity.INFO, "a.launch", 1, 1, "m")
    assert github_command(warning).startswith("::warning file=a.launch,")
    assert github_command(info).startswith("::notice file=a.launch,")


def test_github_render_one_line_per_diagnostic(result: LintResult) -> None:
    lines = render("github", result, BeliefSet.empty(), "1").splitlines()
    assert len(lines) == len(result.diagnostics) > 0
    assert all(line.startswith("::") for line in lines)


def test_unknown_format(result: LintResult) -> None:
    with pytest.raises(ValueError, match="unknown format"):
        render("junit", result, BeliefSet.empty(), "1")


def test_cli_formats(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    monkeypatch.chdir(tmp_path)
    Path("robot.launch").write_text(XML)
    assert main(["check", "--beliefs", "none", "--format", "sarif", "robot.launch"]) == 1
    document = json.loads(capsys.readouterr().out)
    jsonschema.Draft7Validator(SARIF_SUBSET).validate(document)
    expected = lint_paths(["robot.launch"], LintOptions(package_paths=())).diagnostics
    assert len(document["runs"][0]["results"]) == len(expected)
    assert main(["check", "--beliefs", "none", "--format", "github", "robot.launch"]) == 1
    out = capsys.readouterr().out
    assert out.startswith("::error file=robot.launch,line=3,col=3,title=launch-linter dup_sig::")


def test_json_is_written_in_pieces_exactly_as_dumped() -> None:
    import io

    from launch_linter.report import json_report

    document = {"files": [{"path": f"é{i}.launch", "n": i} for i in range(5000)], "x": None}
    out = io.StringIO()
    json_report.write(document, out)
    assert out.getvalue() == json_report.dumps(document) + "\n"


@pytest.mark.parametrize("count", [0, 1, 3])
def test_check_json_streamed_item_by_item_is_the_document_dumped(count: int) -> None:
    # check_pieces makes each file's and finding's JSON only when it is written (flat
    # memory); its text must be that of the whole document dumped at once.
    from launch_linter.model.launch import FileRecord, FileStatus
    from launch_linter.report import json_report

    findings = tuple(
        Diagnostic(
            "dup_sig", Category.LAUNCH, Severity.ERROR, f"dir/é{i}.launch", 3 + i, 5,
            "two \"publishers\"\nof a \ud800 frame", node="tf",
            related=(Location(f"dir/o{i}.launch", 1, 1),),
        )
        for i in range(count)
    )
    files = tuple(FileRecord(f"dir/é{i}.launch", FileStatus.OK, i) for i in range(count))
    result = LintResult(files, (), findings)
    beliefs = BeliefSet.empty()
    expected = "".join(json_report.pieces(json_report.check_document(result, beliefs, "1")))
    assert "".join(json_report.check_pieces(result, beliefs, "1")) == expected
