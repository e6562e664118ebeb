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


MAX_NUMBER = 1e6
"""Largest magnitude of a number on the command line (real z-scores are below 100)."""
MAX_JOBS = 1024


def check_numbers(values: dict[str, object]) -> None:
    """Refuse NaN, infinities and out-of-range numbers (``values``: the parsed command
    line's attributes), naming the option."""
    for attribute, option in (("min_z", "--min-z"), ("p0", "--p0")):
        value = values.get(attribute)
        if isinstance(value, float) and (value != value or abs(value) > MAX_NUMBER):
            raise UsageError(f"{option} must be a number, and finite: not {value!r}")
    commits = values.get("mature_commits")
    if isinstance(commits, int) and commits > 10**9:
        raise UsageError(f"--mature-commits must be at most 10^9, not {commits}")
    jobs = values.get("jobs")
    if isinstance(jobs, int) and jobs > MAX_JOBS:
        raise UsageError(f"--jobs must be at most {MAX_JOBS}, not {jobs}")
