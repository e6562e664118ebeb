"""Differential test on ros_comm's own test launch files: roslaunch against launch-linter.

Takes a git copy of ros/ros_comm (``--repo``; e.g. the one the search tool's ``fetch``
brings to ``/work/.mirror/ros+ros_comm/repo``), exports one commit into a temporary
folder (nothing of it is kept or committed), and loads every test launch file in it
(``*.launch``, ``*.xml``, ``*.test`` under a ``test`` folder, whose root element is
``<launch>``) twice, with ros_comm's packages as the only ``$(find)`` roots, no launch
arguments and an empty environment:

- with the real roslaunch, through the shared oracle tool
  (``../shared/tools/roslaunch_oracle.py`` under Debian's ``/usr/bin/python3`` with
  ``python3-roslaunch``, ``--safe-eval --stable-anon``);
- with launch-linter's ROS 1 loader, **probing every node**: the loader only records
  ``static_transform_publisher`` nodes, so for this script its package/type filter is
  replaced (in this process only) by one that accepts every node; everything else (names,
  namespaces, substitutions, includes, conditions, errors) is the loader as shipped.

For each file roslaunch loads, every node must agree: resolved name, namespace, package,
type, args, the file that holds the ``<node>`` and its line, with nothing unresolved or
conditional and no error from us. For each file roslaunch refuses, we must report an
error-level diagnostic (``parse_error``/``roslaunch_error``). Usage::

    python scripts/differential_ros_comm.py [--repo DIR] [--commit REV] [--verbose]
"""

from __future__ import annotations

import argparse
import io
import json
import os
import subprocess
import sys
import tarfile
import tempfile
from collections import Counter
from collections.abc import Sequence
from typing import Any, Tuple

from launch_linter.frontends import ros1
from launch_linter.frontends.dispatch import load_tree
from launch_linter.frontends.ros1 import LoadOptions, ns_join
from launch_linter.model.launch import LaunchTree
from launch_linter.workspace.packages import PackageIndex

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SHARED = os.path.join(os.path.dirname(REPO), "shared")
DEFAULT_MIRROR = "/work/.mirror/ros+ros_comm/repo"
SYSTEM_PYTHON = "/usr/bin/python3"
EXTENSIONS = (".launch", ".xml", ".test")

NodeKey = Tuple[Any, ...]


class _EveryType(str):
    """Compares unequal to nothing: the loader's type filter lets every node through."""

    __slots__ = ()

    def __ne__(self, other: object) -> bool:
        return False

    def __eq__(self, other: object) -> bool:
        return True

    def __hash__(self) -> int:
        return str.__hash__(self)


class _EveryPackage(Tuple[str, ...]):
    """Contains every package name."""

    def __contains__(self, item: object) -> bool:
        return True


def probe_every_node() -> None:
    """Make the ROS 1 loader record every node (this process only)."""
    ros1.STATIC_TF_TYPE = _EveryType(ros1.STATIC_TF_TYPE)  # type: ignore[misc]
    ros1.TF_PACKAGES = _EveryPackage(ros1.TF_PACKAGES)  # type: ignore[misc]


def export(repo: str, commit: str, target: str) -> None:
    archive = subprocess.run(["git", "-C", repo, "archive", "--format=tar", commit],
                             capture_output=True, check=True).stdout
    with tarfile.open(fileobj=io.BytesIO(archive)) as tar:
        # Plain files and folders inside the target only (no links, no absolute or '..').
        members = [m for m in tar.getmembers() if (m.isfile() or m.isdir())
                   and not os.path.isabs(m.name) and ".." not in m.name.split("/")]
        tar.extractall(target, members=members)


def test_launch_files(root: str) -> list[str]:
    found: list[str] = []
    for folder, _subdirs, files in os.walk(root):
        parts = os.path.relpath(folder, root).split(os.sep)
        if not any(part.startswith("test") for part in parts):
            continue
        for name in files:
            if not name.endswith(EXTENSIONS) or name in ("package.xml", "manifest.xml"):
                continue
            path = os.path.join(folder, name)
            with open(path, "rb") as handle:
                head = handle.read(4096)
            if b"<launch" in head:
                found.append(path)
    return sorted(found)


def run_oracle(tool: str, files: Sequence[str], root: str) -> dict[str, dict[str, Any]]:
    rows: dict[str, dict[str, Any]] = {}
    for start in range(0, len(files), 100):
        chunk = list(files[start:start + 100])
        done = subprocess.run(
            [SYSTEM_PYTHON, tool, "--safe-eval", "--stable-anon", "--pkg-path", root, *chunk],
            capture_output=True, text=True, cwd=root, env={}, check=False, timeout=3600,
        )
        for line in done.stdout.splitlines():
            if line.startswith("{"):
                row = json.loads(line)
                rows[row["file"]] = row
    return rows


def _wants_input(row: dict[str, Any]) -> bool:
    error = str(row.get("error", ""))
    return row.get("error_type") == "ResourceNotFound" or (
        "' arg to be set" in error or "' is not defined" in error
        or "environment variable '" in error
        or (error.startswith("address.") and "$(arg" in error)  # <machine address=$(arg)>
    )


def their_nodes(row: dict[str, Any]) -> list[NodeKey]:
    return sorted(
        (n["resolved_name"], n["namespace"], n["package"], n["type"], n["args"],
         os.path.abspath(n["file"]), n["line"])
        for n in row.get("nodes", [])
    )


def our_nodes(tree: LaunchTree) -> list[NodeKey]:
    return sorted(
        (ns_join(t.namespace, t.name) if t.name else None, t.namespace, t.package,
         t.executable, t.args, os.path.abspath(t.path), t.line)
        for t in tree.transforms
    )


def main(argv: Sequence[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--repo", default=DEFAULT_MIRROR)
    parser.add_argument("--commit", default="HEAD")
    parser.add_argument("--oracle", default=os.path.join(SHARED, "tools", "roslaunch_oracle.py"))
    parser.add_argument("--verbose", action="store_true")
    ns = parser.parse_args(argv)
    if not os.path.isdir(ns.repo):
        print(f"no ros_comm git copy at {ns.repo} (fetch github:ros/ros_comm)")
        return 2
    probe_every_node()
    commit = subprocess.run(["git", "-C", ns.repo, "rev-parse", ns.commit], capture_output=True,
                            text=True, check=True).stdout.strip()
    with tempfile.TemporaryDirectory() as root:
        export(ns.repo, commit, root)
        files = test_launch_files(root)
        rows = run_oracle(ns.oracle, files, root)
        options = LoadOptions(packages=PackageIndex([root]), display_path=os.path.abspath)
        loaded = agree = refused = refused_error = nodes = input_refused = 0
        classes: Counter[str] = Counter()
        examples: dict[str, str] = {}
        for path in files:
            row = rows.get(path)
            name = os.path.relpath(path, root)
            tree = load_tree(path, options)
            errors = [d for d in tree.problems if d.rule in ("parse_error", "roslaunch_error")]
            if row is None:
                classes["oracle gave no answer"] += 1
                examples.setdefault("oracle gave no answer", name)
                continue
            if "error" in row:
                if _wants_input(row):
                    # Not a fault of the file: the run gives no launch arguments, an empty
                    # environment and only ros_comm's packages. We leave such values
                    # unresolved (info), as the linter runs without them by design.
                    kind = "refused for want of an argument, variable or package"
                    input_refused += 1
                    classes[kind] += 1
                    examples.setdefault(kind, f"{name}: {str(row['error'])[:150]!r}")
                    continue
                refused += 1
                kind = "refused: we report an error" if errors else (
                    "refused: we report no error")
                refused_error += bool(errors)
                if ns.verbose and not errors:
                    print(f"  refused, no error from us: {name}")
                classes[kind] += 1
                examples.setdefault(kind, f"{name}: {str(row['error'])[:150]!r}")
                continue
            loaded += 1
            theirs, ours = their_nodes(row), our_nodes(tree)
            nodes += len(theirs)
            problems = []
            if theirs != ours:
                problems.append(("different nodes", f"{name}: only roslaunch "
                                 f"{sorted(set(theirs) - set(ours))[:2]}, only ours "
                                 f"{sorted(set(ours) - set(theirs))[:2]}"))
            if any(t.unresolved or not t.condition.always for t in tree.transforms):
                problems.append(("a node of ours is unresolved or conditional", name))
            if errors:
                problems.append(("we report an error on a file roslaunch loads",
                                 f"{name}:{errors[0].line} {errors[0].message[:120]}"))
            if not problems:
                agree += 1
            for kind, example in problems:
                classes[kind] += 1
                examples.setdefault(kind, example)
                if ns.verbose:
                    print(f"  {kind}: {example}")
    print(f"ros_comm {commit[:12]}: {len(files)} test launch files; roslaunch loads {loaded} "
          f"({nodes} nodes), refuses {refused} for a fault of the file and {input_refused} "
          f"for want of an input this run does not give")
    print(f"files roslaunch loads with every node identical and no error from us: "
          f"{agree}/{loaded}")
    print(f"files roslaunch refuses for a fault of the file on which we report an error: "
          f"{refused_error}/{refused}")
    for kind, count in classes.most_common():
        print(f"  {count:5d}  {kind}\n         e.g. {examples[kind]}")
    return 0 if agree == loaded and refused_error == refused else 1


if __name__ == "__main__":
    sys.exit(main())
