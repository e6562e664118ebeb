"""What an ament_python package installs into ``share/<package>``: ``data_files``.

``setup.py`` is parsed with :mod:`ast` and never run. Its module-level assignments
(``package_name = 'x'``, ``data_files = [...]``, ``data_files += [...]``,
``data_files.append(...)``/``extend(...)``) and the ``data_files=`` keyword of the
``setup(...)`` call are evaluated by a small interpreter of constant expressions: text,
lists and tuples, ``+``, f-strings, ``%``-free ``str.format``-free joins:
``os.path.join``/``dirname``/``basename``, and ``glob(...)``/``glob.glob(...)``, which it
matches against the package's files (a bounded walk) instead of the disk's glob. A list
comprehension over such a list is evaluated too. Anything else makes the layout
incomplete. ``setup.cfg``'s ``[options.data_files]`` is read with :mod:`configparser`.

Each ``(destination, [files])`` entry installs every file at
``destination/<basename>``, as setuptools does.
"""

from __future__ import annotations

import ast
import configparser
import contextlib
import os
import posixpath
import re
from typing import NamedTuple

from launch_linter.resolve import reads
from launch_linter.workspace.discovery import walk
from launch_linter.workspace.install_rules import InstallRule, Layout, share_relative

MAX_SETUP_BYTES = 1024 * 1024
MAX_EVALUATIONS = 20_000
MAX_ITEMS = 20_000
MAX_PACKAGE_FILES = 20_000
MAX_TEXT = 4096


class _Unknown(Exception):
    """A value the interpreter does not know; its text says why."""


class _Evaluator:
    def __init__(self, package_dir: str, names: dict[str, ast.expr]) -> None:
        self.package_dir = package_dir
        self.names = names
        self.steps = 0
        self._files: list[str] | None = None
        self._resolving: set[str] = set()

    def value(self, node: ast.AST, local: dict[str, object] | None = None) -> object:
        self.steps += 1
        if self.steps > MAX_EVALUATIONS:
            raise _Unknown("too much work")
        if isinstance(node, ast.Constant) and isinstance(node.value, str):
            return node.value
        if isinstance(node, ast.Name):
            return self._name(node.id, local)
        if isinstance(node, (ast.List, ast.Tuple)):
            items: list[object] = []
            for element in node.elts:
                if isinstance(element, ast.Starred):
                    items.extend(self._sequence(self.value(element.value, local)))
                else:
                    items.append(self.value(element, local))
            return items if isinstance(node, ast.List) else tuple(items)
        if isinstance(node, ast.BinOp) and isinstance(node.op, ast.Add):
            return self._add(self.value(node.left, local), self.value(node.right, local))
        if isinstance(node, ast.JoinedStr):
            return self._text("".join(self._piece(v, local) for v in node.values))
        if isinstance(node, ast.Call):
            return self._call(node, local)
        if isinstance(node, ast.ListComp):
            return self._comprehension(node, local)
        raise _Unknown(f"{type(node).__name__} is not evaluated")

    def _name(self, name: str, local: dict[str, object] | None) -> object:
        if local is not None and name in local:
            return local[name]
        if name not in self.names or name in self._resolving:
            raise _Unknown(f"name '{name}' is not known")
        self._resolving.add(name)
        try:
            return self.value(self.names[name])
        finally:
            self._resolving.discard(name)

    def _piece(self, node: ast.AST, local: dict[str, object] | None) -> str:
        if isinstance(node, ast.FormattedValue):
            if node.format_spec is not None or node.conversion not in (-1, None):
                raise _Unknown("formatted value")
            node = node.value
        found = self.value(node, local)
        if not isinstance(found, str):
            raise _Unknown("an f-string of something not text")
        return found

    @staticmethod
    def _text(text: str) -> str:
        if len(text) > MAX_TEXT:
            raise _Unknown("text too long")
        return text

    def _add(self, left: object, right: object) -> object:
        if isinstance(left, str) and isinstance(right, str):
            return self._text(left + right)
        if isinstance(left, (list, tuple)) and isinstance(right, (list, tuple)):
            if len(left) + len(right) > MAX_ITEMS:
                raise _Unknown("too many items")
            return [*left, *right] if isinstance(left, list) else (*left, *right)
        raise _Unknown("+ of values of different kinds")

    @staticmethod
    def _sequence(found: object) -> list[object]:
        if not isinstance(found, (list, tuple)):
            raise _Unknown("not a list")
        return list(found)

    def _call(self, node: ast.Call, local: dict[str, object] | None) -> object:
        function = _dotted(node.func)
        args = [self.value(a, local) for a in node.args]
        if not all(isinstance(a, str) for a in args):
            raise _Unknown(f"{function}() of values that are not text")
        texts = [a for a in args if isinstance(a, str)]
        if function in ("os.path.join", "path.join", "join") and texts:
            return self._text(posixpath.join(*texts))
        if function in ("os.path.dirname", "path.dirname", "dirname") and len(texts) == 1:
            return posixpath.dirname(texts[0])
        if function in ("os.path.basename", "path.basename", "basename") and len(texts) == 1:
            return posixpath.basename(texts[0])
        if function in ("glob", "glob.glob") and len(texts) == 1:
            recursive = any(k.arg == "recursive" and isinstance(k.value, ast.Constant)
                            and k.value.value is True for k in node.keywords)
            return self.glob(texts[0], recursive)
        if function == "str" and len(texts) == 1:
            return texts[0]
        raise _Unknown(f"{function}() is not evaluated")

    def _comprehension(self, node: ast.ListComp, local: dict[str, object] | None
                       ) -> list[object]:
        if len(node.generators) != 1 or node.generators[0].ifs or node.generators[0].is_async:
            raise _Unknown("a comprehension with conditions or several loops")
        generator = node.generators[0]
        if not isinstance(generator.target, ast.Name):
            raise _Unknown("a comprehension over unpacked items")
        out: list[object] = []
        for item in self._sequence(self.value(generator.iter, local)):
            scope = dict(local or {})
            scope[generator.target.id] = item
            out.append(self.value(node.elt, scope))
        return out

    def glob(self, pattern: str, recursive: bool) -> list[str]:
        """The package files ``glob(pattern)`` would list, run from the package folder."""
        cleaned = pattern[2:] if pattern.startswith("./") else pattern
        if os.path.isabs(cleaned) or ".." in cleaned.split("/"):
            raise _Unknown(f"glob({pattern!r}) outside the package")
        matcher = re.compile(_glob_regex(cleaned, recursive))
        return [f for f in self.files() if matcher.fullmatch(f)]

    def files(self) -> list[str]:
        if self._files is None:
            self._files = package_files(self.package_dir)
        return self._files


def _glob_regex(pattern: str, recursive: bool) -> str:
    """A regular expression for Python's ``glob`` pattern (``*`` within a name, ``**``
    across folders when recursive, ``[...]`` classes, hidden names not matched)."""
    out: list[str] = []
    index = 0
    while index < len(pattern):
        char = pattern[index]
        if recursive and pattern.startswith("**/", index):
            out.append(r"(?:[^/.][^/]*/)*")
            index += 3
            continue
        if recursive and pattern.startswith("**", index):
            out.append(r"(?:[^/.][^/]*(?:/[^/.][^/]*)*)?")
            index += 2
            continue
        if char in "*?[" and (index == 0 or pattern[index - 1] == "/"):
            out.append(r"(?!\.)")  # like glob, a wildcard does not match a hidden name
        if char == "*":
            out.append(r"[^/]*")
        elif char == "?":
            out.append(r"[^/]")
        elif char == "[":
            end = pattern.find("]", index + 2)
            if end < 0:
                out.append(re.escape(char))
            else:
                body = pattern[index + 1:end]
                negate = body.startswith("!")
                body = body[1:] if negate else body
                out.append("[" + ("^" if negate else "") + body.replace("\\", "\\\\") + "]")
                index = end
        else:
            out.append(re.escape(char))
        index += 1
    return "".join(out)


def package_files(package_dir: str) -> list[str]:
    """The files of a package, ``/``-separated and relative to it, sorted; bounded."""
    found: list[str] = []
    for directory, subdirs, files in walk(package_dir):
        with contextlib.suppress(OSError):  # the results cache: a file added changes them
            reads.note_folder(directory, os.stat(directory), subdirs, files, reads.EVERY_FILE)
        subdirs[:] = sorted(d for d in subdirs if not d.startswith("."))
        relative = os.path.relpath(directory, package_dir).replace(os.sep, "/")
        for name in sorted(files):
            found.append(name if relative == "." else relative + "/" + name)
            if len(found) >= MAX_PACKAGE_FILES:
                return found
    return found


def _dotted(node: ast.AST) -> str:
    if isinstance(node, ast.Name):
        return node.id
    if isinstance(node, ast.Attribute):
        return _dotted(node.value) + "." + node.attr
    return "?"


class _Setup(NamedTuple):
    names: dict[str, ast.expr]
    """Module-level assignments (``+=``, ``append`` and ``extend`` folded in)."""
    keywords: list[ast.keyword]
    """The keywords of the top-level ``setup(...)`` calls (``arg`` None: ``**kwargs``)."""
    blocks: list[ast.stmt]
    """Top-level blocks (``for``, ``if``, ...): what they change is not followed."""
    called: bool


def _read_setup(source: bytes) -> _Setup | None:
    """The top level of a ``setup.py`` (its bytes), None when it does not parse."""
    try:
        module = ast.parse(source[:MAX_SETUP_BYTES])
    except (SyntaxError, ValueError, RecursionError, MemoryError):
        return None
    setup = _Setup({}, [], [], False)
    names = setup.names
    for statement in module.body:
        if isinstance(statement, ast.Assign) and len(statement.targets) == 1 and isinstance(
                statement.targets[0], ast.Name):
            names[statement.targets[0].id] = statement.value
        elif isinstance(statement, ast.AugAssign) and isinstance(statement.target, ast.Name) \
                and isinstance(statement.op, ast.Add) and statement.target.id in names:
            names[statement.target.id] = ast.BinOp(names[statement.target.id], ast.Add(),
                                                   statement.value)
        elif isinstance(statement, ast.Expr) and isinstance(statement.value, ast.Call):
            call = statement.value
            function = _dotted(call.func)
            owner, _, method = function.rpartition(".")
            if method in ("append", "extend") and owner in names and len(call.args) == 1:
                added = call.args[0] if method == "extend" else ast.List([call.args[0]],
                                                                         ast.Load())
                names[owner] = ast.BinOp(names[owner], ast.Add(), added)
            elif method == "setup" or function == "setup":
                setup = setup._replace(called=True)
                setup.keywords.extend(call.keywords)
        elif isinstance(statement, (ast.For, ast.While, ast.If, ast.With, ast.Try)):
            setup.blocks.append(statement)
    return setup


def _changed_in_block(setup: _Setup, name: str) -> int | None:
    """The line of a top-level block that mentions ``name``, if any."""
    return next((b.lineno for b in setup.blocks if name in ast.dump(b)), None)


def read_setup_py(source: bytes, package_dir: str, package: str, origin: str) -> Layout:
    """The ``data_files`` of a ``setup.py`` (its bytes) into ``share/<package>``."""
    layout = Layout()
    setup = _read_setup(source)
    if setup is None:
        layout.unread(f"{origin}: not parsed")
        return layout
    line = _changed_in_block(setup, "data_files")
    if line is not None:
        layout.unread(f"{origin}:{line}: data_files changed in a block")
    if not setup.called:
        layout.unread(f"{origin}: no setup() call at the top level")
    evaluator = _Evaluator(package_dir, setup.names)
    for keyword in setup.keywords:
        if keyword.arg == "data_files":
            _add_entries(layout, evaluator, keyword.value, package, origin)
    return layout


def setup_call(source: bytes, package_dir: str
               ) -> str | tuple[dict[str | None, ast.expr], object]:
    """The keywords of a ``setup.py``'s ``setup(...)`` call (``None``: a ``**kwargs``),
    with what evaluates their values (:func:`setup_value`); or why they are not known."""
    setup = _read_setup(source)
    if setup is None:
        return "not parsed"
    if not setup.called:
        return "no setup() call at the top level"
    for name in ("entry_points", "scripts"):
        line = _changed_in_block(setup, name)
        if line is not None:
            return f"line {line}: {name} changed in a block"
    keywords: dict[str | None, ast.expr] = {}
    for keyword in setup.keywords:
        value = keyword.value
        if isinstance(value, ast.Name) and value.id in setup.names:
            value = setup.names[value.id]
        keywords[keyword.arg] = value
    return keywords, _Evaluator(package_dir, setup.names)


def setup_value(evaluator: object, node: ast.expr) -> object:
    """``node`` evaluated as :func:`read_setup_py` evaluates ``data_files`` (text, lists,
    ``+``, f-strings, ``os.path`` joins, ``glob``); the reason as text when unknown."""
    assert isinstance(evaluator, _Evaluator)
    try:
        return evaluator.value(node)
    except (_Unknown, RecursionError) as exc:
        return str(exc) or "too deep"


def _add_entries(layout: Layout, evaluator: _Evaluator, node: ast.expr, package: str,
                 origin: str) -> None:
    try:
        found = evaluator.value(node)
    except (_Unknown, RecursionError) as exc:
        layout.unread(f"{origin}: data_files not read ({exc or 'too deep'})")
        return
    if not isinstance(found, (list, tuple)):
        layout.unread(f"{origin}: data_files is not a list")
        return
    for item in found:
        if (not isinstance(item, (list, tuple)) or len(item) != 2
                or not isinstance(item[0], str) or not isinstance(item[1], (list, tuple))):
            layout.unread(f"{origin}: a data_files entry is not (destination, [files])")
            continue
        _add_files(layout, item[0], [f for f in item[1] if isinstance(f, str)], package, origin)


def _add_files(layout: Layout, destination: str, files: list[str], package: str,
               origin: str) -> None:
    under = share_relative(destination, package)
    if under is None:
        return
    for file in files:
        source = posixpath.normpath(file[2:] if file.startswith("./") else file)
        target = posixpath.basename(source) if not under else under + "/" + posixpath.basename(
            source)
        layout.add(InstallRule("file", source, target, origin=origin))


def read_setup_cfg(text: str, package_dir: str, package: str, origin: str) -> Layout:
    """``[options.data_files]`` of a ``setup.cfg``: ``destination = file, glob, ...``."""
    layout = Layout()
    parser = configparser.ConfigParser(interpolation=None)
    parser.optionxform = str  # type: ignore[assignment,method-assign]  # keep the case
    try:
        parser.read_string(text[:MAX_SETUP_BYTES])
    except configparser.Error:
        layout.unread(f"{origin}: not parsed")
        return layout
    if not parser.has_section("options.data_files"):
        return layout
    evaluator = _Evaluator(package_dir, {})
    for destination, value in parser.items("options.data_files"):
        files: list[str] = []
        for word in re.split(r"[,\n]", value):
            word = word.strip()
            if not word:
                continue
            if not re.search(r"[*?\[]", word):
                files.append(word)
                continue
            try:
                # setuptools expands glob patterns here (recursive "**" too).
                files.extend(evaluator.glob(word, True))
            except _Unknown as exc:
                layout.unread(f"{origin}: {exc}")
        _add_files(layout, destination, files, package, origin)
    return layout
