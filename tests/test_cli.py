"""The check / rules / explain commands: output formats, selection, exit codes."""

from __future__ import annotations

import json
import re
from pathlib import Path

import pytest

from launch_linter.cli import main
from launch_linter.rules import RULES, Rule

TEXT_LINE = re.compile(
    r"^(?P<path>[^:]+):(?P<line>\d+):(?P<column>\d+): "
    r"(?P<severity>error|warning|info): (?P<message>.+) \[(?P<rule>[a-z_]+)\]$"
)

# error (bad_arity) on line 3, info (leading_slash) on line 5.
MIXED = """<launch>
  <node pkg="tf2_ros" type="static_transform_publisher" name="a"
        args="0 0 0.2 0 0 0 base_link laser 100"/>
  <node pkg="tf" type="static_transform_publisher" name="b"
        args="0.1 0 0.2 0 0 0 base_link /camera 100"/>
</launch>
"""
# warning (rot_degrees: a yaw of 90 reads as radians)
WARNING_ONLY = """<launch>
  <node pkg="tf" type="static_transform_publisher" name="b"
        args="0.1 0 0.2 90 0 0 base_link camera 100"/>
</launch>
"""
INFO_ONLY = """<launch>
  <arg name="frame"/>
  <node pkg="tf2_ros" type="static_transform_publisher" name="c"
        args="0.1 0 0.2 0 0 0 base_link $(arg frame)"/>
</launch>
"""
CLEAN = """<launch>
  <node pkg="tf2_ros" type="static_transform_publisher" name="laser_tf"
        args="0.1 0 0.2 0 0 0 base_link laser"/>
</launch>
"""


@pytest.fixture
def workdir(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    monkeypatch.chdir(tmp_path)
    for name, text in {
        "mixed.launch": MIXED,
        "warn.launch": WARNING_ONLY,
        "info.launch": INFO_ONLY,
        "clean.launch": CLEAN,
        "broken.launch": "<launch><node></launch>",
    }.items():
        (tmp_path / name).write_text(text, encoding="utf-8")
    return tmp_path


def check(capsys: pytest.CaptureFixture[str], *argv: str) -> tuple[int, str, str]:
    status = main(["check", "--beliefs", "none", *argv])
    out, err = capsys.readouterr()
    return status, out, err


def test_text_format(workdir: Path, capsys: pytest.CaptureFixture[str]) -> None:
    status, out, err = check(capsys, "mixed.launch")
    assert status == 1
    lines = out.splitlines()
    parsed = [TEXT_LINE.match(line) for line in lines]
    assert all(parsed), lines
    assert [(m["path"], m["line"], m["column"], m["severity"], m["rule"]) for m in parsed if m] == [
        ("mixed.launch", "2", "3", "error", "bad_arity"),
        ("mixed.launch", "4", "3", "info", "leading_slash"),
    ]
    assert "\033[" not in out
    assert "1 error(s), 0 warning(s), 1 info" in err


def test_colour_on_request(workdir: Path, capsys: pytest.CaptureFixture[str]) -> None:
    _, out, _ = check(capsys, "mixed.launch", "--color", "always")
    assert "\033[31m" in out and "[bad_arity]" in out
    _, out, _ = check(capsys, "mixed.launch", "--color", "never")
    assert "\033[" not in out


def test_json_contract(workdir: Path, capsys: pytest.CaptureFixture[str]) -> None:
    status, out, _ = check(capsys, "mixed.launch", "clean.launch", "broken.launch",
                           "--format", "json")
    assert status == 1
    document = json.loads(out)
    assert document["version"] == 1
    assert document["tool"]["name"] == "launch-linter"
    assert set(document["beliefs"]) == {"source", "min_z", "count"}
    assert document["files"] == [
        {"path": "mixed.launch", "status": "ok", "transforms": 2},
        {"path": "clean.launch", "status": "ok", "transforms": 1},
        {"path": "broken.launch", "status": "parse_error", "transforms": 0},
    ]
    fields = {"rule", "category", "severity", "path", "line", "column", "message", "node",
              "related", "belief", "fix", "included_from"}
    for diagnostic in document["diagnostics"]:
        assert set(diagnostic) == fields
        assert diagnostic["category"] in ("must", "may_semantic", "may_implied", "tf", "launch")
    by_rule = {d["rule"]: d for d in document["diagnostics"]}
    assert by_rule["bad_arity"] == {
        "rule": "bad_arity", "category": "tf", "severity": "error", "path": "mixed.launch",
        "line": 2, "column": 3, "message": by_rule["bad_arity"]["message"], "node": "a",
        "related": [], "belief": None, "fix": by_rule["bad_arity"]["fix"],
        "included_from": None,
    }
    assert by_rule["parse_error"]["path"] == "broken.launch"
    assert by_rule["parse_error"]["fix"] is None


def test_json_related_locations(workdir: Path, capsys: pytest.CaptureFixture[str]) -> None:
    node = CLEAN.splitlines()[1:3]
    text = "\n".join(["<launch>", *node, *node, "</launch>"])
    (workdir / "dup.launch").write_text(text, encoding="utf-8")
    _, out, _ = check(capsys, "dup.launch", "--format", "json", "--select", "dup_sig")
    (diagnostic,) = json.loads(out)["diagnostics"]
    assert diagnostic["related"] == [{"path": "dup.launch", "line": 2, "column": 3}]


def test_folder_lists_every_file_once(workdir: Path, capsys: pytest.CaptureFixture[str]) -> None:
    _, out, _ = check(capsys, ".", "--format", "json")
    paths = [f["path"] for f in json.loads(out)["files"]]
    assert sorted(paths) == sorted(set(paths)) and len(paths) == 5


@pytest.mark.parametrize(
    ("option", "rules"),
    [
        (["--select", "leading_slash"], {"leading_slash"}),
        (["--select", "tf"], {"bad_arity", "leading_slash"}),
        (["--select", "must,leading_slash"], {"leading_slash"}),
        (["--select", "must", "--select", "bad_arity"], {"bad_arity"}),
        (["--ignore", "bad_arity"], {"leading_slash"}),
        (["--ignore", "tf"], set()),
        (["--select", "tf", "--ignore", "leading_slash"], {"bad_arity"}),
    ],
)
def test_select_and_ignore(
    workdir: Path, capsys: pytest.CaptureFixture[str], option: list[str], rules: set[str]
) -> None:
    _, out, _ = check(capsys, "mixed.launch", "--format", "json", *option)
    assert {d["rule"] for d in json.loads(out)["diagnostics"]} == rules


@pytest.mark.parametrize(
    ("path", "fail_on", "status"),
    [
        ("clean.launch", None, 0),
        ("mixed.launch", None, 1),
        ("warn.launch", None, 1),
        ("warn.launch", "error", 0),
        ("warn.launch", "warning", 1),
        ("info.launch", None, 0),
        ("info.launch", "warning", 0),
        ("info.launch", "info", 1),
        ("mixed.launch", "error", 1),
        ("broken.launch", None, 1),
    ],
)
def test_fail_on_and_exit_status(
    workdir: Path, capsys: pytest.CaptureFixture[str], path: str, fail_on: str | None,
    status: int,
) -> None:
    extra = ["--fail-on", fail_on] if fail_on else []
    assert check(capsys, path, *extra)[0] == status


@pytest.mark.parametrize(
    "argv",
    [
        ["check", "mixed.launch", "--select", "no_such_rule"],
        ["check", "mixed.launch", "--ignore", "no_such_rule"],
        ["explain", "no_such_rule"],
        [],
    ],
)
def test_usage_errors_exit_2(
    workdir: Path, capsys: pytest.CaptureFixture[str], argv: list[str]
) -> None:
    assert main(argv) == 2


def test_bad_option_value_exits_2(workdir: Path) -> None:
    with pytest.raises(SystemExit) as exc:
        main(["check", "mixed.launch", "--fail-on", "fatal"])
    assert exc.value.code == 2


def test_rules_table(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["rules"]) == 0
    header, *lines = capsys.readouterr().out.splitlines()
    assert header.split()[:4] == ["ID", "CATEGORY", "SEVERITY", "SUMMARY"]
    assert len(lines) == len(RULES)
    for rule, line in zip(RULES, lines):
        # The contract's columns, in order; what this version adds follows the summary.
        assert line.split()[:3] == [rule.id, rule.category.value, rule.severity.value]
        rest = line.split(None, 3)[3]
        assert rest.startswith(rule.summary + "  [") and rest.endswith("]")


@pytest.mark.parametrize("rule", RULES, ids=lambda r: r.id)
def test_explain(capsys: pytest.CaptureFixture[str], rule: Rule) -> None:
    assert main(["explain", rule.id]) == 0
    out = capsys.readouterr().out
    assert out.startswith(rule.id)
    assert rule.doc in out
    assert "## Why is this bad?" in out


def test_a_core_command_line_builds_only_the_core_parsers() -> None:
    from launch_linter.cli import _core_only, build_parser

    assert _core_only(["check", "--format", "json", "a.launch"])
    assert _core_only(["--version"])
    assert not _core_only(["mine", "corpus", "--db", "x.db"])
    assert not _core_only(["--help"])
    assert not _core_only([])
    commands = build_parser(["check", "a.launch"])._subparsers._group_actions[0].choices  # type: ignore[union-attr]
    assert set(commands) == {"check"}  # a named core command: its parser alone
    commands = build_parser(["--help"])._subparsers._group_actions[0].choices  # type: ignore[union-attr]
    assert {"check", "transforms", "rules", "explain"} <= set(commands)
    assert "mine" in build_parser()._subparsers._group_actions[0].choices  # type: ignore[union-attr]


def test_precision_says_its_sample_and_when_it_is_small() -> None:
    from launch_linter.measured import wilson_interval

    low, high = wilson_interval(1, 1)
    assert round(low, 2) == 0.21 and high == pytest.approx(1.0)
    assert wilson_interval(19, 20)[0] == pytest.approx(0.764, abs=0.001)
    from launch_linter import measured

    table = {"few": {"after": {"judged": 1, "precision": 1.0, "true": 1}},
             "many": {"after": {"judged": 40, "precision": 0.95, "true": 38}}}
    original = measured._table
    try:
        measured._table = lambda: table  # type: ignore[assignment]
        assert measured.precision_text("few") == (
            "100% of 1 judged, small sample: 95% interval 21% to 100%")
        assert measured.precision_text("many") == "95% of 40 judged"
        assert measured.precision_text("none") == "not measured"
    finally:
        measured._table = original  # type: ignore[assignment]
