"""``launch-linter server`` without the lsp extra says how to get it; the core never
imports pygls."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

from launch_linter.cli import main


def test_without_pygls_the_command_names_the_extra(
        monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]) -> None:
    monkeypatch.setitem(sys.modules, "pygls", None)
    monkeypatch.setitem(sys.modules, "pygls.server", None)
    monkeypatch.delitem(sys.modules, "launch_linter.server.lsp", raising=False)
    assert main(["server"]) == 2
    assert "pip install 'launch-linter[lsp]'" in capsys.readouterr().err


def test_check_imports_no_language_server_library() -> None:
    code = ("import sys; from launch_linter.cli import main; main(['check', 'examples']); "
            "print(sorted(m for m in sys.modules if m.split('.')[0] in "
            "('pygls', 'lsprotocol') or m.startswith('launch_linter.server')))")
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                          check=False, cwd=Path(__file__).resolve().parents[2])
    assert done.stdout.strip().splitlines()[-1] == "[]", done.stderr
