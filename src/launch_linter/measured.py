"""Measured precision of each rule, from the judged sample (``data/precision.json``).

Written by ``scripts/precision.py`` (see docs/evaluation/precision.md); read by
``launch-linter rules`` and docs/rules.md so that the figures are data, not prose.
"""

from __future__ import annotations

import json
import math
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


SMALL_SAMPLE = 30
"""Below this many judged findings a rate is shown with its 95% interval: 1 of 1 right is
not "100%" as if it were certain."""


def wilson_interval(true: float, judged: float, z: float = 1.96) -> tuple[float, float]:
    """The Wilson score interval of a proportion (95% for ``z`` = 1.96)."""
    if judged <= 0:
        return 0.0, 1.0
    rate = true / judged
    denominator = 1 + z * z / judged
    centre = (rate + z * z / (2 * judged)) / denominator
    spread = z * math.sqrt(rate * (1 - rate) / judged + z * z / (4 * judged * judged))
    return max(0.0, centre - spread / denominator), min(1.0, centre + spread / denominator)


def _rate(entry: dict[str, float]) -> str:
    """``95% of 40 judged``, or ``100% of 1 judged, small sample: 95% interval 21% to 100%``."""
    true, judged = entry["true"], entry["judged"]
    text = f"{entry['precision']:.0%} of {judged:g} judged"
    if judged < SMALL_SAMPLE:
        low, high = wilson_interval(true, judged)
        text += f", small sample: 95% interval {low:.0%} to {high:.0%}"
    return text


def precision_text(rule_id: str) -> str:
    """The precision at the current levels with its sample size (``100% of 6 judged,
    small sample: 95% interval 61% to 100%``), or that of a rule whose warnings and errors
    went away (``... at the study's level``), or of one judged at warning after the study
    and lowered since (``... at warning, now info``), or ``not measured``."""
    entry = _table().get(rule_id)
    if not entry:
        return "not measured"
    after, before = entry.get("after"), entry.get("before")
    if after:
        return _rate(after)
    if before:
        return f"{_rate(before)}; at the study's level"
    judged = entry.get("judged")
    if judged:
        return f"{_rate(judged)}; at warning, now info"
    return "not measured"
