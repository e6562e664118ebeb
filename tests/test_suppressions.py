"""Inline ``launch-linter:`` directives and the unused_suppression rule."""

from __future__ import annotations

from pathlib import Path

from launch_linter import LintOptions, lint_paths, lint_text
from launch_linter.model import Category, Diagnostic, FileStatus, LaunchTree, Severity
from launch_linter.model.launch import Comment
from launch_linter.suppressions import PathIgnore, apply_suppressions, parse_directives


def node(name: str, args: str, attrs: str = "") -> str:
    return (
        f'<node pkg="tf2_ros" type="static_transform_publisher" name="{name}" '
        f'args="{args}" {attrs}/>'
    )


SAME = "0 0 0 0 0 0 base_link base_link"
SAME2 = "0 0 0 0 0 0 odom odom"


def found(
    xml: str, select: frozenset[str] | None = None, ignore: frozenset[str] = frozenset()
) -> list[tuple[str, int]]:
    options = LintOptions(package_paths=(), select=select, ignore=ignore)
    return [(d.rule, d.line) for d in lint_text(xml, "test.launch", options).diagnostics]


def test_disable_covers_the_next_element_only() -> None:
    xml = "\n".join([
        "<launch>",
        "  <!-- launch-linter: disable=self_transform -->",
        "  " + node("a", SAME),
        "  " + node("b", SAME2),
        "</launch>",
    ])
    assert found(xml) == [("self_transform", 4)]


def test_without_directive_both_are_reported() -> None:
    xml = "\n".join(["<launch>", "  " + node("a", SAME), "  " + node("b", SAME2), "</launch>"])
    assert found(xml) == [("self_transform", 2), ("self_transform", 3)]


def test_multi_line_comment_and_reason_text() -> None:
    xml = "\n".join([
        "<launch>",
        "  <!--",
        "    launch-linter: disable=self_transform   the driver expects it",
        "  -->",
        "  " + node("a", SAME),
        "</launch>",
    ])
    assert found(xml) == []


def test_trailing_comment_on_the_same_line_does_not_cover_that_element() -> None:
    xml = "\n".join([
        "<launch>",
        "  " + node("a", SAME) + " <!-- launch-linter: disable=self_transform -->",
        "  " + node("b", "0 0 0 0 0 0 map odom"),
        "</launch>",
    ])
    assert sorted(found(xml)) == [("self_transform", 2), ("unused_suppression", 2)]


def test_disable_file_covers_the_whole_file() -> None:
    xml = "\n".join([
        "<launch>",
        "  " + node("a", SAME),
        "  <!-- launch-linter: disable-file=self_transform -->",
        "  " + node("b", SAME2),
        "</launch>",
    ])
    assert found(xml) == []


def test_several_ids_and_categories() -> None:
    xml = "\n".join([
        "<launch>",
        "  <!-- launch-linter: disable=must, leading_slash -->",
        "  " + node("a", "0 0 0 0 0 0 /base_link /base_link"),
        "</launch>",
    ])
    assert found(xml) == []


def test_unused_id_is_reported_at_the_comment() -> None:
    xml = "\n".join([
        "<launch>",
        "  <!-- launch-linter: disable=self_transform,dup_sig -->",
        "  " + node("a", SAME),
        "</launch>",
    ])
    result = lint_text(xml, "test.launch", LintOptions(package_paths=()))
    (unused,) = result.diagnostics
    assert (unused.rule, unused.line, unused.severity) == (
        "unused_suppression", 2, Severity.INFO
    )
    assert unused.category is Category.LAUNCH
    assert "dup_sig" in unused.message


def test_unused_file_directive_is_reported() -> None:
    xml = "\n".join([
        "<launch>",
        "  <!-- launch-linter: disable-file=dup_sig -->",
        "  " + node("a", "0 0 0 0 0 0 map odom"),
        "</launch>",
    ])
    assert found(xml) == [("unused_suppression", 2)]


def test_directive_with_no_element_after_it_is_unused() -> None:
    xml = "\n".join([
        "<launch>",
        "  " + node("a", SAME),
        "  <!-- launch-linter: disable=self_transform -->",
        "</launch>",
    ])
    assert found(xml) == [("self_transform", 2), ("unused_suppression", 3)]


def test_unknown_rule_id_is_reported() -> None:
    xml = "\n".join([
        "<launch>",
        "  <!-- launch-linter: disable=self_transfrom -->",
        "  " + node("a", SAME),
        "</launch>",
    ])
    result = lint_text(xml, "test.launch", LintOptions(package_paths=()))
    assert [(d.rule, d.line) for d in result.diagnostics] == [
        ("unused_suppression", 2), ("self_transform", 3)
    ]
    assert "unknown rule 'self_transfrom'" in result.diagnostics[0].message


def test_malformed_directive_is_reported_and_other_comments_are_not() -> None:
    xml = "\n".join([
        "<launch>",
        "  <!-- launch-linter: disabel=self_transform -->",
        "  <!-- run launch-linter: it helps -->",
        "  " + node("a", "0 0 0 0 0 0 map odom"),
        "</launch>",
    ])
    assert found(xml) == [("unused_suppression", 2)]


def test_rule_that_did_not_run_is_not_reported_unused() -> None:
    xml = "\n".join([
        "<launch>",
        "  <!-- launch-linter: disable=dup_sig -->",
        "  " + node("a", SAME),
        "</launch>",
    ])
    assert found(xml, select=frozenset({"self_transform", "unused_suppression"})) == [
        ("self_transform", 3)
    ]
    assert found(xml) == [("unused_suppression", 2), ("self_transform", 3)]


def test_ignoring_unused_suppression_still_applies_suppressions() -> None:
    xml = "\n".join([
        "<launch>",
        "  <!-- launch-linter: disable=self_transform,dup_sig -->",
        "  " + node("a", SAME),
        "</launch>",
    ])
    assert found(xml, ignore=frozenset({"unused_suppression"})) == []
    assert found(xml, select=frozenset({"must"})) == []


def test_unused_suppression_takes_a_severity_override() -> None:
    xml = "<launch>\n  <!-- launch-linter: disable-file=dup_sig -->\n</launch>"
    options = LintOptions(package_paths=(), severity={"unused_suppression": Severity.WARNING})
    (unused,) = lint_text(xml, "test.launch", options).diagnostics
    assert unused.severity is Severity.WARNING


def test_disable_file_unused_suppression_silences_the_reports() -> None:
    xml = "\n".join([
        "<launch>",
        "  <!-- launch-linter: disable-file=unused_suppression -->",
        "  <!-- launch-linter: disable=dup_sig -->",
        "  " + node("a", "0 0 0 0 0 0 map odom"),
        "</launch>",
    ])
    assert found(xml) == []


def test_directive_in_an_included_file(tmp_path: Path) -> None:
    (tmp_path / "inner.launch").write_text("\n".join([
        "<launch>",
        "  <!-- launch-linter: disable=self_transform -->",
        "  " + node("inner", SAME),
        "</launch>",
    ]))
    (tmp_path / "outer.launch").write_text("\n".join([
        "<launch>",
        '  <include file="$(dirname)/inner.launch"/>',
        "  " + node("outer", SAME),
        "</launch>",
    ]))
    result = lint_paths([str(tmp_path / "outer.launch")], LintOptions(package_paths=()))
    assert [(Path(d.path).name, d.rule, d.line) for d in result.diagnostics] == [
        ("outer.launch", "self_transform", 3)
    ]


def test_use_in_any_tree_counts(tmp_path: Path) -> None:
    # inner.launch is linted on its own (frame unresolved: nothing to suppress) and
    # through outer.launch (frame set: the directive is used).
    (tmp_path / "inner.launch").write_text("\n".join([
        "<launch>",
        '  <arg name="frame" default="$(optenv FRAME)"/>',
        "  <!-- launch-linter: disable=self_transform -->",
        "  " + node("inner", "0 0 0 0 0 0 $(arg frame) base_link"),
        "</launch>",
    ]))
    (tmp_path / "outer.launch").write_text("\n".join([
        "<launch>",
        '  <include file="$(dirname)/inner.launch">',
        '    <arg name="frame" value="base_link"/>',
        "  </include>",
        "</launch>",
    ]))
    options = LintOptions(package_paths=(), select=frozenset({"must", "unused_suppression"}))
    assert lint_paths([str(tmp_path)], options).diagnostics == ()
    alone = lint_paths([str(tmp_path / "inner.launch")], options).diagnostics
    assert [(d.rule, d.line) for d in alone] == [("unused_suppression", 3)]


def _tree(comments: list[tuple[int, str]], lines: list[int]) -> LaunchTree:
    return LaunchTree(
        root="robot.launch.py",
        status=FileStatus.OK,
        transforms=(),
        problems=(),
        files=("robot.launch.py",),
        comments=tuple(Comment("robot.launch.py", line, text) for line, text in comments),
        element_lines=tuple(("robot.launch.py", line) for line in lines),
    )


def _diagnostic(rule: str, line: int) -> Diagnostic:
    return Diagnostic(rule, Category.MUST, Severity.ERROR, "robot.launch.py", line, 5, "m")


KNOWN = {"dup_sig": "must", "self_transform": "must", "unused_suppression": "launch"}


def test_hash_comments_of_yaml_and_python_front_ends() -> None:
    tree = _tree([(3, "# launch-linter: disable=dup_sig"), (7, " launch-linter: disable=dup_sig")],
                 [1, 4, 6, 9])
    kept, unused = apply_suppressions(
        [tree], [_diagnostic("dup_sig", 4), _diagnostic("dup_sig", 6), _diagnostic("dup_sig", 9)],
        KNOWN, ran=set(KNOWN), report_unused=True,
    )
    assert [d.line for d in kept] == [6]
    assert unused == []


def test_directives_read_twice_count_once() -> None:
    tree = _tree([(2, "launch-linter: disable=dup_sig"), (2, "launch-linter: disable=dup_sig")],
                 [3, 3])
    directives, malformed = parse_directives([tree, tree])
    assert len(directives) == 1 and directives[0].target == 3 and not malformed
    _, unused = apply_suppressions([tree], [], KNOWN, ran=set(KNOWN), report_unused=True)
    assert len(unused) == 1


def test_no_report_when_unused_suppression_is_off() -> None:
    tree = _tree([(2, "launch-linter: disable=dup_sig,nonsense")], [3])
    kept, unused = apply_suppressions(
        [tree], [_diagnostic("dup_sig", 3)], KNOWN, ran=set(KNOWN), report_unused=False
    )
    assert kept == [] and unused == []


def test_path_ignore_globs(tmp_path: Path) -> None:
    base = str(tmp_path)
    by_name = PathIgnore(base, "*_test.launch", frozenset({"dup_sig"}))
    assert by_name.matches(str(tmp_path / "a" / "b" / "x_test.launch"))
    assert not by_name.matches(str(tmp_path / "x_test.launch.xml"))
    nested = PathIgnore(base, "generated/**", frozenset({"dup_sig"}))
    assert nested.matches(str(tmp_path / "generated" / "deep" / "a.launch"))
    assert not nested.matches(str(tmp_path / "src" / "generated.launch"))
    one_level = PathIgnore(base, "launch/*.launch", frozenset({"dup_sig"}))
    assert one_level.matches(str(tmp_path / "launch" / "a.launch"))
    assert not one_level.matches(str(tmp_path / "launch" / "sub" / "a.launch"))
    any_depth = PathIgnore(base, "**/sim/*.launch", frozenset({"dup_sig"}))
    assert any_depth.matches(str(tmp_path / "sim" / "a.launch"))
    assert any_depth.matches(str(tmp_path / "pkg" / "sim" / "a.launch"))
    outside = PathIgnore(str(tmp_path / "inner"), "**", frozenset({"dup_sig"}))
    assert not outside.matches(str(tmp_path / "other.launch"))
