"""How a package runs Launch-Linter from its pytest tests (as with ament_flake8)."""

from __future__ import annotations

import pytest
from ament_launch_linter.main import main


@pytest.mark.launch_linter
@pytest.mark.linter
def test_launch_linter() -> None:
    assert main(argv=[]) == 0, "Found launch file problems"
