"""``launch-linter graph``: the static transform tree of a launch file, drawn."""
