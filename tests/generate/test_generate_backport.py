"""The Python 3.8 edits: each one on a tiny module, and the problems left for a person."""

from __future__ import annotations

import ast
import shutil
import subprocess
import textwrap
from pathlib import Path

import pytest
from standalone_helpers import oldest_python

from launch_linter.generate import compat
from launch_linter.generate.backport import (
    ADDED,
    COMPAT_MODULE,
    BackportError,
    Types,
    backport,
    class_names,
    module_types,
    python38_problems,
    type_alias_names,
)

NO_TYPES = Types()


def port(source: str, types: Types = NO_TYPES) -> str:
    result = backport(textwrap.dedent(source), "m.py", types)
    assert python38_problems(result, "m.py", types) == []
    ast.parse(result, feature_version=(3, 8))
    return result


def test_a_module_that_needs_nothing_is_unchanged() -> None:
    source = '"""Doc."""\n\nfrom __future__ import annotations\n\nX: int | None = 1\n'
    assert backport(source, "m.py", NO_TYPES) == source


def test_future_annotations_are_added_after_the_docstring() -> None:
    result = port(
        '''\
        """Doc
        on two lines."""

        from collections.abc import Iterable


        def f(x: Iterable[int]) -> list[int] | None:
            return None
        '''
    )
    lines = result.splitlines()
    assert lines[1] == 'on two lines."""; from __future__ import annotations' + ADDED
    assert "def f(x: Iterable[int]) -> list[int] | None:" in result


def test_added_imports_follow_future_imports_or_precede_the_first_statement() -> None:
    source = "from __future__ import division  # old\n\ndef f(x: int):\n    return zip(x, x)\n"
    assert port(source).splitlines()[0] == (
        "from __future__ import division; from __future__ import annotations  # old"
    )
    result = port("import os\ndef f(values: list[int]):\n    return zip(values, strict=True)\n")
    assert result.splitlines()[0] == (
        f"from __future__ import annotations; from {COMPAT_MODULE} import zip; import os"
    )
    # Before a decorated or compound first statement only a line of its own will do.
    result = port("@decorate\ndef f(values):\n    return zip(values, values, strict=True)\n")
    assert result.splitlines()[:2] == [f"from {COMPAT_MODULE} import zip" + ADDED, "@decorate"]


def test_every_line_keeps_its_number() -> None:
    source = textwrap.dedent(
        """\
        \"\"\"Doc.\"\"\"
        from collections.abc import Callable
        from dataclasses import (
            dataclass,  # a comment that goes
            field,
        )

        Check = Callable[
            [int],
            tuple[int, ...] | None,
        ]


        def f(x: int, text: str) -> bool:
            return isinstance(x, int |
                              float) and text.strip(
                ).removeprefix("a") == "b"
        """
    )
    result = port(source).splitlines()
    assert len(result) == len(source.splitlines())
    assert result[2] == f"from dataclasses import field; from {COMPAT_MODULE} import (dataclass"
    assert result[7] == (
        "Check = _typing.Callable[[int], _typing.Union[_typing.Tuple[int, ...], None]"
    )
    assert result[13:] == [
        "def f(x: int, text: str) -> bool:",
        "    return isinstance(x, (int, float",
        ')) and removeprefix(text.strip(',
        '        ), "a") == "b"',
    ]


def test_runtime_type_aliases_are_spelled_with_typing() -> None:
    result = port(
        """\
        from __future__ import annotations

        from collections.abc import Callable, Iterable


        class Hole:
            pass


        Part = str | Hole
        Value = tuple[Part, ...]
        Check = Callable[[Value], Iterable[dict[str, int]]]
        FLAGS = 1 | 2
        """,
        Types(frozenset({"Hole", "Part", "Value"})),
    )
    assert "Part = _typing.Union[str, Hole]\n" in result
    assert "Value = _typing.Tuple[Part, ...]\n" in result
    assert "Check = _typing.Callable[[Value], _typing.Iterable[_typing.Dict[str, int]]]" in result
    assert "FLAGS = 1 | 2\n" in result
    assert "from __future__ import annotations; import typing as _typing" + ADDED in result


def test_isinstance_unions_become_tuples() -> None:
    result = port(
        """\
        import ast


        def f(value, node):
            return isinstance(value, str | int | None) or isinstance(node, ast.Tuple | ast.List)


        def g(node):
            return issubclass(type(node), ast.stmt | ast.expr) or isinstance(
                node, (int | str, float))
        """
    )
    assert "issubclass(type(node), (ast.stmt, ast.expr))" in result
    assert "isinstance(\n        node, (int, str, float))" in result
    assert "isinstance(value, (str, int, None))" in result
    assert "isinstance(node, (ast.Tuple, ast.List))" in result
    assert f"from {COMPAT_MODULE} import ast" in result


def test_standard_names_come_from_the_compat_module_in_place() -> None:
    result = port(
        """\
        from __future__ import annotations

        import ast, re
        from dataclasses import dataclass, field
        from enum import Enum
        from typing import Any, TypeAlias


        def lazy():
            import tomllib as toml
            return toml
        """
    )
    assert "import re; from _launch_linter_compat import ast\n" in result
    assert "from dataclasses import field; from _launch_linter_compat import dataclass\n" in result
    assert "from _launch_linter_compat import Enum\n" in result
    assert "from typing import Any; from _launch_linter_compat import TypeAlias\n" in result
    assert "    from _launch_linter_compat import tomllib as toml\n" in result


def test_removeprefix_calls_become_compat_calls() -> None:
    result = port('def f(p):\n    return p.strip().removeprefix("./") + p.removesuffix(b"x")\n')
    assert 'removeprefix(p.strip(), "./") + removesuffix(p, b"x")' in result
    assert f"from {COMPAT_MODULE} import removeprefix, removesuffix" in result


@pytest.mark.parametrize(
    ("source", "problem"),
    [
        ("match x:\n    case 1:\n        pass\n", "syntax newer than Python 3.8"),
        ("from functools import cache\n", "functools.cache needs Python 3.9"),
        ("import itertools\nitertools.pairwise([])\n", "itertools.pairwise needs Python 3.10"),
        ("from typing import Self\n", "typing.Self needs Python 3.11"),
        ("import graphlib\n", "module graphlib needs Python 3.9"),
        ("from dataclasses import field\nfield(kw_only=True)\n", "needs Python 3.10"),
        ("import dataclasses\n@dataclasses.dataclass(slots=True)\nclass A:\n    pass\n",
         "import dataclass by name"),
        ("x = (1).bit_count()\n", ".bit_count() needs Python 3.10"),
        ("path = __file__\n", "embedded modules have no file"),
        ("import importlib\nimportlib.import_module('x')\n", "plain import statements"),
        ("from importlib import resources\n", "no package data"),
        ("from enum import IntEnum\n", "differs between Python 3.8 and 3.11"),
        ("import pkgutil\n", "cannot be listed"),
        ("import typing\ntyping.get_type_hints(int)\n", "evaluates annotations"),
        ("def f(x):\n    return isinstance(x, dict[str, int])\n", "generic needs Python 3.9"),
        ("print(int | None)\n", "run-time 'X | Y' type union"),
        ("import imp\n", "module imp was removed in Python 3.12"),
    ],
)
def test_what_cannot_be_rewritten_is_named_with_its_line(source: str, problem: str) -> None:
    result = backport(source, "pkg/m.py", NO_TYPES)
    problems = python38_problems(result, "pkg/m.py", NO_TYPES)
    assert any(p.startswith("pkg/m.py:") and problem in p for p in problems), problems


def test_union_aliases_in_isinstance_become_their_members() -> None:
    defining = "class A:\n    pass\n\nclass B:\n    pass\n\nAction = A | B\nNot = A\n"
    types = module_types(defining, "pkg/actions.py")
    assert types.unions == frozenset({"pkg.actions.Action"})
    using = textwrap.dedent(
        """\
        from pkg.actions import Action as Act, A, Not
        from .actions import Action


        def f(x):
            return isinstance(x, Act) or isinstance(x, (Action, int)) or isinstance(x, Not)
        """
    )
    result = backport(using, "pkg/user.py", types)
    assert python38_problems(result, "pkg/user.py", types) == []
    assert (
        "isinstance(x, (*_typing.get_args(Act),)) or "
        "isinstance(x, (*_typing.get_args(Action), int)) or isinstance(x, Not)"
    ) in result
    unresolved = backport(using.replace("Action as Act", "Other as Act"), "pkg/user.py", types)
    assert "isinstance(x, Act)" in unresolved


def test_type_names_are_collected_across_aliases() -> None:
    source = "class A:\n    pass\n\nB = A | None\nC = tuple[B, ...]\nD = 3\nE: Final = 'x'\n"
    assert class_names(source) == {"A"}
    assert type_alias_names(source) == {"B", "C"}


def test_unparsable_source_is_reported() -> None:
    with pytest.raises(BackportError, match=r"m\.py:1"):
        backport("def (:\n", "m.py", NO_TYPES)


@pytest.mark.skipif(oldest_python() is None, reason="no Python 3.8 interpreter found")
def test_the_rewritten_module_runs_on_python_3_8(tmp_path: Path) -> None:
    source = textwrap.dedent(
        """\
        from dataclasses import dataclass, field
        from collections.abc import Iterable

        @dataclass(frozen=True, slots=True)
        class Hole:
            text: str
            tags: tuple[str, ...] = field(default=())

        Part = str | Hole
        Value = tuple[Part, ...]

        def parts(values: Iterable[Part]) -> list[str]:
            return [v if isinstance(v, str | bytes) else v.text for v in values]

        print(parts(["a", Hole("b")]), "x/y".removeprefix("x/"))
        """
    )
    (tmp_path / "m.py").write_text(backport(source, "m.py", Types(frozenset({"Hole", "Part"}))))
    shutil.copy(compat.__file__, tmp_path / f"{COMPAT_MODULE}.py")
    python = oldest_python()
    assert python is not None
    # Not -I: the script's folder must be on the path, for the compat module.
    done = subprocess.run(
        [python, "-E", "-s", "-S", str(tmp_path / "m.py")],
        capture_output=True, text=True, check=False, timeout=60,
    )
    assert done.returncode == 0, done.stderr
    assert done.stdout == "['a', 'b'] y\n"
