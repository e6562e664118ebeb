#!/usr/bin/env bash
# Regenerates the two lock files, each one file for every supported Python (3.8 to 3.13):
# uv resolves once per Python where the versions must differ and writes environment markers,
# so `python -m pip install -r requirements.lock` picks the right pins on any of them.
# Needs uv (`python -m pip install uv`).
set -euo pipefail
cd "$(dirname "$0")/.."
common=(--universal --python-version 3.8 --quiet)
uv pip compile pyproject.toml "${common[@]}" -o requirements.lock
uv pip compile pyproject.toml requirements-dev.in --extra dev --extra lsp "${common[@]}" \
  -o requirements-dev.lock
