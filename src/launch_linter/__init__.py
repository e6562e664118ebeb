"""Launch-Linter: find mistakes in the static transforms that ROS launch files declare."""
from __future__ import annotations

TYPE_CHECKING = False  # typing is not imported at run time: start-up (docs/performance.md)
if TYPE_CHECKING:
    from typing import Any

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

_ENGINE = ("LintOptions", "LintResult", "lint_paths", "lint_text")
_MODEL = ("Diagnostic", "StaticTransform")


def __getattr__(name: str) -> Any:
    # The API is imported on first use, so that ``launch-linter --version`` (which reads
    # only ``__version__``) does not load the engine, the front-ends and the rules.
    if name in _ENGINE:
        from launch_linter import engine

        value = getattr(engine, name)
    elif name in _MODEL:
        from launch_linter import model

        value = getattr(model, name)
    else:
        raise AttributeError(f"module 'launch_linter' has no attribute {name!r}")
    globals()[name] = value
    return value
