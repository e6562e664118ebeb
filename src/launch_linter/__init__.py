"""Launch-Linter: find mistakes in the static transforms that ROS launch files declare."""
from __future__ import annotations

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
