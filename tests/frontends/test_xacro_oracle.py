"""Differential test: our xacro expansion against the real xacro (PyPI ``xacro``).

``scripts/xacro_oracle_driver.py`` runs the real xacro in its own process (it keeps global
state) with ``$(find)`` answered from the fixture packages; the joints of our expansion
(name, type, parent, child, origin xyz and rpy within 1e-9) must equal its output. The
package never imports xacro; without it these tests skip and say why.
"""

from __future__ import annotations

import importlib.util
import json
import subprocess
import sys
from pathlib import Path
from typing import Optional, Tuple

import pytest

from launch_linter.frontends.robot.urdf import joints_of
from launch_linter.frontends.robot.xacro import expand
from launch_linter.model.robot import DescriptionKind, DescriptionSource
from launch_linter.model.transform import Condition

ROOT = Path(__file__).resolve().parent.parent.parent
DRIVER = ROOT / "scripts" / "xacro_oracle_driver.py"
FIXTURES = ROOT / "tests" / "fixtures"
PACKAGES = {
    "demo_description": FIXTURES / "robot_ws" / "src" / "demo_description",
    "urdf_tutorial": FIXTURES / "robot_real" / "urdf_tutorial",
}
DEMO = PACKAGES["demo_description"] / "urdf" / "robot.urdf.xacro"
CASES: list[tuple[Path, dict[str, str]]] = [
    (DEMO, {}),
    (DEMO, {"use_lidar": "false", "prefix": "r1_", "lidar_height": "0.5"}),
    (DEMO.parent / "features.urdf.xacro", {}),
    (FIXTURES / "robot_real" / "urdf_tutorial" / "08-macroed.urdf.xacro", {}),
    (FIXTURES / "robot_real" / "turtlebot3" / "turtlebot3_burger.urdf", {}),
]
Joint = Tuple[str, str, Optional[str], Optional[str], Tuple[float, ...], Tuple[float, ...]]

pytestmark = pytest.mark.skipif(
    importlib.util.find_spec("xacro") is None,
    reason="the real xacro is not installed (pip install -r requirements-dev.lock)",
)


def _numbers(text: str) -> tuple[float, ...]:
    return tuple(float(w) for w in text.split())


def oracle(path: Path, args: dict[str, str]) -> list[Joint]:
    packages = json.dumps({k: str(v) for k, v in PACKAGES.items()})
    words = [f"{k}:={v}" for k, v in args.items()]
    done = subprocess.run([sys.executable, str(DRIVER), str(path), packages, *words],
                          capture_output=True, text=True, check=True, timeout=120)
    answer = json.loads(done.stdout)
    assert "error" not in answer, answer
    return [(j["name"], j["type"], j["parent"], j["child"], _numbers(j["xyz"]),
             _numbers(j["rpy"])) for j in answer["joints"]]


def ours(path: Path, args: dict[str, str]) -> list[Joint]:
    expansion = expand(str(path), dict(args), lambda p: str(PACKAGES[p]) if p in PACKAGES
                       else None)
    assert expansion.problems == []
    assert expansion.root is not None
    source = DescriptionSource(str(path), 1, 1, DescriptionKind.XACRO, str(path))
    return [(j.name, j.joint_type, j.parent, j.child, j.translation or (), j.rpy or ())
            for j in joints_of(expansion.root, source, str, Condition())]


@pytest.mark.parametrize("path, args", CASES, ids=lambda c: getattr(c, "name", str(c)))
def test_joints_equal_the_real_xacros(path: Path, args: dict[str, str]) -> None:
    expected, got = oracle(path, args), ours(path, args)
    assert [j[:4] for j in got] == [j[:4] for j in expected]
    for mine, theirs in zip(got, expected):
        assert mine[4] == pytest.approx(theirs[4], abs=1e-9), mine[0]
        assert mine[5] == pytest.approx(theirs[5], abs=1e-9), mine[0]
    assert got, "a case without joints tests nothing"
