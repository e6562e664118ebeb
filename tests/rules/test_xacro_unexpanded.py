from __future__ import annotations

import shutil
import subprocess
import time
from pathlib import Path

import pytest
from _urdf import joint, link, robot

from launch_linter import LintOptions, lint_text
from launch_linter.frontends.robot.xacro_unexpanded import unlexed_at

RULE = "xacro_unexpanded"
CAMERA = ('<xacro:macro name="camera" params="parent *origin name:=cam">'
          '<link name="${name}_link"/><joint name="${name}_joint" type="fixed">'
          '<xacro:insert_block name="origin"/><parent link="${parent}"/>'
          '<child link="${name}_link"/></joint></xacro:macro>')


def lint(text: str, distro: str | None, rule: str = RULE) -> tuple[object, ...]:
    options = LintOptions(package_paths=(), select=frozenset({rule}), ros_distro=distro)
    return lint_text(text, "robot.urdf.xacro", options).diagnostics


def test_a_call_without_the_prefix_on_noetic_and_ros_2() -> None:
    text = robot(link("base_link") + CAMERA +
                 '\n<camera parent="base_link"><origin xyz="0 0 0"/></camera>')
    for distro in ("noetic", "humble", "jazzy"):
        (found,) = lint(text, distro)
        assert found.line == 3 and found.severity.value == "warning"  # type: ignore[attr-defined]
        assert "<xacro:camera>" in found.message  # type: ignore[attr-defined]
    (unknown,) = lint(text, None)
    assert "deprecation warning" in unknown.message  # type: ignore[attr-defined]


def test_melodic_and_dashing_expand_it() -> None:
    text = robot(link("base_link") + CAMERA +
                 '\n<camera parent="base_link"><origin xyz="0 0 0"/></camera>')
    assert lint(text, "melodic") == () and lint(text, "dashing") == ()


def test_the_links_it_would_make_are_missing() -> None:
    text = robot(link("base_link") + CAMERA +
                 '\n<camera parent="base_link"><origin xyz="0 0 0"/></camera>'
                 + joint("j", "base_link", "cam_link"))
    (missing,) = lint(text, "noetic", "urdf_missing_link")
    assert "cam_link" in missing.message and "<camera>" in missing.message  # type: ignore[attr-defined]
    assert lint(text, "melodic", "urdf_missing_link") == ()


def test_an_element_that_is_no_call_is_left_alone() -> None:
    # A Gazebo <noise> beside a noise macro: its attributes are no parameters of it.
    noise = '<xacro:macro name="noise" params="sigma"><noise stddev="${sigma}"/></xacro:macro>'
    text = robot(link("a") + noise + '<gazebo><noise type="gaussian" stddev="0.1"/></gazebo>'
                 '<xacro:noise sigma="1"/>')
    assert lint(text, "noetic") == ()
    # Fewer element children than block parameters, and no macro of that name by then.
    assert lint(robot(link("base_link") + CAMERA + '<camera parent="base_link"/>'), "noetic") == ()
    assert lint(robot('<camera/>' + CAMERA), "noetic") == ()


def test_a_dollar_brace_never_closed() -> None:
    text = robot(link("a") + '<joint name="j" type="fixed"><parent link="a"/><child link="b"/>'
                 '<origin rpy="0 ${pi/2 0"/></joint>' + link("b"))
    (dropped,) = lint(text, "kinetic")
    assert "'${pi/2 0'" in dropped.message  # type: ignore[attr-defined]
    assert lint(text, "noetic") == ()  # xacro_error's: xacro 1.13.5+ stops
    (refused,) = lint(text, "noetic", "xacro_error")
    assert "invalid expression" in refused.message  # type: ignore[attr-defined]
    closed = text.replace("${pi/2 0", "${pi/2} 0")
    assert lint(closed, "kinetic") == () and lint(closed, "noetic", "xacro_error") == ()


@pytest.mark.parametrize("text, silent, at", [
    ("0 ${pi/2 0", False, 2), ("0 ${pi/2 0", True, 2), ("a $(arg x", False, 2),
    ("${a} $(b) $${c} $", False, None), ("$$a", False, 0), ("$$a", True, None),
    ("${a} ${b", False, 5), ("", False, None),
])
def test_the_lexer_is_xacro_s(text: str, silent: bool, at: int | None) -> None:
    assert unlexed_at(text, silent) == at


@pytest.mark.skipif(shutil.which("xacro") is None, reason="xacro (test oracle) not installed")
@pytest.mark.parametrize("value", ["0 ${pi/2 0", "$(arg x", "${1} ${2", "$$a", "a $ b", "${1}$"])
def test_refusals_agree_with_the_real_xacro(tmp_path: Path, value: str) -> None:
    text = robot(f'<link name="a"><x v="{value}"/></link>')
    (tmp_path / "r.xacro").write_text(text, encoding="utf-8")
    real = subprocess.run(["xacro", str(tmp_path / "r.xacro")], capture_output=True,
                          text=True, timeout=60)
    refused = "invalid expression" in real.stderr
    assert refused == (unlexed_at(value, False) is not None)


def test_twenty_thousand_tokens_then_one_never_closed() -> None:
    value = "${1}" * 20_000 + " ${2"
    start = time.perf_counter()
    assert unlexed_at(value, False) == 80_001
    assert unlexed_at(value, True) == 80_001
    assert unlexed_at("$" * 20_000 + "{", False) is None  # one $$...{ token
    assert unlexed_at("${" * 20_000, False) == 0
    assert time.perf_counter() - start < 2


def test_twenty_thousand_unprefixed_calls() -> None:
    macro = '<xacro:macro name="m" params="n"><link name="${n}"/></xacro:macro>'
    calls = "".join(f'<m n="l{i}"/>' for i in range(20_000))
    start = time.perf_counter()
    found = lint(robot(link("a") + macro + calls), "noetic")
    # The expander keeps its first 1,000 problems.
    assert len(found) == 1_000 and time.perf_counter() - start < 60


def test_a_directive_without_the_prefix() -> None:
    text = robot('<property name="r" value="0.1"/>\n' + link("a") +
                 '<xacro:macro name="m" params="*origin"><joint name="j" type="fixed">'
                 '<parent link="a"/><child link="b"/>\n<insert_block name="origin"/>'
                 '</joint></xacro:macro>' + link("b") + '<xacro:m><origin/></xacro:m>')
    found = lint(text, "noetic")
    assert [(f.line, f.message.split(":")[0]) for f in found] == [  # type: ignore[attr-defined]
        (2, "<property> is the directive <xacro"), (4, "<insert_block> is the directive <xacro")]
    assert "defines no property" in found[0].message  # type: ignore[attr-defined]
    assert lint(text, "melodic") == ()
    # Gazebo's <include> holds a <uri>: not xacro's.
    assert lint(robot(link("a") + '<gazebo><include><uri>model://x</uri></include></gazebo>'),
                "noetic") == ()
