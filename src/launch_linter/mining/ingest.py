"""Reading a corpus into the store: which files there are, and what each one declares.

A corpus is either a folder with a ``manifest.jsonl`` (the format of ``../shared/corpus``:
one line per repository, path and version, naming the stored file), or a plain folder
whose top-level subfolders are repositories (git repositories are dated by their commit
count; other folders count as immature unless ``--mature`` names them).

Every distinct content (SHA-256 of the raw bytes) is parsed once, in parallel, and stored
with its transforms and the files that hold it in one transaction per batch: a run that is
killed loses at most the batch in flight, and the next run parses only what is missing.
"""

from __future__ import annotations

import hashlib
import json
import os
from collections.abc import Callable, Iterable, Iterator, Sequence
from concurrent.futures import ProcessPoolExecutor
from concurrent.futures.process import BrokenProcessPool
from dataclasses import dataclass, field

from launch_linter.engine import discover
from launch_linter.frontends.dispatch import load_tree
from launch_linter.frontends.ros1 import LoadOptions
from launch_linter.mining.gitread import commit_count
from launch_linter.mining.progress import Progress
from launch_linter.mining.store import FileRef, ParsedContent, RepoInfo, Store, transform_row
from launch_linter.model.launch import FileStatus
from launch_linter.resolve.xml_safe import read_launch_bytes
from launch_linter.workspace.packages import PackageIndex

MANIFEST = "manifest.jsonl"
BATCH_SIZE = 256


class CorpusError(Exception):
    """The corpus cannot be read (missing folder, malformed manifest line, …)."""


@dataclass(frozen=True)
class CorpusEntry:
    """One file of the corpus and where to read it."""

    ref: FileRef
    source: str
    """The file to read."""
    parse_path: str
    """The name the front-end sees: the file's own name, in the folder of ``source``."""
    package_roots: tuple[str, ...]
    """Where ``$(find)`` looks (the repository folder; nothing for a manifest corpus)."""


@dataclass(frozen=True)
class Corpus:
    root: str
    kind: str
    """``manifest`` or ``folders``."""
    repos: tuple[RepoInfo, ...]
    entries: tuple[CorpusEntry, ...]
    unknown_mature: tuple[str, ...] = ()
    """Names given to ``--mature`` that match no repository."""


@dataclass
class IngestReport:
    files: int = 0
    """Files in the corpus."""
    new_files: int = 0
    """Files not stored before this run."""
    parsed: int = 0
    """Distinct contents parsed in this run."""
    parse_failures: int = 0
    unreadable: list[tuple[str, str]] = field(default_factory=list)
    """(repo:path, reason) of files that could not be read in this run."""
    unknown_mature: tuple[str, ...] = ()
    """Names given to ``--mature`` that match no repository."""


# -- reading the corpus --------------------------------------------------------------------
def read_corpus(root: str, mature: Sequence[str] = ()) -> Corpus:
    """The files of the corpus at ``root``; ``mature`` names repositories to treat as mature."""
    if not os.path.isdir(root):
        raise CorpusError(f"corpus folder {root!r} does not exist")
    root = os.path.abspath(root)
    if os.path.isfile(os.path.join(root, MANIFEST)):
        return _read_manifest(root, mature)
    return _read_folders(root, mature)


def _inside(real_root: str, path: str) -> bool:
    return os.path.commonpath([real_root, os.path.realpath(path)]) == real_root


def _manifest_lines(path: str) -> Iterator[tuple[int, dict[str, object]]]:
    try:
        with open(path, encoding="utf-8") as handle:
            for number, line in enumerate(handle, 1):
                if not line.strip():
                    continue
                try:
                    row = json.loads(line)
                except json.JSONDecodeError as exc:
                    raise CorpusError(f"{path}:{number}: not JSON: {exc}") from None
                if not isinstance(row, dict):
                    raise CorpusError(f"{path}:{number}: expected a JSON object")
                yield number, row
    except (OSError, UnicodeDecodeError) as exc:
        raise CorpusError(f"cannot read {path}: {exc}") from None


def _text(row: dict[str, object], key: str, where: str) -> str:
    value = row.get(key)
    if not isinstance(value, str) or not value:
        raise CorpusError(f"{where}: '{key}' must be a non-empty string")
    return value


def _read_manifest(root: str, mature: Sequence[str]) -> Corpus:
    manifest = os.path.join(root, MANIFEST)
    commits: dict[str, int | None] = {}
    flagged: set[str] = set()
    entries: list[CorpusEntry] = []
    for number, row in _manifest_lines(manifest):
        where = f"{manifest}:{number}"
        repo = _text(row, "repo", where)
        path = _text(row, "path", where)
        stored = row.get("file") or os.path.join(repo, path)
        if not isinstance(stored, str):
            raise CorpusError(f"{where}: 'file' must be a string")
        version = row.get("commit", row.get("version", ""))
        count = row.get("repo_commits", row.get("commits"))
        if count is not None and (not isinstance(count, int) or isinstance(count, bool)):
            raise CorpusError(f"{where}: 'repo_commits' must be an integer")
        if commits.get(repo) is None:
            commits[repo] = count
        if row.get("mature") is True and count is None:
            flagged.add(repo)
        source = os.path.join(root, stored)
        entries.append(
            CorpusEntry(
                FileRef(repo, path, str(version or ""), row.get("latest", True) is not False),
                source,
                os.path.join(os.path.dirname(source), os.path.basename(path)),
                (),
            )
        )
    named = set(mature)
    repos = tuple(
        RepoInfo(name, count, name in named or name in flagged) for name, count in commits.items()
    )
    return Corpus(root, "manifest", repos, tuple(entries), tuple(sorted(named - set(commits))))


def git_commits(folder: str) -> tuple[int | None, str]:
    """(commits reachable from HEAD, HEAD's SHA) of a git repository, (None, "") otherwise;
    nothing from the repository is run (see :mod:`launch_linter.mining.gitread`)."""
    return commit_count(folder)


def _read_folders(root: str, mature: Sequence[str]) -> Corpus:
    named = {os.path.basename(os.path.normpath(m)) for m in mature}
    repos: list[RepoInfo] = []
    entries: list[CorpusEntry] = []
    for name in sorted(os.listdir(root)):
        folder = os.path.join(root, name)
        if name.startswith(".") or not os.path.isdir(folder):
            continue
        count, head = git_commits(folder)
        repos.append(RepoInfo(name, count, name in named))
        for item in discover([folder]):
            relative = os.path.relpath(item.path, folder).replace(os.sep, "/")
            entries.append(
                CorpusEntry(FileRef(name, relative, head, True), item.path, item.path, (folder,))
            )
    known = {r.name for r in repos}
    return Corpus(root, "folders", tuple(repos), tuple(entries), tuple(sorted(named - known)))


# -- parsing -------------------------------------------------------------------------------
@dataclass(frozen=True)
class ParseJob:
    sha256: str
    source: str
    parse_path: str
    package_roots: tuple[str, ...]


_INDEXES: dict[tuple[str, ...], PackageIndex] = {}


def _identity(path: str) -> str:
    return path


def parse_job(job: ParseJob) -> ParsedContent:
    """Parse one distinct content (runs in a worker process)."""
    try:
        data = read_launch_bytes(job.source)
    except OSError as exc:
        return ParsedContent(job.sha256, 0, "unreadable", f"cannot read: {exc.strerror or exc}", ())
    if hashlib.sha256(data).hexdigest() != job.sha256:
        return ParsedContent(job.sha256, len(data), "unreadable", "changed while ingesting", ())
    index = _INDEXES.get(job.package_roots)
    if index is None:
        index = _INDEXES[job.package_roots] = PackageIndex(list(job.package_roots))
    options = LoadOptions(packages=index, display_path=_identity)
    try:
        tree = load_tree(job.parse_path, options, data)
    except Exception as exc:
        # A front-end bug on one hostile file must not end a corpus-wide run: the file is
        # recorded as a parse failure with the reason, and the run goes on.
        reason = f"front-end failed: {type(exc).__name__}: {exc}"
        return ParsedContent(job.sha256, len(data), FileStatus.PARSE_ERROR.value, reason, ())
    failure: str | None = None
    if tree.status is not FileStatus.OK:
        first = next((d for d in tree.problems if d.rule == "parse_error"), None)
        failure = first.message if first else tree.status.value
    own = [t for t in tree.transforms if t.path == job.parse_path]
    rows = tuple(transform_row(i, t) for i, t in enumerate(own))
    return ParsedContent(job.sha256, len(data), tree.status.value, failure, rows)


def _parsed(jobs: Sequence[ParseJob], workers: int) -> Iterator[ParsedContent]:
    if workers <= 1 or len(jobs) < 2 * workers:
        yield from map(parse_job, jobs)
        return
    position = 0
    while position < len(jobs):
        broken_at: int | None = None
        with ProcessPoolExecutor(max_workers=workers) as pool:
            futures = [pool.submit(parse_job, job) for job in jobs[position:]]
            for offset, future in enumerate(futures):
                try:
                    result = future.result()
                except BrokenProcessPool:
                    broken_at = position + offset
                    break
                yield result
        if broken_at is None:
            return
        # A worker died (killed, out of memory, a crash in C code) and broke the pool: the
        # first unfinished job is tried again alone, and reported if it kills that worker
        # too; the run goes on after it in a new pool.
        yield _parse_alone(jobs[broken_at])
        position = broken_at + 1


def _parse_alone(job: ParseJob) -> ParsedContent:
    try:
        with ProcessPoolExecutor(max_workers=1) as pool:
            return pool.submit(parse_job, job).result()
    except BrokenProcessPool:
        return ParsedContent(job.sha256, 0, FileStatus.PARSE_ERROR.value,
                             "the worker process parsing it died", ())


def _storable(text: str) -> bool:
    """Whether SQLite can store ``text`` (a file name may hold undecodable bytes)."""
    try:
        text.encode("utf-8")
    except UnicodeEncodeError:
        return False
    return True


def _escaped(ref: FileRef) -> FileRef:
    def escape(text: str) -> str:
        return text.encode("utf-8", "backslashreplace").decode("utf-8")

    return FileRef(escape(ref.repo), escape(ref.path), escape(ref.version), ref.latest)


# -- ingest --------------------------------------------------------------------------------
def _batches(items: Iterable[ParsedContent], size: int) -> Iterator[list[ParsedContent]]:
    batch: list[ParsedContent] = []
    for item in items:
        batch.append(item)
        if len(batch) >= size:
            yield batch
            batch = []
    if batch:
        yield batch


def ingest(
    store: Store,
    corpus: Corpus,
    mature_commits: int,
    jobs: int = 1,
    batch_size: int = BATCH_SIZE,
    after_batch: Callable[[int], None] | None = None,
) -> IngestReport:
    """Store every file of ``corpus`` that is not stored yet; parse each new content once.

    ``after_batch`` is called with the number of contents committed so far (tests use it
    to stop a run halfway).
    """
    report = IngestReport(files=len(corpus.entries), unknown_mature=corpus.unknown_mature)
    store.update_repos(corpus.repos, mature_commits)
    stored = store.stored_files()
    known = store.content_ids()
    waiting: dict[str, list[FileRef]] = {}
    parse_jobs: list[ParseJob] = []
    seen: list[tuple[FileRef, str]] = []
    unreadable: list[tuple[FileRef, str]] = []
    real_root = os.path.realpath(corpus.root)
    for entry in corpus.entries:
        if not (_storable(entry.ref.repo) and _storable(entry.ref.path)
                and _storable(entry.ref.version)):
            unreadable.append((_escaped(entry.ref), "its name is not valid UTF-8; not stored"))
            continue
        if not _inside(real_root, entry.source):
            unreadable.append((entry.ref, "outside the corpus folder"))
            continue
        try:
            data = read_launch_bytes(entry.source)
        except OSError as exc:
            unreadable.append((entry.ref, f"cannot read: {exc.strerror or exc}"))
            continue
        sha = hashlib.sha256(data).hexdigest()
        if stored.get((entry.ref.repo, entry.ref.path, entry.ref.version)) == sha:
            continue
        report.new_files += 1
        if sha in known:
            seen.append((entry.ref, sha))
        elif sha in waiting:
            waiting[sha].append(entry.ref)
        else:
            waiting[sha] = [entry.ref]
            parse_jobs.append(ParseJob(sha, entry.source, entry.parse_path, entry.package_roots))
    store.add_files(seen)

    progress = Progress("parsing", len(parse_jobs))
    committed = 0
    try:
        for batch in _batches(_parsed(parse_jobs, jobs), batch_size):
            contents = [(c, waiting[c.sha256]) for c in batch if c.status != "unreadable"]
            for c in batch:
                if c.status == "unreadable":
                    unreadable.extend((ref, c.reason or "unreadable") for ref in waiting[c.sha256])
            store.add_contents(contents)
            committed += len(batch)
            report.parsed += len(contents)
            report.parse_failures += sum(1 for c, _ in contents if c.status != "ok")
            progress.advance(len(batch))
            if after_batch is not None:
                after_batch(committed)
    finally:
        progress.finish()
    store.add_unreadable(unreadable)
    report.unreadable = [(f"{ref.repo}:{ref.path}", reason) for ref, reason in unreadable]
    return report
