"""The stand-ins that the standalone linter uses on Pythons older than 3.11."""

from __future__ import annotations

import ast
import sys
from enum import Enum

import pytest

from launch_linter.generate import compat


def test_on_this_python_the_public_names_are_the_real_ones() -> None:
    import dataclasses

    import tomllib

    assert sys.version_info >= (3, 11)
    assert compat.dataclass is dataclasses.dataclass
    assert compat.zip is zip
    assert compat.Enum is Enum
    assert compat.ast is ast
    assert compat.tomllib is tomllib
    assert compat.removeprefix("a/b", "a/") == "b"


def test_dataclass_stand_in_drops_slots_and_refuses_kw_only() -> None:
    @compat.dataclass_before_3_10(frozen=True, slots=True)
    class Point:
        x: int
        y: int = 0

    assert Point(1) == Point(1, 0) and not hasattr(Point, "__slots__")
    with pytest.raises(AttributeError):
        Point(1).x = 2  # type: ignore[misc]
    with pytest.raises(TypeError, match="kw_only"):
        compat.dataclass_before_3_10(kw_only=True)


def test_zip_stand_in_checks_lengths_only_when_strict() -> None:
    assert list(compat.zip_before_3_10([1, 2], "ab", strict=True)) == [(1, "a"), (2, "b")]
    assert list(compat.zip_before_3_10([1, 2], "a")) == [(1, "a")]
    with pytest.raises(ValueError, match="different lengths"):
        list(compat.zip_before_3_10([1, 2], "a", strict=True))


def test_enum_stand_in_formats_as_python_3_11_does() -> None:
    class Colour(str, compat.EnumBefore311):
        RED = "red"

    class Real(str, Enum):
        RED = "red"

    assert f"{Colour.RED}" == "Colour.RED" and f"{Real.RED}" == "Real.RED"
    assert Colour.RED.value == "red" and Colour("red") is Colour.RED


def test_prefix_stand_ins() -> None:
    assert compat.removeprefix_before_3_9("./a", "./") == "a"
    assert compat.removeprefix_before_3_9("a", "./") == "a"
    assert compat.removesuffix_before_3_9(b"a.x", b".x") == b"a"
    assert compat.removesuffix_before_3_9("a", "") == "a"


PYPROJECT = """\
[build-system]
requires = ["setuptools"]

[project]
name = "launch-linter"
dependencies = [
    "Jinja2",
]

[project.scripts]
launch-linter = "launch_linter.cli:main"

[[tool.mypy.overrides]]
module = "x"
"""


@pytest.mark.parametrize(
    "document",
    ["", "# only a comment\n", PYPROJECT, "[tool]\nblack = {line-length = 100}\n"],
)
def test_toml_stand_in_passes_over_documents_without_settings(document: str) -> None:
    assert compat.toml_loads_before_3_11(document) == {}


@pytest.mark.parametrize(
    "document",
    [
        PYPROJECT + "\n[tool.launch-linter]\nselect = ['must']\n",
        PYPROJECT + '\n[tool."launch-linter".severity]\n',
        "[tool]\nlaunch-linter.select = ['must']\n",
        "select = ['must']\n",
        "[severity]\nrot_degrees = 'error'\n",
        "[tool.black]\n[unknown]\n",
    ],
)
def test_toml_stand_in_refuses_what_might_hold_settings(document: str) -> None:
    with pytest.raises(ValueError, match=r"Python 3\.11"):
        compat.toml_loads_before_3_11(document)


def test_ast_stand_in_keeps_python_3_9_trees() -> None:
    module = compat._ast_before_3_9()
    tree = module.parse("x[1:2, 3]", mode="eval")
    assert ast.dump(tree) == ast.dump(ast.parse("x[1:2, 3]", mode="eval"))
    assert module.Constant is ast.Constant
