"""Helpers for the evaluation tests: inline launch files, linted versions, tiny corpora."""

from __future__ import annotations

import hashlib
import json
from pathlib import Path
from typing import Any

from launch_linter.engine import LintOptions
from launch_linter.evaluation.lint import Linted, Version, lint_bytes
from launch_linter.mining.commands import mine_corpus
from launch_linter.model.beliefs import BeliefSet


def node(name: str, args: str) -> str:
    return f'  <node pkg="tf" type="static_transform_publisher" name="{name}" args="{args}"/>'


def launch(*nodes: str) -> str:
    return "<launch>\n" + "\n".join(nodes) + "\n</launch>\n"


def linted(
    text: str,
    repo: str = "r/one",
    path: str = "launch/a.launch",
    latest: bool = True,
    mature: bool = False,
    version: str = "c1",
    head_paths: tuple[str, ...] = (),
    beliefs: BeliefSet | None = None,
) -> Linted:
    """``text`` linted as one stored version."""
    options = LintOptions(beliefs=beliefs or BeliefSet.empty())
    status, transforms, diagnostics = lint_bytes(
        text.encode("utf-8"), f"/nonexistent/{path.rsplit('/', 1)[-1]}", (), options
    )
    return Linted(
        Version(repo, path, version, latest, mature, head_paths), status, transforms, diagnostics
    )


def build_db(tmp_path: Path, rows: list[dict[str, Any]]) -> tuple[Path, Path]:
    """A corpus folder (``files/`` and ``manifest.jsonl``) under ``tmp_path`` and the
    database mined from it with p0 = 0.5, so that three agreeing files give z = 1.73.

    Each row: ``repo``, ``path``, ``text``, and optionally ``commit``, ``latest``,
    ``commits`` (the repository's commit count, default 100) and ``head_paths``."""
    root = tmp_path / "corpus"
    (root / "files").mkdir(parents=True)
    lines = []
    for row in rows:
        data = row["text"].encode("utf-8")
        sha = hashlib.sha256(data).hexdigest()
        stored = f"files/{sha[:16]}.launch"
        (root / stored).write_bytes(data)
        commits = row.get("commits", 100)
        entry = {
            "repo": row["repo"], "path": row["path"], "commit": row.get("commit", "c1"),
            "date": "2020-01-01T00:00:00+00:00", "latest": row.get("latest", True),
            "repo_commits": commits, "mature": commits >= 30, "sha256": sha,
            "file": stored, "has_stp": "static_transform_publisher" in row["text"],
        }
        if "head_paths" in row:
            entry["head_paths"] = row["head_paths"]
        lines.append(json.dumps(entry))
    (root / "manifest.jsonl").write_text("\n".join(lines) + "\n", encoding="utf-8")
    db = tmp_path / "corpus.db"
    mine_corpus(str(root), str(db), p0=0.5, mature_commits=30)
    return root, db
