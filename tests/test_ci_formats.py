"""JUnit XML and GitLab code quality reports (``--format junit``/``gitlab``), validated.

GitLab documents its code quality report as a JSON list of issues (docs.gitlab.com,
"Code Quality", "Code Quality report format"): ``description``, ``check_name``,
``fingerprint``, ``severity`` (info, minor, major, critical, blocker), ``location.path`` and
``location.lines.begin`` are required. ``GITLAB_SCHEMA`` states exactly that. For JUnit,
``assert_junit`` checks what the JUnit schema read by Jenkins, GitLab and colcon
(junit-10.xsd) allows: the elements, their required and typed attributes, and that the
counts agree with the test cases.
"""

from __future__ import annotations

import json
import xml.etree.ElementTree as ET
from pathlib import Path
from typing import Any

import jsonschema

from launch_linter import LintOptions, lint_paths, lint_text
from launch_linter.cli import main
from launch_linter.engine import LintResult
from launch_linter.model import Category, Diagnostic, Severity
from launch_linter.model.launch import FileRecord, FileStatus
from launch_linter.report.ci_formats import gitlab, junit

ROOT = Path(__file__).resolve().parent.parent
EXAMPLES = ROOT / "examples"

GITLAB_SCHEMA: dict[str, Any] = {
    "type": "array",
    "items": {
        "type": "object",
        "required": ["description", "check_name", "fingerprint", "severity", "location"],
        "properties": {
            "type": {"const": "issue"},
            "description": {"type": "string", "minLength": 1},
            "check_name": {"type": "string", "minLength": 1},
            "fingerprint": {"type": "string", "minLength": 1},
            "severity": {"enum": ["info", "minor", "major", "critical", "blocker"]},
            "location": {
                "type": "object",
                "required": ["path", "lines"],
                "properties": {
                    "path": {"type": "string", "minLength": 1, "not": {"pattern": "^(/|\\./)"}},
                    "lines": {
                        "type": "object",
                        "required": ["begin"],
                        "properties": {"begin": {"type": "integer", "minimum": 1}},
                    },
                },
            },
        },
        "additionalProperties": False,
    },
}

# junit-10.xsd: element -> (required attributes, optional attributes, allowed children)
JUNIT = {
    "testsuites": (set(), {"name", "tests", "failures", "errors", "disabled", "time"},
                   {"testsuite"}),
    "testsuite": ({"name", "tests"}, {"failures", "errors", "disabled", "skipped", "time",
                                      "timestamp", "hostname", "id", "package"},
                  {"testcase", "properties", "system-out", "system-err"}),
    "testcase": ({"name"}, {"classname", "time", "status", "assertions"},
                 {"failure", "error", "skipped", "system-out", "system-err"}),
    "failure": (set(), {"message", "type"}, set()),
    "system-out": (set(), set(), set()),
}
COUNTS = ("tests", "failures", "errors", "disabled", "skipped")


def assert_junit(document: str) -> ET.Element:
    root = ET.fromstring(document.encode("utf-8"))
    for element in root.iter():
        required, optional, children = JUNIT[element.tag]
        assert required <= set(element.attrib) <= required | optional, element.attrib
        assert {child.tag for child in element} <= children, element.tag
        for count in COUNTS:
            if count in element.attrib:
                assert int(element.attrib[count]) >= 0
    for suite in root.iter("testsuite"):
        cases = suite.findall("testcase")
        assert int(suite.attrib["tests"]) == len(cases)
        failing = [c for c in cases if c.find("failure") is not None]
        assert int(suite.attrib["failures"]) == len(failing)
    return root


def run_examples(fail_on: Severity = Severity.WARNING) -> tuple[LintResult, ET.Element]:
    result = lint_paths([str(EXAMPLES)], LintOptions())
    return result, assert_junit(junit(result, fail_on))


def test_junit_has_one_case_per_file_and_a_failure_per_finding() -> None:
    result, root = run_examples()
    cases = {case.attrib["name"]: case for case in root.iter("testcase")}
    assert len(cases) == len(result.files) == 2
    for path, case in cases.items():
        failing = [d for d in result.diagnostics
                   if d.path.endswith(path) and d.severity.rank >= Severity.WARNING.rank]
        assert len(case.findall("failure")) == len(failing) > 0
        assert {f.attrib["type"] for f in case.findall("failure")} == {d.rule for d in failing}


def test_junit_lists_findings_below_fail_on_without_failing() -> None:
    result, root = run_examples(Severity.ERROR)
    out = "\n".join(e.text or "" for e in root.iter("system-out"))
    warnings = [d for d in result.diagnostics if d.severity is Severity.WARNING]
    assert warnings and all(f"[{d.rule}]" in out for d in warnings)
    assert not any(f.attrib["type"] in {d.rule for d in warnings} - {"dup_sig"}
                   for f in root.iter("failure"))


def test_junit_clean_file_passes(tmp_path: Path) -> None:
    clean = tmp_path / "clean.launch"
    clean.write_text('<launch><node pkg="tf2_ros" type="static_transform_publisher" '
                     'name="base_to_laser" args="0.1 0 0.2 0 0 0 base_link laser"/></launch>')
    result = lint_paths([str(clean)], LintOptions())
    root = assert_junit(junit(result, Severity.WARNING))
    (case,) = root.iter("testcase")
    assert case.find("failure") is None and root.attrib["failures"] == "0"


def test_junit_escapes_markup_and_control_characters() -> None:
    hostile = Diagnostic("dup_sig", Category.MUST, Severity.ERROR, "a<&>.launch", 3, 1,
                         "frame ']]><x/>\x01\x1b[31m' and \ud800 twice")
    result = LintResult((FileRecord("b.launch", FileStatus.OK, 0),), (), (hostile,))
    root = assert_junit(junit(result, Severity.WARNING, suite="s\x00", classname="p.x"))
    (failure,) = root.iter("failure")
    assert "\\x01" in failure.attrib["message"] and "]]><x/>" in (failure.text or "")
    assert [c.attrib["name"] for c in root.iter("testcase")] == ["a<&>.launch", "b.launch"]


def test_gitlab_validates_and_fingerprints_are_unique_and_survive_moved_lines() -> None:
    text = (EXAMPLES / "robot.launch").read_text()
    before = json.loads(gitlab(lint_text(text, "examples/robot.launch", LintOptions())
                               .diagnostics))
    moved = text.replace("<launch>", "<launch>\n\n\n", 1)
    after = json.loads(gitlab(lint_text(moved, "examples/robot.launch", LintOptions())
                              .diagnostics))
    jsonschema.Draft7Validator(GITLAB_SCHEMA).validate(before)
    prints = [issue["fingerprint"] for issue in before]
    assert len(set(prints)) == len(prints) > 3
    assert [i["fingerprint"] for i in after] == prints
    assert [i["location"]["lines"]["begin"] for i in after] != [
        i["location"]["lines"]["begin"] for i in before]


def test_gitlab_identical_findings_get_distinct_fingerprints() -> None:
    twice = [Diagnostic("unresolved", Category.LAUNCH, Severity.INFO, "./a.launch", line, 1,
                        "same") for line in (0, 7)]
    issues = json.loads(gitlab(twice))
    jsonschema.Draft7Validator(GITLAB_SCHEMA).validate(issues)
    assert issues[0]["fingerprint"] != issues[1]["fingerprint"]
    assert [i["location"] for i in issues] == [
        {"path": "a.launch", "lines": {"begin": 1}}, {"path": "a.launch", "lines": {"begin": 7}}]


def test_command_line_formats(tmp_path: Path) -> None:
    report = tmp_path / "report.xml"
    assert main(["check", str(EXAMPLES), "--format", "junit", "-o", str(report)]) == 1
    assert_junit(report.read_text(encoding="utf-8"))
    quality = tmp_path / "quality.json"
    assert main(["check", str(EXAMPLES), "--format", "gitlab", "--fail-on", "error",
                 "-o", str(quality)]) == 1
    jsonschema.Draft7Validator(GITLAB_SCHEMA).validate(json.loads(quality.read_text()))
