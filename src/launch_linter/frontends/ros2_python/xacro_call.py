"""A robot description a Python launch file makes with the ``xacro`` module:
``xacro.process_file(path, mappings={...})`` is the document, and its ``toxml()`` or
``toprettyxml(...)`` the text, read as the ``xacro PATH name:=value ...`` command that
``Command([...])`` would run (xacro's ``process_file(input_file_name, **kwargs)`` takes the
``mappings`` as the command line's ``name:=value`` words). The older spelling,
``doc = xacro.parse(open(path))``, ``xacro.process_doc(doc, mappings={...})``,
``doc.toxml()``, is the same command once ``process_doc`` has run on the document. The
description reader then expands it as it does every xacro call
(:mod:`launch_linter.frontends.robot`).
"""

from __future__ import annotations

import ast
from typing import Protocol

from launch_linter.frontends.ros2_python.values import (
    LazyStr,
    OpenFile,
    SubsVal,
    Unknown,
    XacroDocVal,
    XacroParsedDoc,
)
from launch_linter.resolve.ros2_substitution import Call, Sub, Subs, Text

DOCUMENT_TEXT = ("toxml", "toprettyxml")
"""The methods of xacro's document (an ``xml.dom.minidom.Document``) that give its text."""


class Unknowns(Protocol):
    """What the evaluator gives these functions."""

    def unknown(self, node: ast.AST, reason: str) -> Unknown: ...


class Calls(Unknowns, Protocol):
    """What the interpreter (``calls.Calls``) gives these functions."""

    def arg(self, args: list[object], kwargs: dict[str, object], position: int,
            name: str) -> object: ...

    def subs(self, value: object, node: ast.AST, what: str) -> Subs: ...

    def segment(self, node: ast.AST) -> str: ...


def process_file(interp: Calls, args: list[object], kwargs: dict[str, object],
                 node: ast.Call) -> object:
    """``xacro.process_file(input_file_name, mappings=...)``: its document, kept as the
    command whose output its text is."""
    path = interp.arg(args, kwargs, 0, "input_file_name")
    if not isinstance(path, (str, LazyStr, SubsVal)):
        return interp.unknown(node, "xacro.process_file of an unknown file")
    text = xacro_command(interp, interp.subs(path, node, "file"), kwargs.get("mappings"), node)
    return XacroDocVal(text) if isinstance(text, SubsVal) else text


def parse(interp: Calls, args: list[object], kwargs: dict[str, object],
          node: ast.Call) -> object:
    """``xacro.parse(open(path))``: the file's document, expanded by ``process_doc`` later."""
    source = interp.arg(args, kwargs, 0, "inp")
    if isinstance(source, OpenFile):
        return XacroParsedDoc(source.path)
    return interp.unknown(node, "xacro.parse of something other than an opened file")


def process_doc(interp: Calls, args: list[object], kwargs: dict[str, object],
                node: ast.Call) -> object:
    """``xacro.process_doc(doc, mappings=...)``: expands ``doc`` in place (returns None)."""
    document = interp.arg(args, kwargs, 0, "doc")
    if isinstance(document, XacroParsedDoc):
        document.processed = xacro_command(interp, document.path, kwargs.get("mappings"), node)
    return None


def document_text(interp: Unknowns, document: XacroParsedDoc, node: ast.AST) -> object:
    """``doc.toxml()`` of a parsed document: the xacro command's output once
    ``process_doc`` ran on it; before, the unexpanded xacro text, which is not read."""
    if document.processed is None:
        return interp.unknown(node, "a xacro document that xacro.process_doc did not expand")
    return document.processed


def xacro_command(interp: Calls, path: Subs, mappings: object, node: ast.AST) -> object:
    """The ``xacro`` command of ``path`` with ``mappings`` as its ``name:=value`` words
    (unknown when the mappings, or one of their values, are)."""
    words: list[Sub] = [Text("xacro "), *path]
    if mappings is not None:
        if not isinstance(mappings, dict) or not all(isinstance(key, str) for key in mappings):
            return interp.unknown(node, "xacro mappings not known")
        for key, value in mappings.items():
            if isinstance(value, Unknown):
                return value
            words.extend((Text(f" {key}:="), *interp.subs(value, node, "mapping")))
    return SubsVal((Call("command", (tuple(words),), interp.segment(node)),))
