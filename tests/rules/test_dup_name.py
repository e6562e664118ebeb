from __future__ import annotations

from typing import Callable, List, Tuple

from launch_linter.model import Diagnostic, LaunchTree, Location, Severity
from launch_linter.model.record import replace
from launch_linter.rules import RULES_BY_ID, RuleContext

Lint = Callable[..., List[Tuple[str, int]]]
LintDiagnostics = Callable[..., Tuple[Diagnostic, ...]]
LintTree = Callable[..., Tuple[Diagnostic, ...]]

RULE = "dup_name"


def node(name: str, args: str, attrs: str = "", pkg: str = "tf2_ros") -> str:
    return (
        f'<node pkg="{pkg}" type="static_transform_publisher" name="{name}" '
        f'args="{args}" {attrs}/>'
    )


def test_second_occurrence_points_at_first(lint_diagnostics: LintDiagnostics) -> None:
    xml = "\n".join([
        "<launch>",
        node("tf", "0 0 0 0 0 0 a b"),
        node("tf", "0 0 0 0 0 0 a c"),
        node("tf", "0 0 0 0 0 0 a d"),
        "</launch>",
    ])
    found = lint_diagnostics(xml, RULE)
    assert [(d.line, d.severity) for d in found] == [(3, Severity.ERROR), (4, Severity.ERROR)]
    assert all(d.related == (Location("test.launch", 2, 1),) for d in found)
    assert "roslaunch refuses to start" in found[0].message
    assert "[/tf]" in found[0].message


def test_different_namespaces_may_share_a_name(lint: Lint) -> None:
    xml = "\n".join([
        "<launch>",
        '<group ns="robot1">', node("tf", "0 0 0 0 0 0 a b"), "</group>",
        '<group ns="robot2">', node("tf", "0 0 0 0 0 0 a b"), "</group>",
        "</launch>",
    ])
    assert lint(xml, RULE) == []


def test_same_namespace_through_node_ns(lint: Lint) -> None:
    xml = "\n".join([
        "<launch>",
        '<group ns="robot1">', node("tf", "0 0 0 0 0 0 a b"), "</group>",
        node("tf", "0 0 0 0 0 0 a c", 'ns="robot1"'),
        "</launch>",
    ])
    assert lint(xml, RULE) == [(RULE, 5)]


def test_mutually_exclusive_conditions_are_not_duplicates(lint: Lint) -> None:
    xml = "\n".join([
        "<launch>",
        '<arg name="sim"/>',
        node("tf", "0 0 0 0 0 0 a b", 'if="$(arg sim)"'),
        node("tf", "0 0 0 0 0 0 a c", 'unless="$(arg sim)"'),
        "</launch>",
    ])
    assert lint(xml, RULE) == []


def test_skipped_node_does_not_count(lint: Lint) -> None:
    xml = "\n".join([
        "<launch>",
        node("tf", "0 0 0 0 0 0 a b", 'if="false"'),
        node("tf", "0 0 0 0 0 0 a c"),
        "</launch>",
    ])
    assert lint(xml, RULE) == []


def test_unknown_condition_says_if_both_launched(lint_diagnostics: LintDiagnostics) -> None:
    xml = "\n".join([
        "<launch>",
        '<arg name="sim"/>',
        node("tf", "0 0 0 0 0 0 a b"),
        node("tf", "0 0 0 0 0 0 a c", 'if="$(arg sim)"'),
        "</launch>",
    ])
    (found,) = lint_diagnostics(xml, RULE)
    assert found.line == 4 and "if both are launched" in found.message


def test_unresolved_name_is_silent(lint: Lint) -> None:
    xml = "\n".join([
        "<launch>",
        '<arg name="n"/>',
        node("$(arg n)", "0 0 0 0 0 0 a b"),
        node("tf", "0 0 0 0 0 0 a c"),
        "</launch>",
    ])
    assert lint(xml, RULE) == []
    assert lint(xml, RULE, {"n": "tf"}) == [(RULE, 4)]


def test_across_included_files(lint_tree: LintTree) -> None:
    child = "<launch>\n" + node("laser_tf", "0 0 0 0 0 0 base laser") + "\n</launch>\n"
    root = "\n".join([
        "<launch>",
        node("laser_tf", "0 0 0 0 0 0 base laser2"),
        '<include file="$(dirname)/child.launch"/>',
        "</launch>",
    ])
    (found,) = lint_tree({"child.launch": child, "root.launch": root}, "root.launch", RULE)
    assert found.path.endswith("child.launch") and found.line == 2
    assert found.related[0].path.endswith("root.launch") and found.related[0].line == 2
    assert "same launch tree" in found.message
    assert "roslaunch refuses to start" in found.message


def test_same_file_included_twice_in_one_namespace(lint_tree: LintTree) -> None:
    child = "<launch>\n" + node("laser_tf", "0 0 0 0 0 0 base laser") + "\n</launch>\n"
    root = "\n".join([
        "<launch>",
        '<include file="$(dirname)/child.launch"/>',
        '<include file="$(dirname)/child.launch"/>',
        '<include file="$(dirname)/child.launch" ns="other"/>',
        "</launch>",
    ])
    (found,) = lint_tree({"child.launch": child, "root.launch": root}, "root.launch", RULE)
    assert found.path.endswith("child.launch") and found.line == 2
    assert "included twice" in found.message


def test_ros2_duplicate_is_info(lint_diagnostics: LintDiagnostics) -> None:
    xml = "\n".join([
        "<launch>",
        node("tf", "0 0 0 0 0 0 a b"),
        node("tf", "0 0 0 0 0 0 a c"),
        "</launch>",
    ])
    ros1 = lint_diagnostics(xml, RULE)
    assert [d.severity for d in ros1] == [Severity.ERROR]
    # The ROS 2 front-ends mark their transforms ros_version=2; feed such a tree directly.
    from launch_linter import LintOptions, lint_text

    tree = lint_text(xml, "t.launch", LintOptions(package_paths=())).trees[0]
    ros2 = LaunchTree(
        tree.root, tree.status,
        tuple(replace(t, ros_version=2) for t in tree.transforms), (), tree.files,
    )
    # ROS 2 launch starts both nodes: info by default, the study's warning in its profile.
    (found,) = RULES_BY_ID[RULE].check(RuleContext(ros2))
    assert found.severity is Severity.INFO
    (study,) = RULES_BY_ID[RULE].check(RuleContext(ros2, profile="study"))
    assert study.severity is Severity.WARNING
    assert "ROS 2" in found.message and "refuses" not in found.message


def test_study_fig_4b_duplicated_name(lint: Lint) -> None:
    # Fig. 4(b): two nodes named ..._publisher1 (one tf, one tf2_ros) and a ..._publisher3.
    xml = "\n".join([
        "<launch>",
        node("static_transform_publisher1", "0.0 0.365 0.2 -1.57 0.0 0.0 base wheel_l", pkg="tf"),
        node("static_transform_publisher1", "0.0 -0.365 0.2 -1.57 0.0 0.0 base wheel_r"),
        node("static_transform_publisher3", "0.0 -0.365 0.2 -1.57 0.0 0.0 base wheel_c"),
        "</launch>",
    ])
    assert lint(xml, RULE) == [(RULE, 3)]
