"""Which modules are embedded: found from the package's own imports, edges left out."""

from __future__ import annotations

import textwrap
from pathlib import Path

import pytest

from launch_linter.generate import embed
from launch_linter.rules import RULE_MODULES


@pytest.fixture(scope="module")
def embedding() -> embed.Embedding:
    return embed.collect(embed.package_root())


def test_the_check_command_and_every_rule_are_embedded(embedding: embed.Embedding) -> None:
    names = {m.name for m in embedding.modules}
    assert {
        "launch_linter", "launch_linter.cli", "launch_linter.engine", "launch_linter.rules",
        "launch_linter.report.json_report", "launch_linter.report.text",
        "launch_linter.beliefs_files",
    } <= names
    assert {m.__name__ for m in RULE_MODULES} <= names
    assert not [n for n in names if embed._is_under(n, embed.EXCLUDED)]


def test_modules_are_the_package_files_verbatim(embedding: embed.Embedding) -> None:
    root = embed.package_root()
    for module in embedding.modules:
        original = (root / module.path).read_text(encoding="utf-8")
        assert module.source == original, module.path
        assert module.sha256 == embed.hashlib.sha256(original.encode()).hexdigest()
    assert [m.name for m in embedding.modules] == sorted(m.name for m in embedding.modules)


def test_the_digest_covers_names_and_texts(embedding: embed.Embedding) -> None:
    pairs = [(m.name, m.source) for m in embedding.modules]
    assert embedding.sha256 == embed.sources_sha256(pairs)
    assert embed.sources_sha256([*pairs[:-1], (pairs[-1][0], pairs[-1][1] + " ")]) != (
        embedding.sha256
    )


def _package(tmp_path: Path, files: dict[str, str]) -> Path:
    for name, text in files.items():
        path = tmp_path / "launch_linter" / name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(textwrap.dedent(text), encoding="utf-8")
    return tmp_path


def test_a_third_party_import_at_module_level_is_refused_with_its_line(tmp_path: Path) -> None:
    root = _package(tmp_path, {
        "__init__.py": "",
        "beliefs_files.py": "",
        "cli.py": "import json\nfrom launch_linter import core\n",
        "core.py": '"""Core."""\n\nimport yaml\n',
    })
    with pytest.raises(embed.EmbedError) as caught:
        embed.collect(root)
    assert caught.value.problems == [
        "launch_linter/core.py:3: imports yaml, which is not in the standard library"
    ]


def test_an_edge_imported_at_module_level_is_refused(tmp_path: Path) -> None:
    root = _package(tmp_path, {
        "__init__.py": "",
        "beliefs_files.py": "",
        "cli.py": "from launch_linter.mining import store\n",
        "mining/__init__.py": "",
        "mining/store.py": "import sqlite3\n",
    })
    with pytest.raises(embed.EmbedError, match="does not carry"):
        embed.collect(root)


def test_lazy_imports_are_followed_when_possible_and_noted_otherwise(tmp_path: Path) -> None:
    root = _package(tmp_path, {
        "__init__.py": "",
        "beliefs_files.py": "",
        "cli.py": """\
            def run(kind):
                if kind == "fancy":
                    from launch_linter.report import fancy
                if kind == "plain":
                    from launch_linter.report import plain
                from launch_linter import mining
                import yaml
        """,
        "report/__init__.py": "",
        "report/fancy.py": "import jinja2\n",
        "report/plain.py": "from . import helpers\n",
        "report/helpers.py": "try:\n    import yaml\nexcept ImportError:\n    yaml = None\n",
        "mining/__init__.py": "import sqlite3\n",
    })
    found = embed.collect(root)
    names = {m.name for m in found.modules}
    assert {"launch_linter.report.plain", "launch_linter.report.helpers"} <= names
    assert "launch_linter.report.fancy" not in names and "launch_linter.mining" not in names
    assert found.notes == (
        "launch_linter/cli.py:3: launch_linter.report.fancy left out: "
        "launch_linter/report/fancy.py:1: imports jinja2, which is not in the standard library",
        "launch_linter/cli.py:7: needs yaml (not in the standard library)",
        "launch_linter/report/helpers.py:2: needs yaml (not in the standard library)",
    )


def test_a_standard_module_newer_than_python_3_8_is_refused(tmp_path: Path) -> None:
    root = _package(tmp_path, {
        "__init__.py": "",
        "beliefs_files.py": "",
        "cli.py": "import tomllib\n",
    })
    with pytest.raises(embed.EmbedError, match=r"cli.py:1: imports tomllib, new in Python 3.11"):
        embed.collect(root)


def test_standard_modules_are_told_from_installed_ones() -> None:
    assert embed._in_stdlib("json") and embed._in_stdlib("sys") and embed._in_stdlib("ast")
    assert not embed._in_stdlib("yaml") and not embed._in_stdlib("no_such_module_here")
    assert not embed._in_stdlib("tomllib")
