"""``colcon test`` runs Launch-Linter through ament_lint_auto, for real.

A workspace holds the repository's ament packages (``ament/``) and a sample ament_cmake
package that declares ``ament_lint_auto`` and ``ament_cmake_launch_linter`` as test
dependencies. ``colcon build`` and ``colcon test`` must put the linter's findings in
``colcon test-result``: failing on the planted fault (a frame with two parents), passing
once it is fixed. It needs Debian's (or ROS's) colcon and ament packages (.ci/run installs
them where apt works) and skips, saying why, where they are missing.
"""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
SAMPLE = ROOT / "tests" / "fixtures" / "ament_sample"
# CMake loads ament_package with the python3 on PATH; Debian installs it for /usr/bin's.
SYSTEM_PYTHON = "/usr/bin/python3"


def _missing() -> str | None:
    if shutil.which("colcon", path="/usr/bin") is None:
        return "colcon is not installed (apt-get install colcon python3-colcon-ros ...)"
    probe = subprocess.run(
        [SYSTEM_PYTHON, "-c", "import ament_package, colcon_test_result"],
        capture_output=True, check=False,
    )
    if probe.returncode != 0:
        return "ament_package or colcon's test-result for /usr/bin/python3 is missing"
    for share in ("ament_cmake_core", "ament_lint_auto"):
        if not Path("/usr/share", share).is_dir() and not Path("/opt/ros").is_dir():
            return f"{share} is not installed (apt-get install ament-cmake ament-lint)"
    return None


pytestmark = pytest.mark.skipif(_missing() is not None, reason=str(_missing()))


def colcon(workspace: Path, *args: str) -> subprocess.CompletedProcess[str]:
    env = dict(os.environ)
    env["PATH"] = "/usr/bin:" + env.get("PATH", "")
    # the linter of this checkout, whatever Python colcon and ctest run with
    env["LAUNCH_LINTER"] = f"{sys.executable} -m launch_linter"
    env["PYTHONPATH"] = str(ROOT / "src")
    for name in ("VIRTUAL_ENV", "PYTHONHOME"):
        env.pop(name, None)
    return subprocess.run(["colcon", *args], cwd=workspace, env=env, capture_output=True,
                          text=True, check=False, timeout=300)


def test_colcon_test_reports_findings_and_passes_when_fixed(tmp_path: Path) -> None:
    source = tmp_path / "src"
    for package in ("ament_launch_linter", "ament_cmake_launch_linter"):
        shutil.copytree(ROOT / "ament" / package, source / package)
    shutil.copytree(SAMPLE, source / "sample_robot")

    built = colcon(tmp_path, "build")
    assert built.returncode == 0, built.stdout + built.stderr

    tested = colcon(tmp_path, "test", "--packages-select", "sample_robot")
    assert tested.returncode == 0, tested.stdout + tested.stderr
    results = colcon(tmp_path, "test-result", "--verbose")
    assert results.returncode != 0, results.stdout
    xunit = tmp_path / "build/sample_robot/test_results/sample_robot/launch_linter.xunit.xml"
    assert str(xunit.relative_to(tmp_path)) in results.stdout
    assert "1 failure" in results.stdout, results.stdout
    assert "multiple_parents" in results.stdout
    (failure,) = ET.parse(xunit).getroot().iter("failure")
    assert failure.attrib["type"] == "multiple_parents"

    launch = source / "sample_robot" / "launch" / "robot.launch.xml"
    launch.write_text(launch.read_text().replace(
        "--frame-id mount_link --child-frame-id laser",
        "--frame-id base_link --child-frame-id mount_link"))
    tested = colcon(tmp_path, "test", "--packages-select", "sample_robot")
    assert tested.returncode == 0, tested.stdout + tested.stderr
    results = colcon(tmp_path, "test-result", "--all")
    assert results.returncode == 0, results.stdout
    assert "launch_linter.xunit.xml: 1 test, 0 errors, 0 failures" in results.stdout
