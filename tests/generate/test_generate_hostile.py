"""Names from the corpus are untrusted: they must neither break nor inject into the file."""

from __future__ import annotations

import ast
import io
import json
import shlex
import tokenize
from collections.abc import Callable
from pathlib import Path
from xml.sax.saxutils import quoteattr

from standalone_helpers import HOSTILE, Generated, json_pair, run_standalone

from launch_linter.model.beliefs import BELIEF_FORMAT


def _xml_safe(name: str) -> bool:
    """Characters that XML 1.0 can carry at all (even as a character reference)."""
    return all(
        c in "\t\n\r" or 0x20 <= ord(c) <= 0xD7FF or 0xE000 <= ord(c) <= 0xFFFD
        or ord(c) >= 0x10000
        for c in name
    )


def test_hostile_names_are_data_that_reads_back_exactly(standalone: Generated) -> None:
    implications = standalone.assigned("NAME_IMPLICATION")
    antecedents = {row[0] for row in implications}
    assert set(HOSTILE) <= antecedents
    assert {row[1] for row in implications} >= {name + "_partner" for name in HOSTILE}
    assert {row[0][0] for row in standalone.assigned("SIG_NULL_ROT")} >= set(HOSTILE)
    tree = standalone.tree
    # Nothing but the expected statements at the top level: no name became code.
    kinds = {type(node).__name__ for node in tree.body}
    assert kinds <= {"Expr", "Import", "If", "Assign", "FunctionDef", "ClassDef"}
    assigned = [
        node.targets[0].id for node in tree.body
        if isinstance(node, ast.Assign) and isinstance(node.targets[0], ast.Name)
    ]
    assert assigned == [
        "GENERATED", "LIMITATIONS", "P0", "SIG_IMPLICATION", "NAME_IMPLICATION",
        "SIG_NULL_DISP", "NAME_NULL_DISP", "SIG_NULL_ROT", "NAME_NULL_ROT", "BELIEF_TABLES",
        "KNOWLEDGE", "PACKAGES", "MODULES",
    ]


def test_running_with_hostile_beliefs_injects_nothing(
    standalone: Generated, tmp_path: Path
) -> None:
    nodes = "\n".join(
        f'  <node pkg="tf2_ros" type="static_transform_publisher" name={quoteattr(name)}\n'
        f'        args="0 0 0 0 0 0.5 {i}_parent child"/>'
        for i, name in enumerate(HOSTILE) if _xml_safe(name)
    )
    launch = tmp_path / "hostile.launch"
    launch.write_text(f"<launch>\n{nodes}\n</launch>\n", encoding="utf-8")
    expected, actual = json_pair(standalone, [launch.name], cwd=tmp_path)
    assert actual == expected
    reported = {d["belief"]["if"] for d in actual["diagnostics"] if d["rule"] == "name_implication"}
    assert reported == {name for name in HOSTILE if _xml_safe(name)}
    assert not (tmp_path / "PWNED").exists()
    assert not Path("PWNED").exists()


def test_a_hostile_beliefs_file_name_cannot_inject_either(
    generate: Callable[..., Generated], tmp_path: Path
) -> None:
    name = "b'e\"l{{ x }}\n{% if %}\\\"\"\"é #.json"
    path = tmp_path / name
    document = {"format": BELIEF_FORMAT, "p0": 0.9, "beliefs": [
        {"class": "name_null_rot", "if": "a", "n": 10, "e": 10, "z": 2.05},
    ]}
    path.write_text(json.dumps(document), encoding="utf-8")
    generated = generate(str(path), 1.0)
    assert generated.assigned("GENERATED")["beliefs"] == str(path)
    assert shlex.split(generated.assigned("GENERATED")["command"])[3] == str(path)
    (tmp_path / "x.launch").write_text(
        '<launch><node pkg="tf2_ros" type="static_transform_publisher" name="a"'
        ' args="0 0 0 0 0 1 p c"/></launch>', encoding="utf-8"
    )
    done = run_standalone(generated.path, ["x.launch", "--format", "json"], cwd=tmp_path)
    assert done.returncode == 1, done.stderr
    result = json.loads(done.stdout)
    assert result["beliefs"]["source"] == str(path)
    assert [d["rule"] for d in result["diagnostics"]] == ["name_null_rot"]


def test_hostile_text_appears_only_inside_string_tokens(standalone: Generated) -> None:
    tokens = list(tokenize.generate_tokens(io.StringIO(standalone.text).readline))
    for token in tokens:
        if any(word in token.string for word in ("PWNED", "jinja", "quote", "bidi")):
            assert token.type == tokenize.STRING, token
    comments = [t.string for t in tokens if t.type == tokenize.COMMENT]
    assert not [c for c in comments if "PWNED" in c or "{{" in c]
