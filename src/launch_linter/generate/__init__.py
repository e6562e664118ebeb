"""The linter generator: a standalone linter rendered from the package's own modules and beliefs."""
