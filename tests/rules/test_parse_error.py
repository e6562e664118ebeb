"""parse_error: a file without a single element is info as its own root, an error where
another file includes it."""

from __future__ import annotations

from pathlib import Path

from launch_linter.engine import LintOptions, lint_paths
from launch_linter.model.diagnostic import Severity

RULE = "parse_error"


def levels(paths: list[Path]) -> list[tuple[str, int, Severity]]:
    options = LintOptions(package_paths=(), select=frozenset({RULE}))
    result = lint_paths([str(p) for p in paths], options)
    return sorted((Path(d.path).name, d.line, d.severity) for d in result.diagnostics)


def test_an_empty_file_alone_is_a_placeholder(tmp_path: Path) -> None:
    """samples8: empty `.launch` and `.urdf` files that nothing loads (qiqiguaitm/
    mobile_manipulator's tracer.urdf, camera_driver_test.launch) were errors."""
    empty = tmp_path / "placeholder.launch"
    empty.write_text("")
    prolog = tmp_path / "prolog.launch"
    prolog.write_text('<?xml version="1.0"?>\n<!-- to do -->\n')
    description = tmp_path / "robot.urdf"
    description.write_text("")
    assert levels([empty, prolog, description]) == [
        ("placeholder.launch", 1, Severity.INFO), ("prolog.launch", 3, Severity.INFO),
        ("robot.urdf", 1, Severity.INFO)]


def test_an_empty_file_another_includes_stays_an_error(tmp_path: Path) -> None:
    empty = tmp_path / "empty.launch"
    empty.write_text("")
    main = tmp_path / "main.launch"
    main.write_text(f'<launch><include file="{empty}"/></launch>\n')
    assert levels([main, empty]) == [("empty.launch", 1, Severity.ERROR)]
    assert levels([main]) == [("empty.launch", 1, Severity.ERROR)]


def test_a_broken_file_with_elements_stays_an_error(tmp_path: Path) -> None:
    broken = tmp_path / "broken.launch"
    broken.write_text("<launch>\n  <node pkg='a' type='b' name='c'>\n</launch>\n")
    # Placed at the <node> left open, not at the '</launch>' where expat stops.
    assert levels([broken]) == [("broken.launch", 2, Severity.ERROR)]
    # expat says "no element found" also for a root left open at the end of the file.
    unclosed = tmp_path / "unclosed.launch"
    unclosed.write_text("<launch>\n  <node pkg='a' type='b' name='c'/>\n")
    assert levels([unclosed]) == [("unclosed.launch", 3, Severity.ERROR)]
