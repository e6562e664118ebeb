"""``launch-linter mine`` and ``launch-linter beliefs``, and the library calls under them."""

from __future__ import annotations

import argparse
import datetime
import os
import sqlite3
import sys
from collections import Counter
from collections.abc import Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any, TextIO

from launch_linter.commands.common import EXIT_INTERRUPTED, EXIT_OK, EXIT_USAGE
from launch_linter.mining.beliefs import (
    belief_order,
    beliefs_document,
    dumps_document,
    encode_key,
    mine,
)
from launch_linter.mining.stats import check_p0
from launch_linter.mining.store import Store, StoreError
from launch_linter.model.beliefs import BELIEF_CLASSES
from launch_linter.model.diagnostic import Belief
from launch_linter.report.escape import printable

if TYPE_CHECKING:
    from launch_linter.mining.ingest import IngestReport


@dataclass(frozen=True)
class MineReport:
    files: int
    transforms: int
    repos: int
    beliefs: int


def created_now() -> str:
    # SOURCE_DATE_EPOCH (reproducible-builds.org) lets the bundled file be rebuilt byte-for-byte.
    epoch = os.environ.get("SOURCE_DATE_EPOCH")
    moment = (
        datetime.datetime.fromtimestamp(int(epoch), datetime.timezone.utc)
        if epoch and epoch.isdigit()
        else datetime.datetime.now(datetime.timezone.utc)
    )
    return moment.replace(microsecond=0).isoformat().replace("+00:00", "Z")


def mine_store(store: Store, p0: float, mature_commits: int, corpus: str) -> MineReport:
    """Mine every belief with n ≥ 2 from the stored corpus and replace the stored beliefs."""
    check_p0(p0)
    store.set_maturity(mature_commits)
    beliefs = mine(store.mining_transforms(), p0)
    scope = store.mining_scope()
    count = store.replace_beliefs(
        beliefs,
        {
            "p0": p0,
            "mature_commits": mature_commits,
            "corpus": corpus,
            "created": created_now(),
            "files": scope["files"],
            "transforms": scope["transforms"],
            "repos": scope["repos"],
        },
    )
    return MineReport(scope["files"], scope["transforms"], scope["repos"], count)


def mine_corpus(
    corpus_path: str,
    db: str,
    p0: float = 0.9,
    mature_commits: int = 30,
    mature: Sequence[str] = (),
    jobs: int = 1,
) -> tuple[IngestReport, MineReport, dict[str, int]]:
    """Ingest ``corpus_path`` into ``db`` and mine it: (ingest, mining, database counts)."""
    # Imported here (the front-ends and multiprocessing): every command line builds the
    # parser of this module, few mine.
    from launch_linter.mining.ingest import ingest, read_corpus

    check_p0(p0)
    corpus = read_corpus(corpus_path, mature)
    with Store(db) as store:
        ingested = ingest(store, corpus, mature_commits, jobs)
        mined = mine_store(store, p0, mature_commits, corpus_path)
        return ingested, mined, store.statistics()


def _error(message: str) -> int:
    sys.stderr.write(f"launch-linter: error: {printable(message)}\n")
    return EXIT_USAGE


def add_parser(subparsers: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    """Two commands: ``mine`` (ingest and mine a corpus) and ``beliefs`` (list or write)."""
    mine = subparsers.add_parser("mine", help="ingest a corpus into a database and mine beliefs")
    mine.add_argument("corpus")
    mine.add_argument("--db", required=True)
    mine.add_argument("--p0", type=float, default=0.9)
    mine.add_argument("--mature-commits", type=int, default=30)
    mine.add_argument(
        "--mature",
        action="append",
        metavar="REPO",
        help="treat this repository folder as mature (plain folders)",
    )
    mine.add_argument("--jobs", type=int, default=None)
    mine.set_defaults(handler=run_mine)

    beliefs = subparsers.add_parser("beliefs", help="list mined beliefs or write a beliefs file")
    beliefs.add_argument("--db", required=True)
    beliefs.add_argument("--min-z", type=float, default=None)
    beliefs.add_argument("--class", dest="classes", action="append", metavar="CLASS")
    beliefs.add_argument("--format", choices=("table", "json"), default="table")
    beliefs.add_argument("-o", "--output", metavar="FILE")
    beliefs.set_defaults(handler=run_beliefs)


def run_mine(ns: argparse.Namespace) -> int:
    from launch_linter.mining.ingest import CorpusError

    if ns.mature_commits < 0:
        return _error("--mature-commits must not be negative")
    if ns.jobs is not None and ns.jobs < 1:
        return _error("--jobs must be at least 1")
    jobs = ns.jobs or os.cpu_count() or 1
    try:
        ingested, mined, totals = mine_corpus(
            ns.corpus, ns.db, ns.p0, ns.mature_commits, ns.mature or (), jobs
        )
    except (ValueError, CorpusError, StoreError, sqlite3.Error) as exc:
        return _error(str(exc))
    except KeyboardInterrupt:
        sys.stderr.write(
            "launch-linter: interrupted; the database keeps every committed batch, "
            "run the same command again to complete it\n"
        )
        return EXIT_INTERRUPTED
    for name in ingested.unknown_mature:
        sys.stderr.write(f"launch-linter: warning: --mature {printable(name)}: no such "
                         "repository\n")
    for where, reason in ingested.unreadable:
        # Corpus file names are a stranger's: no terminal escapes, one line each.
        sys.stderr.write(f"launch-linter: warning: {printable(where)}: {printable(reason)}\n")
    share = totals["unresolved_transforms"] / totals["transforms"] if totals["transforms"] else 0.0
    sys.stdout.write(
        f"ingested {ingested.new_files} new of {ingested.files} files "
        f"({ingested.parsed} distinct contents parsed, {ingested.parse_failures} parse failures, "
        f"{len(ingested.unreadable)} unreadable)\n"
        f"database: {totals['repos']} repositories ({totals['mature_repos']} mature), "
        f"{totals['files']} files, {totals['contents']} distinct contents, "
        f"{totals['parse_failures']} parse failures, {totals['transforms']} transforms "
        f"({share:.1%} with an unresolved value)\n"
        f"mined {mined.beliefs} beliefs (n >= 2, p0 = {ns.p0}) from {mined.files} files "
        f"({mined.transforms} transforms) of {mined.repos} mature repositories\n"
    )
    return EXIT_OK


def _source(meta: dict[str, str]) -> dict[str, Any]:
    return {
        "corpus": meta.get("corpus", ""),
        "files": int(meta.get("files", 0)),
        "transforms": int(meta.get("transforms", 0)),
        "repos": int(meta.get("repos", 0)),
        "created": meta.get("created", ""),
    }


def _table(beliefs: Sequence[Belief], out: TextIO) -> None:
    rows = [
        (b.cls, f"{b.z:.2f}", str(b.n), str(b.e), encode_key(b.antecedent),
         encode_key(b.consequent))
        for b in beliefs
    ]
    header = ("class", "z", "n", "e", "if", "then")
    widths = [max(len(r[i]) for r in [header, *rows]) for i in range(5)]
    for row in [header, *rows]:
        cells = [
            row[0].ljust(widths[0]), row[1].rjust(widths[1]), row[2].rjust(widths[2]),
            row[3].rjust(widths[3]), row[4].ljust(widths[4]) if row[5] else row[4], row[5],
        ]
        out.write("  ".join(cells).rstrip() + "\n")


def run_beliefs(ns: argparse.Namespace) -> int:
    classes = tuple(ns.classes or ())
    unknown = [c for c in classes if c not in BELIEF_CLASSES]
    if unknown:
        return _error(
            f"unknown belief class(es): {', '.join(unknown)} (one of {', '.join(BELIEF_CLASSES)})"
        )
    try:
        with Store(ns.db, create=False) as store:
            meta = store.meta()
            if "p0" not in meta:
                return _error(f"{ns.db}: nothing mined yet (run 'launch-linter mine')")
            beliefs = sorted(store.beliefs(ns.min_z, classes), key=belief_order)
    except (StoreError, sqlite3.Error) as exc:
        return _error(str(exc))
    document = beliefs_document(
        beliefs, float(meta["p0"]), int(meta["mature_commits"]), _source(meta)
    )
    document["min_z"] = ns.min_z
    if ns.output:
        temporary = f"{ns.output}.tmp{os.getpid()}"
        try:
            with open(temporary, "w", encoding="utf-8") as handle:
                handle.write(dumps_document(document))
            os.replace(temporary, ns.output)
        except OSError as exc:
            return _error(f"cannot write {ns.output}: {exc}")
        counts = Counter(b.cls for b in beliefs)
        summary = ", ".join(f"{c} {counts[c]}" for c in BELIEF_CLASSES if counts[c])
        sys.stderr.write(f"wrote {len(beliefs)} beliefs to {ns.output} ({summary or 'none'})\n")
    elif ns.format == "json":
        sys.stdout.write(dumps_document(document))
    else:
        _table(beliefs, sys.stdout)
    return EXIT_OK
