"""The z-score of a MAY belief (Engler et al.), as the study uses it."""

from __future__ import annotations

import math

DEFAULT_P0 = 0.9


def z_score(n: int, e: int, p0: float = DEFAULT_P0) -> float:
    """``z(n, e) = (e/n - p0) / sqrt(p0 (1 - p0) / n)``.

    ``n`` counts the cases where the antecedent holds and ``e`` those where the consequent
    holds too. The score grows with ``n`` and shrinks with the violations ``n - e``.
    It is rounded to 1e-9 so that scores that are whole on paper, such as z(9, 9) = 1 at
    p0 = 0.9, meet a threshold of that value instead of missing it by a rounding error.
    """
    if n <= 0:
        raise ValueError(f"n must be positive, not {n}")
    if not 0 <= e <= n:
        raise ValueError(f"e must be between 0 and n={n}, not {e}")
    check_p0(p0)
    return round((e / n - p0) / math.sqrt(p0 * (1.0 - p0) / n), 9)


def check_p0(p0: float) -> None:
    """p0 is a probability strictly between 0 and 1 (otherwise z divides by zero)."""
    if not 0.0 < p0 < 1.0:
        raise ValueError(f"p0 must be strictly between 0 and 1, not {p0}")
