from __future__ import annotations

import json
import os
import sqlite3
import subprocess
import sys
from pathlib import Path

import pytest
from corpus_helpers import MakeCorpus, dump, git_repo, launch, node

from launch_linter.mining.commands import mine_corpus, mine_store
from launch_linter.mining.ingest import CorpusError, ingest, read_corpus
from launch_linter.mining.store import SCHEMA_VERSION, TRANSFORM_COLUMNS, Store, StoreError

A = launch(node("base_to_laser", "0 0 0.2 0 0 0 base_link laser 100"),
           node("map_to_odom", "0 0 0 0 0 0 map odom 100"))
B = launch(node("base_to_laser", "0.1 0 0.2 0 0 0 base_link laser 100"))
C = launch(node("cam", "0 0 0 0 0 0 base_link camera $(arg period)"),
           '  <arg name="unused" default="1"/>')
BROKEN = "<launch>\n  <node pkg='tf' type='static_transform_publisher'\n"


def rows_for(*texts: str, repo: str = "o/r", commits: int = 100) -> list[dict[str, object]]:
    return [{"repo": repo, "path": f"launch/f{i}.launch", "text": text, "commits": commits}
            for i, text in enumerate(texts)]


def counts(db: Path) -> dict[str, int]:
    with Store(str(db)) as store:
        return store.statistics()


def test_manifest_corpus_is_stored_with_every_field(
    make_corpus: MakeCorpus, tmp_path: Path
) -> None:
    root = make_corpus(rows_for(A, B))
    db = tmp_path / "c.db"
    ingested, _, totals = mine_corpus(str(root), str(db))
    assert (ingested.files, ingested.new_files, ingested.parsed) == (2, 2, 2)
    assert totals["transforms"] == 3 and totals["parse_failures"] == 0
    conn = sqlite3.connect(db)
    conn.row_factory = sqlite3.Row
    row = conn.execute(
        "SELECT * FROM transform_rows WHERE name = 'map_to_odom'").fetchone()
    assert row["repo"] == "o/r" and row["file_path"] == "launch/f0.launch"
    assert row["latest"] == 1 and row["mature"] == 1 and row["version"] == "c0"
    assert (row["parent"], row["child"], row["tx"], row["period_ms"]) == ("map", "odom", 0.0, 100.0)
    assert row["null_displacement"] == 1 and row["resolved"] == 1
    assert json.loads(row["tokens"])[-1] == "100"
    assert row["package"] == "tf" and row["executable"] == "static_transform_publisher"
    assert set(TRANSFORM_COLUMNS) <= set(row.keys())
    assert conn.execute("PRAGMA user_version").fetchone()[0] == SCHEMA_VERSION


def test_identical_contents_are_stored_once(make_corpus: MakeCorpus, tmp_path: Path) -> None:
    rows = rows_for(A, repo="o/one") + rows_for(B, A, repo="o/two")
    root = make_corpus(rows)
    db = tmp_path / "c.db"
    ingested, _, totals = mine_corpus(str(root), str(db))
    assert totals["files"] == 3 and totals["contents"] == 2 and ingested.parsed == 2
    assert totals["transforms"] == 3
    # The miner sees each distinct content once: base_link→laser is in two files, not three.
    with Store(str(db)) as store:
        (belief,) = store.beliefs(classes=("sig_null_disp",))
    assert belief.antecedent == ("base_link", "laser") and (belief.n, belief.e) == (2, 0)


def test_unresolved_values_are_recorded(make_corpus: MakeCorpus, tmp_path: Path) -> None:
    root = make_corpus(rows_for(C))
    db = tmp_path / "c.db"
    mine_corpus(str(root), str(db))
    conn = sqlite3.connect(db)
    resolved, unresolved, reasons = conn.execute(
        "SELECT resolved, unresolved, unresolved_reasons FROM transforms").fetchone()
    assert resolved == 0 and json.loads(unresolved) and json.loads(reasons)
    assert counts(db)["unresolved_transforms"] == 1


def test_parse_failures_are_recorded_with_their_reason(
    make_corpus: MakeCorpus, tmp_path: Path
) -> None:
    root = make_corpus(rows_for(A, BROKEN, "<robot/>"))
    db = tmp_path / "c.db"
    ingested, _, totals = mine_corpus(str(root), str(db))
    assert ingested.parse_failures == 2 and totals["parse_failures"] == 2
    with Store(str(db)) as store:
        failures = store.parse_failures()
    reasons = sorted(reason for _, reason, _ in failures)
    assert any("well-formed" in r for r in reasons) and any("<robot>" in r for r in reasons)
    assert {where for _, _, where in failures} == {"o/r:launch/f1.launch", "o/r:launch/f2.launch"}


def test_unreadable_and_escaping_files_are_recorded(
    make_corpus: MakeCorpus, tmp_path: Path
) -> None:
    root = make_corpus(rows_for(A))
    (tmp_path / "secret.launch").write_text(A)
    manifest = root / "manifest.jsonl"
    manifest.write_text(manifest.read_text() + "\n".join([
        json.dumps({"repo": "o/r", "path": "gone.launch", "file": "files/missing.launch"}),
        json.dumps({"repo": "o/r", "path": "x.launch", "file": "../secret.launch"}),
    ]) + "\n")
    db = tmp_path / "c.db"
    ingested, _, totals = mine_corpus(str(root), str(db))
    assert sorted(ingested.unreadable) == [
        ("o/r:gone.launch", "cannot read: No such file or directory"),
        ("o/r:x.launch", "outside the corpus folder"),
    ]
    assert totals["unreadable_files"] == 2 and totals["transforms"] == 2


def test_second_run_adds_nothing(make_corpus: MakeCorpus, tmp_path: Path) -> None:
    root = make_corpus(rows_for(A, B, C, BROKEN))
    db = tmp_path / "c.db"
    mine_corpus(str(root), str(db))
    first = dump(db)
    ingested, _, _ = mine_corpus(str(root), str(db))
    assert ingested.new_files == 0 and ingested.parsed == 0
    assert dump(db) == first


def test_changed_file_is_stored_again(make_corpus: MakeCorpus, tmp_path: Path) -> None:
    root = make_corpus(rows_for(A))
    db = tmp_path / "c.db"
    mine_corpus(str(root), str(db))
    stored = next((root / "files").iterdir())
    stored.write_text(B)
    ingested, _, totals = mine_corpus(str(root), str(db))
    assert ingested.new_files == 1 and ingested.parsed == 1
    assert totals["files"] == 1 and totals["contents"] == 2


def test_only_latest_versions_of_mature_repositories_are_mined(
    make_corpus: MakeCorpus, tmp_path: Path
) -> None:
    null_laser = launch(node("t", "0 0 0 0 0 0 base_link laser 100"))
    rows = [
        {"repo": "o/mature", "path": "a.launch", "text": null_laser, "commits": 30},
        {"repo": "o/mature", "path": "b.launch", "text": B, "commits": 30},
        {"repo": "o/mature", "path": "b.launch", "text": A, "commits": 30, "latest": False,
         "commit": "old"},
        {"repo": "o/young", "path": "a.launch", "text": B.replace("0.1", "0.3"), "commits": 29},
    ]
    root = make_corpus(rows)
    db = tmp_path / "c.db"
    _, mined, _ = mine_corpus(str(root), str(db))
    assert (mined.files, mined.repos) == (2, 1)
    with Store(str(db)) as store:
        (belief,) = store.beliefs(classes=("sig_null_disp",))
        assert (belief.n, belief.e) == (2, 1)
        # Lowering the bar brings the young repository in, without a new ingest.
        mined = mine_store(store, 0.9, 29, str(root))
        (belief,) = store.beliefs(classes=("sig_null_disp",))
    assert (mined.files, mined.repos, belief.n, belief.e) == (3, 2, 3, 1)


def test_parallel_ingest_stores_the_same(make_corpus: MakeCorpus, tmp_path: Path) -> None:
    texts = [launch(node(f"n{i}", f"{i} 0 0 0 0 0 base_link f{i % 3} 100")) for i in range(12)]
    root = make_corpus(rows_for(*texts, BROKEN))
    serial, parallel = tmp_path / "serial.db", tmp_path / "parallel.db"
    mine_corpus(str(root), str(serial), jobs=1)
    mine_corpus(str(root), str(parallel), jobs=2)
    assert dump(serial) == dump(parallel)


def test_interrupted_run_keeps_committed_batches_and_completes(
    make_corpus: MakeCorpus, tmp_path: Path
) -> None:
    texts = [launch(node(f"n{i}", f"{i} 0 0 0 0 0 base_link f{i} 100")) for i in range(6)]
    root = make_corpus(rows_for(*texts))
    clean, broken = tmp_path / "clean.db", tmp_path / "broken.db"
    mine_corpus(str(root), str(clean))

    def stop(done: int) -> None:
        if done == 2:
            raise KeyboardInterrupt

    corpus = read_corpus(str(root))
    with Store(str(broken)) as store, pytest.raises(KeyboardInterrupt):
        ingest(store, corpus, 30, batch_size=1, after_batch=stop)
    assert counts(broken)["contents"] == 2 and counts(broken)["files"] == 2
    mine_corpus(str(root), str(broken))
    assert dump(broken) == dump(clean)


KILLER = """
import os, signal, sys
from launch_linter.mining import store as store_module
from launch_linter.mining.ingest import ingest, read_corpus

calls = 0
original = store_module.Store._put_files

def put_files_then_die(self, refs, repo_ids):
    global calls
    calls += 1
    original(self, refs, repo_ids)
    if calls == 3:  # inside the second batch's transaction, before its commit
        os.kill(os.getpid(), signal.SIGKILL)

store_module.Store._put_files = put_files_then_die
with store_module.Store(sys.argv[2]) as store:
    ingest(store, read_corpus(sys.argv[1]), 30, batch_size=1)
"""


def test_killed_process_leaves_a_consistent_database(
    make_corpus: MakeCorpus, tmp_path: Path
) -> None:
    texts = [launch(node(f"n{i}", f"{i} 0 0 0 0 0 base_link f{i} 100")) for i in range(5)]
    root = make_corpus(rows_for(*texts))
    clean, killed = tmp_path / "clean.db", tmp_path / "killed.db"
    mine_corpus(str(root), str(clean))
    done = subprocess.run([sys.executable, "-c", KILLER, str(root), str(killed)],
                          capture_output=True, env={**os.environ, "PYTHONPATH": ""}, check=False)
    assert done.returncode == -9
    conn = sqlite3.connect(killed)
    assert conn.execute("PRAGMA integrity_check").fetchone() == ("ok",)
    # Only the first batch survived: one content, its transform, its file.
    assert conn.execute("SELECT count(*) FROM contents").fetchone()[0] == 1
    assert conn.execute("SELECT count(*) FROM transforms").fetchone()[0] == 1
    assert conn.execute("SELECT count(*) FROM files").fetchone()[0] == 1
    conn.close()
    mine_corpus(str(root), str(killed))
    assert dump(killed) == dump(clean)


def test_plain_folders_with_git_history(tmp_path: Path) -> None:
    root = tmp_path / "repos"
    git_repo(root / "old_lab", {"pkg/launch/tf.launch": A, "pkg/package.xml": "<package/>"}, 3)
    git_repo(root / "new_lab", {"launch/tf.launch": B}, 1)
    (root / "plain").mkdir()
    (root / "plain" / "x.launch").write_text(B)
    db = tmp_path / "c.db"
    corpus = read_corpus(str(root), ["plain"])
    assert {r.name: (r.commits, r.named_mature) for r in corpus.repos} == {
        "old_lab": (3, False), "new_lab": (1, False), "plain": (None, True),
    }
    entry = next(e for e in corpus.entries if e.ref.repo == "old_lab")
    assert entry.ref.path == "pkg/launch/tf.launch" and len(entry.ref.version) == 40
    _, mined, totals = mine_corpus(str(root), str(db), mature_commits=3, mature=["plain"])
    assert (totals["repos"], totals["mature_repos"], totals["files"]) == (3, 2, 3)
    # B's content is in new_lab (immature) and plain (named mature): counted once.
    assert (mined.files, mined.repos) == (2, 2)
    _, again, _ = mine_corpus(str(root), str(db), mature_commits=1, mature=["plain"])
    assert again.repos == 3
    # --mature holds for the run that names it.
    _, later, _ = mine_corpus(str(root), str(db), mature_commits=1)
    assert later.repos == 2


def test_bad_corpora_are_errors(tmp_path: Path) -> None:
    with pytest.raises(CorpusError, match="does not exist"):
        read_corpus(str(tmp_path / "nope"))
    (tmp_path / "manifest.jsonl").write_text('{"repo": "a", "path": "p"}\nnot json\n')
    with pytest.raises(CorpusError, match=r"manifest.jsonl:2"):
        read_corpus(str(tmp_path))
    (tmp_path / "manifest.jsonl").write_text('{"repo": "a"}\n')
    with pytest.raises(CorpusError, match="'path'"):
        read_corpus(str(tmp_path))


def test_store_refuses_other_schemas_and_non_databases(tmp_path: Path) -> None:
    other = tmp_path / "other.db"
    conn = sqlite3.connect(other)
    conn.execute("CREATE TABLE x (y)")
    conn.execute("PRAGMA user_version = 7")
    conn.commit()
    conn.close()
    with pytest.raises(StoreError, match="schema version 7"):
        Store(str(other))
    junk = tmp_path / "junk.db"
    junk.write_bytes(b"this is not a database at all, not even close" * 10)
    with pytest.raises(StoreError):
        Store(str(junk))
    with pytest.raises(StoreError, match="no such database"):
        Store(str(tmp_path / "missing.db"), create=False)
