from __future__ import annotations

import time
from pathlib import Path

from conftest import run_rule
from launch_linter.frontends.ros1 import LoadOptions, Ros1Loader
from launch_linter.frontends.ros1_attributes import ignored_attributes
from launch_linter.model.budget import Budget
from launch_linter.resolve.xml_safe import parse_xml

RULE = "ros1_ignored_attribute"


def found(xml: str) -> list[tuple[int, str]]:
    return [(d.line, d.severity.value) for d in run_rule(xml, RULE)]


def test_an_include_given_args_passes_nothing() -> None:
    """Learning_ROS 2nd edition PR #18: args="gui:=false" on an <include>."""
    xml = ('<launch>\n<include file="$(dirname)/world.launch" args="gui:=false">\n'
           '</include>\n</launch>')
    (diagnostic,) = run_rule(xml, RULE)
    assert (diagnostic.line, diagnostic.severity.value) == (2, "warning")
    assert "'args' on <node> and <test>, not on <include>" in diagnostic.message
    fixed = xml.replace(' args="gui:=false">', '>\n<arg name="gui" value="false"/>')
    assert found(fixed) == []


def test_a_tag_roslaunch_skips_where_it_is_written() -> None:
    # A <param> inside an <include> sets nothing (roslaunch reads <arg> and <env> there).
    xml = ('<launch>\n<include file="$(dirname)/mapping.launch">\n'
           '<param name="base_frame" value="base_footprint"/>\n</include>\n'
           '<node pkg="p" type="t" name="n">\n<arg name="x" value="1"/>\n'
           '<Param name="rate" value="5"/>\n</node>\n</launch>')
    # The node's <Param> is read (roslaunch lowers a node's children's names).
    assert found(xml) == [(3, "warning"), (6, "warning")]


def test_labels_and_words_no_tag_reads_are_info() -> None:
    xml = ('<launch>\n<group name="odometry">\n<node pkg="p" type="t" name="n" '
           'display="screen"/>\n</group>\n<arg name="a" default="1" description="d"/>\n'
           '<sphinxdoc><![CDATA[text]]></sphinxdoc>\n</launch>')
    assert sorted(found(xml)) == [(2, "info"), (3, "info"), (5, "info"), (6, "info")]


def test_what_roslaunch_reads_is_silent() -> None:
    xml = ('<launch>\n<master auto="start"/>\n<arg name="a" default="1" doc="d"/>\n'
           '<group ns="r" clear_params="true" if="$(arg a)">\n'
           '<node pkg="p" type="t" name="n" output="screen" respawn="true" '
           'respawn_delay="2" launch-prefix="nice" required="false" cwd="node" '
           'machine="m" ns="x" clear_params="true" args="1" unless="0">\n'
           '<remap from="a" to="b"/><param name="p" value="1" type="int"/>\n'
           '<rosparam command="load" subst_value="true" param="q">{}</rosparam>\n'
           '<env name="E" value="1"/></node>\n'
           '<include file="$(dirname)/x.launch" ns="i" pass_all_args="true">'
           '<arg name="b" value="2"/><env name="F" value="2"/></include>\n'
           '</group>\n<test test-name="t" pkg="p" type="t" time-limit="10" retry="1"/>\n'
           '</launch>')
    assert found(xml) == []


def test_twenty_thousand_tags_are_read_once_each() -> None:
    """Hostile: 20,000 nodes with an unknown attribute each, and 20,000 params inside an
    include: one pass over the elements."""
    nodes = "".join(f'<node pkg="p" type="t" name="n{i}" display="screen"/>'
                    for i in range(20_000))
    params = "".join(f'<param name="p{i}" value="1"/>' for i in range(20_000))
    xml = f'<launch>{nodes}<include file="x.launch">{params}</include></launch>'
    launch = parse_xml(xml.encode("utf-8")).root
    steps: list[int] = []
    start = time.process_time()
    found_here = list(ignored_attributes(launch, steps.append))
    assert time.process_time() - start < 30.0
    # One step per element, charged per parent: the launch's 20,001 children, then the
    # include's 20,000 (a leaf is charged nothing of its own).
    assert len(found_here) == 40_000 and sorted(steps) == [20_000, 20_001]


def test_a_budget_spent_on_the_root_file_is_said_not_raised(tmp_path: Path) -> None:
    """The root file is scanned before the walk (whose catch says a spent budget)."""
    path = tmp_path / "big.launch"
    path.write_text("<launch>" + '<arg name="a" default="1"/>' * 5_000 + "</launch>",
                    encoding="utf-8")
    loader = Ros1Loader(LoadOptions())
    loader.budget = Budget(max_steps=2_000)
    tree = loader.load(str(path))
    assert any(p.rule == "unresolved" and "budget" in p.message for p in tree.problems)
