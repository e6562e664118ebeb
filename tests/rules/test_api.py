"""The rule API: rules yield findings, the registry stamps id, category and severity."""

from __future__ import annotations

from launch_linter.engine import LintOptions, lint_text
from launch_linter.model.diagnostic import Category, Location, Problem, Severity
from launch_linter.model.transform import ArgForm, Field, StaticTransform
from launch_linter.rules import RULES_BY_ID
from launch_linter.rules._api import Finding, finding_at, finding_of


def _transform(**changes: object) -> StaticTransform:
    fields: dict[str, object] = dict(
        path="a.launch", line=3, column=5, root="a.launch", included_from=None, name="tf",
        namespace="/", package="tf2_ros", executable="static_transform_publisher",
        args_written="", args="", tokens=(), parent_written="base", child_written="laser",
        translation=(0.0, 0.0, 0.0), rotation=None, period_ms=None, form=ArgForm.YPR,
    )
    fields.update(changes)
    return StaticTransform(**fields)  # type: ignore[arg-type]


def test_a_finding_is_located_at_its_transform_and_names_no_rule() -> None:
    other = _transform(line=9)
    finding = finding_at(_transform(), "m", related=(other, Location("b.launch", 1, 2)))
    assert (finding.path, finding.line, finding.column, finding.node) == ("a.launch", 3, 5, "tf")
    assert finding.related == (Location("a.launch", 9, 5), Location("b.launch", 1, 2))
    assert finding.severity is None and not hasattr(finding, "rule")


def test_the_registry_stamps_id_category_and_severity() -> None:
    rule = RULES_BY_ID["bad_quaternion"]
    plain = rule.diagnostic(Finding("a.launch", 1, 1, "m"))
    assert (plain.rule, plain.category, plain.severity) == (
        "bad_quaternion", Category.TF, Severity.ERROR
    )
    # A documented second level of the rule, and a configured override above both.
    notice = Finding("a.launch", 1, 1, "m", severity=Severity.INFO)
    assert rule.diagnostic(notice).severity is Severity.INFO
    assert rule.diagnostic(notice, Severity.WARNING).severity is Severity.WARNING


def test_front_end_problems_carry_no_severity() -> None:
    problem = Problem("unresolved", "a.launch", 2, 3, "cannot resolve child statically", "tf")
    assert not hasattr(problem, "severity") and not hasattr(problem, "category")
    assert finding_of(problem) == Finding("a.launch", 2, 3, "cannot resolve child statically",
                                          "tf")
    diagnostic = RULES_BY_ID["unresolved"].diagnostic(finding_of(problem))
    assert (diagnostic.category, diagnostic.severity) == (Category.LAUNCH, Severity.INFO)


def test_configured_severity_applies_to_front_end_and_rule_findings() -> None:
    xml = """<launch>
  <node pkg="tf2_ros" type="static_transform_publisher" name="a"
        args="0 0 0 0 0 0 base $(arg child)"/>
  <node pkg="tf2_ros" type="static_transform_publisher" name="b"
        args="0 0 0 0 0 0 base base"/>
</launch>"""
    options = LintOptions(
        package_paths=(),
        severity={"unresolved": Severity.WARNING, "self_transform": Severity.INFO},
    )
    found = {d.rule: d.severity for d in lint_text(xml, "t.launch", options).diagnostics}
    assert found == {"unresolved": Severity.WARNING, "self_transform": Severity.INFO}


def test_unresolved_fields_are_typed() -> None:
    transform = _transform(unresolved=frozenset({Field.CHILD, Field.NAME}))
    assert transform.is_unresolved(Field.CHILD) and transform.is_unresolved(Field.ROTATION,
                                                                            Field.CHILD)
    assert transform.knows(Field.PARENT) and not transform.knows(Field.PARENT, Field.CHILD)
    assert transform.unresolved_names == ("name", "child")
    assert transform.signature is None


def test_unresolved_names_keep_each_front_end_s_order() -> None:
    hidden = frozenset({Field.ARITY, Field.TRANSLATION, Field.ROTATION, Field.PARENT,
                        Field.CHILD})
    assert _transform(unresolved=hidden).unresolved_names == (
        "arity", "translation", "rotation", "parent", "child"
    )
    assert _transform(unresolved=hidden, ros_version=2).unresolved_names == (
        "translation", "rotation", "parent", "child", "arity"
    )
