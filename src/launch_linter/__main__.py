from __future__ import annotations

import sys

from launch_linter.cli import entry

sys.exit(entry())
