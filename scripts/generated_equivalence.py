#!/usr/bin/env python3
"""The generated standalone linter against ``launch-linter check`` on the whole corpus.

    python scripts/generated_equivalence.py [--corpus ../shared/corpus] [--beliefs bundled]
                                            [--min-z 1.0] [--repeat 3] [--python PY ...]

Generates a linter with ``launch-linter generate`` into a temporary folder, then lints two
sets of corpus files, each in one run of each tool: the latest version of every file
(``manifest.jsonl``, ``latest``) and every stored version (``files/``). For each set it
prints whether the two JSON documents agree (``diagnostics``, ``files``, and the whole
document), and the wall-clock time of each tool, the median of ``--repeat`` runs with the
tools interleaved, with the ratio generated / check. ``--python`` adds interpreters that
run the generated file too (e.g. a Python 3.8), compared and timed the same way. The
generated file runs as documented, ``python -I FILE.py``.
"""

from __future__ import annotations

import argparse
import json
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path
from typing import Any

REPO = Path(__file__).resolve().parents[1]


def corpus_sets(corpus: Path) -> dict[str, list[str]]:
    """Paths relative to ``corpus``: the latest versions, and every stored file."""
    latest: set[str] = set()
    with open(corpus / "manifest.jsonl", encoding="utf-8") as handle:
        for line in handle:
            entry = json.loads(line)
            if entry.get("latest"):
                latest.add(entry["file"])
    every = sorted(p.relative_to(corpus).as_posix() for p in (corpus / "files").iterdir())
    return {"latest": sorted(latest), "all": every}


def run(command: list[str], cwd: Path) -> tuple[float, dict[str, Any], int]:
    start = time.perf_counter()
    done = subprocess.run(command, cwd=cwd, capture_output=True, text=True, check=False)
    elapsed = time.perf_counter() - start
    if done.returncode not in (0, 1):
        sys.exit(f"{command[:4]} failed ({done.returncode}):\n{done.stderr[-2000:]}")
    return elapsed, json.loads(done.stdout), done.returncode


def compare(expected: dict[str, Any], actual: dict[str, Any]) -> str:
    same = {key: expected[key] == actual[key] for key in ("diagnostics", "files")}
    if all(same.values()) and expected == actual:
        return "identical (diagnostics, files and the whole document)"
    lines = [f"{key}: {'same' if ok else 'DIFFERENT'}" for key, ok in same.items()]
    for key in ("diagnostics", "files"):
        only_check = [d for d in expected[key] if d not in actual[key]]
        only_generated = [d for d in actual[key] if d not in expected[key]]
        lines.append(f"{key}: {len(only_check)} only from check, "
                     f"{len(only_generated)} only from the generated linter")
        lines.extend(f"  check only: {d}" for d in only_check[:3])
        lines.extend(f"  generated only: {d}" for d in only_generated[:3])
    if all(same.values()):
        lines.append("other keys differ: " + ", ".join(
            k for k in expected if expected.get(k) != actual.get(k)))
    return "\n".join(lines)


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--corpus", type=Path, default=REPO.parent / "shared" / "corpus")
    parser.add_argument("--beliefs", default="bundled")
    parser.add_argument("--min-z", type=float, default=1.0)
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--python", action="append", default=[],
                        help="another interpreter to run the generated file with")
    ns = parser.parse_args()
    corpus = ns.corpus.resolve()
    check = shutil.which("launch-linter")
    check_command = [check] if check else [sys.executable, "-m", "launch_linter"]
    belief_options = ["--beliefs", ns.beliefs, "--min-z", repr(ns.min_z)]

    with tempfile.TemporaryDirectory() as folder:
        script = Path(folder) / "launch_lint.py"
        subprocess.run([*check_command, "generate", *belief_options, "-o", str(script)],
                       check=True, capture_output=True)
        text = script.read_text(encoding="utf-8")
        modules = text.count("\nMODULES[")
        print(f"generated file: {script.stat().st_size:,} bytes, {len(text.splitlines()):,} "
              f"lines, {modules} embedded modules "
              f"({' '.join(belief_options)})")
        tools = {"check": [*check_command, "check", "--format", "json", *belief_options]}
        for python in [sys.executable, *ns.python]:
            version = subprocess.run(
                [python, "-c", "import sys; print('%d.%d.%d' % sys.version_info[:3])"],
                capture_output=True, text=True, check=True,
            ).stdout.strip()
            tools[f"generated (Python {version})"] = [python, "-I", str(script), "--format",
                                                      "json"]
        for name, paths in corpus_sets(corpus).items():
            times: dict[str, list[float]] = {tool: [] for tool in tools}
            documents: dict[str, dict[str, Any]] = {}
            statuses: dict[str, int] = {}
            for _ in range(ns.repeat):
                for tool, command in tools.items():
                    elapsed, document, status = run([*command, *paths], corpus)
                    times[tool].append(elapsed)
                    documents.setdefault(tool, document)
                    statuses.setdefault(tool, status)
            reference = documents["check"]
            print(f"\n{name}: {len(paths):,} files, {len(reference['diagnostics']):,} "
                  f"diagnostics from check (exit {statuses['check']})")
            base = statistics.median(times["check"])
            for tool in tools:
                median = statistics.median(times[tool])
                runs = ", ".join(f"{t:.2f}" for t in times[tool])
                print(f"  {tool:<28} median {median:6.2f} s  ({runs})  ratio {median / base:.2f}")
            for tool in tools:
                if tool != "check":
                    verdict = compare(reference, documents[tool])
                    print(f"  {tool} vs check (exit {statuses[tool]}): {verdict}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
