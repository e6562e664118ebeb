"""The ROS 1 walk's short paths for literal attributes and lone optional node attributes
give what the general paths give: the same refusals, values and anonymous names."""

from __future__ import annotations

import textwrap
from pathlib import Path

import pytest

from launch_linter.frontends.dispatch import load_tree
from launch_linter.frontends.ros1 import LoadOptions
from launch_linter.frontends.ros1_tags import MAX_YAML_BODIES
from launch_linter.model.launch import LaunchTree
from launch_linter.workspace.packages import PackageIndex


def tree_of(tmp_path: Path, body: str) -> LaunchTree:
    path = tmp_path / "t.launch"
    path.write_text("<launch>\n" + textwrap.dedent(body).strip() + "\n</launch>\n")
    return load_tree(str(path), LoadOptions(packages=PackageIndex([])))


def errors(tmp_path: Path, body: str) -> list[str]:
    return [p.message for p in tree_of(tmp_path, body).problems if p.rule == "roslaunch_error"]


NODE = '<node name="n" pkg="p" type="t" {}/>'


@pytest.mark.parametrize(("attrs", "expected"), [
    # One optional attribute alone (resolved without the ordered loop), then with others.
    ('output="bogus"', ["output must be one of 'log', 'screen'"]),
    ('output="$(arg out)"', ["output must be one of 'log', 'screen'"]),
    ('respawn="maybe"', ["invalid bool value for respawn: maybe"]),
    ('required="maybe"', ["invalid bool value for required: maybe"]),
    ('respawn_delay="soon"', ["invalid float value for respawn_delay: soon"]),
    ('cwd="home"', ["cwd must be one of 'ROS_HOME', 'node'"]),
    ('required="true" respawn="true"', ["respawn and required cannot both be set to true"]),
    ('required="true" respawn="false" output="screen"', []),
    ('args="1 2"', []),
    ('output="screen"', []),
])
def test_optional_node_attributes(tmp_path: Path, attrs: str, expected: list[str]) -> None:
    body = '<arg name="out" default="bogus"/>\n' + NODE.format(attrs)
    assert errors(tmp_path, body) == expected


def test_literal_and_substituted_node_fields(tmp_path: Path) -> None:
    tree = tree_of(tmp_path, """
        <arg name="pkg" default="p2"/>
        <node name="a" pkg="p1" type="t1"/>
        <node name="$(anon b)" pkg="$(arg pkg)" type="t2" output="$(anon b)"/>
        <node name="" pkg="" type="t3"/>
    """)
    nodes = [(n.name, n.package, n.executable) for n in tree.nodes]
    assert nodes == [("a", "p1", "t1"), ("b_anon1", "p2", "t2"), ("", "", "t3")]
    assert errors(tmp_path, '<node name="" pkg="" type="t3"/>') == [
        "package must be non-empty"]


def test_literal_args_and_params(tmp_path: Path) -> None:
    tree = tree_of(tmp_path, """
        <arg name="frame" default="base"/>
        <arg name="empty" default=""/>
        <arg name="copy" value="$(arg frame)"/>
        <node name="n" pkg="p" type="t">
          <param name="literal" value="odom"/>
          <param name="read" value="$(arg copy)"/>
          <param name="blank" value=""/>
          <param name="anon" value="$(anon x)"/>
        </node>
        <param name="count" type="int" value="$(arg empty)"/>
    """)
    (node,) = tree.nodes
    params = dict(node.params)
    assert (params["literal"], params["read"], params["blank"]) == ("odom", "base", "")
    assert params["anon"] != "$(anon x)"
    # The blank root default is noticed with the literal path: not a roslaunch error.
    assert [p.rule for p in tree.problems if "empty default" in p.message] == ["unresolved"]


def test_a_node_rosparam_text_is_read_once_and_judged(tmp_path: Path,
                                                      monkeypatch: pytest.MonkeyPatch) -> None:
    """A node's ``<rosparam>`` text is parsed once: judged (roslaunch refuses text that is
    not YAML) and read for the node's record from the same parse; only a text that does not
    read is judged again by the syntax check."""
    from launch_linter.frontends import ros1_tags

    judged: list[str] = []
    original = ros1_tags.yaml_syntax_error
    monkeypatch.setattr(ros1_tags, "yaml_syntax_error",
                        lambda text: judged.append(text) or original(text))
    tree = tree_of(tmp_path, """
        <node name="n" pkg="p" type="t">
          <rosparam>gain: 2
frame: odom</rosparam>
        </node>
    """)
    assert dict(tree.nodes[0].params) == {"gain": "2", "frame": "odom"}
    assert judged == [] and [p for p in tree.problems if p.rule == "roslaunch_error"] == []
    # rosparam's own tags do not construct, but they compose: no error.
    tags = '<node name="n" pkg="p" type="t"><rosparam>a: !degrees 90</rosparam></node>'
    assert errors(tmp_path, tags) == []
    assert judged == ["a: !degrees 90"]
    bad = '<node name="n" pkg="p" type="t"><rosparam>a: [1, 2</rosparam></node>'
    (refused,) = errors(tmp_path, bad)
    assert refused.startswith("error loading <rosparam> tag: Error within YAML block:")
    # A text put under a ``param`` is not read as the node's parameters: only judged.
    under = '<node name="n" pkg="p" type="t"><rosparam param="g">[1, 2</rosparam></node>'
    (refused,) = errors(tmp_path, under)
    assert refused.startswith("error loading <rosparam> tag: Error within YAML block:")
    assert judged[-1] == "[1, 2"


def test_more_node_rosparam_texts_than_the_tree_keeps(tmp_path: Path) -> None:
    """Past the texts a tree keeps parsed, each node's text is still read and judged."""
    count = MAX_YAML_BODIES + 6
    nodes = "\n".join(f'<node name="n{i}" pkg="p" type="t"><rosparam>k{i}: {i}</rosparam>'
                      f'<rosparam>bad{i}: [</rosparam></node>' for i in range(count))
    tree = tree_of(tmp_path, nodes)
    assert [dict(n.params) for n in tree.nodes] == [{f"k{i}": str(i)} for i in range(count)]
    assert len([p for p in tree.problems if "Error within YAML block" in p.message]) == count
