"""Measured precision of each rule, from the judged sample (``data/precision.json``).

Written by ``scripts/precision.py`` (see docs/evaluation/precision.md); read by
``launch-linter rules`` and docs/rules.md so that the figures are data, not prose.
"""

from __future__ import annotations

import json
import os
from functools import lru_cache

DATA = "precision.json"


@lru_cache(maxsize=None)
def _table() -> dict[str, dict[str, dict[str, float]]]:
    # A plain file next to the module: a standalone linter (which embeds modules without
    # their data) finds none and says "not measured".
    path = os.path.join(os.path.dirname(os.path.abspath(__file__)), "data", DATA)
    try:
        with open(path, encoding="utf-8") as handle:
            rules = json.load(handle).get("rules", {})
    except (OSError, ValueError):
        return {}
    return rules if isinstance(rules, dict) else {}


def precision_text(rule_id: str) -> str:
    """``100% (6/6)`` at the current levels, or ``0% (0/52) before, now info`` for a rule
    whose warnings and errors went away, ``39% (7/18) at warning, now info`` for one judged
    at warning after the study and lowered since, or ``not measured``."""
    entry = _table().get(rule_id)
    if not entry:
        return "not measured"
    after, before = entry.get("after"), entry.get("before")
    if after:
        return f"{after['precision']:.0%} ({after['true']:g}/{after['judged']:g})"
    if before:
        return (f"{before['precision']:.0%} ({before['true']:g}/{before['judged']:g}) "
                f"at the study's level")
    judged = entry.get("judged")
    if judged:
        return (f"{judged['precision']:.0%} ({judged['true']:g}/{judged['judged']:g}) "
                f"at warning, now info")
    return "not measured"
