"""The JSON contracts of ``check`` and ``transforms`` (see DESIGN.md)."""

from __future__ import annotations

import json
from collections.abc import Iterator
from typing import Any, TextIO

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


def _encoder() -> json.JSONEncoder:
    return json.JSONEncoder(indent=2, ensure_ascii=False, allow_nan=False, default=str)


def dumps(document: dict[str, Any]) -> str:
    return _encoder().encode(document)


def pieces(document: dict[str, Any]) -> Iterator[str]:
    """``dumps(document)`` and a newline, piece by piece: the whole text of a large run
    (and the list of its pieces) is never held at once."""
    batch: list[str] = []
    for chunk in _encoder().iterencode(document):
        batch.append(chunk)
        if len(batch) >= 4096:
            yield "".join(batch)
            batch.clear()
    batch.append("\n")
    yield "".join(batch)


def write(document: dict[str, Any], out: TextIO) -> None:
    """Write ``dumps(document)`` and a newline to ``out`` (see ``pieces``)."""
    for piece in pieces(document):
        out.write(piece)
