"""The language server (``launch-linter server``): the ``lsp`` extra's edge package."""
