"""Measured precision of each rule, from the judged sample (``data/precision.json``).

Written by ``scripts/precision.py`` (see docs/evaluation/precision.md); read by
``launch-linter rules`` and docs/rules.md so that the figures are data, not prose.
"""

from __future__ import annotations

import json
import math
import os
from functools import lru_cache
from typing import Any

DATA = "precision.json"
VERDICTS = "verdicts.json"
"""The verdicts recorded per rule in docs/evaluation's verdict files, counted as written
(``scripts/verdict_counts.py``): different samples and code states, not one precision."""


def _rules_of(name: str) -> dict[str, Any]:
    # A plain file next to the module: a standalone linter (which embeds modules without
    # their data) finds none and says "not measured".
    path = os.path.join(os.path.dirname(os.path.abspath(__file__)), "data", name)
    try:
        with open(path, encoding="utf-8") as handle:
            rules = json.load(handle).get("rules", {})
    except (OSError, ValueError, AttributeError):
        return {}
    return rules if isinstance(rules, dict) else {}


@lru_cache(maxsize=None)
def _table() -> dict[str, dict[str, dict[str, float]]]:
    return _rules_of(DATA)


@lru_cache(maxsize=None)
def _verdicts() -> dict[str, list[list[Any]]]:
    return _rules_of(VERDICTS)


def _label(label: str) -> str:
    """A verdict label as written, quoted when it is more than one word."""
    return label if label.replace("_", "").isalnum() else repr(label)


def _recorded(rule_id: str) -> str:
    """``not measured``, with the verdicts recorded for the rule where there are some:
    each verdict file and its labels as written, never merged into a rate."""
    files = _verdicts().get(rule_id)
    if not isinstance(files, list) or not files:
        return "not measured"
    shown = "; ".join(
        f"{name} " + ", ".join(f"{count} {_label(label)}" for label, count in labels.items())
        for name, labels in files)
    return ("not measured on one sample; verdicts recorded in docs/evaluation (different "
            f"samples and code states, not a rate): {shown}")


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
    and lowered since (``... at warning, now info``), or ``not measured`` (with the
    verdicts recorded for it elsewhere, per file, where there are some)."""
    entry = _table().get(rule_id)
    if not entry:
        return _recorded(rule_id)
    after, before = entry.get("after"), entry.get("before")
    if after:
        return _rate(after)
    if before:
        return f"{_rate(before)}; at the study's level"
    judged = entry.get("judged")
    if judged:
        return f"{_rate(judged)}; at warning, now info"
    return _recorded(rule_id)
