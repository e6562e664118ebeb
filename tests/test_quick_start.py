"""The README's install commands hold on every supported Python, and CI runs them as written.

Installing for real on 3.8, 3.10, 3.12 and 3.13 takes minutes: scripts/quick_start_trial.py
does it. Here: each lock file pins exactly one version of every package it names for every
Python from 3.8 to 3.13 (so pip never meets two pins, or none, of a package it needs), the
project's own dependencies among them, and .ci/run runs the README's test command word for
word on both its Pythons.
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest

markers = pytest.importorskip("packaging.markers")
requirements = pytest.importorskip("packaging.requirements")

ROOT = Path(__file__).resolve().parent.parent
PYTHONS = ("3.8.18", "3.9.18", "3.10.13", "3.11.7", "3.12.1", "3.13.0")


def pins(lock: str) -> list[requirements.Requirement]:
    lines = (ROOT / lock).read_text().splitlines()
    return [requirements.Requirement(line) for line in lines
            if line.strip() and not line.lstrip().startswith("#")]


def environment(python: str) -> dict[str, str]:
    return {"python_version": ".".join(python.split(".")[:2]), "python_full_version": python,
            "sys_platform": "linux", "platform_machine": "x86_64", "os_name": "posix",
            "platform_python_implementation": "CPython", "implementation_name": "cpython",
            "platform_system": "Linux"}


def chosen(lock: str, python: str) -> dict[str, list[str]]:
    picked: dict[str, list[str]] = {}
    for pin in pins(lock):
        if pin.marker is None or pin.marker.evaluate(environment(python)):
            picked.setdefault(pin.name.lower().replace("_", "-"), []).append(str(pin.specifier))
    return picked


def project_dependencies(python: str) -> set[str]:
    text = (ROOT / "pyproject.toml").read_text()
    block = re.search(r"^dependencies = \[(.*?)^\]", text, re.DOTALL | re.MULTILINE)
    assert block is not None
    wanted = set()
    for line in re.findall(r'"([^"]+)"', block.group(1)):
        dependency = requirements.Requirement(line)
        if dependency.marker is None or dependency.marker.evaluate(environment(python)):
            wanted.add(dependency.name.lower())
    return wanted


@pytest.mark.parametrize("python", PYTHONS)
@pytest.mark.parametrize("lock", ["requirements.lock", "requirements-dev.lock"])
def test_every_python_gets_one_exact_pin_of_each_dependency(lock: str, python: str) -> None:
    picked = chosen(lock, python)
    assert all(len(specs) == 1 and specs[0].startswith("==") for specs in picked.values()), {
        name: specs for name, specs in picked.items() if len(specs) != 1}
    missing = project_dependencies(python) - set(picked)
    assert not missing, f"{lock} pins nothing of {missing} for Python {python}"


def test_tomli_only_where_tomllib_is_missing() -> None:
    assert "tomli" in chosen("requirements.lock", "3.8.18")
    assert "tomli" in chosen("requirements.lock", "3.10.13")
    assert "tomli" not in chosen("requirements.lock", "3.11.7")


def test_language_server_pins_reach_every_python() -> None:
    for python in PYTHONS:
        assert "pygls" in chosen("requirements-dev.lock", python), python


def test_ci_runs_the_readme_test_command_on_both_pythons() -> None:
    readme = (ROOT / "README.md").read_text()
    blocks = re.findall(r"```sh\n(.*?)```", readme, re.DOTALL)
    command = blocks[1].strip()
    assert command.startswith("python -m pip install -q -r requirements-dev.lock")
    assert (ROOT / ".ci" / "run").read_text().count(command) == 2


def test_readme_names_only_lock_files_that_exist() -> None:
    readme = (ROOT / "README.md").read_text()
    for name in set(re.findall(r"requirements[\w-]*\.lock", readme)):
        assert (ROOT / name).is_file(), name
