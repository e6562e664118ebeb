"""Fixtures for the evaluation tests."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest
from evaluation_helpers import build_db

MakeDb = Callable[[list[dict[str, Any]]], tuple[Path, Path]]


@pytest.fixture
def make_db(tmp_path: Path) -> MakeDb:
    """``make_db(rows)`` -> (corpus folder, database), see ``build_db``."""

    def make(rows: list[dict[str, Any]]) -> tuple[Path, Path]:
        return build_db(tmp_path, rows)

    return make
