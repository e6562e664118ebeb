"""Rewrite the package's own modules so that Python 3.8 runs them as Python 3.11 does.

The package is written for Python 3.11; the standalone linter must run on 3.8 (ROS Noetic's
Python). The generator therefore embeds each core module with a few targeted edits, made
at the places the syntax tree points to, so that comments and layout survive and a
reviewer can diff an embedded module against its file:

* ``from __future__ import annotations`` is added where missing, so that annotations
  such as ``Iterable[Diagnostic]`` or ``str | None`` are never evaluated;
* type expressions that *are* evaluated (type aliases, ``isinstance`` arguments, base
  classes, ``cast``/``TypeVar``/``NewType`` arguments) are spelled with ``typing``:
  ``str | Hole`` becomes ``_typing.Union[str, Hole]``, ``tuple[int, ...]`` becomes
  ``_typing.Tuple[int, ...]``, and ``isinstance(x, A | B)`` becomes ``isinstance(x, (A, B))``;
* a few standard-library names come from ``compat.py`` (embedded as
  ``_launch_linter_compat``), which re-exports the real object on new Pythons:
  ``dataclass`` (``slots=``), ``zip`` (``strict=``), ``Enum`` (``format()``), ``ast``
  (the subscript shape of 3.9) and ``tomllib``; ``x.removeprefix(p)`` becomes
  ``removeprefix(x, p)``.

:func:`python38_problems` then checks the result for what these edits do not cover and
the generator refuses to embed a module with problems, naming the file and line.
"""

from __future__ import annotations

import ast
import builtins
import itertools
from collections.abc import Iterable, Iterator
from dataclasses import dataclass

COMPAT_MODULE = "_launch_linter_compat"
ADDED = "  # launch-linter generate: for Python < 3.11"

COMPAT_FROM = {
    ("dataclasses", "dataclass"),
    ("enum", "Enum"),
    ("typing", "TypeAlias"),
}
"""Names imported from a standard module that are taken from the compat module instead."""
COMPAT_IMPORT = ("ast", "tomllib")
"""Standard modules that are taken from the compat module instead."""
COMPAT_METHODS = ("removeprefix", "removesuffix")
"""Methods (Python 3.9) whose calls become calls of the compat function of that name."""

BUILTIN_GENERICS = {
    "tuple": "Tuple",
    "list": "List",
    "dict": "Dict",
    "set": "Set",
    "frozenset": "FrozenSet",
    "type": "Type",
}
ABC_GENERICS = {
    "AsyncGenerator", "AsyncIterable", "AsyncIterator", "Awaitable", "ByteString",
    "Callable", "Collection", "Container", "Coroutine", "Generator", "ItemsView",
    "Iterable", "Iterator", "KeysView", "Mapping", "MappingView", "MutableMapping",
    "MutableSequence", "MutableSet", "Reversible", "Sequence", "ValuesView",
}
ABC_RENAMED = {"Set": "AbstractSet"}
OTHER_GENERICS = {("re", "Pattern"): "Pattern", ("re", "Match"): "Match"}
BUILTIN_TYPES = frozenset(
    name for name, value in vars(builtins).items() if isinstance(value, type)
) | {"None"}

TYPING_NEWER = {
    "ParamSpec": "3.10", "Concatenate": "3.10", "TypeGuard": "3.10", "TypeAlias": "3.10",
    "ParamSpecArgs": "3.10", "ParamSpecKwargs": "3.10", "is_typeddict": "3.10",
    "Self": "3.11", "Never": "3.11", "LiteralString": "3.11", "Required": "3.11",
    "NotRequired": "3.11", "Unpack": "3.11", "TypeVarTuple": "3.11", "assert_never": "3.11",
    "assert_type": "3.11", "reveal_type": "3.11", "dataclass_transform": "3.11",
    "get_overloads": "3.11", "clear_overloads": "3.11", "override": "3.12",
    "TypeAliasType": "3.12", "get_protocol_members": "3.13", "is_protocol": "3.13",
    "ReadOnly": "3.13", "TypeIs": "3.13", "NoDefault": "3.13",
}
MODULE_NEWER = {
    ("enum", "StrEnum"): "3.11", ("enum", "ReprEnum"): "3.11", ("enum", "verify"): "3.11",
    ("enum", "member"): "3.11", ("enum", "nonmember"): "3.11", ("enum", "global_enum"): "3.11",
    ("enum", "EnumCheck"): "3.11", ("enum", "FlagBoundary"): "3.11",
    ("functools", "cache"): "3.9", ("itertools", "pairwise"): "3.10",
    ("itertools", "batched"): "3.12", ("math", "lcm"): "3.9", ("math", "nextafter"): "3.9",
    ("math", "ulp"): "3.9", ("math", "cbrt"): "3.11", ("math", "exp2"): "3.11",
    ("math", "sumprod"): "3.12", ("math", "fma"): "3.13", ("sys", "stdlib_module_names"): "3.10",
    ("sys", "orig_argv"): "3.10", ("ast", "unparse"): "3.9", ("random", "randbytes"): "3.9",
    ("os", "process_cpu_count"): "3.13", ("contextlib", "chdir"): "3.11",
    ("contextlib", "aclosing"): "3.10", ("operator", "call"): "3.11",
    ("hashlib", "file_digest"): "3.11", ("inspect", "get_annotations"): "3.10",
    ("types", "NoneType"): "3.10", ("types", "EllipsisType"): "3.10",
    ("types", "UnionType"): "3.10", ("types", "GenericAlias"): "3.9",
    ("dataclasses", "KW_ONLY"): "3.10",
}
MODULES_NEWER = {"graphlib": "3.9", "zoneinfo": "3.9", "tomllib": "3.11"}
MODULES_REMOVED = {
    **dict.fromkeys(("asynchat", "asyncore", "distutils", "imp", "smtpd"), "3.12"),
    **dict.fromkeys(
        ("aifc", "audioop", "cgi", "cgitb", "chunk", "crypt", "imghdr", "mailcap", "msilib",
         "nis", "nntplib", "ossaudiodev", "pipes", "sndhdr", "spwd", "sunau", "telnetlib", "uu",
         "xdrlib", "lib2to3"),
        "3.13",
    ),
}
"""Standard modules that newer Pythons, which the standalone linter also runs on, lack."""
METHODS_NEWER = {
    "removeprefix": "3.9", "removesuffix": "3.9", "bit_count": "3.10",
    "is_relative_to": "3.9", "with_stem": "3.9", "hardlink_to": "3.10",
}
BUILTINS_NEWER = {
    "aiter": "3.10", "anext": "3.10", "EncodingWarning": "3.10",
    "ExceptionGroup": "3.11", "BaseExceptionGroup": "3.11",
}
NOT_STANDALONE = {
    "__file__": "embedded modules have no file",
    "__import__": "embedded modules are found only through plain import statements",
    "pkgutil": "embedded modules cannot be listed",
    "importlib.import_module": "embedded modules are found only through plain import statements",
    "importlib.resources": "embedded modules have no package data",
    "typing.get_type_hints": "it evaluates annotations, which use Python 3.10 syntax",
    "enum.IntEnum": "str() of its members differs between Python 3.8 and 3.11",
    "enum.IntFlag": "str() of its members differs between Python 3.8 and 3.11",
}
"""What embedded modules cannot use (names, modules and ``module.name``), and why."""


@dataclass(frozen=True, slots=True)
class Types:
    """What the embedded modules define that their run-time type expressions name."""

    names: frozenset[str] = frozenset()
    """Classes and type aliases, by bare name."""
    unions: frozenset[str] = frozenset()
    """Type aliases that are unions (``A | B``), by qualified name (``pkg.module.Name``):
    ``isinstance(x, Name)`` becomes ``isinstance(x, _typing.get_args(Name))``, since
    before Python 3.10 ``isinstance`` does not take a ``typing.Union``."""

    def __or__(self, other: Types) -> Types:
        return Types(self.names | other.names, self.unions | other.unions)


def module_name(path: str) -> tuple[str, bool]:
    """``pkg/sub/mod.py`` to (``pkg.sub.mod``, is a package)."""
    parts = path.removesuffix(".py").split("/")
    if parts[-1] == "__init__":
        return ".".join(parts[:-1]), True
    return ".".join(parts), False


class BackportError(ValueError):
    """The source cannot be rewritten; ``problems`` are ``path:line: message`` texts."""

    def __init__(self, problems: list[str]) -> None:
        super().__init__("\n".join(problems))
        self.problems = problems


@dataclass(frozen=True, slots=True)
class _Edit:
    start: int
    end: int
    text: str


class _Positions:
    """Turns the syntax tree's (line, UTF-8 byte column) into offsets in the text."""

    def __init__(self, source: str) -> None:
        self.source = source
        self.lines = source.splitlines(keepends=True)
        self.starts = [0]
        for line in self.lines:
            self.starts.append(self.starts[-1] + len(line))

    def offset(self, line: int, byte_column: int) -> int:
        if line > len(self.lines):
            return len(self.source)
        text = self.lines[line - 1].encode("utf-8")[:byte_column].decode("utf-8")
        return self.starts[line - 1] + len(text)

    def span(self, node: ast.expr | ast.stmt) -> tuple[int, int]:
        end_line = node.end_lineno
        end_column = node.end_col_offset
        assert end_line is not None and end_column is not None
        return self.offset(node.lineno, node.col_offset), self.offset(end_line, end_column)

    def text(self, node: ast.expr) -> str:
        start, end = self.span(node)
        return self.source[start:end]

    def line_start(self, line: int) -> int:
        return self.starts[min(line, len(self.lines))]


def is_type_checking(test: ast.expr) -> bool:
    return (isinstance(test, ast.Name) and test.id == "TYPE_CHECKING") or (
        isinstance(test, ast.Attribute) and test.attr == "TYPE_CHECKING"
    )


def _runtime_nodes(tree: ast.Module) -> Iterator[ast.AST]:
    """Every node evaluated at run time: annotations and ``if TYPE_CHECKING:`` left out."""
    stack: list[ast.AST] = [tree]
    while stack:
        node = stack.pop()
        yield node
        if isinstance(node, ast.If) and is_type_checking(node.test):
            stack.extend(node.orelse)
            continue
        for name, value in ast.iter_fields(node):
            if name in ("annotation", "returns"):
                continue
            if isinstance(value, ast.AST):
                stack.append(value)
            elif isinstance(value, list):
                stack.extend(v for v in value if isinstance(v, ast.AST))


class _Names:
    """What names mean in one module, as far as type expressions are concerned."""

    def __init__(self, tree: ast.Module, types: Types, path: str = "") -> None:
        self.type_names = set(types.names) | BUILTIN_TYPES | class_names_of(tree)
        self.abc: dict[str, str] = {}
        self.other: dict[str, str] = {}
        self.unions: set[str] = set()
        """Local names of union aliases (defined here or imported)."""
        module, is_package = module_name(path)
        for node in ast.walk(tree):
            if not isinstance(node, ast.ImportFrom):
                continue
            source = _absolute(node, module, is_package)
            for alias in node.names:
                local = alias.asname or alias.name
                if f"{source}.{alias.name}" in types.unions:
                    self.unions.add(local)
                if source == "collections.abc" and (
                    alias.name in ABC_GENERICS or alias.name in ABC_RENAMED
                ):
                    self.abc[local] = ABC_RENAMED.get(alias.name, alias.name)
                if (source, alias.name) in OTHER_GENERICS:
                    self.other[local] = OTHER_GENERICS[(source, alias.name)]
                if alias.name[:1].isupper():
                    self.type_names.add(local)
        self.unions |= {
            n for n in union_alias_names(tree, self) if f"{module}.{n}" in types.unions
        }

    def generic(self, node: ast.expr) -> str | None:
        """The ``typing`` name for a subscripted generic that Python 3.8 cannot subscript."""
        if isinstance(node, ast.Name):
            if node.id in BUILTIN_GENERICS:
                return BUILTIN_GENERICS[node.id]
            return self.abc.get(node.id) or self.other.get(node.id)
        if isinstance(node, ast.Attribute) and isinstance(node.value, ast.Name):
            if node.value.id == "re" and ("re", node.attr) in OTHER_GENERICS:
                return OTHER_GENERICS[("re", node.attr)]
            if node.value.id == "abc" or node.value.id.endswith("abc"):
                return ABC_RENAMED.get(node.attr) or (
                    node.attr if node.attr in ABC_GENERICS else None
                )
        return None

    def type_like(self, node: ast.expr) -> bool:
        """True for an expression that can only be a type (the leaves of a ``|`` union)."""
        if isinstance(node, ast.Constant):
            return node.value is None
        if isinstance(node, ast.Name):
            return node.id in self.type_names
        if isinstance(node, ast.Attribute):
            return node.attr[:1].isupper() and not node.attr.isupper()
        if isinstance(node, ast.Subscript):
            return self.generic(node.value) is not None or self.type_like(node.value)
        if isinstance(node, ast.BinOp) and isinstance(node.op, ast.BitOr):
            return self.type_like(node.left) and self.type_like(node.right)
        return False

    def needs_rewrite(self, node: ast.expr) -> bool:
        """True when a run-time type expression uses Python 3.9/3.10 spelling."""
        for sub in ast.walk(node):
            if isinstance(sub, ast.BinOp) and isinstance(sub.op, ast.BitOr) and self.type_like(sub):
                return True
            if isinstance(sub, ast.Subscript) and self.generic(sub.value) is not None:
                return True
        return False


def _absolute(node: ast.ImportFrom, module: str, is_package: bool) -> str:
    if not node.level:
        return node.module or ""
    parts = module.split(".") if is_package else module.split(".")[:-1]
    anchor = ".".join(parts[: len(parts) - node.level + 1])
    return f"{anchor}.{node.module}" if node.module else anchor


def _is_union(node: ast.expr, names: _Names) -> bool:
    if isinstance(node, ast.BinOp) and isinstance(node.op, ast.BitOr):
        return names.type_like(node)
    if isinstance(node, ast.Subscript):
        base = node.value
        name = base.attr if isinstance(base, ast.Attribute) else (
            base.id if isinstance(base, ast.Name) else ""
        )
        return name in ("Union", "Optional")
    return False


def union_alias_names(tree: ast.Module, names: _Names) -> set[str]:
    """Module-level names bound to a union of types."""
    found = set()
    for statement in tree.body:
        name, value = _assigned_name(statement), _assigned(statement)
        if name is not None and value is not None and _is_union(value, names):
            found.add(name)
    return found


def _union_members(node: ast.expr) -> list[ast.expr]:
    if isinstance(node, ast.BinOp) and isinstance(node.op, ast.BitOr):
        return [*_union_members(node.left), *_union_members(node.right)]
    return [node]


def _typing(name: str) -> ast.expr:
    return ast.Attribute(value=ast.Name(id="_typing", ctx=ast.Load()), attr=name, ctx=ast.Load())


class _TypingSpelling(ast.NodeTransformer):
    """``A | B`` to ``_typing.Union[A, B]``, ``tuple[...]`` to ``_typing.Tuple[...]``."""

    def __init__(self, names: _Names) -> None:
        self.names = names

    def visit_BinOp(self, node: ast.BinOp) -> ast.expr:
        if isinstance(node.op, ast.BitOr) and self.names.type_like(node):
            members = [self.visit(m) for m in _union_members(node)]
            return ast.Subscript(
                value=_typing("Union"), slice=ast.Tuple(elts=members, ctx=ast.Load()),
                ctx=ast.Load(),
            )
        visited: ast.expr = self.generic_visit(node)  # type: ignore[assignment]
        return visited

    def visit_Subscript(self, node: ast.Subscript) -> ast.expr:
        name = self.names.generic(node.value)
        visited: ast.Subscript = self.generic_visit(node)  # type: ignore[assignment]
        if name is None:
            return visited
        return ast.Subscript(value=_typing(name), slice=visited.slice, ctx=ast.Load())


def _type_positions(tree: ast.Module, names: _Names) -> Iterator[tuple[ast.expr, bool]]:
    """Run-time type expressions: (expression, is an isinstance/issubclass class argument)."""
    for node in _runtime_nodes(tree):
        if isinstance(node, ast.Module | ast.ClassDef):
            for statement in node.body:
                value = _assigned(statement)
                if value is not None and names.type_like(value):
                    yield value, False
        if isinstance(node, ast.ClassDef):
            for base in node.bases:
                yield base, False
        if isinstance(node, ast.Call):
            callee = node.func.attr if isinstance(node.func, ast.Attribute) else (
                node.func.id if isinstance(node.func, ast.Name) else ""
            )
            if callee in ("isinstance", "issubclass") and len(node.args) == 2:
                yield node.args[1], True
            elif callee == "cast" and node.args:
                yield node.args[0], False
            elif callee == "NewType" and len(node.args) == 2:
                yield node.args[1], False
            elif callee == "TypeVar":
                yield from ((a, False) for a in node.args[1:])
                yield from ((k.value, False) for k in node.keywords if k.arg == "bound")


def _assigned(statement: ast.stmt) -> ast.expr | None:
    """The value of ``name = value`` or ``name: annotation = value``."""
    if isinstance(statement, ast.Assign) and len(statement.targets) == 1:
        return statement.value
    if isinstance(statement, ast.AnnAssign):
        return statement.value
    return None


def _assigned_name(statement: ast.stmt) -> str | None:
    if isinstance(statement, ast.Assign) and len(statement.targets) == 1:
        target = statement.targets[0]
    elif isinstance(statement, ast.AnnAssign):
        target = statement.target
    else:
        return None
    return target.id if isinstance(target, ast.Name) else None


def type_alias_names(source: str) -> set[str]:
    """Module-level names bound to a type expression (they are types in other modules too)."""
    tree = ast.parse(source)
    names = _Names(tree, Types(frozenset(class_names(source))))
    found: set[str] = set()
    changed = True
    while changed:
        changed = False
        for statement in tree.body:
            name, value = _assigned_name(statement), _assigned(statement)
            if (
                name is not None
                and name not in found
                and value is not None
                and not isinstance(value, ast.Constant)
                and names.type_like(value)
            ):
                found.add(name)
                names.type_names.add(name)
                changed = True
    return found


def class_names_of(tree: ast.Module) -> set[str]:
    return {n.name for n in ast.walk(tree) if isinstance(n, ast.ClassDef)}


def class_names(source: str) -> set[str]:
    return class_names_of(ast.parse(source))


def module_types(source: str, path: str) -> Types:
    """What one module contributes to :class:`Types`."""
    tree = ast.parse(source)
    names = class_names_of(tree) | type_alias_names(source)
    module, _ = module_name(path)
    unions = union_alias_names(tree, _Names(tree, Types(frozenset(names)), path))
    return Types(frozenset(names), frozenset(f"{module}.{n}" for n in unions))


def _same_lines(positions: _Positions, start: int, end: int, text: str) -> _Edit:
    """An edit whose text spans as many lines as what it replaces (the text is code that
    ends with a bracket, inside which line breaks are free), so line numbers stay."""
    missing = positions.source.count("\n", start, end) - text.count("\n")
    if missing > 0:
        if text.endswith((")", "]")):
            text = text[:-1] + "\n" * missing + text[-1]
        else:
            text = "(" + text + "\n" * missing + ")"
    return _Edit(start, end, text)


def _import_edit(
    node: ast.Import | ast.ImportFrom, positions: _Positions
) -> _Edit | None:
    """The statement with its compat names moved to an import from the compat module."""
    moved: list[ast.alias] = []
    kept: list[ast.alias] = []
    for alias in node.names:
        if isinstance(node, ast.Import):
            use_compat = alias.name in COMPAT_IMPORT
        else:
            use_compat = node.level == 0 and (node.module, alias.name) in COMPAT_FROM
        (moved if use_compat else kept).append(alias)
    if not moved:
        return None
    statements: list[ast.stmt] = []
    if kept:
        if isinstance(node, ast.Import):
            statements.append(ast.Import(names=kept))
        else:
            statements.append(ast.ImportFrom(module=node.module, names=kept, level=node.level))
    statements.append(ast.ImportFrom(module=COMPAT_MODULE, names=moved, level=0))
    start, end = positions.span(node)
    texts = [ast.unparse(s) for s in statements]
    if positions.source.count("\n", start, end):
        # Parentheses let _same_lines keep the lines that the statement spanned.
        names = ", ".join(ast.unparse(a) for a in moved)
        texts[-1] = f"from {COMPAT_MODULE} import ({names})"
    return _same_lines(positions, start, end, "; ".join(texts))


def _insertion_point(tree: ast.Module, positions: _Positions) -> tuple[int, bool]:
    """Where added imports go, and whether they go before the statement found there:
    after the docstring and future imports, on the same line (so that every line of the
    module keeps its number); else before the first statement, on its line when that is a
    simple statement."""
    last: ast.stmt | None = None
    for index, statement in enumerate(tree.body):
        is_docstring = (
            index == 0
            and isinstance(statement, ast.Expr)
            and isinstance(statement.value, ast.Constant)
            and isinstance(statement.value.value, str)
        )
        is_future = isinstance(statement, ast.ImportFrom) and statement.module == "__future__"
        if not (is_docstring or is_future):
            break
        last = statement
    if last is not None:
        return positions.span(last)[1], False
    first = tree.body[0]
    decorators = getattr(first, "decorator_list", [])
    line = min([first.lineno] + [d.lineno for d in decorators])
    return positions.line_start(line - 1), True


_COMPOUND = (
    ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef, ast.If, ast.For, ast.AsyncFor,
    ast.While, ast.With, ast.AsyncWith, ast.Try, ast.Match,
)


def _has_annotations(tree: ast.Module) -> bool:
    return any(
        (isinstance(n, ast.arg) and n.annotation is not None)
        or (isinstance(n, ast.FunctionDef | ast.AsyncFunctionDef) and n.returns is not None)
        or isinstance(n, ast.AnnAssign)
        for n in ast.walk(tree)
    )


def _has_future_annotations(tree: ast.Module) -> bool:
    return any(
        isinstance(s, ast.ImportFrom)
        and s.module == "__future__"
        and any(a.name == "annotations" for a in s.names)
        for s in tree.body
    )


def _zip_strict(tree: ast.Module) -> bool:
    return any(
        isinstance(n, ast.Call)
        and isinstance(n.func, ast.Name)
        and n.func.id == "zip"
        and any(k.arg == "strict" for k in n.keywords)
        for n in ast.walk(tree)
    )


def _method_edits(tree: ast.Module, positions: _Positions) -> tuple[list[_Edit], set[str]]:
    """``x.removeprefix(p)`` to ``removeprefix(x, p)``, the compat function (Python 3.9)."""
    edits: list[_Edit] = []
    used: set[str] = set()
    for node in _runtime_nodes(tree):
        if (
            isinstance(node, ast.Call)
            and isinstance(node.func, ast.Attribute)
            and node.func.attr in COMPAT_METHODS
            and len(node.args) == 1
            and not node.keywords
            and not isinstance(node.args[0], ast.Starred)
        ):
            receiver = positions.text(node.func.value)
            argument = positions.text(node.args[0])
            start, end = positions.span(node)
            text = f"{node.func.attr}({receiver}, {argument})"
            edits.append(_same_lines(positions, start, end, text))
            used.add(node.func.attr)
    return edits, used


def backport(source: str, path: str, types: Types) -> str:
    """``source`` (the file ``path`` of the package, ``/``-separated) with the edits
    described in the module docstring (unchanged if none)."""
    try:
        tree = ast.parse(source)
    except SyntaxError as exc:
        raise BackportError([f"{path}:{exc.lineno}: {exc.msg}"]) from None
    positions = _Positions(source)
    names = _Names(tree, types, path)
    edits: list[_Edit] = []
    added: list[str] = []
    if not _has_future_annotations(tree) and _has_annotations(tree):
        added.append("from __future__ import annotations")
    for node in _runtime_nodes(tree):
        if isinstance(node, ast.Import | ast.ImportFrom):
            edit = _import_edit(node, positions)
            if edit is not None:
                edits.append(edit)
    needs_typing = False
    for expression, class_argument in _type_positions(tree, names):
        start, end = positions.span(expression)
        members = _union_members(expression)
        if class_argument:
            # The class argument of isinstance() is a type or a tuple of them, so ``|``
            # there can only be a union, whatever its members look like; a tuple of
            # classes is what every Python takes.
            parts = expression.elts if isinstance(expression, ast.Tuple) else [expression]
            members = [m for part in parts for m in _union_members(part)]
            changed = len(members) != len(parts)
            texts = []
            for member in members:
                if isinstance(member, ast.Name) and member.id in names.unions:
                    texts.append(f"*_typing.get_args({member.id})")
                    changed = needs_typing = True
                else:
                    texts.append(positions.text(member))
            if not changed:
                continue
            text = "(" + ", ".join(texts) + ("," if len(texts) == 1 else "") + ")"
        elif names.needs_rewrite(expression):
            text = ast.unparse(_TypingSpelling(names).visit(expression))
            needs_typing = True
        else:
            continue
        edits.append(_same_lines(positions, start, end, text))
    if needs_typing:
        added.append("import typing as _typing")
    method_edits, methods = _method_edits(tree, positions)
    edits.extend(method_edits)
    compat_names = sorted(methods | ({"zip"} if _zip_strict(tree) else set()))
    if compat_names:
        added.append(f"from {COMPAT_MODULE} import {', '.join(compat_names)}")
    if not edits and not added:
        return source
    edits.sort(key=lambda e: e.start)
    for before, after in itertools.pairwise(edits):
        if after.start < before.end:
            raise BackportError([f"{path}: overlapping rewrites (a bug in the generator)"])
    result = source
    for edit in reversed(edits):
        result = result[: edit.start] + edit.text + result[edit.end :]
    if added:
        offset, ahead = _insertion_point(tree, positions)
        # Edits never touch the docstring or future imports, which come before ``offset``.
        if not ahead:
            rest = source[offset:].split("\n", 1)[0]
            block = "; " + "; ".join(added) + ("" if rest.strip() else ADDED)
        elif isinstance(tree.body[0], _COMPOUND) or getattr(tree.body[0], "decorator_list", []):
            block = "".join(line + ADDED + "\n" for line in added)
        else:
            block = "; ".join(added) + "; "
        result = result[:offset] + block + result[offset:]
    return result


def python38_problems(
    source: str, path: str, types: Types, allowed: tuple[str, ...] = ()
) -> list[str]:
    """What in ``source`` Python 3.8 cannot run, or runs differently from Python 3.11;
    ``allowed`` names :data:`NOT_STANDALONE` entries that the caller takes care of."""
    try:
        tree = ast.parse(source, feature_version=(3, 8))
    except SyntaxError as exc:
        return [f"{path}:{exc.lineno}: syntax newer than Python 3.8: {exc.msg}"]
    names = _Names(tree, types, path)
    found = {
        (getattr(node, "lineno", 1), message)
        for node in _runtime_nodes(tree)
        for message in _node_problems(node, names, allowed)
    }
    return [f"{path}:{line}: {message}" for line, message in sorted(found)]


def _node_problems(node: ast.AST, names: _Names, allowed: tuple[str, ...]) -> Iterable[str]:
    blocked = {k: v for k, v in NOT_STANDALONE.items() if k not in allowed}
    if isinstance(node, ast.BinOp) and isinstance(node.op, ast.BitOr) and names.type_like(node):
        yield "a run-time 'X | Y' type union needs Python 3.10 (use a tuple or typing.Union)"
    if isinstance(node, ast.Subscript) and names.generic(node.value) is not None:
        yield "a run-time subscripted builtin or collections.abc generic needs Python 3.9"
    if isinstance(node, ast.Import | ast.ImportFrom):
        modules = [a.name for a in node.names] if isinstance(node, ast.Import) else [
            node.module or ""
        ]
        for name in modules:
            top = name.split(".")[0]
            if top in MODULES_REMOVED and not (isinstance(node, ast.ImportFrom) and node.level):
                yield f"module {top} was removed in Python {MODULES_REMOVED[top]}"
    if isinstance(node, ast.Import):
        for alias in node.names:
            top = alias.name.split(".")[0]
            if top in MODULES_NEWER:
                yield f"module {top} needs Python {MODULES_NEWER[top]}"
            if alias.name in blocked:
                yield f"{alias.name}: {blocked[alias.name]}"
    if isinstance(node, ast.ImportFrom) and node.module:
        top = node.module.split(".")[0]
        if top in MODULES_NEWER and node.module != COMPAT_MODULE:
            yield f"module {top} needs Python {MODULES_NEWER[top]}"
        for alias in node.names:
            if node.module == "typing" and alias.name in TYPING_NEWER:
                yield f"typing.{alias.name} needs Python {TYPING_NEWER[alias.name]}"
            newer = MODULE_NEWER.get((node.module, alias.name))
            if newer is not None:
                yield f"{node.module}.{alias.name} needs Python {newer}"
            qualified = f"{node.module}.{alias.name}"
            if qualified in blocked or node.module in blocked:
                yield f"{qualified}: {blocked.get(qualified) or blocked[node.module]}"
    if isinstance(node, ast.Attribute):
        if isinstance(node.value, ast.Name):
            key = (node.value.id, node.attr)
            if key in MODULE_NEWER:
                yield f"{key[0]}.{key[1]} needs Python {MODULE_NEWER[key]}"
            if node.value.id == "typing" and node.attr in TYPING_NEWER:
                yield f"typing.{node.attr} needs Python {TYPING_NEWER[node.attr]}"
            qualified = f"{node.value.id}.{node.attr}"
            if qualified in blocked:
                yield f"{qualified}: {blocked[qualified]}"
        if node.attr in METHODS_NEWER:
            yield f".{node.attr}() needs Python {METHODS_NEWER[node.attr]}"
    if isinstance(node, ast.Name):
        if node.id in BUILTINS_NEWER:
            yield f"builtin {node.id} needs Python {BUILTINS_NEWER[node.id]}"
        if node.id in ("__file__", "__import__") and node.id in blocked:
            yield f"{node.id}: {blocked[node.id]}"
    if isinstance(node, ast.Call):
        keywords = {k.arg for k in node.keywords}
        callee = node.func.attr if isinstance(node.func, ast.Attribute) else (
            node.func.id if isinstance(node.func, ast.Name) else ""
        )
        if "kw_only" in keywords and callee in ("dataclass", "field"):
            yield f"{callee}(kw_only=...) needs Python 3.10"
        if "slots" in keywords and callee == "dataclass" and isinstance(node.func, ast.Attribute):
            yield "dataclasses.dataclass(slots=...) needs Python 3.10 (import dataclass by name)"
        if callee in ("isinstance", "issubclass") and len(node.args) == 2:
            classes = node.args[1]
            for part in classes.elts if isinstance(classes, ast.Tuple) else [classes]:
                if _is_union(part, names) or (
                    isinstance(part, ast.Name) and part.id in names.unions
                ):
                    yield f"{callee}() with a union needs Python 3.10 (use a tuple)"
        if callee in ("bisect", "bisect_left", "bisect_right", "insort", "insort_left",
                      "insort_right") and "key" in keywords:
            yield f"{callee}(key=...) needs Python 3.10"
