from __future__ import annotations

from _urdf import lint_urdf, robot

RULE = "xacro_unused_block"


def test_a_block_never_inserted() -> None:
    text = robot('<xacro:macro name="m" params="*origin **content"><link name="a"/>'
                 '<xacro:insert_block name="content"/></xacro:macro>')
    (found,) = lint_urdf(text, RULE)
    assert "'*origin'" in found.message and found.severity.value == "info"


def test_a_block_inserted_deep_or_by_an_expression() -> None:
    deep = robot('<xacro:macro name="m" params="*origin"><joint name="j"><xacro:insert_block '
                 'name="origin"/></joint></xacro:macro>')
    assert lint_urdf(deep, RULE) == ()
    named = robot('<xacro:macro name="m" params="*origin"><xacro:insert_block '
                  'name="${b}"/></xacro:macro>')
    assert lint_urdf(named, RULE) == ()
