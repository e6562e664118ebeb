"""Render a standalone linter: beliefs, embedded module sources and options to Python text.

Pure: nothing is read but the template. Every value that reaches the generated file goes
through :func:`py_literal` (data) or :func:`source_literal` (module text) and is marked
:class:`Code`; the Jinja environment refuses to print anything else, so text from the
corpus (frame and node names) or from the command line (a beliefs file name) can never
become code or comments.
"""

from __future__ import annotations

import math
import os
import re
from collections.abc import Sequence
from dataclasses import dataclass

import jinja2

from launch_linter.generate.embed import Embedding
from launch_linter.knowledge import BUNDLED_FILES, bundled_path
from launch_linter.model.beliefs import BELIEF_CLASSES, BELIEF_FORMAT, BeliefSet
from launch_linter.model.diagnostic import Belief

TEMPLATE = "standalone.py.jinja"
MIN_PYTHON = (3, 8)
_MODULE_NAME = re.compile(r"[A-Za-z_][A-Za-z0-9_]*(\.[A-Za-z_][A-Za-z0-9_]*)*")
_MODULE_PATH = re.compile(r"[A-Za-z0-9_][A-Za-z0-9_./-]*\.py")
_SHA256 = re.compile(r"[0-9a-f]{64}")

CLASS_TEXT = {
    "sig_implication": (
        "a file with the transform (parent, child) IF usually also has THEN",
        "(IF (parent, child), THEN (parent, child), n, e, z)",
    ),
    "name_implication": (
        "a file with the node named IF usually also has the node named THEN",
        "(IF node name, THEN node name, n, e, z)",
    ),
    "sig_null_disp": (
        "the transform (parent, child) usually has zero displacement",
        "((parent, child), n, e, z)",
    ),
    "name_null_disp": (
        "the node with this name usually has zero displacement",
        "(node name, n, e, z)",
    ),
    "sig_null_rot": (
        "the transform (parent, child) usually has zero rotation",
        "((parent, child), n, e, z)",
    ),
    "name_null_rot": (
        "the node with this name usually has zero rotation",
        "(node name, n, e, z)",
    ),
}


class RenderError(ValueError):
    """The beliefs or sources cannot be rendered."""


class Code(str):
    """Python source text made by this module, safe to put in the generated file as is."""

    __slots__ = ()


@dataclass(frozen=True)
class RenderOptions:
    beliefs_source: str
    """As given to ``generate --beliefs`` (``bundled``, ``study`` or a file name)."""
    min_z: float
    classes: tuple[str, ...]
    """The belief classes kept (all of them unless ``--class`` narrowed the choice)."""
    version: str
    """Of the package that generates."""
    command: str
    """The ``launch-linter generate`` command line that gives the same file."""


def py_literal(value: object) -> Code:
    """A Python literal for ``value`` in ASCII: quotes, backslashes, newlines, ``{{``,
    non-ASCII and control characters all come out escaped inside one string literal."""
    if value is None or isinstance(value, bool):
        return Code(repr(value))
    if isinstance(value, int):
        return Code(repr(value))
    if isinstance(value, float):
        if math.isfinite(value):
            return Code(repr(value))
        return Code(f"float({repr(value)!r})")
    if isinstance(value, str):
        return Code(ascii(value))
    if isinstance(value, (tuple, list)):
        items = [py_literal(v) for v in value]
        if isinstance(value, tuple):
            return Code("(" + ", ".join(items) + ("," if len(items) == 1 else "") + ")")
        return Code("[" + ", ".join(items) + "]")
    raise RenderError(f"cannot write a {type(value).__name__} as a Python literal")


def source_literal(text: str) -> Code:
    """``text`` as a triple-quoted string literal, raw when that is exact, so that an
    embedded module reads as code; otherwise escaped. The literal starts with a newline
    (so that the module's first line starts a line), which the loader drops."""
    body = "\n" + text
    raw_safe = (
        "'''" not in body
        and not body.endswith(("\\", "'"))
        and not any(c == "\r" or (ord(c) < 32 and c not in "\n\t\f") for c in body)
    )
    if raw_safe:
        return Code("r'''" + body + "'''")
    escaped = []
    for char in body:
        if char == "\\":
            escaped.append("\\\\")
        elif char == "'":
            escaped.append("\\'")
        elif char in "\n\t":
            escaped.append(char)
        elif ord(char) < 32 or ord(char) == 127:
            escaped.append(f"\\x{ord(char):02x}")
        else:
            escaped.append(char)
    return Code("'''" + "".join(escaped) + "'''")


def _key(value: tuple[str, ...] | str | None) -> tuple[str, ...]:
    if value is None:
        return ()
    return (value,) if isinstance(value, str) else value


def belief_rows(beliefs: Sequence[Belief], cls: str) -> list[Code]:
    """The table rows of one class, sorted by antecedent and consequent (so that
    regenerating after new mining gives a small diff), strongest first on ties."""
    implication = cls.endswith("_implication")
    rows: list[Code] = []
    chosen = sorted(
        (b for b in beliefs if b.cls == cls),
        key=lambda b: (_key(b.antecedent), _key(b.consequent), -b.z, -b.n, -b.e),
    )
    for belief in chosen:
        if not implication and belief.consequent is not None:
            raise RenderError(f"a {cls} belief has a consequent: {belief.to_json()!r}")
        fields: list[object] = [belief.antecedent]
        if implication:
            fields.append(belief.consequent)
        fields.extend((belief.n, belief.e, belief.z))
        rows.append(py_literal(tuple(fields)))
    return rows


def _finalize(value: object) -> object:
    if isinstance(value, (Code, jinja2.Undefined)):
        # An undefined value raises its own error when printed.
        return value
    raise RenderError(
        f"the template printed a raw {type(value).__name__}; use the py filter: {value!r:.60}"
    )


def environment() -> jinja2.Environment:
    env = jinja2.Environment(
        loader=jinja2.PackageLoader("launch_linter.generate", "templates"),
        autoescape=False,
        undefined=jinja2.StrictUndefined,
        keep_trailing_newline=True,
        trim_blocks=True,
        lstrip_blocks=True,
        finalize=_finalize,
    )
    env.filters["py"] = py_literal
    return env


def render(beliefs: BeliefSet, embedding: Embedding, options: RenderOptions) -> str:
    """The standalone linter's source text."""
    unknown = [c for c in options.classes if c not in BELIEF_CLASSES]
    if unknown:
        raise RenderError(f"unknown belief class(es): {', '.join(unknown)}")
    for module in embedding.modules:
        if not (
            _MODULE_NAME.fullmatch(module.name)
            and _MODULE_PATH.fullmatch(module.path)
            and _SHA256.fullmatch(module.sha256)
        ):
            raise RenderError(f"not an embeddable module: {module.name!r} ({module.path!r})")
    selected = beliefs.restricted(options.classes)
    tables = [
        {
            "cls": cls,
            "variable": Code(cls.upper()),
            "selected": cls in options.classes,
            "meaning": Code(CLASS_TEXT[cls][0]),
            "columns": Code(CLASS_TEXT[cls][1]),
            "rows": belief_rows(selected.beliefs, cls),
        }
        for cls in BELIEF_CLASSES
    ]
    modules = [
        {
            "name": m.name,
            # Checked above to hold only these characters, so they may stand in a comment.
            "path": Code(m.path),
            "is_package": m.is_package,
            "sha256": Code(m.sha256),
            "literal": source_literal(m.source),
        }
        for m in embedding.modules
    ]
    generated = {
        "generator": f"launch-linter {options.version}",
        "command": options.command,
        "beliefs": options.beliefs_source,
        "beliefs_format": BELIEF_FORMAT,
        "p0": selected.p0,
        "min_z": options.min_z,
        "classes": tuple(options.classes),
        "beliefs_count": len(selected.beliefs),
        "sources_sha256": embedding.sha256,
        "python": ".".join(str(v) for v in MIN_PYTHON),
    }
    template = environment().get_template(TEMPLATE)
    return template.render(
        generated=generated,
        tables=tables,
        modules=modules,
        notes=list(embedding.notes),
        min_python=MIN_PYTHON,
        python=Code(".".join(str(v) for v in MIN_PYTHON)),
        knowledge=Code("(" + "".join(source_literal(_knowledge_text(name)) + ", "
                                     for name in BUNDLED_FILES) + ")"),
    )


def _knowledge_text(name: str) -> str:
    """A bundled knowledge file's JSON, which the standalone linter carries as text."""
    return _read_data(bundled_path(name), name)


def _read_data(path: str | None, name: str) -> str:
    """The text of the bundled data file ``name`` at ``path``."""
    if path is None or not os.path.isfile(path):
        raise RenderError(f"the package's knowledge base file {name} cannot be found")
    with open(path, encoding="utf-8") as stream:
        return stream.read()
