"""A robot description a Python launch file makes with the ``xacro`` module:
``xacro.process_file(path, mappings={...})`` is the document, and its ``toxml()`` or
``toprettyxml(...)`` the text, read as the ``xacro PATH name:=value ...`` command that
``Command([...])`` would run (xacro's ``process_file(input_file_name, **kwargs)`` takes the
``mappings`` as the command line's ``name:=value`` words). The description reader then
expands it as it does every xacro call (:mod:`launch_linter.frontends.robot`).
"""

from __future__ import annotations

import ast
from typing import Protocol

from launch_linter.frontends.ros2_python.values import LazyStr, SubsVal, Unknown, XacroDocVal
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
