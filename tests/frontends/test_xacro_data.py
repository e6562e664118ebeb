"""xacro data values: ``load_yaml`` (dict/list properties, ``d['k']``, ``d.k``) and
``${ns.x}`` properties of a namespaced include."""

from __future__ import annotations

import builtins
import time
from pathlib import Path
from typing import Any

import pytest

from launch_linter.frontends.robot.xacro import ExpandedNode, Expansion, expand

HEAD = '<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">'


def run(tmp_path: Path, body: str) -> Expansion:
    path = tmp_path / "urdf" / "r.xacro"
    path.parent.mkdir(exist_ok=True)
    path.write_text(HEAD + body + "</robot>", encoding="utf-8")
    return expand(str(path), {}, lambda p: str(tmp_path) if p == "pkg" else None)


def first(expansion: Expansion, tag: str) -> ExpandedNode:
    assert expansion.root is not None
    return next(n for n in expansion.root.children if n.tag == tag)


LIMITS = """
arm:
  shoulder: {lower: -1.5, upper: 1.5}
  joints: [a, b, c]
  length: 0.4
"""


@pytest.mark.parametrize("call", [
    "load_yaml('$(find pkg)/config/limits.yaml')",
    "xacro.load_yaml('$(find pkg)/config/limits.yaml')",
    "xacro.load_yaml('../config/limits.yaml')",  # beside the file being expanded
])
def test_load_yaml_gives_a_dict_read_by_key_attribute_and_index(
        tmp_path: Path, call: str) -> None:
    (tmp_path / "config").mkdir()
    (tmp_path / "config" / "limits.yaml").write_text(LIMITS, encoding="utf-8")
    body = (f'<xacro:property name="props" value="${{{call}}}"/>'
            '<limit lower="${props[\'arm\'][\'shoulder\'][\'lower\']}" '
            'upper="${props.arm.shoulder.upper * 2}" name="${props.arm.joints[2]}" '
            'length="${props[\'arm\'].length}"/>')
    node = first(run(tmp_path, body), "limit")
    assert not node.unknown
    assert node.attrib == {"lower": "-1.5", "upper": "3.0", "name": "c", "length": "0.4"}


def test_a_dict_passed_to_a_macro_parameter_stays_a_dict(tmp_path: Path) -> None:
    (tmp_path / "config").mkdir()
    (tmp_path / "config" / "limits.yaml").write_text(LIMITS, encoding="utf-8")
    body = ('<xacro:property name="props" '
            'value="${load_yaml(\'$(find pkg)/config/limits.yaml\')}"/>'
            '<xacro:macro name="m" params="arm"><limit upper="${arm.shoulder.upper}"/>'
            '</xacro:macro><xacro:m arm="${props[\'arm\']}"/>')
    assert first(run(tmp_path, body), "limit").attrib == {"upper": "1.5"}


def test_without_pyyaml_the_value_is_unknown(tmp_path: Path,
                                             monkeypatch: pytest.MonkeyPatch) -> None:
    (tmp_path / "config").mkdir()
    (tmp_path / "config" / "flat.yaml").write_text("length: 0.4\n", encoding="utf-8")
    real_import = builtins.__import__

    def no_yaml(name: str, *args: Any, **kwargs: Any) -> Any:
        if name == "yaml":
            raise ImportError(name)
        return real_import(name, *args, **kwargs)

    monkeypatch.setattr(builtins, "__import__", no_yaml)
    body = ('<xacro:property name="p" value="${load_yaml(\'$(find pkg)/config/flat.yaml\')}"/>'
            '<limit upper="${p.length}"/>')
    node = first(run(tmp_path, body), "limit")
    assert "PyYAML" in node.unknown["upper"]


@pytest.mark.parametrize("text, reason", [
    ("a: !!python/object:os.system {}\n", "not readable YAML"),
    ("a: 1\n", "no key or attribute 'missing'"),
])
def test_tags_and_missing_keys_are_unknown(tmp_path: Path, text: str, reason: str) -> None:
    (tmp_path / "x.yaml").write_text(text, encoding="utf-8")
    body = ('<xacro:property name="p" value="${load_yaml(\'$(find pkg)/x.yaml\')}"/>'
            '<limit upper="${p.missing}"/>')
    assert reason in first(run(tmp_path, body), "limit").unknown["upper"]


def test_alias_explosion_stops_at_the_bound_quickly(tmp_path: Path) -> None:
    lines = ["a0: &a0 [x, x, x, x, x, x, x, x, x, x]"]
    lines += [f"a{i}: &a{i} [*a{i - 1}, *a{i - 1}, *a{i - 1}, *a{i - 1}, *a{i - 1}, "
              f"*a{i - 1}, *a{i - 1}, *a{i - 1}, *a{i - 1}, *a{i - 1}]" for i in range(1, 12)]
    (tmp_path / "bomb.yaml").write_text("\n".join(lines) + "\n", encoding="utf-8")
    body = ('<xacro:property name="p" value="${load_yaml(\'$(find pkg)/bomb.yaml\')}"/>'
            '<limit upper="${p.a0[0]}"/>')
    started = time.process_time()
    node = first(run(tmp_path, body), "limit")
    assert time.process_time() - started < 60
    assert "more than 20,000 items" in node.unknown["upper"]


def test_namespaced_include_properties_read_as_ns_dot_name(tmp_path: Path) -> None:
    (tmp_path / "urdf").mkdir()
    (tmp_path / "urdf" / "parts.xacro").write_text(
        HEAD + '<xacro:property name="wheel_radius" value="0.1"/>'
        '<xacro:property name="label" value="left"/>'
        '<xacro:property name="broken" value="$(arg nope)"/>'
        '<xacro:macro name="wheel" params="side"><link name="${side}_wheel"/></xacro:macro>'
        "</robot>", encoding="utf-8")
    body = ('<xacro:include filename="parts.xacro" ns="parts"/>'
            '<xacro:parts.wheel side="${parts.label}"/>'
            '<limit upper="${parts.wheel_radius * 2}" other="${parts.broken}"/>')
    expansion = run(tmp_path, body)
    assert first(expansion, "link").attrib == {"name": "left_wheel"}
    node = first(expansion, "limit")
    assert node.attrib["upper"] == "0.2"
    assert "broken" in node.unknown["other"]


def test_a_namespaced_macro_calls_its_own_files_macros(tmp_path: Path) -> None:
    """xacro runs ``ns.macro``'s body in the namespace's scope, where the included file's
    other macros are (rosbot_xl's ``gazebo.imu`` calls ``gauss_noise``)."""
    (tmp_path / "urdf").mkdir()
    (tmp_path / "urdf" / "gazebo.xacro").write_text(
        HEAD + '<xacro:macro name="noise" params="s"><noise stddev="${s}"/></xacro:macro>'
        '<xacro:macro name="imu" params="frame"><sensor frame="${frame}"><xacro:noise s="1"/>'
        "</sensor></xacro:macro></robot>", encoding="utf-8")
    expansion = run(tmp_path, '<xacro:include filename="gazebo.xacro" ns="gazebo"/>'
                              '<xacro:gazebo.imu frame="imu_link"/>')
    assert not expansion.problems
    sensor = first(expansion, "sensor")
    assert sensor.attrib == {"frame": "imu_link"}
    assert sensor.children[0].attrib == {"stddev": "1"}


def test_xacros_angle_tags_are_read_as_numbers(tmp_path: Path) -> None:
    # UR's joint_limits.yaml: ``max_position: !degrees 360.0``.
    (tmp_path / "limits.yaml").write_text(
        "a: !degrees 180.0\nb: !radians pi/2\nc: !degrees open('x')\n", encoding="utf-8")
    body = ('<xacro:property name="p" value="${load_yaml(\'$(find pkg)/limits.yaml\')}"/>'
            '<limit a="${p.a}"/>')
    node = first(run(tmp_path, body), "limit")
    assert "not readable YAML" in node.unknown["a"]  # c's call is refused: all unknown
    (tmp_path / "limits.yaml").write_text("a: !degrees 180.0\nb: !radians pi/2\n",
                                          encoding="utf-8")
    node = first(run(tmp_path / ".", body.replace("p.a}", "p.a} ${p.b}")), "limit")
    assert node.attrib == {"a": "3.141592653589793 1.5707963267948966"}
