"""Which of the package's modules a standalone linter carries, read from the package itself.

The set is found, not listed: starting from the command line (``launch_linter.cli``, for
the ``check`` command) the imports of each module are followed through the package's own
source files. An import at module level must be satisfiable from the standard library of
Python 3.8; one inside a function (a lazy import) is followed when
the module it reaches can be embedded, and otherwise noted as unavailable in the
standalone linter. The edge packages (mining, generate, evaluation, graph) are never
embedded; ``beliefs_files`` is, but the standalone linter answers its reads of the
package's beliefs files from the embedded tables.

Modules are embedded verbatim: the core is written so that Python 3.8 runs it as it stands
(``tests/test_python38.py`` keeps it so), hence a standalone linter carries the core files
exactly as released and their digests match the package's files.
"""

from __future__ import annotations

import ast
import hashlib
import importlib.util
import sys
import sysconfig
from collections.abc import Iterable, Iterator
from dataclasses import dataclass
from pathlib import Path

PACKAGE = "launch_linter"
ROOTS = ("launch_linter.cli", "launch_linter.beliefs_files")
EXCLUDED = (
    "launch_linter.__main__",
    "launch_linter.evaluation",
    "launch_linter.generate",
    "launch_linter.graph",
    "launch_linter.measured",
    "launch_linter.mining",
)
"""Edges reached only from commands other than ``check``."""
MODULES_NEWER = {"graphlib": "3.9", "zoneinfo": "3.9", "tomllib": "3.11"}
"""Standard modules that Python 3.8, the oldest the standalone linter runs on, lacks."""


def _in_stdlib(top: str) -> bool:
    """Whether ``top`` is a standard module of this Python (and of Python 3.8)."""
    if top in MODULES_NEWER:
        return False
    if sys.version_info >= (3, 10):
        return top in sys.stdlib_module_names
    if top in sys.builtin_module_names:
        return True
    # Before 3.10 there is no list: a module found under the standard library's folder
    # (and not in its site-packages) is standard. find_spec of a top-level name runs nothing.
    spec = importlib.util.find_spec(top)
    origin = spec.origin if spec is not None else None
    if origin is None:
        return False
    paths = sysconfig.get_paths()
    stdlib = (paths["stdlib"], paths["platstdlib"])
    site = (paths["purelib"], paths["platlib"])
    return origin.startswith(stdlib) and not origin.startswith(site)


class EmbedError(ValueError):
    """The package's modules cannot be embedded; ``problems`` say where and why."""

    def __init__(self, problems: list[str]) -> None:
        super().__init__(
            "cannot build a standalone linter from this package:\n  " + "\n  ".join(problems)
        )
        self.problems = problems


@dataclass(frozen=True)
class Module:
    """One embedded module: its import name, file (relative, ``/``-separated), source."""

    name: str
    path: str
    is_package: bool
    source: str
    """The package file's text, verbatim."""
    sha256: str
    """Of that text, so that a reviewer can match it to a release."""


@dataclass(frozen=True)
class Embedding:
    modules: tuple[Module, ...]
    """Sorted by name."""
    notes: tuple[str, ...]
    """What the standalone linter cannot do that the package can (lazy imports left out)."""

    @property
    def sha256(self) -> str:
        """One digest of every embedded module's name and text."""
        return sources_sha256(sorted((m.name, m.source) for m in self.modules))


@dataclass(frozen=True)
class _Import:
    target: str
    line: int
    lazy: bool
    """Inside a function (runs only when called), or guarded by ``except ImportError``."""


def sources_sha256(modules: Iterable[tuple[str, str]]) -> str:
    """The digest of :attr:`Embedding.sha256`: (name, source) pairs in name order."""
    digest = hashlib.sha256()
    for name, source in modules:
        digest.update(name.encode("utf-8") + b"\0")
        digest.update(source.encode("utf-8") + b"\0")
    return digest.hexdigest()


def _is_under(name: str, prefixes: Iterable[str]) -> bool:
    return any(name == p or name.startswith(p + ".") for p in prefixes)


class _Package:
    """The package's source files under ``root`` (the folder holding ``launch_linter``)."""

    def __init__(self, root: Path) -> None:
        self.root = root
        self._sources: dict[str, str] = {}

    def file_of(self, name: str) -> tuple[Path, bool] | None:
        base = self.root.joinpath(*name.split("."))
        if (base / "__init__.py").is_file():
            return base / "__init__.py", True
        if base.with_suffix(".py").is_file():
            return base.with_suffix(".py"), False
        return None

    def source(self, name: str) -> str:
        if name not in self._sources:
            found = self.file_of(name)
            if found is None:
                raise EmbedError([f"module {name} has no source file under {self.root}"])
            self._sources[name] = found[0].read_text(encoding="utf-8")
        return self._sources[name]

    def relative(self, name: str) -> str:
        found = self.file_of(name)
        assert found is not None
        return found[0].relative_to(self.root).as_posix()


def _is_type_checking(test: ast.expr) -> bool:
    return (isinstance(test, ast.Name) and test.id == "TYPE_CHECKING") or (
        isinstance(test, ast.Attribute) and test.attr == "TYPE_CHECKING"
    )


def _guarded(handlers: list[ast.ExceptHandler]) -> bool:
    def names(node: ast.expr | None) -> Iterator[str]:
        if isinstance(node, ast.Name):
            yield node.id
        elif isinstance(node, ast.Tuple):
            for element in node.elts:
                yield from names(element)

    caught = ("ImportError", "ModuleNotFoundError", "Exception")
    return any(n in caught for h in handlers for n in names(h.type))


def _imports(source: str, name: str, is_package: bool, package: _Package) -> Iterator[_Import]:
    """Every import in ``source``, with absolute targets (``x.y`` for ``from x import y``
    when ``x.y`` is a module of the package)."""
    tree = ast.parse(source)
    base = name if is_package else name.rpartition(".")[0]

    def visit(node: ast.AST, lazy: bool) -> Iterator[_Import]:
        if isinstance(node, ast.If) and _is_type_checking(node.test):
            for statement in node.orelse:
                yield from visit(statement, lazy)
            return
        if isinstance(node, ast.Try):
            guarded = lazy or _guarded(node.handlers)
            for statement in node.body:
                yield from visit(statement, guarded)
            for part in (*node.handlers, *node.orelse, *node.finalbody):
                yield from visit(part, lazy)
            return
        if isinstance(node, ast.Import):
            for alias in node.names:
                yield _Import(alias.name, node.lineno, lazy)
            return
        if isinstance(node, ast.ImportFrom):
            module = node.module or ""
            if node.level:
                parts = base.split(".")
                anchor = ".".join(parts[: len(parts) - node.level + 1])
                module = f"{anchor}.{module}" if module else anchor
            yield _Import(module, node.lineno, lazy)
            if _is_under(module, (PACKAGE,)):
                for alias in node.names:
                    candidate = f"{module}.{alias.name}"
                    if package.file_of(candidate) is not None:
                        yield _Import(candidate, node.lineno, lazy)
            return
        inner = lazy or isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.Lambda))
        for child in ast.iter_child_nodes(node):
            yield from visit(child, inner)

    yield from visit(tree, False)


def _parents(name: str) -> list[str]:
    parts = name.split(".")
    return [".".join(parts[:i]) for i in range(1, len(parts))]


class _Closure:
    def __init__(self, package: _Package) -> None:
        self.package = package
        self.imports: dict[str, list[_Import]] = {}

    def imports_of(self, name: str) -> list[_Import]:
        if name not in self.imports:
            found = self.package.file_of(name)
            assert found is not None
            self.imports[name] = list(
                _imports(self.package.source(name), name, found[1], self.package)
            )
        return self.imports[name]

    def eager(self, start: str) -> tuple[set[str], list[str]]:
        """Modules that importing ``start`` imports, and why any of them cannot be embedded."""
        seen: set[str] = set()
        problems: list[str] = []
        todo = [start]
        while todo:
            name = todo.pop()
            if name in seen:
                continue
            seen.add(name)
            if self.package.file_of(name) is None:
                problems.append(f"{name}: no such module in the package")
                continue
            todo.extend(p for p in _parents(name) if p not in seen)
            where = self.package.relative(name)
            for item in self.imports_of(name):
                if item.lazy:
                    continue
                problem = self._eager_problem(item)
                if problem is not None:
                    problems.append(f"{where}:{item.line}: {problem}")
                elif _is_under(item.target, (PACKAGE,)):
                    todo.append(item.target)
        return seen, problems

    def _eager_problem(self, item: _Import) -> str | None:
        top = item.target.split(".")[0]
        if top == PACKAGE:
            if _is_under(item.target, EXCLUDED):
                return f"imports {item.target}, which the standalone linter does not carry"
            return None
        if top == "__future__" or _in_stdlib(top):
            return None
        if top in MODULES_NEWER:
            return f"imports {top}, new in Python {MODULES_NEWER[top]}"
        return f"imports {top}, which is not in the standard library"


def collect(root: Path) -> Embedding:
    """The modules a standalone linter carries, from the package sources under ``root``."""
    package = _Package(root)
    closure = _Closure(package)
    chosen: set[str] = set()
    problems: list[str] = []
    for start in ROOTS:
        found, trouble = closure.eager(start)
        chosen |= found
        problems.extend(trouble)
    notes: list[str] = []
    pending = True
    while pending:
        pending = False
        for name in sorted(chosen):
            for item in closure.imports_of(name):
                if not item.lazy or item.target in chosen:
                    continue
                where = f"{package.relative(name)}:{item.line}"
                top = item.target.split(".")[0]
                if top != PACKAGE:
                    if top != "__future__" and not _in_stdlib(top):
                        notes.append(f"{where}: needs {top} (not in the standard library)")
                    continue
                if _is_under(item.target, EXCLUDED):
                    continue
                found, trouble = closure.eager(item.target)
                if trouble:
                    notes.append(f"{where}: {item.target} left out: " + "; ".join(trouble))
                    continue
                chosen |= found
                pending = True
    if problems:
        raise EmbedError(sorted(set(problems)))
    return _verbatim(package, sorted(chosen), tuple(sorted(set(notes))))


def _verbatim(package: _Package, names: list[str], notes: tuple[str, ...]) -> Embedding:
    modules: list[Module] = []
    for name in names:
        source = package.source(name)
        found = package.file_of(name)
        assert found is not None
        digest = hashlib.sha256(source.encode("utf-8")).hexdigest()
        modules.append(Module(name, package.relative(name), found[1], source, digest))
    return Embedding(tuple(modules), notes)


def package_root() -> Path:
    """The folder holding the installed ``launch_linter`` package's source."""
    import launch_linter

    return Path(launch_linter.__file__).resolve().parent.parent
