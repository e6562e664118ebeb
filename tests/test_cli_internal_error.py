"""An internal failure is exit status 2 with a one-line message, never a traceback."""

from __future__ import annotations

import pytest

from launch_linter import cli
from launch_linter.commands import check


def test_internal_failure_is_exit_2_without_traceback(
    monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str], tmp_path: object
) -> None:
    def broken(*args: object, **kwargs: object) -> object:
        raise RuntimeError("boom")

    monkeypatch.setattr(check, "lint_command_paths", broken)
    monkeypatch.delenv("LAUNCH_LINTER_DEBUG", raising=False)
    status = cli.main(["check", "--beliefs", "none", str(tmp_path)])
    err = capsys.readouterr().err
    assert status == 2
    assert "internal error: RuntimeError: boom" in err
    assert "Traceback" not in err


def test_debug_variable_shows_the_traceback(
    monkeypatch: pytest.MonkeyPatch, tmp_path: object
) -> None:
    def broken(*args: object, **kwargs: object) -> object:
        raise RuntimeError("boom")

    monkeypatch.setattr(check, "lint_command_paths", broken)
    monkeypatch.setenv("LAUNCH_LINTER_DEBUG", "1")
    with pytest.raises(RuntimeError):
        cli.main(["check", "--beliefs", "none", str(tmp_path)])
