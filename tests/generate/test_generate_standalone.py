"""The generated file: its structure, and running it as a user would (``python -I``)."""

from __future__ import annotations

import ast
import json
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest
from standalone_helpers import (
    BELIEFS,
    FIXTURES,
    REPO,
    Generated,
    run_check,
    run_standalone,
)

from launch_linter import __version__
from launch_linter.generate.commands import generate_text
from launch_linter.generate.embed import sources_sha256
from launch_linter.model.beliefs import BELIEF_CLASSES, BeliefSet

IMPLIED = str((FIXTURES / "implied.launch").relative_to(REPO))
CLEAN = str((FIXTURES / "clean.launch").relative_to(REPO))


def _outside_modules(text: str) -> str:
    return text[: text.index("\nMODULES = {}\n")]


def test_header_says_how_and_from_what(standalone: Generated) -> None:
    generated = standalone.assigned("GENERATED")
    assert generated == {
        "generator": f"launch-linter {__version__}",
        "command": f"launch-linter generate --beliefs {standalone.beliefs} --min-z 1.0",
        "beliefs": standalone.beliefs,
        "beliefs_format": "launch-linter-beliefs/1",
        "p0": 0.9,
        "min_z": 1.0,
        "classes": BELIEF_CLASSES,
        "beliefs_count": sum(1 for b in BELIEFS["beliefs"] if b["z"] >= 1.0),
        "sources_sha256": generated["sources_sha256"],
        "python": "3.8",
    }
    modules = standalone.modules()
    assert generated["sources_sha256"] == sources_sha256(
        sorted((name, text[1:]) for name, text in modules.items())
    )
    lines = standalone.text.splitlines()
    assert lines[0] == "#!/usr/bin/env python3"
    # The version check comes before anything that an old Python could fail on.
    first_import = next(i for i, line in enumerate(lines) if line.startswith("import "))
    assert lines[first_import : first_import + 3] == [
        "import sys", "", "if sys.version_info < (3, 8):"
    ]
    assert not re.search(r"\d{4}-\d\d-\d\d|\d\d:\d\d:\d\d", _outside_modules(standalone.text))


def test_the_file_is_python_3_8_and_reads_the_same_every_time(standalone: Generated) -> None:
    ast.parse(standalone.text, feature_version=(3, 8))
    assert _outside_modules(standalone.text).isascii()
    again = [generate_text(standalone.beliefs, 1.0, BELIEF_CLASSES) for _ in range(2)]
    assert again[0] == again[1]


def _row_key(row: tuple[object, ...]) -> tuple[tuple[object, ...], ...]:
    return tuple((f,) if isinstance(f, str) else tuple(f) for f in row[:-3])  # type: ignore[arg-type]


def test_belief_tables_are_sorted_one_per_class(standalone: Generated) -> None:
    expected = BeliefSet.from_json(BELIEFS, "x", 1.0)
    positions = [standalone.text.index(f"\n{cls.upper()} = [") for cls in BELIEF_CLASSES]
    assert positions == sorted(positions)
    for cls in BELIEF_CLASSES:
        rows = standalone.assigned(cls.upper())
        assert rows == sorted(rows, key=_row_key)
        assert len(rows) == len(expected.of_class(cls))
    assert ("map_to_odom", 25, 24, 1.0) in standalone.assigned("NAME_NULL_ROT")
    assert (("map", "odom"), ("odom", "base_link"), 40, 39, 2.1) in standalone.assigned(
        "SIG_IMPLICATION"
    )


def test_exit_status_and_text_output_match_the_package(standalone: Generated) -> None:
    for args in ([IMPLIED], [CLEAN], [IMPLIED, "--fail-on", "error"], [CLEAN, "--fail-on", "info"],
                 [IMPLIED, "--select", "may_implied", "--ignore", "sig_null_rot"],
                 [IMPLIED, "--format", "sarif"], [IMPLIED, "--format", "github"]):
        status, out, err = run_check(["--beliefs", standalone.beliefs, *args])
        done = run_standalone(standalone.path, args)
        assert (done.returncode, done.stdout, done.stderr) == (status, out, err), args
    assert run_standalone(standalone.path, [IMPLIED]).returncode == 1
    assert run_standalone(standalone.path, [CLEAN]).returncode == 0


@pytest.mark.parametrize(
    ("args", "message"),
    [
        ([CLEAN, "--select", "no_such_rule"], "unknown rule id"),
        ([CLEAN, "--arg", "no-separator"], "--arg must look like"),
        ([CLEAN, "--format", "yaml"], "invalid choice"),
    ],
)
def test_usage_errors_exit_2(standalone: Generated, args: list[str], message: str) -> None:
    done = run_standalone(standalone.path, args)
    assert done.returncode == 2 and message in done.stderr


def test_help_shows_the_check_options(standalone: Generated) -> None:
    done = run_standalone(standalone.path, ["--help"])
    assert done.returncode == 0
    for option in ("--format", "--select", "--ignore", "--fail-on", "--arg", "--package-path"):
        assert option in done.stdout


def test_it_runs_from_an_empty_folder_with_the_documented_command(
    standalone: Generated, tmp_path: Path
) -> None:
    script = tmp_path / "lint.py"
    shutil.copy(standalone.path, script)
    (tmp_path / "a.launch").write_text((FIXTURES / "implied.launch").read_text())
    done = run_standalone(script, ["a.launch", "--format", "json"], cwd=tmp_path, flags=["-I"])
    assert done.returncode == 1, done.stderr
    document = json.loads(done.stdout)
    assert document["files"] == [{"path": "a.launch", "status": "ok", "transforms": 3}]


def test_the_package_is_never_imported(standalone: Generated) -> None:
    probe = (
        "import runpy, sys; runpy.run_path(sys.argv[1]); import launch_linter.engine as e; "
        "print(type(e.__spec__.loader).__name__, e.__spec__.origin)"
    )
    done = subprocess.run(
        [sys.executable, "-I", "-c", probe, str(standalone.path)],
        capture_output=True, text=True, check=False, timeout=120,
    )
    assert done.returncode == 0, done.stderr
    assert done.stdout.split()[0] == "_EmbeddedModules"


def test_it_refuses_to_mix_with_the_installed_package(standalone: Generated) -> None:
    probe = "import runpy, sys, launch_linter; runpy.run_path(sys.argv[1])"
    done = subprocess.run(
        [sys.executable, "-I", "-c", probe, str(standalone.path)],
        capture_output=True, text=True, check=False, timeout=120,
    )
    assert done.returncode == 1 and "cannot run in a process that has imported" in done.stderr


def test_beliefs_options(standalone: Generated, beliefs_file: Path) -> None:
    def document(*args: str) -> dict[str, object]:
        done = run_standalone(standalone.path, [IMPLIED, "--format", "json", *args])
        assert done.returncode in (0, 1), done.stderr
        result: dict[str, object] = json.loads(done.stdout)
        return result

    assert document("--beliefs", "none")["beliefs"] == {"source": "none", "min_z": 1.0, "count": 0}
    raised = document("--min-z", "2.0")
    assert raised["beliefs"] == {"source": str(beliefs_file), "min_z": 2.0, "count": 3}
    lowered = document("--min-z", "0.1")
    assert lowered["beliefs"]["min_z"] == 1.0  # type: ignore[index]
    from_file = document("--beliefs", str(beliefs_file), "--min-z", "0.1")
    assert from_file["beliefs"]["min_z"] == 0.1  # type: ignore[index]
    _, out, _ = run_check(["--format", "json", "--beliefs", str(beliefs_file),
                          "--min-z", "0.1", IMPLIED])
    assert json.loads(out)["diagnostics"] == from_file["diagnostics"]
    done = run_standalone(standalone.path, [IMPLIED, "--beliefs", "study"])
    assert done.returncode == 2 and "carries only the beliefs it was generated from" in done.stderr


def test_a_pruned_belief_is_no_longer_checked(standalone: Generated, tmp_path: Path) -> None:
    row = "    (('world', 'map'), 30, 30, 3.16),\n"
    assert row in standalone.text
    pruned = tmp_path / "pruned.py"
    pruned.write_text(standalone.text.replace(row, ""), encoding="utf-8")

    def rules(script: Path) -> list[str]:
        done = run_standalone(script, [IMPLIED, "--format", "json"])
        return [d["rule"] for d in json.loads(done.stdout)["diagnostics"]]

    before, after = rules(standalone.path), rules(pruned)
    assert "sig_null_disp" in before and "sig_null_disp" not in after
    assert sorted(before) == sorted([*after, "sig_null_disp"])


@pytest.mark.parametrize(
    ("row", "message"),
    [
        ("    (('world', 'map'), 30, 3.16),\n", "SIG_NULL_DISP has a row that is not"),
        ("    (('world', 'map'), 30, 30, 'high'),\n", "malformed belief"),
    ],
)
def test_a_table_broken_by_hand_is_a_usage_error(
    standalone: Generated, tmp_path: Path, row: str, message: str
) -> None:
    edited = tmp_path / "edited.py"
    edited.write_text(
        standalone.text.replace("    (('world', 'map'), 30, 30, 3.16),\n", row), encoding="utf-8"
    )
    done = run_standalone(edited, [CLEAN])
    assert done.returncode == 2 and message in done.stderr
    assert "Traceback" not in done.stderr


def test_an_internal_failure_exits_2(standalone: Generated, tmp_path: Path) -> None:
    broken = tmp_path / "broken.py"
    broken.write_text(
        standalone.text.replace("def lint_paths(", "def lint_paths(*_a, **_k):\n    raise"
                                " RuntimeError('boom')\n\n\ndef _unused_lint_paths(", 1),
        encoding="utf-8",
    )
    done = run_standalone(broken, [CLEAN])
    assert done.returncode == 2
    assert "RuntimeError: boom" in done.stderr and "internal error" in done.stderr


def _python(version: str) -> str | None:
    for path in sorted((Path.home() / ".pyenv" / "versions").glob(f"{version}.*/bin/python3")):
        return str(path)
    return shutil.which(f"python{version}")


@pytest.mark.skipif(_python("3.7") is None, reason="no Python 3.7 interpreter found")
def test_too_old_a_python_is_told_so(standalone: Generated) -> None:
    python = _python("3.7")
    assert python is not None
    done = run_standalone(standalone.path, [CLEAN], python=python)
    assert done.returncode == 2 and "needs Python 3.8 or newer" in done.stderr


def test_the_results_cache_works_in_a_standalone_linter(
    standalone: Generated, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Its modules have no ``__file__``: the script stamps the tool in the cache's key (a
    run with the cache was an internal error)."""
    from launch_linter.commands.options import NO_CACHE_VARIABLE

    monkeypatch.delenv(NO_CACHE_VARIABLE, raising=False)
    shutil.copy(FIXTURES / "implied.launch", tmp_path / "implied.launch")
    runs = [run_standalone(standalone.path, ["--format", "json", "implied.launch"], tmp_path)
            for _ in range(2)]
    assert [run.returncode for run in runs] == [1, 1], runs[0].stderr
    assert runs[0].stdout == runs[1].stdout
    assert list((tmp_path / ".launch-linter-cache").glob("results-*.json"))
    monkeypatch.setenv(NO_CACHE_VARIABLE, "1")
    plain = run_standalone(standalone.path, ["--format", "json", "implied.launch"], tmp_path)
    assert plain.stdout == runs[0].stdout
