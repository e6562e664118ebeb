"""Where beliefs come from: the bundled file, the study's, none, or a file."""

from __future__ import annotations

import json
import os

from launch_linter.model.beliefs import BeliefFormatError, BeliefSet

BUNDLED = "beliefs-bundled.json"
STUDY = "beliefs-study.json"


class BeliefsNotFound(ValueError):
    """The named beliefs cannot be read."""


def load_beliefs(spec: str, min_z: float) -> BeliefSet:
    """``spec`` is ``bundled``, ``study``, ``none`` or a path to a beliefs file."""
    if spec == "none":
        return BeliefSet("none", min_z, ())
    if spec in ("bundled", "study"):
        name = BUNDLED if spec == "bundled" else STUDY
        try:
            # The package data sits beside this module (importlib.resources.files needs 3.9).
            path = os.path.join(os.path.dirname(os.path.abspath(__file__)), "data", name)
            with open(path, encoding="utf-8") as handle:
                text = handle.read()
        except OSError as exc:
            raise BeliefsNotFound(f"the {spec} beliefs file is not installed: {exc}") from None
        return BeliefSet.from_json(json.loads(text), spec, min_z)
    try:
        with open(spec, encoding="utf-8") as handle:
            data = json.load(handle)
    except (OSError, json.JSONDecodeError) as exc:
        raise BeliefsNotFound(f"cannot read beliefs file {spec}: {exc}") from None
    try:
        return BeliefSet.from_json(data, spec, min_z)
    except BeliefFormatError as exc:
        raise BeliefsNotFound(f"{spec}: {exc}") from None
