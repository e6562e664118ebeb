"""Every test runs without the results cache unless it asks for it: a ``check`` run in the
repository or a test's folder must not leave a cache folder there, nor answer from one
that another test left (tests/test_results_cache.py turns it on where it is tested)."""

from __future__ import annotations

import pytest

from launch_linter.commands.options import NO_CACHE_VARIABLE


@pytest.fixture(autouse=True)
def _no_results_cache(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv(NO_CACHE_VARIABLE, "1")
