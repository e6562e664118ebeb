"""On every launch fixture of the repository, the generated linter reports exactly what
``launch-linter check`` reports with the same beliefs and threshold.

Compared: the ``diagnostics`` and ``files`` arrays, and ``beliefs`` too. The ``tool`` block
is the same as well (the standalone linter embeds the package's own JSON reporter and
version), so the whole document is compared. The generated linter runs as documented,
``python -I``: ROS 2 YAML launch files need PyYAML, which it uses when the Python running
it has it (without it such a file is a parse_error that says so, tested below).
"""

from __future__ import annotations

import json
from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest
from standalone_helpers import (
    FIXTURES,
    REPO,
    Generated,
    json_pair,
    launch_fixtures,
    other_pythons,
    run_standalone,
)


def _differences(expected: dict[str, Any], actual: dict[str, Any]) -> list[str]:
    out = []
    for key in ("files", "diagnostics"):
        missing = [e for e in expected[key] if e not in actual[key]]
        extra = [a for a in actual[key] if a not in expected[key]]
        out.extend(f"{key} only from check: {m}" for m in missing[:5])
        out.extend(f"{key} only from the generated linter: {m}" for m in extra[:5])
    return out


def test_there_are_fixtures_to_compare() -> None:
    fixtures = launch_fixtures()
    assert len(fixtures) >= 5
    assert str((FIXTURES / "implied.launch").relative_to(REPO)) in fixtures


@pytest.mark.parametrize(
    "options",
    [
        [],
        ["--package-path", str((FIXTURES / "pkgs").relative_to(REPO)), "--env",
         "SENSOR_FRAME=lidar", "--arg", "offset:=0.5", "--arg", "sensor:=velodyne"],
        ["--select", "may_implied,tf", "--fail-on", "info"],
        ["--jobs", "3"],
    ],
    ids=["plain", "resolution-options", "selection", "jobs"],
)
@pytest.mark.parametrize("beliefs", ["bundled", "tests"])
def test_every_fixture_gives_the_same_json(
    generate: Callable[..., Generated], beliefs_file: Path, beliefs: str, options: list[str]
) -> None:
    generated = generate("bundled", 1.0) if beliefs == "bundled" else generate(
        str(beliefs_file), 1.5
    )
    expected, actual = json_pair(generated, [*launch_fixtures(), *options], flags=["-I"])
    assert expected["diagnostics"], "the fixtures should give something to compare"
    assert _differences(expected, actual) == []
    assert actual == expected


def test_without_pyyaml_a_yaml_launch_file_says_what_it_needs(
    standalone: Generated, tmp_path: Path
) -> None:
    (tmp_path / "a.launch.yaml").write_text("launch:\n- arg: {name: x}\n", encoding="utf-8")
    done = run_standalone(standalone.path, ["a.launch.yaml", "--format", "json"], cwd=tmp_path)
    assert done.returncode == 1
    (diagnostic,) = json.loads(done.stdout)["diagnostics"]
    assert diagnostic["rule"] == "parse_error" and "needs PyYAML" in diagnostic["message"]


@pytest.mark.parametrize("python", other_pythons() or [pytest.param(None, marks=pytest.mark.skip(
    reason="no other Python 3.8 to 3.13 found"))])
def test_other_pythons_give_the_same_json(
    generate: Callable[..., Generated], python: str
) -> None:
    """Python 3.8 to 3.13, on every fixture whose launch tree has no YAML file (their
    PyYAML, if any, is not this Python's)."""
    generated = generate("bundled", 1.0)
    options = ["--package-path", str((FIXTURES / "pkgs").relative_to(REPO)),
               "--env", "SENSOR_FRAME=lidar", "--arg", "offset:=0.5"]
    fixtures = launch_fixtures(yaml=False)
    expected, actual = json_pair(generated, [*fixtures, *options], python=python)
    assert _differences(expected, actual) == []
    assert actual == expected
