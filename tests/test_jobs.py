"""``--jobs N`` lints in several processes with the output of a serial run."""

from __future__ import annotations

from pathlib import Path

import pytest

from launch_linter import LintOptions, lint_paths
from launch_linter.cli import main

NODE = '  <node pkg="tf2_ros" type="static_transform_publisher" name="{name}" args="{args}"/>'


def write_tree(folder: Path) -> None:
    """Eleven files: includes across files, errors, a suppression, a broken file."""
    for i in range(8):
        lines = ["<launch>"]
        if i % 3 == 0:
            lines.append("  <!-- launch-linter: disable=dup_sig -->")
        lines.append(NODE.format(name=f"n{i}", args=f"0 0 {i} 0 0 0 base_link sensor{i}"))
        lines.append(NODE.format(name=f"m{i}", args=f"0 0 1 0 0 0 base_link sensor{i}"))
        if i % 2 == 0:
            lines.append(NODE.format(name=f"n{i}", args="0 0 0 0 0 0 /map /map"))
        if i > 0:
            lines.append(f'  <include file="$(dirname)/part{i - 1}.launch"/>')
        lines.append("</launch>")
        (folder / f"part{i}.launch").write_text("\n".join(lines))
    (folder / "broken.launch").write_text("<launch><node></launch>")
    (folder / "sub").mkdir()
    (folder / "sub" / "a.launch.xml").write_text(
        "<launch>\n" + NODE.format(name="x", args="0 0 0 0 0 0 $(arg p) c") + "\n</launch>"
    )
    (folder / "sub" / "notes.xml").write_text("<notes/>")


def test_parallel_result_equals_serial(tmp_path: Path) -> None:
    write_tree(tmp_path)
    serial = lint_paths([str(tmp_path)], LintOptions(package_paths=()))
    parallel = lint_paths([str(tmp_path)], LintOptions(package_paths=(), jobs=2))
    assert len(serial.files) == 10 and len(serial.diagnostics) > 20
    assert parallel == serial
    many = lint_paths([str(tmp_path)], LintOptions(package_paths=(), jobs=16))
    assert many == serial


def test_cli_output_is_identical(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    write_tree(tmp_path)
    monkeypatch.chdir(tmp_path)
    outputs = []
    for jobs in ("1", "2", "3"):
        for fmt in ("json", "sarif", "text"):
            status = main(["check", ".", "--beliefs", "none", "--format", fmt, "--jobs", jobs])
            outputs.append((jobs, fmt, status, capsys.readouterr()))
    by_format: dict[str, set[tuple[int, str, str]]] = {}
    for jobs, fmt, status, captured in outputs:
        by_format.setdefault(fmt, set()).add((status, captured.out, captured.err))
        assert status == 1, jobs
    assert all(len(variants) == 1 for variants in by_format.values())


def test_jobs_must_be_positive(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    for jobs in ("0", "-1"):
        assert main(["check", str(tmp_path), "--beliefs", "none", "--jobs", jobs]) == 2
        assert "--jobs" in capsys.readouterr().err


def test_the_default_job_count_is_one_for_few_files_and_bounded_by_the_cpus() -> None:
    import os

    from launch_linter.engine import FILES_PER_JOB, auto_jobs

    assert auto_jobs(0) == auto_jobs(1) == auto_jobs(FILES_PER_JOB - 1) == 1
    assert 1 <= auto_jobs(10**6) <= (os.cpu_count() or 1)


def test_automatic_jobs_give_the_serial_result(tmp_path: Path) -> None:
    from launch_linter.engine import AUTO_JOBS

    (tmp_path / "a.launch").write_text(
        '<launch><node pkg="tf" type="static_transform_publisher" name="t" '
        'args="0 0 0 0 0 0 a a 100"/></launch>'
    )
    serial = lint_paths([str(tmp_path)], LintOptions(jobs=1))
    assert lint_paths([str(tmp_path)], LintOptions(jobs=AUTO_JOBS)) == serial
