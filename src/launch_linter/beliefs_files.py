"""Where beliefs come from: the bundled file, the study's, none, or a file."""

from __future__ import annotations

import json
import os
import re

from launch_linter.model.beliefs import BeliefFormatError, BeliefSet
from launch_linter.resolve import reads
from launch_linter.resolve.xml_safe import read_file_within

BUNDLED = "beliefs-bundled.json"
STUDY = "beliefs-study.json"


MAX_BELIEFS_BYTES = 8 * 1024 * 1024
"""The mined beliefs of the 350-repository corpus take 261 KB; 8 MB of the smallest JSON
items (``{},``) is some 200 MB in memory, where 64 MB ran out of memory under 1 GB."""
MAX_JSON_DEPTH = 64
"""Deepest nesting accepted in a JSON input (a beliefs file needs 4 levels)."""

_JSON_STRING = re.compile(r'"(?:[^"\\]|\\.)*"')
_JSON_BRACKETS = re.compile(r"[\[\]{}]")


def data_folder() -> str:
    """Where the package data sits, beside this module (importlib.resources.files needs
    3.9); asked at each read (a standalone linter has no ``__file__``: it answers the
    reads itself)."""
    return os.path.join(os.path.dirname(os.path.abspath(__file__)), "data")


class BeliefsNotFound(ValueError):
    """The named beliefs cannot be read."""


def _reject_constant(name: str) -> object:
    raise ValueError(f"{name} is not a JSON number")


def load_json(text: str, max_depth: int = MAX_JSON_DEPTH) -> object:
    """``json.loads`` for untrusted text: nesting checked first (in linear time), and NaN,
    Infinity and -Infinity refused (they are not JSON)."""
    depth = 0
    for bracket in _JSON_BRACKETS.finditer(_JSON_STRING.sub("", text)):
        depth += 1 if bracket.group() in "[{" else -1
        if depth > max_depth:
            raise ValueError(f"nested more than {max_depth} levels deep")
    return json.loads(text, parse_constant=_reject_constant)


def load_beliefs(spec: str, min_z: float) -> BeliefSet:
    """``spec`` is ``bundled``, ``study``, ``none`` or a path to a beliefs file."""
    if spec == "none":
        return BeliefSet("none", min_z, ())
    if spec in ("bundled", "study"):
        name = BUNDLED if spec == "bundled" else STUDY
        try:
            with open(os.path.join(data_folder(), name), "rb") as handle:
                content = handle.read()
        except OSError as exc:
            raise BeliefsNotFound(f"the {spec} beliefs file is not installed: {exc}") from None
        # Decoded when a rule first reads it; until then the digest of its bytes stands
        # for it in the results cache's key.
        return BeliefSet.stored(spec, min_z, reads.digest(content), lambda: BeliefSet.from_json(
            json.loads(content.decode("utf-8")), spec, min_z))
    try:
        raw = read_file_within(spec, MAX_BELIEFS_BYTES)
    except OSError as exc:  # FileTooLarge included
        raise BeliefsNotFound(f"cannot read beliefs file {spec}: {exc.strerror or exc}") from None
    try:
        data = load_json(raw.decode("utf-8-sig"))
    except (UnicodeDecodeError, ValueError) as exc:
        raise BeliefsNotFound(f"cannot read beliefs file {spec}: {exc}") from None
    try:
        return BeliefSet.from_json(data, spec, min_z)
    except BeliefFormatError as exc:
        raise BeliefsNotFound(f"{spec}: {exc}") from None
