"""Launch-Linter: find mistakes in the static transforms that ROS launch files declare."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from launch_linter.engine import LintOptions, LintResult, lint_paths, lint_text
    from launch_linter.model import Diagnostic, StaticTransform

__version__ = "0.1.0"

__all__ = [
    "Diagnostic",
    "LintOptions",
    "LintResult",
    "StaticTransform",
    "__version__",
    "lint_paths",
    "lint_text",
]

_LAZY = {
    "LintOptions": "launch_linter.engine",
    "LintResult": "launch_linter.engine",
    "lint_paths": "launch_linter.engine",
    "lint_text": "launch_linter.engine",
    "Diagnostic": "launch_linter.model",
    "StaticTransform": "launch_linter.model",
}


def __getattr__(name: str) -> Any:
    # The API is imported on first use, so that ``launch-linter --version`` (which reads
    # only ``__version__``) does not load the engine, the front-ends and the rules.
    module = _LAZY.get(name)
    if module is None:
        raise AttributeError(f"module 'launch_linter' has no attribute {name!r}")
    import importlib

    value = getattr(importlib.import_module(module), name)
    globals()[name] = value
    return value
