"""Generate standalone linters once per session (cached by their options)."""

from __future__ import annotations

import json
from collections.abc import Callable
from pathlib import Path

import pytest
from standalone_helpers import BELIEFS, Generated

from launch_linter.generate.commands import generate_text
from launch_linter.model.beliefs import BELIEF_CLASSES


@pytest.fixture(scope="session")
def beliefs_file(tmp_path_factory: pytest.TempPathFactory) -> Path:
    path = tmp_path_factory.mktemp("beliefs") / "beliefs.json"
    path.write_text(json.dumps(BELIEFS, ensure_ascii=False), encoding="utf-8")
    return path


@pytest.fixture(scope="session")
def generate(tmp_path_factory: pytest.TempPathFactory) -> Callable[..., Generated]:
    """``generate(beliefs, min_z=1.0, classes=all)``: a standalone linter (cached)."""
    cache: dict[tuple[str, float, tuple[str, ...]], Generated] = {}

    def make(
        beliefs: str, min_z: float = 1.0, classes: tuple[str, ...] = BELIEF_CLASSES
    ) -> Generated:
        key = (beliefs, min_z, classes)
        if key not in cache:
            text = generate_text(beliefs, min_z, classes)
            path = tmp_path_factory.mktemp("generated") / "launch_lint.py"
            path.write_text(text, encoding="utf-8")
            cache[key] = Generated(path, text, beliefs, min_z)
        return cache[key]

    return make


@pytest.fixture(scope="session")
def standalone(generate: Callable[..., Generated], beliefs_file: Path) -> Generated:
    """The linter generated from the test beliefs (threshold 1.0)."""
    return generate(str(beliefs_file), 1.0)
