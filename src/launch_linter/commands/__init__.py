"""The subcommands of ``launch-linter``: each module owns its ``add_parser`` and ``run``.

``common`` (exit statuses, :class:`~launch_linter.commands.common.UsageError`) is a leaf;
``options`` turns the shared resolution and selection flags into ``LintOptions``;
``launch_linter.cli`` only assembles the parser and dispatches.
"""
