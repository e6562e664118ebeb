#!/usr/bin/env python3
"""How many corpus launch files folder discovery finds, before and after issue 14.

    python scripts/discovery_corpus.py [CORPUS]

CORPUS defaults to ``../shared/corpus``. The corpus stores contents under hashed names,
so the HEAD version of every file is first written back at its original path
(``<repo>/<path>``) in a temporary folder; then the old rule (the five ``.launch*``
suffixes, ``*.xml`` holding ``<launch`` in its first 4 KiB) and the new discovery are
run over that tree and over the corpus folder as stored.
"""

from __future__ import annotations

import argparse
import json
import os
import shutil
import sys
import tempfile

from launch_linter.workspace.discovery import discover

OLD_SUFFIXES = (".launch", ".launch.xml", ".launch.yaml", ".launch.yml", ".launch.py")


def old_discover(root: str) -> list[str]:
    found = []
    for directory, subdirs, files in os.walk(root):
        subdirs[:] = sorted(d for d in subdirs if not d.startswith("."))
        for name in sorted(files):
            full = os.path.join(directory, name)
            if name.endswith(OLD_SUFFIXES):
                found.append(full)
            elif name.endswith(".xml"):
                with open(full, "rb") as handle:
                    if b"<launch" in handle.read(4096):
                        found.append(full)
    return found


def materialise(corpus: str, target: str) -> int:
    count = 0
    with open(os.path.join(corpus, "manifest.jsonl"), encoding="utf-8") as handle:
        for line in handle:
            entry = json.loads(line)
            if not entry.get("latest"):
                continue
            path = os.path.join(target, entry["repo"].replace("/", "+"), entry["path"])
            os.makedirs(os.path.dirname(path), exist_ok=True)
            shutil.copyfile(os.path.join(corpus, entry["file"]), path)
            count += 1
    return count


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("corpus", nargs="?", default=os.path.join("..", "shared", "corpus"))
    ns = parser.parse_args()
    stored = os.path.join(ns.corpus, "files")
    print(f"stored files/: before {len(old_discover(stored))}, after {len(discover([stored]))}")
    with tempfile.TemporaryDirectory() as target:
        total = materialise(ns.corpus, target)
        before = {os.path.relpath(p, target) for p in old_discover(target)}
        after = {os.path.relpath(f.path, target) for f in discover([target])}
        print(f"HEAD files at their original paths: {total}")
        print(f"  before {len(before)}, after {len(after)} (+{len(after - before)} new, "
              f"-{len(before - after)} no longer)")
        for path in sorted(before - after):
            print(f"  no longer: {path}")
        suffixes: dict[str, int] = {}
        for path in after - before:
            key = "_launch.py" if path.endswith("_launch.py") else os.path.splitext(path)[1]
            suffixes[key] = suffixes.get(key, 0) + 1
        print(f"  new by kind: {dict(sorted(suffixes.items()))}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
