"""Helpers for the mining tests: tiny launch files, corpora and git repositories."""

from __future__ import annotations

import hashlib
import json
import os
import sqlite3
import subprocess
from pathlib import Path
from typing import Any, Callable, Dict, List


def node(name: str, args: str, pkg: str = "tf") -> str:
    return f'  <node pkg="{pkg}" type="static_transform_publisher" name="{name}" args="{args}"/>'


def launch(*nodes: str) -> str:
    return "<launch>\n" + "\n".join(nodes) + "\n</launch>\n"


MakeCorpus = Callable[[List[Dict[str, Any]]], Path]


def write_corpus(root: Path, rows: list[dict[str, Any]]) -> Path:
    """A corpus folder at ``root`` with ``files/`` and ``manifest.jsonl`` in the shared
    corpus's format; ``rows`` are ``{"repo", "path", "text", "latest"?, "commits"?,
    "commit"?}``."""
    (root / "files").mkdir(parents=True, exist_ok=True)
    lines = []
    for row in rows:
        data = row["text"].encode("utf-8")
        sha = hashlib.sha256(data).hexdigest()
        stored = f"files/{sha[:16]}.launch"
        (root / stored).write_bytes(data)
        lines.append(json.dumps({
            "repo": row["repo"], "path": row["path"],
            "commit": row.get("commit", "c0"), "latest": row.get("latest", True),
            "repo_commits": row.get("commits", 100), "sha256": sha, "file": stored,
        }))
    (root / "manifest.jsonl").write_text("\n".join(lines) + "\n", encoding="utf-8")
    return root


def git_repo(folder: Path, files: dict[str, str], commits: int) -> None:
    """A git repository at ``folder`` holding ``files``, with ``commits`` commits."""
    folder.mkdir(parents=True)
    for name, text in files.items():
        target = folder / name
        target.parent.mkdir(parents=True, exist_ok=True)
        target.write_text(text, encoding="utf-8")
    env = {
        **os.environ,
        "GIT_AUTHOR_NAME": "t", "GIT_AUTHOR_EMAIL": "t@example.org",
        "GIT_COMMITTER_NAME": "t", "GIT_COMMITTER_EMAIL": "t@example.org",
        "GIT_CONFIG_NOSYSTEM": "1", "HOME": str(folder),
    }

    def git(*args: str) -> None:
        subprocess.run(["git", "-C", str(folder), *args], check=True, env=env,
                       capture_output=True)

    git("init", "-q")
    git("add", ".")
    git("commit", "-q", "-m", "first")
    for i in range(commits - 1):
        git("commit", "-q", "--allow-empty", "-m", f"commit {i}")


def dump(db: Path) -> dict[str, list[tuple[Any, ...]]]:
    """The database's content without row ids, to compare two runs."""
    conn = sqlite3.connect(db)
    try:
        return {
            "repos": sorted(conn.execute("SELECT name, commits, named_mature, mature FROM repos")),
            "contents": sorted(conn.execute(
                "SELECT sha256, bytes, status, reason, transforms FROM contents")),
            "files": sorted(conn.execute(
                "SELECT r.name, f.path, f.version, f.latest, c.sha256, f.error FROM files f "
                "JOIN repos r ON r.id = f.repo_id LEFT JOIN contents c ON c.id = f.content_id")),
            "transforms": sorted(conn.execute(
                "SELECT c.sha256, t.ordinal, t.line, t.name, t.parent, t.child, t.tx, "
                "t.null_displacement, t.null_rotation, t.unresolved FROM transforms t "
                "JOIN contents c ON c.id = t.content_id")),
            "beliefs": sorted(conn.execute("SELECT * FROM beliefs")),
        }
    finally:
        conn.close()
