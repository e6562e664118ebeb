"""Data values in xacro expressions: ``load_yaml`` and include namespaces.

xacro's ``${load_yaml('$(find pkg)/config/x.yaml')}`` (also ``xacro.load_yaml``) gives a
property whose value is the YAML document, read as ``${props['key']}``,
``${props.key}`` (xacro's YAML dicts read keys as attributes) and nested indexing. The
file is parsed with PyYAML's safe loader (and xacro's ``!radians``/``!degrees`` angle
tags, their expressions evaluated by our own interpreter), imported on first use (the
core is stdlib only): without PyYAML, or for a document with other tags, the value is
unknown, never guessed.
The document is copied into the evaluator's values by a bounded walk (items and depth;
an alias is counted each time it is reached, so a "billion laughs" document stops at the
bound), and its size is charged to the expansion's work.
"""

from __future__ import annotations

import math
import os
import typing
from collections.abc import Callable, Iterator
from typing import Any

from launch_linter.frontends.robot.xacro_values import _literal, _Property, _Table, _Unknown
from launch_linter.resolve.eval_values import (
    AttributeDict,
    EvalError,
    Machine,
    _auto_convert,
    function,
)
from launch_linter.resolve.safe_eval import EvalScope, evaluate_value
from launch_linter.resolve.xml_safe import read_file_within

MAX_YAML_BYTES = 512 * 1024
MAX_YAML_ITEMS = 20_000
"""Scalars, lists and mappings one ``load_yaml`` may give (aliases counted each time)."""
MAX_YAML_DEPTH = 64


def read_yaml_data(path: str) -> object:
    """The YAML document at ``path`` as evaluator values (dicts readable by attribute,
    lists, text, numbers, booleans, None); raises :class:`_Unknown` when it is not read."""
    # The file first: a missing file is missing with or without PyYAML (the standalone
    # linter, which runs without it, then says what the installed one says).
    try:
        data = read_file_within(path, MAX_YAML_BYTES)
    except OSError as exc:  # FileTooLarge included
        raise _Unknown(f"load_yaml({path!r}): {exc.strerror or exc}") from None
    try:
        # Imported on use: PyYAML stays out of the standard-library core.
        import yaml  # type: ignore[import-untyped]
    except ImportError:
        raise _Unknown(f"load_yaml({path!r}): reading YAML needs PyYAML") from None
    try:
        document: Any = yaml.load(data.decode("utf-8", "replace"), Loader=_loader(yaml))
    except (yaml.YAMLError, RecursionError, ValueError) as exc:
        raise _Unknown(f"load_yaml({path!r}): not readable YAML "
                       f"({str(exc).splitlines()[0][:120] if str(exc) else 'error'})") from None
    return as_values(document, path)


_LOADERS: dict[int, Any] = {}


def _loader(yaml: Any) -> Any:
    """PyYAML's safe loader with xacro's two unit tags, ``!radians EXPR`` and
    ``!degrees EXPR`` (the expression evaluated by our own interpreter, as a number)."""
    made = _LOADERS.get(id(yaml))
    if made is not None:
        return made

    def angle(loader: Any, node: Any, degrees: bool) -> float:
        text = str(loader.construct_scalar(node))
        scope = EvalScope(args={}, env={}, find=lambda _: None, anon=lambda n: n,
                          dirname=None)
        try:
            value = evaluate_value(text, scope)
        except EvalError as exc:
            raise yaml.constructor.ConstructorError(None, None, exc.reason) from None
        if not isinstance(value, (int, float)) or isinstance(value, bool):
            raise yaml.constructor.ConstructorError(None, None, f"{text!r} is not a number")
        return math.radians(value) if degrees else float(value)

    class XacroLoader(yaml.SafeLoader):  # type: ignore[misc]
        """Only the safe loader's types, and the two angles."""

    XacroLoader.add_constructor("!radians", lambda loader, node: angle(loader, node, False))
    XacroLoader.add_constructor("!degrees", lambda loader, node: angle(loader, node, True))
    _LOADERS[id(yaml)] = XacroLoader
    return XacroLoader


def as_values(document: object, path: str) -> object:
    """A copy of ``document`` made of evaluator values, bounded in items and depth."""
    count = 0

    def copy(node: object, depth: int) -> object:
        nonlocal count
        count += 1
        if count > MAX_YAML_ITEMS:
            raise _Unknown(f"load_yaml({path!r}): more than {MAX_YAML_ITEMS:,} items")
        if depth > MAX_YAML_DEPTH:
            raise _Unknown(f"load_yaml({path!r}): nested more than {MAX_YAML_DEPTH} levels")
        if node is None or isinstance(node, (bool, int, float, str)):
            return node
        if isinstance(node, dict):
            out = AttributeDict()
            for key, value in node.items():
                if not (key is None or isinstance(key, (bool, int, float, str))):
                    raise _Unknown(f"load_yaml({path!r}): a key that is not a scalar")
                out[key] = copy(value, depth + 1)
            return out
        if isinstance(node, (list, tuple)):
            return [copy(item, depth + 1) for item in node]
        # Dates and binary values of the safe loader: not values of the language.
        raise _Unknown(f"load_yaml({path!r}): a {type(node).__name__} value")

    # Recursion is bounded by MAX_YAML_DEPTH, far below Python's limit.
    return copy(document, 0)


def yaml_loader(where: Callable[[], str], charge: Callable[[int], None],
                cache: dict[str, tuple[object, int] | _Unknown]) -> object:
    """The ``load_yaml`` function of one expansion: a relative name is read beside the
    file being expanded (``where()``), each file once (with its size, charged at every
    use)."""

    def load_yaml(machine: Machine, args: tuple[object, ...]) -> object:
        if len(args) != 1 or not isinstance(args[0], str):
            raise EvalError("load_yaml() takes one file name")
        name = args[0]
        path = os.path.normpath(os.path.join(os.path.dirname(where()), name))
        if path not in cache:
            try:
                document = read_yaml_data(path)
            except _Unknown as unknown:
                cache[path] = unknown
            else:
                cache[path] = (document, _size(document))
        found = cache[path]
        if isinstance(found, _Unknown):
            raise found
        document, size = found
        machine.charge(1)
        charge(size)
        return document

    return function("load_yaml", load_yaml)


def _size(value: object) -> int:
    if isinstance(value, dict):
        return 1 + sum(_size(v) for v in value.values())
    if isinstance(value, list):
        return 1 + sum(_size(v) for v in value)
    return 1


class _Expander(typing.Protocol):
    """What :class:`Symbols` asks of the expander."""

    def property_value(self, name: str, table: _Table, prop: _Property) -> str | None: ...

    def yaml_loader(self) -> object: ...

    def _charge(self, units: int = 1) -> None: ...



def namespace_values(expander: _Expander, table: _Table) -> AttributeDict:
    """The properties of a namespaced include as ``${ns.x}`` reads them; one whose
    value is unknown is left out (reading it is then unknown too)."""
    values = AttributeDict()
    for name, prop in table.properties.items():
        expander._charge()
        try:
            text = expander.property_value(name, table, prop)
        except _Unknown:
            continue
        if prop.namespace is not None:
            values[name] = namespace_values(expander, prop.namespace)
        elif prop.data is not None:
            values[name] = prop.data
        elif text is not None:
            values[name] = _auto_convert(_literal(text))
    return values


class Symbols(typing.Mapping[str, object]):
    """The properties visible from a table, evaluated on demand, as the evaluator's args."""

    def __init__(self, expander: _Expander, table: _Table) -> None:
        self._expander = expander
        self._table = table

    def __contains__(self, name: object) -> bool:
        return isinstance(name, str) and (self._table.find_property(name) is not None
                                          or name in ("load_yaml", "xacro"))

    def __getitem__(self, name: str) -> object:
        found = self._table.find_property(name)
        if found is None:
            loader = self._expander.yaml_loader()
            if name == "xacro":  # xacro's own namespace: xacro.load_yaml(...)
                return AttributeDict(load_yaml=loader)
            if name == "load_yaml":
                return loader
            raise KeyError(name)
        value = self._expander.property_value(name, found[0], found[1])
        if found[1].namespace is not None:
            return namespace_values(self._expander, found[1].namespace)
        if found[1].data is not None:
            return found[1].data
        return None if value is None else _literal(value)

    def __iter__(self) -> Iterator[str]:
        return iter(())

    def __len__(self) -> int:
        return 0
