"""Meta-tests: every rule is registered, named, documented, and its documentation runs."""

from __future__ import annotations

import importlib.util
import re
from pathlib import Path
from types import ModuleType

import pytest

from launch_linter import LintOptions, lint_text
from launch_linter.beliefs_files import load_beliefs
from launch_linter.model import Category, Severity
from launch_linter.rules import RULE_MODULES, RULES, RULES_BY_ID, Rule, rules_for_profile

ROOT = Path(__file__).resolve().parent.parent
RULES_DIR = ROOT / "src" / "launch_linter" / "rules"
SNAKE_CASE = re.compile(r"^[a-z][a-z0-9]*(_[a-z0-9]+)*$")
SECTIONS = ("## What it does", "## Why is this bad?", "## Example", "## Use instead")
OPTIONAL_SECTIONS = ("## Known problems", "## Options", "## Fix")
XML_BLOCK = re.compile(r"```(?:xml|python|yaml)\n(.*?)```", re.DOTALL)
MODULES = {m.ID: m for m in RULE_MODULES}

# The rules table of DESIGN.md (a contract): id -> (category, severity). The severities are
# the study's: the study profile keeps them; the default profile sets levels from measured
# precision (docs/severity.md), checked below.
CONTRACT = {
    "self_transform": (Category.MUST, Severity.ERROR),
    "dup_name": (Category.MUST, Severity.ERROR),
    "dup_sig": (Category.MUST, Severity.ERROR),
    "reversed_name": (Category.MAY_SEMANTIC, Severity.WARNING),
    "rot_degrees": (Category.MAY_SEMANTIC, Severity.WARNING),
    "int_suffix": (Category.MAY_SEMANTIC, Severity.WARNING),
    "ned_transform": (Category.MAY_SEMANTIC, Severity.WARNING),
    "sensor_null": (Category.MAY_SEMANTIC, Severity.WARNING),
    "sig_implication": (Category.MAY_IMPLIED, Severity.WARNING),
    "name_implication": (Category.MAY_IMPLIED, Severity.WARNING),
    "sig_null_disp": (Category.MAY_IMPLIED, Severity.WARNING),
    "name_null_disp": (Category.MAY_IMPLIED, Severity.WARNING),
    "sig_null_rot": (Category.MAY_IMPLIED, Severity.WARNING),
    "name_null_rot": (Category.MAY_IMPLIED, Severity.WARNING),
    "bad_arity": (Category.TF, Severity.ERROR),
    "bad_number": (Category.TF, Severity.ERROR),
    "bad_quaternion": (Category.TF, Severity.ERROR),
    "leading_slash": (Category.TF, Severity.WARNING),
    "multiple_parents": (Category.TF, Severity.ERROR),
    "tf_cycle": (Category.TF, Severity.ERROR),
    "unresolved": (Category.LAUNCH, Severity.INFO),
    "parse_error": (Category.LAUNCH, Severity.ERROR),
}

# The rules of the MUST / MAY-Semantic / tf issue each have tests/rules/test_<id>.py.
RULE_TEST_CATEGORIES = (Category.MUST, Category.MAY_SEMANTIC, Category.TF)


def _section(doc: str, heading: str) -> str:
    """The text of one ``## heading`` section, up to the next ``## ``."""
    start = doc.index(heading) + len(heading)
    following = doc.find("\n## ", start)
    return doc[start:] if following == -1 else doc[start:following]


def _first_xml(doc: str, heading: str) -> str:
    match = XML_BLOCK.search(_section(doc, heading))
    assert match is not None, f"no ```xml block under {heading}"
    return match.group(1)


def _run(rule: Rule, xml: str, heading: str = "", folder: Path | None = None) -> list[int]:
    """Lines where ``rule`` reports, with every rule on, as ``launch-linter check`` runs.
    A module may name the file its example is (``EXAMPLE_PATH``, e.g. a ``.launch.py``),
    the distribution it targets (``EXAMPLE_DISTRO``) and the file the example includes
    (``EXAMPLE_INCLUDED``: the second block under ``heading``, written into ``folder``
    beside the example; a tuple of names: the blocks after the first, in order, and the
    folder is then a package) or the files of the package it is in (``EXAMPLE_FILES``: the
    later blocks, one file each, the folder then a package path)."""
    module = MODULES[rule.id]
    path = getattr(module, "EXAMPLE_PATH", "example.launch")
    included = getattr(module, "EXAMPLE_INCLUDED", None)
    files = getattr(module, "EXAMPLE_FILES", None)
    package_paths: tuple[str, ...] = ()
    if included is not None and folder is not None:
        blocks = XML_BLOCK.findall(_section(rule.doc, heading))
        names = (included,) if isinstance(included, str) else included
        for name, block in zip(names, blocks[1:]):
            (folder / name).write_text(block, encoding="utf-8")
        path = str(folder / path)
        if not isinstance(included, str):
            # Several files written beside the example make its folder a package.
            package_paths = (str(folder),)
    elif files is not None and folder is not None:
        # A package the example's launch file runs a node of: one file per later block.
        blocks = XML_BLOCK.findall(_section(rule.doc, heading))
        for name, block in zip(files, blocks[1:]):
            (folder / name).parent.mkdir(parents=True, exist_ok=True)
            (folder / name).write_text(block, encoding="utf-8")
        path, package_paths = str(folder / path), (str(folder),)
    options = LintOptions(package_paths=package_paths, beliefs=load_beliefs("bundled", 1.0),
                          ros_distro=getattr(module, "EXAMPLE_DISTRO", None))
    result = lint_text(xml, path, options)
    return [d.line for d in result.diagnostics if d.rule == rule.id]


def test_every_rule_module_is_registered() -> None:
    files = sorted(p.stem for p in RULES_DIR.glob("*.py") if not p.stem.startswith("_"))
    registered = sorted(m.__name__.rsplit(".", 1)[-1] for m in RULE_MODULES)
    assert registered == files


def test_the_catalog_lists_every_rule_with_its_category_in_table_order() -> None:
    # The catalog is what a run answered by the results cache knows of the rules.
    from launch_linter.rules._catalog import CATALOG

    assert tuple((r.id, r.category) for r in RULES) == CATALOG


def test_ids_are_unique_snake_case_and_match_module_names() -> None:
    ids = [r.id for r in RULES]
    assert len(ids) == len(set(ids))
    assert all(SNAKE_CASE.match(i) for i in ids)
    module: ModuleType
    for module in RULE_MODULES:
        assert module.__name__.rsplit(".", 1)[-1] == module.ID


@pytest.mark.parametrize("rule_id", sorted(CONTRACT))
def test_contract_rules_have_their_category_and_severity(rule_id: str) -> None:
    rule = {r.id: r for r in rules_for_profile("study")}[rule_id]
    assert (rule.category, rule.severity) == CONTRACT[rule_id]


DEFAULT_LOWERED = {"reversed_name", "int_suffix", "sensor_null", "leading_slash"}


@pytest.mark.parametrize("rule_id", sorted(CONTRACT))
def test_default_profile_lowers_only_the_rules_measured_below_the_bar(rule_id: str) -> None:
    expected = Severity.INFO if rule_id in DEFAULT_LOWERED else CONTRACT[rule_id][1]
    assert RULES_BY_ID[rule_id].severity is expected


@pytest.mark.parametrize("rule", RULES, ids=lambda r: r.id)
def test_documented(rule: Rule) -> None:
    lines = rule.doc.splitlines()
    assert lines and lines[0].strip() and not lines[0].startswith("#")
    assert lines[0].rstrip().endswith(".")
    positions = [rule.doc.find(heading) for heading in SECTIONS]
    assert all(p > 0 for p in positions), f"missing one of {SECTIONS}"
    assert positions == sorted(positions), "sections out of order"
    headings = [line for line in lines if line.startswith("## ")]
    assert set(headings) <= set(SECTIONS) | set(OPTIONAL_SECTIONS)
    _first_xml(rule.doc, "## Example")
    _first_xml(rule.doc, "## Use instead")


@pytest.mark.parametrize("rule", RULES, ids=lambda r: r.id)
def test_example_triggers_and_fix_does_not(rule: Rule, tmp_path: Path) -> None:
    example, instead = "## Example", "## Use instead"
    assert _run(rule, _first_xml(rule.doc, example), example, tmp_path), (
        "the Example does not trigger")
    assert _run(rule, _first_xml(rule.doc, instead), instead, tmp_path) == [], (
        "Use instead triggers")


@pytest.mark.parametrize(
    "rule", [r for r in RULES if r.category in RULE_TEST_CATEGORIES], ids=lambda r: r.id
)
def test_rule_has_a_test_file(rule: Rule) -> None:
    assert (ROOT / "tests" / "rules" / f"test_{rule.id}.py").is_file()


def _generator() -> ModuleType:
    spec = importlib.util.spec_from_file_location(
        "gen_rule_docs", ROOT / "scripts" / "gen_rule_docs.py"
    )
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_docs_rules_md_is_current() -> None:
    expected = _generator().render()
    current = (ROOT / "docs" / "rules.md").read_text(encoding="utf-8")
    assert current == expected, "docs/rules.md is stale: run python scripts/gen_rule_docs.py"


def test_docs_hold_every_rule() -> None:
    text = _generator().render()
    for rule in RULES:
        assert f"\n## {rule.id}\n" in text
        assert _section(rule.doc, "## Why is this bad?").strip() in text


@pytest.mark.parametrize("rule", RULES, ids=lambda r: r.id)
def test_fix_kind_is_documented(rule: Rule) -> None:
    """A rule that offers a fix says so in a ``## Fix`` section naming its kind."""
    if rule.fix is None:
        assert "## Fix" not in rule.doc
        return
    section = rule.doc.split("## Fix", 1)[1]
    assert section.strip().lower().startswith(rule.fix.value)


@pytest.mark.parametrize("rule_id", ["camera_frame_not_optical", "duplicate_publisher",
                                     "robot_frame_collision", "sim_time_mismatch"])
def test_rules_raised_after_the_study_profile_keep_info_there(rule_id: str) -> None:
    """The study profile reproduces the levels of its time: rules added at info and raised
    later from their judged samples stay at info there."""
    study = {r.id: r for r in rules_for_profile("study")}[rule_id]
    default = {r.id: r for r in rules_for_profile("default")}[rule_id]
    assert study.severity is Severity.INFO
    assert default.severity is not Severity.INFO
