"""The JSON contracts of ``check`` and ``transforms`` (see DESIGN.md)."""

from __future__ import annotations

import json
import os
from collections.abc import Callable, Iterable, Iterator, Mapping

from launch_linter.engine import LintResult
from launch_linter.model.beliefs import BeliefSet
from launch_linter.model.diagnostic import Diagnostic
from launch_linter.model.included import included_from
from launch_linter.model.launch import FileRecord
from launch_linter.model.robot import RobotJoint
from launch_linter.model.transform import StaticTransform
from launch_linter.report.escape import json_escaped, json_safe

TYPE_CHECKING = False  # typing is not imported at run time: start-up (docs/performance.md)
if TYPE_CHECKING:
    from typing import Any, TextIO

JSON_VERSION = 1


def _file_json(record: FileRecord) -> dict[str, Any]:
    return {"path": record.path, "status": record.status.value, "transforms": record.transforms}


def _files(result: LintResult) -> list[dict[str, Any]]:
    return [_file_json(f) for f in result.files]


def _check_head(beliefs: BeliefSet, version: str) -> dict[str, Any]:
    return {
        "version": JSON_VERSION,
        "tool": {"name": "launch-linter", "version": version},
        "beliefs": {
            "source": beliefs.source,
            "min_z": beliefs.min_z,
            "count": beliefs.count,
        },
    }


def diagnostic_json(diagnostic: Diagnostic) -> dict[str, Any]:
    """A finding in JSON; ``included_from``: the include its text was reached through
    (``{"path", "line", "column"}``), null for text of the file linted itself."""
    site = included_from(diagnostic.message, diagnostic.related)
    return {**diagnostic.to_json(), "included_from": None if site is None else {
        "path": site.path, "line": site.line, "column": site.column}}


def check_document(result: LintResult, beliefs: BeliefSet, version: str) -> dict[str, Any]:
    return {
        **_check_head(beliefs, version),
        "files": _files(result),
        "diagnostics": [diagnostic_json(d) for d in result.diagnostics],
    }


def check_pieces(result: LintResult, beliefs: BeliefSet, version: str) -> Iterator[str]:
    """``pieces(check_document(...))``, with each file and finding made JSON only when it is
    written: a run of many files never holds every finding's JSON object (and its escaped
    copy) at once, only the findings themselves."""
    lists: dict[str, tuple[Iterable[Any], Callable[[Any], Any]]] = {
        "files": (result.files, _file_json),
        "diagnostics": (result.diagnostics, diagnostic_json),
    }
    return _batched(_streamed(_check_head(beliefs, version), lists))


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
        "source": "launch",
    }


def _shown(path: str | None) -> str | None:
    """A description file as paths are shown elsewhere: relative below the working folder."""
    if path is None:
        return None
    relative = os.path.relpath(path)
    return path if relative.startswith("..") else relative


def joint_json(root: str, j: RobotJoint) -> dict[str, Any]:
    """A URDF joint as a tf edge (an additive part of the transforms contract)."""
    source = j.source
    return {
        "path": j.path,
        "line": j.line,
        "column": j.column,
        "root": root,
        "source": "urdf",
        "name": j.name,
        "joint_type": j.joint_type,
        "dynamic": j.dynamic,
        "parent": j.parent,
        "child": j.child,
        "translation": list(j.translation) if j.translation is not None else None,
        "rotation": {"kind": "rpy", "values": list(j.rpy)} if j.rpy is not None else None,
        "condition": "always" if j.condition.always else "unknown",
        "unresolved": list(j.unresolved),
        "description": {
            "path": source.path,
            "line": source.line,
            "column": source.column,
            "kind": source.kind.value,
            "file": _shown(source.file),
            "args": {name: value for name, value in source.args},
        },
    }


def transforms_document(result: LintResult, distro: str | None = None) -> dict[str, Any]:
    """Each edge once (see :mod:`launch_linter.report.published`): ``root`` is the first
    tree it was found in, ``entry_points`` every entry point that publishes it."""
    from launch_linter.report.published import published  # transforms only, not check

    transforms: list[dict[str, Any]] = []
    joints: list[dict[str, Any]] = []
    for item in published(result, distro):
        edge = item.edge
        if isinstance(edge, RobotJoint):
            joints.append({**joint_json(item.entry_points[0], edge),
                           "entry_points": list(item.entry_points)})
        else:
            transforms.append({**transform_json(edge), "entry_points": list(item.entry_points)})
    return {
        "version": JSON_VERSION,
        "files": _files(result),
        "transforms": transforms,
        "urdf_edges": joints,
    }


def _encoder() -> json.JSONEncoder:
    return json.JSONEncoder(indent=2, ensure_ascii=False, allow_nan=False, default=str)


def dumps(document: Any) -> str:
    """``document`` as indented JSON that every reader takes and no terminal acts on (see
    ``report.escape``); the one encoding of every JSON-type output (json, SARIF, GitLab)."""
    return json_escaped(_encoder().encode(json_safe(document)))


def pieces(document: dict[str, Any]) -> Iterator[str]:
    """``dumps(document)`` and a newline, piece by piece: the whole text of a large run
    (and the list of its pieces) is never held at once."""
    return _batched(_encoder().iterencode(json_safe(document)))


def _batched(chunks: Iterable[str]) -> Iterator[str]:
    """``chunks`` joined in batches, then a newline."""
    batch: list[str] = []
    for chunk in chunks:
        batch.append(chunk)
        if len(batch) >= 4096:
            yield json_escaped("".join(batch))
            batch.clear()
    batch.append("\n")
    yield json_escaped("".join(batch))


ITEM_INDENT = "\n    "
"""A line break inside an item of a list that is a value of the top-level object (the
encoder's indent is 2). JSON text has no raw line break inside a string, so an item
encoded alone is indented for that depth by indenting each of its line breaks."""


def _streamed(head: Mapping[str, Any],
              lists: Mapping[str, tuple[Iterable[Any], Callable[[Any], Any]]]) -> Iterator[str]:
    """The text ``_encoder`` gives for ``{**head, key: [make(item) ...] for each of lists}``,
    made one item at a time."""
    encoder = _encoder()
    separator = "{"
    for key, value in head.items():
        yield f"{separator}\n  {encoder.encode(json_safe(key))}: "
        yield encoder.encode(json_safe(value)).replace("\n", "\n  ")
        separator = ","
    for key, (items, make) in lists.items():
        yield f"{separator}\n  {encoder.encode(json_safe(key))}: "
        separator = ","
        opened = False
        for item in items:
            yield ",\n    " if opened else "[\n    "
            opened = True
            yield encoder.encode(json_safe(make(item))).replace("\n", ITEM_INDENT)
        yield "\n  ]" if opened else "[]"
    yield "\n}" if separator == "," else "{}"


def write(document: dict[str, Any], out: TextIO) -> None:
    """Write ``dumps(document)`` and a newline to ``out`` (see ``pieces``)."""
    for piece in pieces(document):
        out.write(piece)
