"""The package, its tests and scripts are written in Python that 3.8 runs as it stands.

ROS Noetic's Python is 3.8, and the standalone linter embeds the core verbatim, so a
construct newer than 3.8 anywhere is a bug even when the suite passes on 3.11. Two checks:
every file is read with the syntax tree of Python 3.8 and searched for the run-time
constructs that parse on 3.8 but fail there (``zip(strict=)``, ``str | None`` evaluated,
``dataclass(slots=)``, ...); and, when a Python 3.8 is installed, every core module is
imported by it with nothing but its standard library.
"""

from __future__ import annotations

import ast
import subprocess
import sys
import textwrap
from pathlib import Path
from typing import Iterator

import pytest

ROOT = Path(__file__).resolve().parent.parent
TREES = ("src", "tests", "scripts", "benchmarks")
EDGES = ("evaluation", "generate", "graph", "mining", "server")
"""Packages and modules that may import third-party ones; the rest is the stdlib-only core."""

GENERIC_BUILTINS = {"list", "tuple", "dict", "set", "frozenset", "type"}
NEWER_METHODS = {
    "removeprefix": "3.9", "removesuffix": "3.9", "is_relative_to": "3.9", "with_stem": "3.9",
    "bit_count": "3.10", "hardlink_to": "3.10",
}
NEWER_NAMES = {
    ("functools", "cache"): "3.9", ("itertools", "pairwise"): "3.10",
    ("datetime", "UTC"): "3.11", ("enum", "StrEnum"): "3.11", ("typing", "TypeAlias"): "3.10",
    ("typing", "Self"): "3.11", ("ast", "unparse"): "3.9", ("resources", "files"): "3.9",
    ("math", "lcm"): "3.9", ("dataclasses", "KW_ONLY"): "3.10",
}
NEWER_MODULES = {"tomllib": "3.11", "zoneinfo": "3.9", "graphlib": "3.9"}


INPUT_DATA = ROOT / "tests" / "faults"
"""Launch files copied from other projects (the real-fault benchmark): input, not our code,
left out as ruff leaves them out (pyproject ``extend-exclude``)."""


def python_files() -> list[Path]:
    return sorted(
        p for tree in TREES for p in (ROOT / tree).rglob("*.py") if INPUT_DATA not in p.parents
    )


def _union(node: ast.expr) -> bool:
    return isinstance(node, ast.BinOp) and isinstance(node.op, ast.BitOr)


def _runtime_generic(node: ast.expr, abc_names: set[str], type_names: set[str]) -> bool:
    """``list[int]``, ``Callable[...]`` of collections.abc, or ``A | B`` of types."""
    for inner in ast.walk(node):
        if isinstance(inner, ast.Subscript) and isinstance(inner.value, ast.Name) and (
            inner.value.id in GENERIC_BUILTINS or inner.value.id in abc_names
        ):
            return True
        if isinstance(inner, ast.BinOp) and isinstance(inner.op, ast.BitOr) and any(
            isinstance(side, ast.Subscript)
            or (isinstance(side, ast.Constant) and side.value is None)
            or (isinstance(side, ast.Name) and side.id in type_names)
            for side in (inner.left, inner.right)
        ):
            return True
    return False


def problems(source: str, name: str) -> Iterator[str]:
    """Where ``source`` uses what Python 3.8 cannot run."""
    try:
        tree = ast.parse(source, name, feature_version=(3, 8))
    except SyntaxError as exc:
        yield f"{name}:{exc.lineno}: not Python 3.8 syntax: {exc.msg}"
        return
    abc_names: set[str] = set()
    # Names that stand for types here: builtins, classes of this file, imported capitals.
    type_names = GENERIC_BUILTINS | {"str", "int", "float", "bool", "bytes", "object"}
    type_names = type_names | {n.name for n in ast.walk(tree) if isinstance(n, ast.ClassDef)}
    type_names = type_names | {
        a.asname or a.name for n in ast.walk(tree) if isinstance(n, ast.ImportFrom)
        for a in n.names if (a.asname or a.name)[:1].isupper()
    }
    has_future = False
    for node in ast.walk(tree):
        where = f"{name}:{getattr(node, 'lineno', 0)}"
        if isinstance(node, ast.ImportFrom):
            module = node.module or ""
            has_future |= module == "__future__" and any(
                a.name == "annotations" for a in node.names
            )
            if module == "collections.abc":
                abc_names |= {a.asname or a.name for a in node.names}
            for alias in node.names:
                newer = NEWER_NAMES.get((module.rpartition(".")[2], alias.name))
                if newer:
                    yield f"{where}: {module}.{alias.name} needs Python {newer}"
            if module in NEWER_MODULES:
                yield f"{where}: {module} needs Python {NEWER_MODULES[module]}"
        elif isinstance(node, ast.Import):
            for alias in node.names:
                if alias.name in NEWER_MODULES:
                    yield f"{where}: {alias.name} needs Python {NEWER_MODULES[alias.name]}"
        elif isinstance(node, ast.Attribute) and isinstance(node.value, ast.Name):
            newer = NEWER_NAMES.get((node.value.id, node.attr))
            if newer:
                yield f"{where}: {node.value.id}.{node.attr} needs Python {newer}"
        if isinstance(node, ast.Call):
            func = node.func
            called = func.id if isinstance(func, ast.Name) else (
                func.attr if isinstance(func, ast.Attribute) else ""
            )
            keywords = {k.arg for k in node.keywords}
            if called == "zip" and "strict" in keywords:
                yield f"{where}: zip(strict=) needs Python 3.10"
            if called == "dataclass" and keywords & {"slots", "kw_only", "match_args"}:
                yield f"{where}: dataclass(slots=/kw_only=/match_args=) needs Python 3.10"
            if isinstance(func, ast.Attribute) and func.attr in NEWER_METHODS:
                yield f"{where}: .{func.attr}() needs Python {NEWER_METHODS[func.attr]}"
            if called in ("isinstance", "issubclass") and len(node.args) == 2 and (
                _union(node.args[1])
            ):
                yield f"{where}: {called}() with 'X | Y' needs Python 3.10 (use a tuple)"
    # ``ast.Subscript.slice`` is wrapped in ``ast.Index`` on 3.8; subscript_index unwraps it.
    called = {id(n.func) for n in ast.walk(tree) if isinstance(n, ast.Call)}
    unwrapper = [n for n in ast.walk(tree)
                 if isinstance(n, ast.FunctionDef) and n.name == "subscript_index"]
    inside = {id(n) for f in unwrapper for n in ast.walk(f)}
    for node in ast.walk(tree):
        if isinstance(node, ast.Attribute) and node.attr == "slice" and (
            id(node) not in called and id(node) not in inside
        ):
            yield (
                f"{name}:{node.lineno}: .slice of a subscript is ast.Index on Python 3.8;"
                " use resolve.safe_eval.subscript_index"
            )
    # Values evaluated at import: module- and class-level assignments and base classes.
    scopes: list[ast.AST] = [tree, *(n for n in ast.walk(tree) if isinstance(n, ast.ClassDef))]
    for scope in scopes:
        if isinstance(scope, ast.ClassDef):
            for base in scope.bases:
                if _runtime_generic(base, abc_names, type_names):
                    yield f"{name}:{scope.lineno}: base class needs Python 3.9+ generics"
        for statement in getattr(scope, "body", []):
            value = statement.value if isinstance(statement, ast.Assign) else None
            if value is not None and _runtime_generic(value, abc_names, type_names):
                yield (
                    f"{name}:{statement.lineno}: a type evaluated at run time needs "
                    "Python 3.9+ (spell it with typing.List/Tuple/Union/Optional/Callable)"
                )
    if not has_future and any(
        isinstance(n, (ast.AnnAssign, ast.arg, ast.FunctionDef, ast.AsyncFunctionDef))
        and (getattr(n, "annotation", None) or getattr(n, "returns", None))
        for n in ast.walk(tree)
    ):
        yield f"{name}:1: annotations without 'from __future__ import annotations'"


def test_every_file_is_python_3_8() -> None:
    found = [p for path in python_files() for p in problems(
        path.read_text(encoding="utf-8"), str(path.relative_to(ROOT))
    )]
    assert found == []


@pytest.mark.parametrize(("source", "expected"), [
    ("match x:\n    case 1:\n        pass\n", "not Python 3.8 syntax"),
    pytest.param(
        "with (open(a) as f, open(b) as g):\n    pass\n", "not Python 3.8 syntax",
        marks=pytest.mark.skipif(
            sys.version_info >= (3, 13),
            reason="Python 3.13's parser accepts parenthesised context managers whatever"
            " feature_version says; the Python 3.8 leg of CI still rejects them",
        ),
    ),
    ("for a, b in zip(x, y, strict=True):\n    pass\n", "zip(strict=)"),
    ("@dataclass(frozen=True, slots=True)\nclass A:\n    x = 1\n", "dataclass(slots="),
    ("y = x.removeprefix('./')\n", ".removeprefix() needs Python 3.9"),
    ("ok = isinstance(x, int | float)\n", "isinstance() with 'X | Y'"),
    ("Key = tuple[str, ...]\n", "a type evaluated at run time"),
    ("Key = str | None\n", "a type evaluated at run time"),
    ("class A:\n    pass\nclass B:\n    pass\nAB = A | B\n", "a type evaluated at run time"),
    ("from collections.abc import Callable\nF = Callable[[int], int]\n", "evaluated at run"),
    ("from functools import cache\n", "functools.cache needs Python 3.9"),
    ("import datetime\nnow = datetime.UTC\n", "datetime.UTC needs Python 3.11"),
    ("import tomllib\n", "tomllib needs Python 3.11"),
    ("key = node.slice\n", "use resolve.safe_eval.subscript_index"),
    ("def f(x: list[int]) -> None:\n    pass\n", "without 'from __future__"),
])
def test_what_python_3_8_cannot_run_is_found(source: str, expected: str) -> None:
    found = list(problems(source, "m.py"))
    assert any(expected in p for p in found), found


@pytest.mark.parametrize("source", [
    "from __future__ import annotations\ndef f(x: list[int] | None) -> tuple[int, ...]:\n"
    "    return ()\n",
    "from typing import Optional, Tuple\nKey = Tuple[Optional[str], ...]\n",
    "ok = isinstance(x, (int, float))\nflags = a | b\n",
    "for a, b in zip(x, y):\n    pass\n",
    "@dataclass(frozen=True)\nclass A:\n    x = 1\n",
])
def test_what_python_3_8_runs_passes(source: str) -> None:
    assert list(problems(source, "m.py")) == []


def _python38() -> str | None:
    for path in sorted((Path.home() / ".pyenv" / "versions").glob("3.8.*/bin/python3.8")):
        return str(path)
    return None


@pytest.mark.skipif(_python38() is None, reason="no Python 3.8 found under ~/.pyenv/versions")
def test_python_3_8_imports_every_core_module_with_its_standard_library_alone() -> None:
    script = textwrap.dedent(f"""
        import importlib, pkgutil, sys
        sys.path.insert(0, {str(ROOT / "src")!r})
        import launch_linter
        edges = tuple("launch_linter." + e for e in {EDGES!r})
        for module in pkgutil.walk_packages(launch_linter.__path__, "launch_linter."):
            if module.name.startswith(edges) or module.name == "launch_linter.__main__":
                continue
            importlib.import_module(module.name)
        print("imported", len(sys.modules))
    """)
    python = _python38()
    assert python is not None
    # -S: no site-packages, so a third-party import in the core fails here.
    done = subprocess.run(
        [python, "-S", "-c", script], capture_output=True, text=True, timeout=120, check=False
    )
    assert done.returncode == 0, done.stderr
    assert done.stdout.startswith("imported")
