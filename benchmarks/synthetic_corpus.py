#!/usr/bin/env python3
"""Build a synthetic corpus of 50,000 files from the real one, mine it, report time and memory.

    python benchmarks/synthetic_corpus.py [--files 50000] [--jobs N] [--out DIR] [--keep]
                                          [CORPUS]

The study mined about 55,000 files; ours is far smaller. This makes a corpus of the same
order from CORPUS (default ``../shared/corpus``): copy k of every repository is named
``<repo>~k``, and in copy k ≥ 1 every frame id in a ``static_transform_publisher``'s
``args`` gets the suffix ``_k``, so each copy brings its own signatures and the pairs the
implication miner counts multiply with the copies. A comment naming the copy, in the
file's own syntax (``<!-- -->`` in XML, ``#`` in Python and YAML), makes every file
distinct, so that deduplication does not collapse the copies and every file is parsed.
Each copy keeps its file's full suffix (``.launch``, ``.launch.xml``, ``.launch.py``), so
``check`` discovers every copy. Manifest rows are copied in order until ``--files`` rows
exist.

Then ``mine`` runs on it into a fresh database (both phases timed) with ``--jobs``
workers (default: every CPU), and the script prints the wall-clock time and the peak
resident memory of the main process and of the largest worker (``resource.getrusage``).
"""

from __future__ import annotations

import argparse
import hashlib
import json
import os
import re
import resource
import shutil
import sys
import tempfile
import time
from collections.abc import Iterator

from launch_linter.mining.commands import mine_corpus

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DEFAULT = os.path.join(ROOT, "..", "shared", "corpus")

NODE = re.compile(rb"<node\b[^>]*?static_transform_publisher[^>]*>", re.S)
ARGS = re.compile(rb"""(\bargs\s*=\s*)(["'])(.*?)\2""", re.S)
WORD = re.compile(rb"\s+|(?:\$\([^)]*\)|\S)+")
NUMBER = re.compile(rb"^[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?$")


def rename_frames(data: bytes, suffix: bytes) -> bytes:
    """Append ``suffix`` to every frame-like word of every static transform's ``args``."""

    def in_args(match: re.Match[bytes]) -> bytes:
        pieces = WORD.findall(match.group(3))
        renamed = [
            p + suffix
            if not p.isspace() and not NUMBER.match(p) and b"$" not in p and not p.startswith(b"-")
            else p
            for p in pieces
        ]
        return match.group(1) + match.group(2) + b"".join(renamed) + match.group(2)

    return NODE.sub(lambda node: ARGS.sub(in_args, node.group(0)), data)


def full_suffix(name: str) -> str:
    """``.launch.py`` for ``abc.launch.py`` (``os.path.splitext`` would give ``.py``)."""
    base = os.path.basename(name)
    dot = base.find(".")
    return base[dot:] if dot > 0 else ""


def copy_comment(suffix: str, copy: int) -> bytes:
    """A line that names the copy, as a comment in the file's own syntax."""
    if suffix.endswith((".py", ".yaml", ".yml")):
        return f"\n# synthetic copy {copy}\n".encode()
    return f"\n<!-- synthetic copy {copy} -->\n".encode()


def manifest(corpus: str) -> list[dict[str, object]]:
    with open(os.path.join(corpus, "manifest.jsonl"), encoding="utf-8") as handle:
        return [json.loads(line) for line in handle if line.strip()]


def synthetic_rows(
    rows: list[dict[str, object]], files: int
) -> Iterator[tuple[int, dict[str, object]]]:
    copy = 0
    produced = 0
    while produced < files:
        for row in rows:
            if produced >= files:
                return
            yield copy, row
            produced += 1
        copy += 1


def build(corpus: str, out: str, files: int) -> tuple[int, int]:
    """Write the synthetic corpus to ``out``; return (files, copies)."""
    os.makedirs(os.path.join(out, "files"), exist_ok=True)
    rows = manifest(corpus)
    cache: dict[str, bytes] = {}
    copies = 0
    with open(os.path.join(out, "manifest.jsonl"), "w", encoding="utf-8") as target:
        for copy, row in synthetic_rows(rows, files):
            copies = max(copies, copy + 1)
            stored = str(row["file"])
            if stored not in cache:
                with open(os.path.join(corpus, stored), "rb") as handle:
                    cache[stored] = handle.read()
            data = cache[stored]
            if copy:
                data = rename_frames(data, f"_{copy}".encode())
            suffix = full_suffix(stored)
            data += copy_comment(suffix, copy)
            sha = hashlib.sha256(data).hexdigest()
            name = f"files/{sha[:16]}{suffix}"
            with open(os.path.join(out, name), "wb") as handle:
                handle.write(data)
            target.write(json.dumps({**row, "repo": f"{row['repo']}~{copy}", "sha256": sha,
                                     "file": name}) + "\n")
    return files, copies


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("corpus", nargs="?", default=DEFAULT)
    parser.add_argument("--files", type=int, default=50_000)
    parser.add_argument("--jobs", type=int, default=os.cpu_count() or 1)
    parser.add_argument("--out", help="where to build the corpus (default: a temporary folder)")
    parser.add_argument("--keep", action="store_true", help="keep the corpus and database")
    ns = parser.parse_args()
    if not os.path.isfile(os.path.join(ns.corpus, "manifest.jsonl")):
        print(f"no manifest corpus at {ns.corpus}", file=sys.stderr)
        return 2
    scratch = ns.out or tempfile.mkdtemp(prefix="synthetic-corpus-")
    try:
        start = time.perf_counter()
        files, copies = build(ns.corpus, os.path.join(scratch, "corpus"), ns.files)
        built = time.perf_counter() - start
        print(f"built {files} files ({copies} copies of the corpus) in {built:.1f} s")
        start = time.perf_counter()
        _, mined, totals = mine_corpus(
            os.path.join(scratch, "corpus"), os.path.join(scratch, "corpus.db"), jobs=ns.jobs
        )
        elapsed = time.perf_counter() - start
        own = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
        workers = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss / 1024
        size = os.path.getsize(os.path.join(scratch, "corpus.db")) / 2**20
        print(f"ingest + mine: {elapsed:.1f} s with {ns.jobs} jobs "
              f"({os.cpu_count()} CPUs)")
        print(f"peak memory: {own:.0f} MiB (main), {workers:.0f} MiB (largest worker)")
        print(f"stored: {totals['files']} files, {totals['contents']} distinct contents, "
              f"{totals['parse_failures']} parse failures, {totals['transforms']} transforms; "
              f"database {size:.0f} MiB")
        print(f"mined: {mined.beliefs} beliefs from {mined.files} files "
              f"({mined.transforms} transforms) of {mined.repos} mature repositories")
    finally:
        if not ns.keep:
            shutil.rmtree(scratch, ignore_errors=True)
        else:
            print(f"kept {scratch}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
