"""Mutation fuzzing of the xacro reader, a few seconds' worth (``scripts/fuzz_xacro.py``
runs the same property long)."""

from __future__ import annotations

from pathlib import Path

from hypothesis import HealthCheck, given, settings
from xacro_fuzzing import check_xacro_case, mutated, seeds

SEEDS = seeds()


def test_mutated_xacro_never_crashes(tmp_path: Path) -> None:
    assert len(SEEDS) >= 5

    @settings(max_examples=60, deadline=None, database=None,
              suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])
    @given(data=mutated(SEEDS))
    def run(data: bytes) -> None:
        check_xacro_case(tmp_path, data)

    run()
