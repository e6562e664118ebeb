"""The corpus database: the only module that speaks SQL (SQLite, schema versioned).

Layout (see ``docs/mining.md``): ``repos`` (one row per repository), ``contents`` (one row
per distinct file content, by SHA-256, with its parse status), ``files`` (one row per
repository, path and version, pointing at its content), ``transforms`` (one row per static
transform of a content, every field of the model), ``beliefs`` (the last mining run) and
``meta``. The view ``transform_rows`` gives one row per transform and file with the file
id, repository, latest flag and maturity flag, as the study's table had.

Every write is one transaction, so a run that is killed leaves the database as it was
after the last batch it committed.
"""

from __future__ import annotations

import functools
import json
import os
import sqlite3
import time
from collections.abc import Iterable, Iterator, Mapping, Sequence
from dataclasses import dataclass
from types import TracebackType
from typing import Any

from launch_linter.mining.beliefs import MinedTransform, decode_key, encode_key
from launch_linter.model.diagnostic import Belief
from launch_linter.model.transform import Field, StaticTransform

SCHEMA_VERSION = 1

_SCHEMA = """
CREATE TABLE meta (
    key TEXT PRIMARY KEY,
    value TEXT NOT NULL
);
CREATE TABLE repos (
    id INTEGER PRIMARY KEY,
    name TEXT NOT NULL UNIQUE,
    commits INTEGER,
    named_mature INTEGER NOT NULL DEFAULT 0,
    mature INTEGER NOT NULL DEFAULT 0
);
CREATE TABLE contents (
    id INTEGER PRIMARY KEY,
    sha256 TEXT NOT NULL UNIQUE,
    bytes INTEGER NOT NULL,
    status TEXT NOT NULL,
    reason TEXT,
    transforms INTEGER NOT NULL
);
CREATE TABLE files (
    id INTEGER PRIMARY KEY,
    repo_id INTEGER NOT NULL REFERENCES repos(id),
    path TEXT NOT NULL,
    version TEXT NOT NULL,
    latest INTEGER NOT NULL,
    content_id INTEGER REFERENCES contents(id),
    error TEXT,
    UNIQUE (repo_id, path, version)
);
CREATE INDEX files_content ON files(content_id);
CREATE TABLE transforms (
    id INTEGER PRIMARY KEY,
    content_id INTEGER NOT NULL REFERENCES contents(id),
    ordinal INTEGER NOT NULL,
    line INTEGER NOT NULL,
    col INTEGER NOT NULL,
    name TEXT,
    namespace TEXT NOT NULL,
    package TEXT NOT NULL,
    executable TEXT NOT NULL,
    args_written TEXT NOT NULL,
    args TEXT NOT NULL,
    tokens TEXT NOT NULL,
    parent_written TEXT,
    child_written TEXT,
    parent TEXT,
    child TEXT,
    tx REAL,
    ty REAL,
    tz REAL,
    rotation_kind TEXT,
    rotation TEXT,
    period_ms REAL,
    form TEXT NOT NULL,
    arity_issue TEXT,
    number_issues TEXT NOT NULL,
    condition TEXT NOT NULL,
    condition_literals TEXT NOT NULL,
    included_from TEXT,
    unresolved TEXT NOT NULL,
    unresolved_reasons TEXT NOT NULL,
    resolved INTEGER NOT NULL,
    name_resolved INTEGER NOT NULL,
    null_displacement INTEGER,
    null_rotation INTEGER,
    ros_version INTEGER NOT NULL,
    launch_format TEXT NOT NULL,
    UNIQUE (content_id, ordinal)
);
CREATE TABLE beliefs (
    class TEXT NOT NULL,
    antecedent TEXT NOT NULL,
    consequent TEXT NOT NULL,
    n INTEGER NOT NULL,
    e INTEGER NOT NULL,
    z REAL NOT NULL,
    PRIMARY KEY (class, antecedent, consequent)
);
CREATE INDEX beliefs_z ON beliefs(class, z);
CREATE VIEW transform_rows AS
    SELECT f.id AS file_id, r.name AS repo, f.path AS file_path, f.version, f.latest,
           r.mature, t.*
    FROM transforms t
    JOIN files f ON f.content_id = t.content_id
    JOIN repos r ON r.id = f.repo_id;
"""

TRANSFORM_COLUMNS = (
    "ordinal", "line", "col", "name", "namespace", "package", "executable", "args_written",
    "args", "tokens", "parent_written", "child_written", "parent", "child", "tx", "ty", "tz",
    "rotation_kind", "rotation", "period_ms", "form", "arity_issue", "number_issues",
    "condition", "condition_literals", "included_from", "unresolved", "unresolved_reasons",
    "resolved", "name_resolved", "null_displacement", "null_rotation", "ros_version",
    "launch_format",
)

TransformRow = tuple[Any, ...]


class StoreError(Exception):
    """The database cannot be used (wrong schema version, not a database, …)."""


MAX_STATEMENT_SECONDS = 600.0
"""Longest one SQL statement may run before it is interrupted."""
_PROGRESS_EVERY = 100_000
"""SQLite virtual-machine instructions between two looks at the clock."""


def _harden(conn: sqlite3.Connection) -> None:
    """Defensive settings for a database file that may come from anyone: no schema-borne
    functions, no writes to the schema, and every statement interrupted past a time limit."""
    conn.execute("PRAGMA trusted_schema = OFF")
    defensive = getattr(sqlite3, "SQLITE_DBCONFIG_DEFENSIVE", None)
    if defensive is not None and hasattr(conn, "setconfig"):
        conn.setconfig(defensive, True)
    started: list[float] = [time.monotonic()]

    def progress() -> int:
        # Non-zero interrupts the statement (sqlite3.OperationalError: interrupted).
        return 1 if time.monotonic() - started[0] > MAX_STATEMENT_SECONDS else 0

    conn.set_progress_handler(progress, _PROGRESS_EVERY)
    conn.set_trace_callback(lambda _statement: started.__setitem__(0, time.monotonic()))


def _schema(conn: sqlite3.Connection) -> set[tuple[str, str, str]]:
    rows = conn.execute("SELECT type, name, sql FROM sqlite_master WHERE sql IS NOT NULL")
    return {(kind, name, " ".join(sql.split())) for kind, name, sql in rows}


@functools.lru_cache(maxsize=None)  # noqa: UP033 - Python 3.8 has no functools.cache
def _expected_schema() -> frozenset[tuple[str, str, str]]:
    conn = sqlite3.connect(":memory:")
    try:
        conn.executescript(_SCHEMA)
        return frozenset(_schema(conn))
    finally:
        conn.close()


@dataclass(frozen=True, slots=True)
class RepoInfo:
    name: str
    commits: int | None
    named_mature: bool


@dataclass(frozen=True, slots=True)
class FileRef:
    """One (repository, path, version) of the corpus."""

    repo: str
    path: str
    version: str
    latest: bool


@dataclass(frozen=True, slots=True)
class ParsedContent:
    """A distinct content and what the front-end made of it."""

    sha256: str
    size: int
    status: str
    reason: str | None
    rows: tuple[TransformRow, ...]


@dataclass(frozen=True, slots=True)
class StoredVersion:
    """One stored (repository, path, version), as the evaluation reads it back."""

    repo: str
    path: str
    version: str
    latest: bool
    mature: bool
    """The repository's maturity as of the last mining run."""
    sha256: str | None
    """The content's SHA-256; None when the file could not be read."""


def _json(value: object) -> str:
    return json.dumps(value, ensure_ascii=False, separators=(",", ":"))


def _flag(value: bool | None) -> int | None:
    return None if value is None else int(value)


def transform_row(ordinal: int, t: StaticTransform) -> TransformRow:
    """The ``transforms`` columns (after ``content_id``) of one transform."""
    signature = t.signature
    translation = t.translation
    rotation = t.rotation
    return (
        ordinal, t.line, t.column, t.name, t.namespace, t.package, t.executable,
        t.args_written, t.args, _json(list(t.tokens)), t.parent_written, t.child_written,
        signature[0] if signature else None, signature[1] if signature else None,
        *(translation if translation is not None else (None, None, None)),
        rotation.kind.value if rotation is not None else None,
        _json(list(rotation.values)) if rotation is not None else None,
        t.period_ms, t.form.value, t.arity_issue,
        _json([[i.index, i.written, i.read_as] for i in t.number_issues]),
        t.condition.describe(),
        _json([[lit.text, lit.positive] for lit in t.condition.literals]),
        _json(list(t.included_from)) if t.included_from is not None else None,
        _json(list(t.unresolved_names)), _json(list(t.unresolved_reasons)),
        int(t.fully_resolved), int(t.name is not None and t.knows(Field.NAME)),
        _flag(t.null_displacement), _flag(t.null_rotation), t.ros_version, t.launch_format.value,
    )


class Store:
    """An open corpus database. Use as a context manager, or call :meth:`close`."""

    def __init__(self, path: str, create: bool = True) -> None:
        if not create and not os.path.isfile(path):
            raise StoreError(f"{path}: no such database (make one with 'launch-linter mine')")
        if os.path.exists(path) and not os.path.isfile(path):
            raise StoreError(f"{path}: not a regular file")
        try:
            self.conn = sqlite3.connect(path, timeout=60.0)
            _harden(self.conn)
            self.conn.execute("PRAGMA foreign_keys = ON")
            self.conn.execute("PRAGMA synchronous = NORMAL")
            version = self.conn.execute("PRAGMA user_version").fetchone()[0]
            tables = self.conn.execute("SELECT count(*) FROM sqlite_master").fetchone()[0]
        except sqlite3.DatabaseError as exc:
            raise StoreError(f"{path}: not a usable SQLite database: {exc}") from None
        if version == 0 and tables == 0:
            self._create()
        elif version != SCHEMA_VERSION:
            self.conn.close()
            raise StoreError(
                f"{path}: database schema version {version}, this launch-linter uses "
                f"{SCHEMA_VERSION}; mine into a new database"
            )
        elif _schema(self.conn) != _expected_schema():
            # A database from elsewhere may carry views or triggers of its own (a recursive
            # view runs forever): only our own schema is used.
            self.conn.close()
            raise StoreError(f"{path}: not a launch-linter database (its schema differs)")

    def _create(self) -> None:
        # WAL keeps readers working during a long ingest and makes commits cheap.
        self.conn.execute("PRAGMA journal_mode = WAL")
        self.conn.executescript(
            f"BEGIN;\n{_SCHEMA}\nPRAGMA user_version = {SCHEMA_VERSION};\nCOMMIT;"
        )

    def close(self) -> None:
        self.conn.close()

    def __enter__(self) -> Store:
        return self

    def __exit__(
        self,
        exc_type: type[BaseException] | None,
        exc: BaseException | None,
        tb: TracebackType | None,
    ) -> None:
        self.close()

    # -- meta -----------------------------------------------------------------------
    def meta(self) -> dict[str, str]:
        return dict(self.conn.execute("SELECT key, value FROM meta"))

    def _set_meta(self, values: Mapping[str, object]) -> None:
        self.conn.executemany(
            "INSERT INTO meta(key, value) VALUES (?, ?) "
            "ON CONFLICT(key) DO UPDATE SET value = excluded.value",
            [(k, str(v)) for k, v in values.items()],
        )

    def set_meta(self, values: Mapping[str, object]) -> None:
        with self.conn:
            self._set_meta(values)

    # -- ingest ---------------------------------------------------------------------
    def update_repos(self, repos: Iterable[RepoInfo], mature_commits: int) -> None:
        """Add or refresh repositories, and their maturity under ``mature_commits``."""
        with self.conn:
            self.conn.executemany(
                "INSERT INTO repos(name, commits, named_mature) VALUES (?, ?, ?) "
                "ON CONFLICT(name) DO UPDATE SET commits = excluded.commits, "
                "named_mature = excluded.named_mature",
                [(r.name, r.commits, int(r.named_mature)) for r in repos],
            )
            self._set_maturity(mature_commits)

    def set_maturity(self, mature_commits: int) -> None:
        """A repository is mature when ``--mature`` named it or it has enough commits."""
        with self.conn:
            self._set_maturity(mature_commits)

    def _set_maturity(self, mature_commits: int) -> None:
        self.conn.execute(
            "UPDATE repos SET mature = (named_mature OR (commits IS NOT NULL AND commits >= ?))",
            (mature_commits,),
        )

    def content_ids(self) -> dict[str, int]:
        return dict(self.conn.execute("SELECT sha256, id FROM contents"))

    def stored_files(self) -> dict[tuple[str, str, str], str]:
        """(repo, path, version) → SHA-256 of every file whose content is stored."""
        rows = self.conn.execute(
            "SELECT r.name, f.path, f.version, c.sha256 FROM files f "
            "JOIN repos r ON r.id = f.repo_id JOIN contents c ON c.id = f.content_id"
        )
        return {(a, b, c): sha for a, b, c, sha in rows}

    def _repo_ids(self) -> dict[str, int]:
        return {name: rid for rid, name in self.conn.execute("SELECT id, name FROM repos")}

    def _put_files(
        self, refs: Iterable[tuple[FileRef, int | None, str | None]], repo_ids: Mapping[str, int]
    ) -> None:
        self.conn.executemany(
            "INSERT INTO files(repo_id, path, version, latest, content_id, error) "
            "VALUES (?, ?, ?, ?, ?, ?) ON CONFLICT(repo_id, path, version) DO UPDATE SET "
            "latest = excluded.latest, content_id = excluded.content_id, error = excluded.error",
            [
                (repo_ids[ref.repo], ref.path, ref.version, int(ref.latest), cid, error)
                for ref, cid, error in refs
            ],
        )

    def add_files(self, refs: Sequence[tuple[FileRef, str]]) -> None:
        """Files whose content (given by SHA-256) is already stored."""
        ids = self.content_ids()
        with self.conn:
            self._put_files(((ref, ids[sha], None) for ref, sha in refs), self._repo_ids())

    def add_unreadable(self, refs: Sequence[tuple[FileRef, str]]) -> None:
        """Files that could not be read, with the reason."""
        with self.conn:
            self._put_files(((ref, None, error) for ref, error in refs), self._repo_ids())

    def add_contents(self, batch: Sequence[tuple[ParsedContent, Sequence[FileRef]]]) -> None:
        """Distinct contents with their transforms and the files that hold them, at once."""
        repo_ids = self._repo_ids()
        placeholders = ", ".join("?" for _ in range(len(TRANSFORM_COLUMNS) + 1))
        insert_transform = (
            f"INSERT INTO transforms(content_id, {', '.join(TRANSFORM_COLUMNS)}) "
            f"VALUES ({placeholders})"
        )
        with self.conn:
            for content, refs in batch:
                cursor = self.conn.execute(
                    "INSERT INTO contents(sha256, bytes, status, reason, transforms) "
                    "VALUES (?, ?, ?, ?, ?)",
                    (content.sha256, content.size, content.status, content.reason,
                     len(content.rows)),
                )
                cid = cursor.lastrowid
                self.conn.executemany(insert_transform, [(cid, *row) for row in content.rows])
                self._put_files(((ref, cid, None) for ref in refs), repo_ids)

    # -- mining ---------------------------------------------------------------------
    def mining_transforms(self) -> Iterator[MinedTransform]:
        """Transforms of the distinct contents that are the latest version of a file of a
        mature repository (maturity as of the last :meth:`update_repos`)."""
        rows = self.conn.execute(
            "SELECT t.content_id, t.parent, t.child, t.name, t.name_resolved, "
            "t.null_displacement, t.null_rotation FROM transforms t "
            "WHERE t.content_id IN (SELECT f.content_id FROM files f "
            "JOIN repos r ON r.id = f.repo_id WHERE f.latest = 1 AND r.mature = 1) "
            "ORDER BY t.content_id, t.ordinal"
        )
        for cid, parent, child, name, name_ok, null_disp, null_rot in rows:
            yield MinedTransform(
                cid,
                (parent, child) if parent is not None and child is not None else None,
                name if name_ok else None,
                None if null_disp is None else bool(null_disp),
                None if null_rot is None else bool(null_rot),
            )

    def mining_scope(self) -> dict[str, int]:
        """How much the miner sees: files, transforms and repositories."""
        files, transforms = self.conn.execute(
            "SELECT count(*), coalesce(sum(c.transforms), 0) FROM contents c WHERE c.id IN "
            "(SELECT f.content_id FROM files f JOIN repos r ON r.id = f.repo_id "
            "WHERE f.latest = 1 AND r.mature = 1)"
        ).fetchone()
        repos = self.conn.execute(
            "SELECT count(DISTINCT f.repo_id) FROM files f JOIN repos r ON r.id = f.repo_id "
            "WHERE f.latest = 1 AND r.mature = 1 AND f.content_id IS NOT NULL"
        ).fetchone()[0]
        return {"files": files, "transforms": transforms, "repos": repos}

    def replace_beliefs(self, beliefs: Iterable[Belief], meta: Mapping[str, object]) -> int:
        """Replace the stored beliefs (one transaction); return how many were stored."""
        with self.conn:
            self.conn.execute("DELETE FROM beliefs")
            cursor = self.conn.executemany(
                "INSERT INTO beliefs(class, antecedent, consequent, n, e, z) "
                "VALUES (?, ?, ?, ?, ?, ?)",
                (
                    (b.cls, encode_key(b.antecedent), encode_key(b.consequent), b.n, b.e, b.z)
                    for b in beliefs
                ),
            )
            self._set_meta(meta)
            return cursor.rowcount

    def beliefs(self, min_z: float | None = None, classes: Sequence[str] = ()) -> list[Belief]:
        """Stored beliefs with ``z ≥ min_z`` (all when None), of ``classes`` (all when
        empty), strongest first within each class."""
        sql = "SELECT class, antecedent, consequent, n, e, z FROM beliefs WHERE 1 = 1"
        params: list[object] = []
        if min_z is not None:
            sql += " AND z >= ?"
            params.append(min_z)
        if classes:
            sql += f" AND class IN ({', '.join('?' for _ in classes)})"
            params.extend(classes)
        out: list[Belief] = []
        for cls, antecedent, consequent, n, e, z in self.conn.execute(sql, params):
            then = decode_key(consequent) if consequent else None
            out.append(Belief(cls, decode_key(antecedent), then, n, e, z))
        return out

    # -- evaluation -----------------------------------------------------------------
    def file_versions(self) -> list[StoredVersion]:
        """Every stored file version with its repository's maturity and its content's
        SHA-256, ordered by repository, path and version (read-only)."""
        rows = self.conn.execute(
            "SELECT r.name, f.path, f.version, f.latest, r.mature, c.sha256 "
            "FROM files f JOIN repos r ON r.id = f.repo_id "
            "LEFT JOIN contents c ON c.id = f.content_id "
            "ORDER BY r.name, f.path, f.version"
        )
        return [
            StoredVersion(repo, path, version, bool(latest), bool(mature), sha)
            for repo, path, version, latest, mature, sha in rows
        ]

    # -- statistics -----------------------------------------------------------------
    def statistics(self) -> dict[str, int]:
        """Counts for the ingest report."""
        one = self.conn.execute

        def count(sql: str) -> int:
            return int(one(sql).fetchone()[0])

        return {
            "repos": count("SELECT count(*) FROM repos"),
            "mature_repos": count("SELECT count(*) FROM repos WHERE mature = 1"),
            "files": count("SELECT count(*) FROM files"),
            "unreadable_files": count("SELECT count(*) FROM files WHERE content_id IS NULL"),
            "contents": count("SELECT count(*) FROM contents"),
            "parse_failures": count("SELECT count(*) FROM contents WHERE status != 'ok'"),
            "transforms": count("SELECT count(*) FROM transforms"),
            "unresolved_transforms": count("SELECT count(*) FROM transforms WHERE resolved = 0"),
            "beliefs": count("SELECT count(*) FROM beliefs"),
        }

    def parse_failures(self) -> list[tuple[str, str, str]]:
        """(sha256, reason, one file that has it) for every content that did not parse."""
        rows = self.conn.execute(
            "SELECT c.sha256, coalesce(c.reason, ''), "
            "(SELECT r.name || ':' || f.path FROM files f JOIN repos r ON r.id = f.repo_id "
            " WHERE f.content_id = c.id ORDER BY f.id LIMIT 1) "
            "FROM contents c WHERE c.status != 'ok' ORDER BY c.id"
        )
        return [(a, b, c or "") for a, b, c in rows]
