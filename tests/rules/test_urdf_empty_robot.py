from __future__ import annotations

from pathlib import Path

from _urdf import link, lint_loaded, lint_urdf, robot

RULE = "urdf_empty_robot"
MACROS = robot('<xacro:macro name="wheel" params="side"><link name="${side}"/></xacro:macro>')


def test_a_macros_only_file_loaded_as_the_robot(tmp_path: Path) -> None:
    (found,) = lint_loaded(tmp_path, MACROS, RULE)
    assert found.path.endswith("robot.launch")
    assert "only defines macros" in found.message
    assert "No link elements found in urdf file" in found.message


def test_a_macro_library_linted_on_its_own_is_fine() -> None:
    assert lint_urdf(MACROS, RULE) == ()


def test_a_robot_with_links(tmp_path: Path) -> None:
    assert lint_loaded(tmp_path, robot(link("a")), RULE) == ()


def test_an_include_not_read_may_hold_the_links(tmp_path: Path) -> None:
    text = robot('<xacro:include filename="$(find nowhere)/robot.xacro"/>')
    assert lint_loaded(tmp_path, text, RULE) == ()
