"""Exit statuses and the usage error, shared by every subcommand (stdlib only, a leaf)."""

from __future__ import annotations

EXIT_OK = 0
EXIT_FINDINGS = 1
"""``check`` found a diagnostic at or above ``--fail-on``."""
EXIT_USAGE = 2
"""A usage mistake, an unreadable input the command needs, or an internal error."""
EXIT_INTERRUPTED = 130
"""``mine`` interrupted by Ctrl-C (128 + SIGINT, as shells report it)."""


class UsageError(Exception):
    """A command-line mistake: reported on stderr, exit status 2."""
