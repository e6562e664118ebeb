"""Stand-ins that let the standalone linter's embedded modules run on Python 3.8 to 3.10.

The generator embeds this file in every standalone linter as the top-level module
``_launch_linter_compat``, and rewrites the imports of the embedded package modules that
need it (see ``backport.py``). On a Python that has the real thing, each public name here
*is* the real thing, so a standalone linter behaves on Python 3.11 exactly as the package
does; on older Pythons each stand-in (``*_before_3_x``, defined everywhere so that the
package's tests exercise them) gives the Python 3.11 behaviour the package relies on.

This module must itself run on Python 3.8 with the standard library only.
"""

# This file must run on Python 3.8, which the project's ruff target (3.11) does not know:
# ruff: noqa: UP006, UP029

from __future__ import annotations

import ast as _ast
import builtins
import dataclasses
import enum
import itertools
import re
import sys
import types
from typing import Any, Iterable, Iterator, Tuple, TypeVar

AnyStr = TypeVar("AnyStr", str, bytes)


def dataclass_before_3_10(cls: Any = None, **options: Any) -> Any:
    """``dataclasses.dataclass`` without the Python 3.10 options that only save memory.

    ``slots`` and ``match_args`` change neither the fields nor the methods that the package
    uses; ``kw_only`` would change the constructor, so it is refused.
    """
    options.pop("slots", None)
    options.pop("match_args", None)
    if options.pop("kw_only", False):
        raise TypeError("dataclass(kw_only=True) needs Python 3.10 or newer")
    if cls is None:
        return dataclasses.dataclass(**options)
    return dataclasses.dataclass(cls, **options)


_END = object()


def zip_before_3_10(*iterables: Iterable[Any], strict: bool = False) -> Iterator[Tuple[Any, ...]]:
    """``zip`` with Python 3.10's ``strict`` check that all iterables have one length."""
    if not strict:
        return builtins.zip(*iterables)
    return _zip_strict(iterables)


def _zip_strict(iterables: Tuple[Iterable[Any], ...]) -> Iterator[Tuple[Any, ...]]:
    for items in itertools.zip_longest(*iterables, fillvalue=_END):
        if any(item is _END for item in items):
            raise ValueError("zip() arguments have different lengths")
        yield items


class EnumBefore311(enum.Enum):
    """An enum whose ``format()`` (and f-string) text is its ``str()``, as from 3.11.

    Before 3.11 a member of a ``(str, Enum)`` class formatted as its value.
    """

    def __format__(self, format_spec: str) -> str:
        return str.__format__(str(self), format_spec)


def removeprefix_before_3_9(text: AnyStr, prefix: AnyStr) -> AnyStr:
    """``text.removeprefix(prefix)`` (Python 3.9), for ``str`` and ``bytes``."""
    return text[len(prefix) :] if text.startswith(prefix) else text


def removesuffix_before_3_9(text: AnyStr, suffix: AnyStr) -> AnyStr:
    """``text.removesuffix(suffix)`` (Python 3.9), for ``str`` and ``bytes``."""
    return text[: len(text) - len(suffix)] if suffix and text.endswith(suffix) else text


class _Python39Shape(_ast.NodeTransformer):
    """Python 3.9 dropped the ``Index`` and ``ExtSlice`` wrappers of subscripts."""

    def visit_Index(self, node: Any) -> Any:
        return self.visit(node.value)

    def visit_ExtSlice(self, node: Any) -> Any:
        dims = [self.visit(dim) for dim in node.dims]
        tuple_node = _ast.Tuple(elts=dims, ctx=_ast.Load())
        return _ast.copy_location(tuple_node, dims[0]) if dims else tuple_node


def _parse_before_3_9(source: Any, *args: Any, **kwargs: Any) -> Any:
    return _Python39Shape().visit(_ast.parse(source, *args, **kwargs))


def _ast_before_3_9() -> types.ModuleType:
    """A copy of the ``ast`` module whose ``parse`` gives trees of Python 3.9's shape."""
    module = types.ModuleType("ast", _ast.__doc__)
    module.__dict__.update({k: v for k, v in vars(_ast).items() if not k.startswith("__")})
    module.parse = _parse_before_3_9  # type: ignore[attr-defined]
    return module


_HEADER = re.compile(r"\s*\[\[?\s*(?P<first>\"[^\"]*\"|'[^']*'|[A-Za-z0-9_-]+)")
_PYPROJECT_TABLES = ("build-system", "project", "tool", "dependency-groups")


class TOMLDecodeErrorBefore311(ValueError):
    """A TOML document that the stand-in for ``tomllib`` does not read."""


def toml_loads_before_3_11(text: str, **_options: object) -> dict[str, object]:
    """What this linter can know of a TOML document without a TOML parser.

    A document that cannot hold launch-linter settings reads as empty, so that such a
    ``pyproject.toml`` is passed over as it is with ``tomllib``: no top-level keys, only the
    usual ``pyproject.toml`` tables, and ``launch-linter`` in no table header and no key of
    the ``[tool]`` table (short of spelling it with escape sequences). Anything else is
    refused, never guessed at.
    """
    refused = TOMLDecodeErrorBefore311(
        "this standalone linter reads configuration files only on Python 3.11 or newer"
        " (tomllib); run it with a newer Python or give the settings as options"
    )
    table: str | None = None
    for line in text.splitlines():
        stripped = line.strip()
        if not stripped or stripped.startswith("#"):
            continue
        header = _HEADER.match(stripped) if stripped.startswith("[") else None
        if header is not None:
            first = header.group("first").strip("\"'")
            if first not in _PYPROJECT_TABLES or "launch-linter" in stripped:
                raise refused
            table = re.sub(r"[\s\"']", "", stripped.strip("[").partition("]")[0])
        elif table is None or (table == "tool" and "launch-linter" in stripped.partition("=")[0]):
            raise refused
    return {}


def _toml_load_before_3_11(handle: Any, **options: object) -> dict[str, object]:
    return toml_loads_before_3_11(handle.read().decode("utf-8"), **options)


def _tomllib_before_3_11() -> types.ModuleType:
    module = types.ModuleType("tomllib", "Stand-in for tomllib (Python 3.11) on older Pythons.")
    module.loads = toml_loads_before_3_11  # type: ignore[attr-defined]
    module.load = _toml_load_before_3_11  # type: ignore[attr-defined]
    module.TOMLDecodeError = TOMLDecodeErrorBefore311  # type: ignore[attr-defined]
    return module


if sys.version_info >= (3, 9):
    import ast

    def removeprefix(text: AnyStr, prefix: AnyStr) -> AnyStr:
        return text.removeprefix(prefix)

    def removesuffix(text: AnyStr, suffix: AnyStr) -> AnyStr:
        return text.removesuffix(suffix)
else:
    ast = _ast_before_3_9()
    removeprefix = removeprefix_before_3_9
    removesuffix = removesuffix_before_3_9

if sys.version_info >= (3, 10):
    from builtins import zip
    from dataclasses import dataclass
    from typing import TypeAlias
else:
    dataclass = dataclass_before_3_10
    zip = zip_before_3_10
    # Only ever named in annotations, which ``from __future__ import annotations`` leaves
    # unevaluated.
    TypeAlias = "TypeAlias"

if sys.version_info >= (3, 11):
    from enum import Enum

    import tomllib
else:
    tomllib = _tomllib_before_3_11()
    Enum = EnumBefore311


__all__ = [
    "Enum", "TypeAlias", "ast", "dataclass", "removeprefix", "removesuffix", "tomllib", "zip",
]
