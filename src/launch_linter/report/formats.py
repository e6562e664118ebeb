"""Machine formats for code review tools: SARIF 2.1.0 and GitHub workflow commands."""

from __future__ import annotations

import os
from typing import Any
from urllib.parse import quote

from launch_linter.engine import LintResult
from launch_linter.model.beliefs import BeliefSet
from launch_linter.model.diagnostic import Diagnostic, Fix, Location, Severity
from launch_linter.model.included import included_from
from launch_linter.report.escape import printable
from launch_linter.report.json_report import dumps
from launch_linter.rules import RULES, Rule

SARIF_SCHEMA = "https://json.schemastore.org/sarif-2.1.0.json"
SARIF_VERSION = "2.1.0"
_SARIF_LEVELS = {Severity.ERROR: "error", Severity.WARNING: "warning", Severity.INFO: "note"}
_GITHUB_LEVELS = {Severity.ERROR: "error", Severity.WARNING: "warning", Severity.INFO: "notice"}


def render(fmt: str, result: LintResult, beliefs: BeliefSet, version: str) -> str:
    """``result`` as ``sarif`` (a JSON document) or ``github`` (one command per line)."""
    if fmt == "sarif":
        document = sarif_document(result, beliefs, version)
        return dumps(document) + "\n"
    if fmt == "github":
        return "".join(github_command(d) + "\n" for d in result.diagnostics)
    raise ValueError(f"unknown format {fmt!r}")


# -- SARIF ---------------------------------------------------------------------------------


def artifact_uri(path: str) -> str:
    """A URI reference for ``path``: relative paths stay relative (GitHub resolves them
    against the repository root), absolute ones become ``file://`` URIs."""
    posix = path.replace(os.sep, "/")
    if os.path.isabs(path):
        return "file://" + quote(posix if posix.startswith("/") else "/" + posix)
    while posix.startswith("./"):
        posix = posix[2:]
    return quote(posix)


def doc_section(doc: str, title: str) -> str:
    """The text of the ``## title`` section of a rule's documentation ('' if absent)."""
    lines = doc.splitlines()
    heading = f"## {title}"
    if heading not in lines:
        return ""
    body: list[str] = []
    for line in lines[lines.index(heading) + 1 :]:
        if line.startswith("## "):
            break
        body.append(line)
    return " ".join(" ".join(body).split())


def _rule_descriptor(rule: Rule) -> dict[str, Any]:
    return {
        "id": rule.id,
        "name": "".join(part.capitalize() for part in rule.id.split("_")),
        "shortDescription": {"text": rule.summary},
        "fullDescription": {"text": doc_section(rule.doc, "What it does") or rule.summary},
        "help": {"text": rule.doc, "markdown": rule.doc},
        "defaultConfiguration": {"level": _SARIF_LEVELS[rule.severity]},
        "properties": {"category": rule.category.value, "tags": [rule.category.value]},
    }


def _physical(path: str, line: int, column: int) -> dict[str, Any]:
    return {
        "artifactLocation": {"uri": artifact_uri(path)},
        "region": {"startLine": max(line, 1), "startColumn": max(column, 1)},
    }


def _related(index: int, location: Location, site: Location | None) -> dict[str, Any]:
    return {
        "id": index,
        "physicalLocation": _physical(location.path, location.line, location.column),
        "message": {"text": "included from here" if location is site else "related location"},
    }


def _result(diagnostic: Diagnostic, rule_index: dict[str, int]) -> dict[str, Any]:
    out: dict[str, Any] = {
        "ruleId": diagnostic.rule,
        "level": _SARIF_LEVELS[diagnostic.severity],
        "message": {"text": diagnostic.message},
        "locations": [
            {"physicalLocation": _physical(diagnostic.path, diagnostic.line, diagnostic.column)}
        ],
    }
    if diagnostic.rule in rule_index:
        out["ruleIndex"] = rule_index[diagnostic.rule]
    if diagnostic.related:
        site = included_from(diagnostic.message, diagnostic.related)
        out["relatedLocations"] = [_related(i, r, site)
                                   for i, r in enumerate(diagnostic.related)]
    properties: dict[str, Any] = {"category": diagnostic.category.value}
    if diagnostic.node is not None:
        properties["node"] = diagnostic.node
    if diagnostic.belief is not None:
        properties["belief"] = diagnostic.belief.to_json()
    if diagnostic.fix is not None and diagnostic.fix.edits:
        out["fixes"] = [_fix(diagnostic.fix)]
        properties["fixApplicability"] = diagnostic.fix.applicability.value
    out["properties"] = properties
    return out


def _fix(fix: Fix) -> dict[str, Any]:
    """A SARIF 2.1.0 ``fix``: one ``artifactChange`` per file, byte-offset regions."""
    changes: dict[str, list[dict[str, Any]]] = {}
    for edit in fix.edits:
        changes.setdefault(edit.path, []).append(
            {
                "deletedRegion": {"byteOffset": edit.start, "byteLength": edit.end - edit.start},
                "insertedContent": {"text": edit.content},
            }
        )
    return {
        "description": {"text": f"{fix.message} ({fix.applicability.value} fix)"},
        "artifactChanges": [
            {"artifactLocation": {"uri": artifact_uri(path)}, "replacements": replacements}
            for path, replacements in changes.items()
        ],
    }


def sarif_document(result: LintResult, beliefs: BeliefSet, version: str) -> dict[str, Any]:
    rule_index = {rule.id: i for i, rule in enumerate(RULES)}
    return {
        "$schema": SARIF_SCHEMA,
        "version": SARIF_VERSION,
        "runs": [
            {
                "tool": {
                    "driver": {
                        "name": "launch-linter",
                        "version": version,
                        "semanticVersion": version,
                        "rules": [_rule_descriptor(rule) for rule in RULES],
                    }
                },
                "columnKind": "unicodeCodePoints",
                "results": [_result(d, rule_index) for d in result.diagnostics],
                "properties": {
                    "beliefs": {
                        "source": beliefs.source,
                        "min_z": beliefs.min_z,
                        "count": len(beliefs.beliefs),
                    },
                    "files": [
                        {"path": f.path, "status": f.status.value, "transforms": f.transforms}
                        for f in result.files
                    ],
                },
            }
        ],
    }


# -- GitHub workflow commands --------------------------------------------------------------


def escape_data(text: str) -> str:
    """Escape a workflow command's message the way the GitHub Actions runner unescapes it."""
    # Other control characters (ESC...) and lone surrogates are shown as escapes.
    return printable(text.replace("%", "%25").replace("\r", "%0D").replace("\n", "%0A"))


def escape_property(text: str) -> str:
    """Escape a workflow command property value (``file=``, ``title=``, …)."""
    return escape_data(text).replace(":", "%3A").replace(",", "%2C")


def github_command(diagnostic: Diagnostic) -> str:
    """``::error file=…,line=…,col=…,title=…::message`` for one diagnostic."""
    level = _GITHUB_LEVELS[diagnostic.severity]
    properties = ",".join(
        f"{key}={escape_property(value)}"
        for key, value in (
            ("file", diagnostic.path.replace(os.sep, "/")),
            ("line", str(max(diagnostic.line, 1))),
            ("col", str(max(diagnostic.column, 1))),
            ("title", f"launch-linter {diagnostic.rule}"),
        )
    )
    return f"::{level} {properties}::{escape_data(diagnostic.message)}"
