"""How a file's path is shown (see :mod:`launch_linter.model.paths`, where the one
function lives so that rules quoting a path use it too)."""

from __future__ import annotations

from launch_linter.model.paths import shown_path

__all__ = ["shown_path"]
