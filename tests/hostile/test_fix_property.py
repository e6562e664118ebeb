"""The fix property, a bounded number of cases (``scripts/fuzz_fix.py`` runs it long)."""

from __future__ import annotations

from fix_property import check_fix_property, launch_files
from hypothesis import HealthCheck, given, settings


@settings(max_examples=150, deadline=None, database=None,
          suppress_health_check=[HealthCheck.too_slow])
@given(case=launch_files())
def test_fixes_change_exactly_the_named_words(case: tuple[str, bytes, bytes]) -> None:
    check_fix_property(*case)
