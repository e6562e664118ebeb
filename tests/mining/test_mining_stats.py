from __future__ import annotations

import math

import pytest

from launch_linter.mining.stats import z_score


def test_the_studys_example() -> None:
    # (42/42 - 0.9) / sqrt(0.9 · 0.1 / 42) = 0.1 / 0.046291 = 2.1602
    assert round(z_score(42, 42), 2) == 2.16
    assert z_score(42, 42) == pytest.approx(2.160247, abs=1e-6)


@pytest.mark.parametrize(
    ("n", "e", "p0", "expected"),
    [
        (9, 9, 0.9, 1.0),  # 0.1 / sqrt(0.09 / 9) = 0.1 / 0.1
        (36, 36, 0.9, 2.0),  # 0.1 / sqrt(0.09 / 36) = 0.1 / 0.05
        (900, 900, 0.9, 10.0),  # 0.1 / 0.01
        (10, 9, 0.9, 0.0),  # e/n equals p0
        (30, 29, 0.9, 1.217161),  # 0.066667 / 0.054772
        (2, 0, 0.9, -4.242641),  # -0.9 / 0.212132
        (27, 26, 0.9, 1.090551),  # 0.062963 / 0.057735
        (42, 42, 0.85, 2.722456),  # 0.15 / 0.055097: the p0 of the study's artifact
    ],
)
def test_hand_computed(n: int, e: int, p0: float, expected: float) -> None:
    assert z_score(n, e, p0) == pytest.approx(expected, abs=1e-6)


def test_whole_scores_meet_their_threshold() -> None:
    # Without rounding, z(9, 9) is 0.9999999999999999 and would miss --min-z 1.
    assert z_score(9, 9) >= 1.0
    assert z_score(36, 36) >= 2.0


def test_grows_with_support_and_falls_with_violations() -> None:
    assert z_score(20, 20) > z_score(10, 10)
    assert z_score(20, 19) < z_score(20, 20)
    assert math.isclose(z_score(100, 90), 0.0, abs_tol=1e-9)


@pytest.mark.parametrize(("n", "e", "p0"), [(0, 0, 0.9), (3, 4, 0.9), (3, -1, 0.9),
                                            (3, 3, 1.0), (3, 3, 0.0)])
def test_rejects_impossible_input(n: int, e: int, p0: float) -> None:
    with pytest.raises(ValueError):
        z_score(n, e, p0)
