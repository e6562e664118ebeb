"""Differential test: the URDF structure rules against urdfdom's own ``check_urdf``
(Debian ``liburdfdom-tools``), on generated trees (with extra roots, duplicate names,
missing links, loops and links with two parents) and on the real descriptions kept in the
fixtures: both must accept or refuse each one, and agree on the root link.

A description urdfdom accepts may still loop (a link with two parents on a cycle reached
from the root): check_urdf then prints the tree forever, so its output is read with a
time limit and only its first lines count. Without ``check_urdf`` these tests skip.
"""

from __future__ import annotations

import importlib.util
import json
import re
import shutil
import subprocess
import sys
from pathlib import Path
from typing import Optional, Tuple

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from launch_linter import LintOptions, lint_paths
from launch_linter.frontends.robot.describe import RobotCache
from launch_linter.frontends.robot.standalone import load_description
from launch_linter.workspace.packages import PackageIndex

ROOT = Path(__file__).resolve().parent.parent.parent
FIXTURES = ROOT / "tests" / "fixtures"
STRUCTURE_RULES = frozenset({"urdf_root", "urdf_duplicate_name", "urdf_missing_link"})
CHECK_URDF = shutil.which("check_urdf")
_ROOT_LINK = re.compile(r"root Link: (\S+)")

pytestmark = pytest.mark.skipif(
    CHECK_URDF is None,
    reason="check_urdf is not installed (Debian: apt-get install liburdfdom-tools)",
)
Verdict = Tuple[bool, Optional[str]]


def urdfdom(path: Path) -> Verdict:
    """(accepted, root link) as check_urdf says."""
    assert CHECK_URDF is not None
    try:
        done = subprocess.run([CHECK_URDF, str(path)], capture_output=True, timeout=20)
        out = done.stdout
    except subprocess.TimeoutExpired as stopped:  # an accepted tree with a loop
        out = stopped.stdout or b""
    text = out[:4096].decode("utf-8", "replace")
    accepted = "Successfully Parsed XML" in text
    root = _ROOT_LINK.search(text)
    return accepted, root.group(1) if accepted and root else None


def linter(path: Path) -> Verdict:
    """(accepted, root link) as the linter reads the file on its own."""
    options = LintOptions(package_paths=(), select=STRUCTURE_RULES)
    refused = any(d.severity.value != "info"
                  for d in lint_paths([str(path)], options).diagnostics)
    tree = load_description(str(path), {}, PackageIndex([]), RobotCache(), str, {})
    (robot,) = tree.robots
    children = {joint.child for joint in robot.joints}
    roots = [link.name for link in robot.links if link.name not in children]
    return not refused, roots[0] if not refused and roots else None


NAMES = st.sampled_from(["base", "arm", "hand", "cam", "laser", "wheel"])


@st.composite
def robots(draw: st.DrawFn) -> str:
    links = draw(st.lists(NAMES, min_size=1, max_size=6))
    ends = st.sampled_from([*links, *links, "ghost"])
    joints = draw(st.lists(st.tuples(st.sampled_from(["j1", "j2", "j3", "j4", "j5", "j6"]),
                                     ends, ends), max_size=7))
    body = "".join(f'<link name="{name}"/>' for name in links)
    body += "".join(f'<joint name="{name}" type="fixed"><parent link="{parent}"/>'
                    f'<child link="{child}"/></joint>' for name, parent, child in joints)
    return f'<robot name="generated">{body}</robot>'


@settings(max_examples=60, deadline=None,
          suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(robots())
def test_generated_descriptions(tmp_path: Path, text: str) -> None:
    path = tmp_path / "generated.urdf"
    path.write_text(text, encoding="utf-8")
    assert linter(path) == urdfdom(path), text


def test_a_link_without_a_name(tmp_path: Path) -> None:
    """urdfdom keeps a nameless link as '' and refuses the second root (ROSOnWindows#50)."""
    path = tmp_path / "nameless.urdf"
    path.write_text('<robot name="sample"><link name="camera_frame"/><link nmae="foo"/>'
                    "</robot>", encoding="utf-8")
    assert linter(path) == urdfdom(path) == (False, None)


MATERIAL = '<material name="m"><color rgba="1 0 0 1"/></material>'
VISUAL = f'<visual><geometry><box size="1 1 1"/></geometry>{MATERIAL}</visual>'


@pytest.mark.parametrize("body", [
    MATERIAL + MATERIAL,  # alike: refused all the same
    MATERIAL + MATERIAL.replace("1 0 0 1", "0 1 0 1"),
    "<material/><material/>",  # both kept as ''
    MATERIAL + f'<link name="b">{VISUAL}</link><link name="c">{VISUAL}</link>'
    '<joint name="j" type="fixed"><parent link="a"/><child link="b"/></joint>'
    '<joint name="k" type="fixed"><parent link="a"/><child link="c"/></joint>',
])
def test_top_level_materials(tmp_path: Path, body: str) -> None:
    """urdfdom refuses a second top-level material of a name; a visual's is the link's."""
    path = tmp_path / "materials.urdf"
    path.write_text(f'<robot name="m"><link name="a"/>{body}</robot>', encoding="utf-8")
    assert linter(path) == urdfdom(path)


def test_real_urdf() -> None:
    path = FIXTURES / "robot_ws" / "src" / "demo_description" / "urdf" / "plain.urdf"
    assert linter(path) == urdfdom(path)


@pytest.mark.skipif(importlib.util.find_spec("xacro") is None,
                    reason="the real xacro is not installed (pip install -r requirements-dev.lock)")
@pytest.mark.parametrize("path", [
    FIXTURES / "robot_real" / "urdf_tutorial" / "08-macroed.urdf.xacro",
    # A .urdf with xacro elements in it: the linter expands it as xacro, as its users do.
    FIXTURES / "robot_real" / "turtlebot3" / "turtlebot3_burger.urdf",
    FIXTURES / "robot_ws" / "src" / "demo_description" / "urdf" / "robot.urdf.xacro",
])
def test_real_xacro_expanded_by_the_real_xacro(tmp_path: Path, path: Path) -> None:
    """The real xacro expands the file for check_urdf; the linter expands it itself."""
    driver = ROOT / "scripts" / "xacro_oracle_driver.py"
    packages = {"demo_description": str(FIXTURES / "robot_ws" / "src" / "demo_description"),
                "urdf_tutorial": str(FIXTURES / "robot_real" / "urdf_tutorial")}
    done = subprocess.run([sys.executable, str(driver), str(path), json.dumps(packages),
                           "--urdf"], capture_output=True, text=True, check=True, timeout=120)
    expanded = tmp_path / "expanded.urdf"
    expanded.write_text(done.stdout, encoding="utf-8")
    assert linter(path)[0] == urdfdom(expanded)[0]
    assert linter(path) == urdfdom(expanded)
