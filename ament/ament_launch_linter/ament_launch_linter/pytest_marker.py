"""The ``launch_linter`` pytest marker (``linter`` itself comes from ament_lint)."""

from __future__ import annotations

from typing import Any


def pytest_configure(config: Any) -> None:
    config.addinivalue_line(
        "markers", "launch_linter: marks tests checking launch files with Launch-Linter"
    )
