"""Fixtures of the mining tests."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest
from corpus_helpers import MakeCorpus, write_corpus


@pytest.fixture
def make_corpus(tmp_path: Path) -> MakeCorpus:
    """``make_corpus(rows)``: a manifest corpus under ``tmp_path / "corpus"``."""

    def make(rows: list[dict[str, Any]]) -> Path:
        return write_corpus(tmp_path / "corpus", rows)

    return make
