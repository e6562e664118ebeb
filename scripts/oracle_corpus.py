"""Compare launch-linter's ROS 1 loader with the real roslaunch over the whole corpus.

Runs the project's shared oracle tool (``../shared/tools/roslaunch_oracle.py``, under
Debian's ``/usr/bin/python3`` with ``python3-roslaunch``) with ``--safe-eval
--stable-anon``, in batches of files per process, over every file of
``../shared/corpus/files``, with no package roots, no launch args and an empty
environment, and loads each file with launch-linter the same way.

For every file roslaunch loads, the static transform nodes (package ``tf``/``tf2_ros``,
type ``static_transform_publisher``) must agree: the set of (resolved name, namespace,
package, type, args) and the line of each ``<node>``. The script prints the agreement
rate, every class of disagreement with its count and an example, what we report on the
files roslaunch refuses, and corpus figures (transforms found, share unresolved, top
reasons). Usage::

    python scripts/oracle_corpus.py [--corpus DIR] [--oracle FILE] [--batch N] [--jobs N]
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tempfile
from collections import Counter
from collections.abc import Sequence
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass, field
from typing import Any, Optional, Tuple

from launch_linter.frontends.dispatch import load_tree
from launch_linter.frontends.ros1 import TF_PACKAGES, LoadOptions, ns_join
from launch_linter.model.launch import LaunchTree
from launch_linter.model.transform import StaticTransform
from launch_linter.workspace.packages import PackageIndex

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SHARED = os.path.join(os.path.dirname(REPO), "shared")
SYSTEM_PYTHON = "/usr/bin/python3"

Key = Tuple[Optional[str], str, str, str, str]


def oracle_available() -> bool:
    if not os.path.exists(SYSTEM_PYTHON):
        return False
    probe = subprocess.run([SYSTEM_PYTHON, "-c", "import roslaunch"], capture_output=True,
                           check=False)
    return probe.returncode == 0


def run_oracle(tool: str, files: Sequence[str], cwd: str, batch: int, jobs: int,
               options: Sequence[str] = ()) -> dict[str, dict[str, Any]]:
    """Run the shared oracle over ``files`` in batches; results by file path."""
    chunks = [list(files[i:i + batch]) for i in range(0, len(files), batch)]

    def one(chunk: list[str]) -> list[dict[str, Any]]:
        done = subprocess.run(
            [SYSTEM_PYTHON, tool, "--safe-eval", "--stable-anon", *options, *chunk],
            capture_output=True, text=True, cwd=cwd, env={}, check=False, timeout=3600,
        )
        return [json.loads(line) for line in done.stdout.splitlines() if line.startswith("{")]

    results: dict[str, dict[str, Any]] = {}
    with ThreadPoolExecutor(max_workers=jobs) as pool:
        for rows in pool.map(one, chunks):
            for row in rows:
                results[row["file"]] = row
    return results


def oracle_keys(row: dict[str, Any]) -> dict[Key, int]:
    """Static transform nodes of one oracle row: key -> line (0 if the tool has none)."""
    return {
        (n["resolved_name"], n["namespace"], n["package"], n["type"], n["args"]): n["line"] or 0
        for n in row.get("static_tf", [])
        if n["package"] in TF_PACKAGES
    }


def our_key(t: StaticTransform) -> Key:
    resolved_name = ns_join(t.namespace, t.name) if t.name else None
    return (resolved_name, t.namespace, t.package, t.executable, t.args)


@dataclass
class Report:
    files: int = 0
    loaded: int = 0
    agree: int = 0
    classes: Counter[str] = field(default_factory=Counter)
    examples: dict[str, str] = field(default_factory=dict)
    refused: Counter[str] = field(default_factory=Counter)
    refused_examples: dict[str, str] = field(default_factory=dict)

    def disagree(self, kind: str, example: str) -> None:
        self.classes[kind] += 1
        self.examples.setdefault(kind, example)


def compare(path: str, row: dict[str, Any], tree: LaunchTree, report: Report) -> None:
    name = os.path.basename(path)
    rules = {d.rule for d in tree.problems}
    if "error" in row:
        report.refused[row["error_type"]] += 1
        seen = sorted(rules & {"parse_error", "roslaunch_error", "unresolved"})
        kind = f"{row['error_type']} -> ours: {', '.join(seen) or 'nothing'}"
        report.refused[kind] += 1
        report.refused_examples.setdefault(kind, f"{name}: {row['error'][:160]!r}")
        return
    report.loaded += 1
    # Pair the nodes by line (corpus files are flat: no include resolves), then compare.
    theirs = {line: key for key, line in oracle_keys(row).items()}
    ours_by_line = {t.line: t for t in tree.transforms}
    problems: list[tuple[str, str]] = []
    for line in sorted(theirs.keys() | ours_by_line.keys()):
        key = theirs.get(line)
        transform = ours_by_line.get(line)
        where = f"{name}:{line}"
        if transform is None:
            problems.append(("roslaunch has a transform we lack", f"{where} {key}"))
            continue
        if key is None:
            problems.append(("we have a transform roslaunch lacks", f"{where} {transform.name}"))
            continue
        if transform.unresolved:
            problems.append(("ours unresolved, roslaunch resolved",
                             f"{where} {transform.unresolved} {transform.unresolved_reasons[:1]}"))
            continue
        if not transform.condition.always:
            problems.append(("ours conditional, roslaunch decided",
                             f"{where} {transform.condition.describe()}"))
        mine = our_key(transform)
        for index, field_name in enumerate(("resolved name", "namespace", "package", "type",
                                            "args")):
            if mine[index] != key[index]:
                problems.append((f"different {field_name}",
                                 f"{where} ours {mine[index]!r}, roslaunch {key[index]!r}"))
    if tree.status.value != "ok":
        problems.append(("ours parse_error, roslaunch loads", name))
    errors = [d for d in tree.problems if d.rule in ("parse_error", "roslaunch_error")]
    if errors:
        problems.append(("ours reports a roslaunch error, roslaunch loads",
                         f"{name}:{errors[0].line} {errors[0].message[:120]}"))
    if not problems:
        report.agree += 1
    for kind, example in dict(problems).items():
        report.disagree(kind, example)


def corpus_figures(trees: list[LaunchTree]) -> None:
    transforms = [t for tree in trees for t in tree.transforms]
    unresolved = [t for t in transforms if t.unresolved]
    conditional = [t for t in transforms if not t.condition.always]
    print(f"\ncorpus files parsed: {len(trees)}; "
          f"parse errors: {sum(1 for t in trees if t.status.value != 'ok')}")
    print(f"transforms found: {len(transforms)}; unresolved: {len(unresolved)} "
          f"({100.0 * len(unresolved) / max(1, len(transforms)):.1f}%); "
          f"with an unresolved condition: {len(conditional)}")
    reasons: Counter[str] = Counter()
    for t in unresolved:
        kinds = {_reason_kind(r) for r in t.unresolved_reasons} or {"(no substitution)"}
        reasons.update(kinds)
    print("top reasons (transforms per kind of blocking substitution):")
    for kind, count in reasons.most_common(10):
        print(f"  {count:6d}  {kind}")


def _reason_kind(reason: str) -> str:
    text, _, why = reason.partition(": ")
    command = text[2:].split(" ", 1)[0].rstrip(")") if text.startswith("$(") else text
    if "not found under the package path" in why:
        return f"$({command}): package not found"
    if "is not set" in why or "not set" in why:
        return f"$({command}): value not given"
    if "unresolved condition" in why:
        return f"$({command}): set under an unresolved condition"
    if "not given" in why:
        return f"$({command}): not given"
    return f"$({command}): {why[:60]}"


def missing_package(row: dict[str, Any]) -> str | None:
    """The package a refusal names, if roslaunch refused for want of a package."""
    if row.get("error_type") != "ResourceNotFound":
        return None
    message = str(row["error"]).strip()
    name = message.rsplit(": ", 1)[-1] if "was not found in" in message else message
    name = name.splitlines()[0].strip() if name else ""
    return name if name and " " not in name else None


def stub_packages(root: str, names: set[str]) -> None:
    for name in names:
        folder = os.path.join(root, name)
        os.makedirs(folder, exist_ok=True)
        with open(os.path.join(folder, "package.xml"), "w", encoding="utf-8") as handle:
            handle.write(f"<package><name>{name}</name></package>\n")


def with_stub_packages(ns: argparse.Namespace, folder: str, results: dict[str, dict[str, Any]],
                       baseline: dict[str, LaunchTree]) -> None:
    """Give roslaunch empty packages for every package it missed, until no new one is
    missed, and check the files it then loads: with the same packages we must agree, and
    without them each transform of ours must be either the same or unresolved."""
    pending = {p: r for p, r in results.items() if missing_package(r)}
    refused = set(pending)
    names: set[str] = set()
    with tempfile.TemporaryDirectory() as root:
        for _ in range(8):
            new = {missing_package(r) for r in pending.values()} - names - {None}
            if not new:
                break
            names |= {n for n in new if n}
            stub_packages(root, names)
            rerun = run_oracle(ns.oracle, sorted(pending), folder, ns.batch, ns.jobs,
                               ["--pkg-path", root])
            pending = {p: r for p, r in rerun.items() if missing_package(r)}
            results = {**results, **rerun}
        report = Report()
        same = unresolved_ok = wrong = 0
        wrong_example = ""
        options = LoadOptions(packages=PackageIndex([root]))
        for path in sorted(refused):
            row = results[path]
            if "error" in row:
                continue
            tree = load_tree(path, options)
            compare(path, row, tree, report)
            theirs = {line: key for key, line in oracle_keys(row).items()}
            for t in baseline[path].transforms:
                if t.unresolved or not t.condition.always:
                    unresolved_ok += 1
                elif theirs.get(t.line) != our_key(t):
                    wrong += 1
                    wrong_example = wrong_example or f"{os.path.basename(path)}:{t.line}"
                else:
                    same += 1
    print(f"\nwith empty stand-ins for the {len(names)} packages it missed, roslaunch loads "
          f"{report.loaded} of the {len(refused)} files it refused for want of a package; "
          f"agreement {report.agree}/{report.loaded}")
    for kind, count in report.classes.most_common():
        print(f"  {count:6d}  {kind}\n          e.g. {report.examples[kind]}")
    print(f"  without the packages, our transforms there: {same} the same as roslaunch's "
          f"with them, {unresolved_ok} unresolved, "
          f"{wrong} resolved differently{' (e.g. ' + wrong_example + ')' if wrong else ''}")


def main(argv: Sequence[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--corpus", default=os.path.join(SHARED, "corpus"))
    parser.add_argument("--oracle", default=os.path.join(SHARED, "tools", "roslaunch_oracle.py"))
    parser.add_argument("--batch", type=int, default=250)
    parser.add_argument("--jobs", type=int, default=2)
    ns = parser.parse_args(argv)
    if not oracle_available():
        print(f"{SYSTEM_PYTHON} cannot import roslaunch (apt-get install python3-roslaunch)")
        return 2
    folder = os.path.join(ns.corpus, "files")
    names = sorted(os.listdir(folder))
    paths = [os.path.join(folder, n) for n in names]
    results = run_oracle(ns.oracle, paths, folder, ns.batch, ns.jobs)
    report = Report()
    options = LoadOptions(packages=PackageIndex([]))
    trees: list[LaunchTree] = []
    for path in paths:
        tree = load_tree(path, options)
        trees.append(tree)
        report.files += 1
        row = results.get(path)
        if row is None:
            report.disagree("oracle gave no answer", os.path.basename(path))
            continue
        compare(path, row, tree, report)
    print(f"files: {report.files}; roslaunch loads {report.loaded}, "
          f"refuses {report.files - report.loaded}")
    rate = 100.0 * report.agree / max(1, report.loaded)
    print(f"agreement on files roslaunch loads: {report.agree}/{report.loaded} ({rate:.2f}%)")
    print("disagreements (files per class):")
    for kind, count in report.classes.most_common():
        print(f"  {count:6d}  {kind}\n          e.g. {report.examples[kind]}")
    print("files roslaunch refuses, and what we report on them:")
    for kind, count in sorted(report.refused.items(), key=lambda kv: (-kv[1], kv[0])):
        example = report.refused_examples.get(kind)
        print(f"  {count:6d}  {kind}" + (f"\n          e.g. {example}" if example else ""))
    corpus_figures(trees)
    with_stub_packages(ns, folder, results, dict(zip(paths, trees)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
