"""Mutation fuzzing of every front-end, a few seconds' worth (``scripts/fuzz_frontends.py``
runs the same properties for hours)."""

from __future__ import annotations

from pathlib import Path

import pytest
from fuzzing import check_case, mutated, seeds
from hypothesis import HealthCheck, given, settings

SEEDS = seeds()
KINDS = sorted({kind for kind, _ in SEEDS})


def test_every_front_end_has_seeds() -> None:
    assert KINDS == ["py", "ros2", "xml", "yaml"]


@pytest.fixture(scope="module")
def scratch(tmp_path_factory: pytest.TempPathFactory) -> Path:
    return tmp_path_factory.mktemp("fuzz")


@pytest.mark.parametrize("kind", KINDS)
def test_mutated_files_never_crash(kind: str, scratch: Path) -> None:
    pool = [seed for seed in SEEDS if seed[0] == kind]

    @settings(max_examples=40, deadline=None, database=None,
              suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])
    @given(case=mutated(pool))
    def run(case: tuple[str, bytes]) -> None:
        check_case(scratch, *case)

    run()
