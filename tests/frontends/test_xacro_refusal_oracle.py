"""Differential test: what ``xacro_error`` says xacro refuses, the real xacro (PyPI
``xacro``, a development-only oracle run by ``scripts/xacro_oracle_driver.py``) refuses,
with the same cause; and what it accepts, the rule leaves alone. Without xacro it skips."""

from __future__ import annotations

import importlib.util
import json
import subprocess
import sys
from pathlib import Path

import pytest

from launch_linter import LintOptions, lint_paths

ROOT = Path(__file__).resolve().parent.parent.parent


DRIVER = ROOT / "scripts" / "xacro_oracle_driver.py"


XACRO = 'xmlns:xacro="http://www.ros.org/wiki/xacro"'


WHEEL = ('<xacro:macro name="wheel" params="side *origin"><link name="${side}"/>'
         '<joint name="${side}_j" type="fixed"><xacro:insert_block name="origin"/>'
         '<parent link="base"/><child link="${side}"/></joint></xacro:macro>')

pytestmark = pytest.mark.skipif(
    importlib.util.find_spec("xacro") is None,
    reason="the real xacro is not installed (pip install -r requirements-dev.lock)",
)

# (body, what the real xacro says, what the linter's message says); None: both accept.


CASES = [
    ('<xacro:wheeel side="l"><origin/></xacro:wheeel>', "unknown macro name",
     "unknown macro 'wheeel'"),
    ("<xacro:wheel><origin/></xacro:wheel>", "Undefined parameters", "undefined parameters"),
    ('<xacro:wheel side="l" size="2"><origin/></xacro:wheel>', "Invalid parameter",
     "invalid parameter 'size'"),
    ('<xacro:wheel side="l"/>', "Not enough blocks", "not enough blocks"),
    ('<xacro:wheel side="l"><origin/><origin/></xacro:wheel>', "Unused block",
     "unused block"),
    ('<link name="$(arg tool)"/>', "Undefined substitution argument", "$(arg tool)"),
    ('<xacro:macro name="m" params=""><xacro:insert_block name="b"/></xacro:macro><xacro:m/>',
     "Undefined block", "undefined block 'b'"),
    ('<xacro:property name="" value="0.36"/>', "Property names must be valid python "
     "identifiers", "property names must be valid Python identifiers"),
    ('<xacro:property name="class" value="0.36"/>', "Property names must be valid python "
     "identifiers", "property names must be valid Python identifiers"),
    ('<xacro:if value="false"><xacro:property name="imu_x" value="0"/></xacro:if>'
     '<link name="imu${imu_x}"/>', "name 'imu_x' is not defined",
     "name 'imu_x' is not defined"),
    ('<link name="l${radians(pi)}${math.floor(2.5)}${sorted([2, 1])[0]}"/>', None, None),
    # An expression that is no Python: an unmatched, mismatched or unclosed bracket.
    ('<link name="l"><inertial><mass value="${2 * (1 + 2) / 12)}"/></inertial></link>',
     "unmatched ')'", "')' closes no bracket"),
    ('<link name="${[1, (2]}"/>', "does not match", "']' does not close its bracket"),
    # (Python's own words, which xacro passes on: "was never closed" from 3.10 on.)
    ('<link name="${\'a\' + (1}"/>',
     "never closed" if sys.version_info >= (3, 10) else "unexpected EOF",
     "'(' is not closed"),
    # Brackets inside strings, and a macro never called, are not evaluated as such.
    ("<link name=\"${'a(' + 'b]'}\"/>", None, None),
    ('<xacro:macro name="bad" params=""><link name="${(1}"/></xacro:macro>', None, None),
    ('<xacro:property name="wheel_gap" value="0.36"/>', None, None),
    ('<xacro:wheel side="l"><origin xyz="1 0 0"/></xacro:wheel>', None, None),
    ('<xacro:arg name="tool" default="t"/><link name="$(arg tool)"/>', None, None),
]


def real_xacro(path: Path) -> str | None:
    done = subprocess.run([sys.executable, str(DRIVER), str(path), json.dumps({})],
                          capture_output=True, text=True, check=True, timeout=120)
    return json.loads(done.stdout).get("error")


@pytest.mark.parametrize("body, xacro_says, we_say", CASES)


def test_the_rule_and_the_real_xacro_agree(tmp_path: Path, body: str, xacro_says: str | None,
                                            we_say: str | None) -> None:
    path = tmp_path / "robot.urdf.xacro"
    path.write_text(f'<robot name="r" {XACRO}><link name="base"/>{WHEEL}{body}</robot>',
                    encoding="utf-8")
    refusal = real_xacro(path)
    options = LintOptions(package_paths=(), select=frozenset({"xacro_error"}))
    found = lint_paths([str(path)], options).diagnostics
    if xacro_says is None:
        assert refusal is None and found == ()
        return
    assert refusal is not None and xacro_says in refusal
    assert len(found) == 1 and we_say is not None and we_say in found[0].message


def test_every_global_symbol_of_the_real_xacro_is_listed() -> None:
    import xacro  # type: ignore[import-untyped]

    from launch_linter.frontends.robot.xacro_globals import xacro_defines

    names = [name for name in xacro.create_global_symbols() if not xacro_defines(name)]
    assert names == []
