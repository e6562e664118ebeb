"""Fixtures for the evaluation tests."""

from __future__ import annotations

from pathlib import Path
from typing import Any, Callable, Dict, List, Tuple

import pytest
from evaluation_helpers import build_db

MakeDb = Callable[[List[Dict[str, Any]]], Tuple[Path, Path]]


@pytest.fixture
def make_db(tmp_path: Path) -> MakeDb:
    """``make_db(rows)`` -> (corpus folder, database), see ``build_db``."""

    def make(rows: list[dict[str, Any]]) -> tuple[Path, Path]:
        return build_db(tmp_path, rows)

    return make
