"""Reports for test and CI systems: JUnit XML and GitLab code quality JSON.

JUnit: one ``<testcase>`` per file (every input file, and every file a finding is in, such as
an included launch file or a xacro), one ``<failure>`` per finding that reaches ``fail-on``
(the suite's ``failures`` counts the failing test cases, never more than ``tests``);
findings below it are listed in the test case's ``<system-out>`` and fail nothing, so the
test result agrees with the exit status. The elements and attributes are those of the JUnit
schema that Jenkins, GitLab and colcon (``colcon test-result``) read.

GitLab: the code quality report (a JSON list of issues with ``description``, ``check_name``,
``fingerprint``, ``severity``, ``location.path`` and ``location.lines.begin``). A
fingerprint hashes the path, rule and message (not the line, nor the lines a message names,
so that a finding keeps its identity when lines above it move) and the finding's rank among
identical ones.
"""

from __future__ import annotations

import hashlib
import os
import re
import xml.etree.ElementTree as ET
from collections.abc import Iterable

from launch_linter.engine import LintResult
from launch_linter.model.diagnostic import Diagnostic, Severity
from launch_linter.report.escape import printable
from launch_linter.report.json_report import dumps

# Messages name other findings' places ("at line 18", "(robot.launch:18)"): they move too.
_LINE_REFERENCE = re.compile(r"\blines? \d+|:\d+(?::\d+)?\b")
GITLAB_SEVERITIES = {Severity.ERROR: "critical", Severity.WARNING: "major", Severity.INFO: "info"}


def _relative(path: str) -> str:
    """``path`` relative to the working folder (the repository root in CI) when it is in it."""
    if os.path.isabs(path):
        inside = os.path.relpath(path)
        path = path if inside.startswith("..") else inside
    while path.startswith("./"):
        path = path[2:]
    return path


def _line(diagnostic: Diagnostic) -> str:
    return printable(
        f"{diagnostic.path}:{diagnostic.line}:{diagnostic.column}: {diagnostic.severity.value}:"
        f" {diagnostic.message} [{diagnostic.rule}]"
    )


def junit(result: LintResult, fail_on: Severity, suite: str = "launch-linter",
          classname: str = "launch-linter") -> str:
    """``result`` as a JUnit XML document (``suite`` names the test suite, ``classname``
    prefixes each test case's class: ament's linters use ``<package>.<linter>``)."""
    by_file: dict[str, list[Diagnostic]] = {record.path: [] for record in result.files}
    for diagnostic in result.diagnostics:
        by_file.setdefault(diagnostic.path, []).append(diagnostic)
    failures = sum(1 for findings in by_file.values()
                   if any(d.severity.rank >= fail_on.rank for d in findings))
    counts = {"tests": str(len(by_file)), "failures": str(failures), "errors": "0", "time": "0"}
    root = ET.Element("testsuites", {"name": printable(suite), **counts})
    suite_element = ET.SubElement(root, "testsuite",
                                  {"name": printable(suite), **counts, "skipped": "0"})
    for path in sorted(by_file):
        _testcase(suite_element, path, by_file[path], fail_on, classname)
    if hasattr(ET, "indent"):  # Python 3.9+; without it the document is only less readable
        ET.indent(root)
    return '<?xml version="1.0" encoding="UTF-8"?>\n' + ET.tostring(root, "unicode") + "\n"


def _testcase(parent: ET.Element, path: str, findings: list[Diagnostic], fail_on: Severity,
              classname: str) -> None:
    name = printable(_relative(path))
    # no ``file`` attribute: junit-10.xsd (the schema pytest's xunit2 follows) has none
    case = ET.SubElement(parent, "testcase", {"name": name, "classname": printable(classname),
                                              "time": "0"})
    below: list[str] = []
    for diagnostic in findings:
        if diagnostic.severity.rank < fail_on.rank:
            below.append(_line(diagnostic))
            continue
        failure = ET.SubElement(case, "failure", {
            "type": diagnostic.rule,
            "message": printable(f"{diagnostic.line}:{diagnostic.column}: {diagnostic.message}"
                                 f" [{diagnostic.rule}]"),
        })
        failure.text = _line(diagnostic)
    if below:
        ET.SubElement(case, "system-out").text = "\n".join(below)


def gitlab(diagnostics: Iterable[Diagnostic]) -> str:
    """The findings as a GitLab code quality report (a JSON list)."""
    seen: dict[str, int] = {}
    issues = []
    for diagnostic in diagnostics:
        path = _relative(diagnostic.path)
        identity = "\0".join((path, diagnostic.rule, _LINE_REFERENCE.sub("", diagnostic.message)))
        rank = seen[identity] = seen.get(identity, -1) + 1
        fingerprint = hashlib.sha256(f"{identity}\0{rank}".encode("utf-8", "backslashreplace"))
        issues.append({
            "type": "issue",
            "description": diagnostic.message,
            "check_name": diagnostic.rule,
            "fingerprint": fingerprint.hexdigest(),
            "severity": GITLAB_SEVERITIES[diagnostic.severity],
            "location": {"path": path, "lines": {"begin": max(diagnostic.line, 1)}},
        })
    return dumps(issues) + "\n"
