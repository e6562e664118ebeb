"""The layer table of docs/ARCHITECTURE.md holds for every import, and no import circle.

Imports are read from the source (ast), never executed, so a module's lazy imports inside
functions count too: a lazy import still ties the two modules together.
"""

from __future__ import annotations

import ast
import re
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parent.parent
PACKAGE_DIR = REPO / "src" / "launch_linter"
ARCHITECTURE = REPO / "docs" / "ARCHITECTURE.md"
ROOT = "launch_linter"


def _layer_table() -> tuple[dict[str, str], dict[str, set[str]]]:
    """(module path pattern -> layer, layer -> layers it may import) from the doc."""
    text = ARCHITECTURE.read_text(encoding="utf-8")
    section = text.split("## Layers", 1)[1].split("\n## ", 1)[0]
    rows = [line for line in section.splitlines() if line.startswith("|")]
    assert rows[0].replace(" ", "") == "|layer|modules|mayimport|", rows[0]
    patterns: dict[str, str] = {}
    allowed: dict[str, set[str]] = {}
    for row in rows[2:]:
        layer, modules, may = (cell.strip() for cell in row.strip("|").split("|"))
        for pattern in re.findall(r"`([^`]+)`", modules):
            assert pattern not in patterns, f"{pattern} is in two rows"
            patterns[pattern] = layer
        allowed[layer] = {m.strip() for m in may.split(",")} - {"stdlib"}
    layers = set(allowed)
    for layer, may in allowed.items():
        if may == {"anything"}:
            allowed[layer] = set(layers)
        unknown = allowed[layer] - layers
        assert not unknown, f"row {layer!r} names unknown layers {unknown}"
        allowed[layer].add(layer)
    return patterns, allowed


def _module_files() -> dict[str, Path]:
    """Dotted module name -> file, for every module of the package."""
    modules: dict[str, Path] = {}
    for path in sorted(PACKAGE_DIR.rglob("*.py")):
        parts = list(path.relative_to(PACKAGE_DIR).with_suffix("").parts)
        if parts[-1] == "__init__":
            parts.pop()
        modules[".".join([ROOT, *parts])] = path
    return modules


def _imports(name: str, path: Path, modules: dict[str, Path]) -> set[str]:
    """The package's modules that ``name`` imports (at any depth of its syntax tree)."""
    is_package = path.name == "__init__.py"
    found: set[str] = set()

    def resolve(target: str) -> None:
        # The longest prefix that is a module: ``a.b.C`` is module ``a.b``'s name C.
        parts = target.split(".")
        for end in range(len(parts), 0, -1):
            candidate = ".".join(parts[:end])
            if candidate in modules:
                if candidate != name:
                    found.add(candidate)
                return

    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.Import):
            for alias in node.names:
                if alias.name.split(".")[0] == ROOT:
                    resolve(alias.name)
        elif isinstance(node, ast.ImportFrom):
            base = node.module or ""
            if node.level:
                package = name if is_package else name.rsplit(".", 1)[0]
                package = ".".join(package.split(".")[: len(package.split(".")) - node.level + 1])
                base = f"{package}.{base}" if base else package
            if base.split(".")[0] != ROOT:
                continue
            for alias in node.names:
                resolve(f"{base}.{alias.name}")
    return found


def _layer_of(path: Path, patterns: dict[str, str]) -> str | None:
    relative = path.relative_to(PACKAGE_DIR).as_posix()
    best: tuple[int, str] | None = None
    for pattern, layer in patterns.items():
        hit = relative == pattern or (pattern.endswith("/") and relative.startswith(pattern))
        if hit and (best is None or len(pattern) > best[0]):
            best = (len(pattern), layer)
    return best[1] if best else None


MODULES = _module_files()
GRAPH = {name: _imports(name, path, MODULES) for name, path in MODULES.items()}


def test_every_module_has_a_layer() -> None:
    patterns, _ = _layer_table()
    missing = [name for name, path in MODULES.items() if _layer_of(path, patterns) is None]
    assert not missing, f"add these modules to the layer table of {ARCHITECTURE.name}: {missing}"


def _violations(graph: dict[str, set[str]]) -> list[str]:
    patterns, allowed = _layer_table()
    wrong = []
    for name, targets in sorted(graph.items()):
        layer = _layer_of(MODULES[name], patterns)
        assert layer is not None
        for target in sorted(targets):
            target_layer = _layer_of(MODULES[target], patterns)
            if target_layer not in allowed[layer]:
                wrong.append(f"{name} ({layer}) imports {target} ({target_layer})")
    return wrong


def test_imports_follow_the_layer_table() -> None:
    wrong = _violations(GRAPH)
    assert not wrong, "\n".join(wrong)


def test_the_table_check_catches_a_wrong_import() -> None:
    # The workspace may import only model and resolve: a front-end module is reported.
    graph = {"launch_linter.workspace.packages": {"launch_linter.frontends.ros1"}}
    assert _violations(graph) == [
        "launch_linter.workspace.packages (workspace) imports launch_linter.frontends.ros1 "
        "(frontends)"
    ]


def _cycles(graph: dict[str, set[str]]) -> list[list[str]]:
    """Strongly connected components of more than one module (Tarjan, iterative)."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on_stack: set[str] = set()
    found: list[list[str]] = []
    counter = 0
    for start in sorted(graph):
        if start in index:
            continue
        work = [(start, iter(sorted(graph[start])))]
        index[start] = low[start] = counter
        counter += 1
        stack.append(start)
        on_stack.add(start)
        while work:
            node, children = work[-1]
            child = next(children, None)
            if child is not None:
                if child not in index:
                    index[child] = low[child] = counter
                    counter += 1
                    stack.append(child)
                    on_stack.add(child)
                    work.append((child, iter(sorted(graph[child]))))
                elif child in on_stack:
                    low[node] = min(low[node], index[child])
                continue
            work.pop()
            if work:
                parent = work[-1][0]
                low[parent] = min(low[parent], low[node])
            if low[node] == index[node]:
                component = []
                while True:
                    member = stack.pop()
                    on_stack.discard(member)
                    component.append(member)
                    if member == node:
                        break
                if len(component) > 1:
                    found.append(sorted(component))
    return found


def test_no_import_circle() -> None:
    assert _cycles(GRAPH) == []


@pytest.mark.parametrize(("graph", "expected"), [
    ({"a": {"b"}, "b": {"c"}, "c": {"a"}, "d": {"a"}}, [["a", "b", "c"]]),
    ({"a": {"b"}, "b": set()}, []),
])
def test_the_circle_finder_finds_circles(
    graph: dict[str, set[str]], expected: list[list[str]]
) -> None:
    assert _cycles(graph) == expected
