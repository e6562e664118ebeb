"""The JSON contracts of ``check`` and ``transforms`` (see DESIGN.md)."""

from __future__ import annotations

import json
from typing import Any

from launch_linter.engine import LintResult
from launch_linter.model.beliefs import BeliefSet
from launch_linter.model.transform import StaticTransform

JSON_VERSION = 1


def _files(result: LintResult) -> list[dict[str, Any]]:
    return [
        {"path": f.path, "status": f.status.value, "transforms": f.transforms} for f in result.files
    ]


def check_document(result: LintResult, beliefs: BeliefSet, version: str) -> dict[str, Any]:
    return {
        "version": JSON_VERSION,
        "tool": {"name": "launch-linter", "version": version},
        "beliefs": {
            "source": beliefs.source,
            "min_z": beliefs.min_z,
            "count": len(beliefs.beliefs),
        },
        "files": _files(result),
        "diagnostics": [d.to_json() for d in result.diagnostics],
    }


def transform_json(t: StaticTransform) -> dict[str, Any]:
    return {
        "path": t.path,
        "line": t.line,
        "column": t.column,
        "root": t.root,
        "included_from": list(t.included_from) if t.included_from else None,
        "name": t.name,
        "namespace": t.namespace,
        "package": t.package,
        "executable": t.executable,
        "args": t.args,
        "parent": t.parent,
        "child": t.child,
        "translation": list(t.translation) if t.translation else None,
        "rotation": (
            {"kind": t.rotation.kind.value, "values": list(t.rotation.values)}
            if t.rotation
            else None
        ),
        "period_ms": t.period_ms,
        "condition": "always" if t.condition.always else "unknown",
        "unresolved": list(t.unresolved_names),
    }


def transforms_document(result: LintResult) -> dict[str, Any]:
    return {
        "version": JSON_VERSION,
        "files": _files(result),
        "transforms": [transform_json(t) for t in result.transforms],
    }


def dumps(document: dict[str, Any]) -> str:
    return json.dumps(document, indent=2, ensure_ascii=False, allow_nan=False, default=str)
