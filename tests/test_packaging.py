"""The wheel and sdist: ``python -m build`` makes both, ``twine check`` passes them, and the
wheel installed in a fresh virtual environment lints the examples. One version source.

Building needs the ``build`` and ``twine`` dev dependencies and pip's network access for
the build requirements; without them the build test skips and says why.
"""

from __future__ import annotations

import re
import subprocess
import sys
import venv
import zipfile
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent


def test_one_version_source() -> None:
    from launch_linter import __version__

    pyproject = (ROOT / "pyproject.toml").read_text()
    assert 'dynamic = ["version"]' in pyproject
    assert 'version = {attr = "launch_linter.__version__"}' in pyproject
    assert not re.search(r'^version\s*=\s*"', pyproject, re.MULTILINE)
    # the ament packages carry the version ROS tools read; they must agree
    for manifest in (ROOT / "ament").glob("*/package.xml"):
        assert f"<version>{__version__}</version>" in manifest.read_text(), manifest
    assert f'version="{__version__}"' in (ROOT / "ament/ament_launch_linter/setup.py").read_text()


def test_build_twine_check_and_install_in_a_fresh_venv(tmp_path: Path) -> None:
    pytest.importorskip("build", reason="python -m build needs the build package (dev)")
    pytest.importorskip("twine", reason="twine is a dev dependency")
    from launch_linter import __version__

    dist = tmp_path / "dist"
    built = subprocess.run([sys.executable, "-m", "build", "--outdir", str(dist), str(ROOT)],
                           capture_output=True, text=True, check=False, timeout=600)
    if built.returncode != 0 and "Could not find a version" in built.stdout + built.stderr:
        pytest.skip("the build requirements cannot be downloaded here")
    assert built.returncode == 0, built.stdout[-3000:] + built.stderr[-3000:]
    (wheel,) = dist.glob(f"launch_linter-{__version__}-py3-none-any.whl")
    (sdist,) = dist.glob(f"launch_linter-{__version__}.tar.gz")
    checked = subprocess.run([sys.executable, "-m", "twine", "check", "--strict", str(wheel),
                              str(sdist)], capture_output=True, text=True, check=False)
    assert checked.returncode == 0, checked.stdout + checked.stderr
    names = zipfile.ZipFile(wheel).namelist()
    assert "launch_linter/data/precision.json" in names
    assert any(n.startswith("launch_linter/generate/templates/") for n in names)
    assert "launch_linter/py.typed" in names

    environment = tmp_path / "venv"
    venv.create(environment, with_pip=True)
    python = environment / "bin" / "python"
    installed = subprocess.run(
        [str(python), "-m", "pip", "install", "-q", "-r", str(ROOT / "requirements.lock"),
         str(wheel)], capture_output=True, text=True, check=False, timeout=600)
    assert installed.returncode == 0, installed.stderr[-3000:]
    linted = subprocess.run([str(environment / "bin" / "launch-linter"), "check", "examples"],
                            cwd=ROOT, capture_output=True, text=True, check=False)
    assert linted.returncode == 1, linted.stderr
    assert "[multiple_parents]" in linted.stdout
    version = subprocess.run([str(environment / "bin" / "launch-linter"), "--version"],
                             capture_output=True, text=True, check=False)
    assert version.stdout.strip() == f"launch-linter {__version__}"
