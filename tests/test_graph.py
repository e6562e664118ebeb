"""``launch-linter graph``: DOT and Mermaid content, and images through Graphviz."""

from __future__ import annotations

import re
import shutil
import subprocess
from pathlib import Path

import pytest

from launch_linter import LintOptions, lint_text
from launch_linter.cli import main
from launch_linter.graph import commands
from launch_linter.graph.model import Edge, Frame, TfGraph, build_graph
from launch_linter.graph.render import to_dot, to_mermaid

NODE = '<node pkg="tf2_ros" type="static_transform_publisher" name="{name}" args="{args}" {attrs}/>'


def node(name: str, args: str, attrs: str = "") -> str:
    return "  " + NODE.format(name=name, args=args, attrs=attrs)


ROBOT = "\n".join([
    "<launch>",
    '  <arg name="use_gps"/>',
    node("base_to_laser", "0.2 0 0.15 0 0 0 base_link laser"),
    node("base_to_gps", "0 0 0.5 0 0 0 base_link gps", 'if="$(arg use_gps)"'),
    node("laser_again", "0.2 0 0.15 0 0 0 base_link laser"),
    node("cam", "0 0 0 0 0 0 1 base_link $(arg camera)"),
    "</launch>",
])


def graph_of(xml: str) -> TfGraph:
    return build_graph(lint_text(xml, "robot.launch", LintOptions(package_paths=())))


def dot_edges(dot: str) -> list[str]:
    return [line for line in dot.splitlines() if " -> " in line]


def test_frames_and_edges() -> None:
    graph = graph_of(ROBOT)
    assert [f.label for f in graph.frames] == ["base_link", "laser", "gps", "$(arg camera)"]
    assert [(e.parent, e.child) for e in graph.edges][:3] == [
        ("base_link", "laser"), ("base_link", "gps"), ("base_link", "laser")
    ]
    assert [f.resolved for f in graph.frames] == [True, True, True, False]


def test_dot_content() -> None:
    dot = to_dot(graph_of(ROBOT))
    assert dot.startswith("digraph tf {") and dot.rstrip().endswith("}")
    assert 'f0 [label="base_link"]' in dot
    edges = dot_edges(dot)
    assert len(edges) == 4
    first, conditional, duplicate, unresolved = edges
    assert first.startswith("  f0 -> f1 ")
    assert 'label="/base_to_laser\\nxyz 0.2 0 0.15\\nypr 0 0 0\\nrobot.launch:3"' in first
    assert "dashed" not in first and "#c62828" not in first
    assert "style=dashed" in conditional and "if='$(arg use_gps)'" in conditional
    # the second base_link -> laser is a dup_sig error: red, with the rule and a tooltip
    assert 'color="#c62828"' in duplicate and "! dup_sig" in duplicate
    assert "tooltip=" in duplicate and "[dup_sig]" in duplicate
    assert "q 0 0 0 1" in unresolved
    assert re.search(r'f1 \[label="laser", color="#c62828"', dot)
    assert re.search(r'f3 \[label="\$\(arg camera\)", style=dotted\]', dot)


def test_info_diagnostics_do_not_mark() -> None:
    graph = graph_of(ROBOT)
    unresolved = graph.edges[3]
    assert not unresolved.flagged and "[unresolved]" in unresolved.tooltip


def test_diagnostics_not_at_a_transform_become_notes() -> None:
    xml = "\n".join(
        ["<launch>", node("a", "0 0 0 0 0 0 a b"), '  <include file="none.launch"/>', "</launch>"]
    )
    graph = graph_of(xml)
    assert len(graph.notes) == 1 and "roslaunch_error" in graph.notes[0]
    assert "none.launch" in to_dot(graph).splitlines()[1]


def test_untrusted_names_are_escaped() -> None:
    xml = "<launch>\n" + node("n", "0 0 0 0 0 0 a\\&quot;];x b|&lt;i&gt;") + "\n</launch>"
    graph = graph_of(xml)
    assert [f.label for f in graph.frames] == ['a"];x', "b|<i>"]
    dot = to_dot(graph)
    assert 'f0 [label="a\\"];x"];' in dot
    (edge,) = dot_edges(dot)
    assert edge.startswith("  f0 -> f1 [")
    mermaid = to_mermaid(graph)
    assert "b#124;#lt;i#gt;" in mermaid and "<i>" not in mermaid
    if shutil.which("dot"):
        done = subprocess.run(["dot", "-Tsvg"], input=dot.encode(), capture_output=True,
                              check=False)
        assert done.returncode == 0, done.stderr


def test_dot_escapes_backslashes_and_line_breaks() -> None:
    graph = TfGraph(
        "t", (Frame("a", "a\\N", True, False), Frame("b", 'b\n"', True, False)),
        (Edge("a", "b", ("x\\l",), False, False, ""),), (),
    )
    dot = to_dot(graph)
    assert 'f0 [label="a\\\\N"];' in dot
    assert 'f1 [label="b\\n\\""];' in dot
    assert 'f0 -> f1 [label="x\\\\l"' in dot


def test_mermaid_content() -> None:
    mermaid = to_mermaid(graph_of(ROBOT))
    lines = mermaid.splitlines()
    assert lines[0] == "---" and lines[3] == "flowchart LR"  # one rank of four: wider than deep
    assert '  f0(["base_link"])' in lines
    edges = [line for line in lines if "|" in line and "-" in line and "linkStyle" not in line]
    assert edges[0].startswith("  f0 -->|") and edges[0].endswith("| f1")
    assert edges[1].startswith("  f0 -.->|")
    assert "  linkStyle 2 stroke:#c62828,color:#c62828,stroke-width:2px" in lines
    assert "  class f1 flagged" in lines and "  class f3 unresolved" in lines


@pytest.fixture
def launch_file(tmp_path: Path) -> Path:
    path = tmp_path / "robot.launch"
    path.write_text(ROBOT)
    return path


def test_cli_dot_and_mermaid(
    launch_file: Path, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    assert main(["graph", "--beliefs", "none", str(launch_file)]) == 0
    assert capsys.readouterr().out.startswith("digraph tf {")
    out = tmp_path / "tree.mmd"
    assert main(["graph", "--beliefs", "none", str(launch_file), "-o", str(out)]) == 0
    assert "flowchart LR" in out.read_text()
    assert main(["graph", "--beliefs", "none", str(launch_file), "-o", str(tmp_path / "t.dot"),
                 "--arg", "use_gps:=false"]) == 0
    assert "base_to_gps" not in (tmp_path / "t.dot").read_text()


@pytest.mark.skipif(shutil.which("dot") is None, reason="Graphviz is not installed")
def test_cli_svg_and_png(launch_file: Path, tmp_path: Path) -> None:
    svg = tmp_path / "tree.svg"
    assert main(["graph", "--beliefs", "none", str(launch_file), "-o", str(svg)]) == 0
    text = svg.read_text()
    assert "<svg" in text and "base_link" in text and "base_to_laser" in text
    png = tmp_path / "tree.png"
    assert main(["graph", "--beliefs", "none", str(launch_file), "-o", str(png)]) == 0
    assert png.read_bytes().startswith(b"\x89PNG\r\n\x1a\n")


def test_images_without_graphviz_say_what_to_install(
    launch_file: Path, tmp_path: Path, monkeypatch: pytest.MonkeyPatch,
    capsys: pytest.CaptureFixture[str],
) -> None:
    monkeypatch.setattr(commands.shutil, "which", lambda name: None)
    status = main(["graph", "--beliefs", "none", str(launch_file), "-o", str(tmp_path / "t.png")])
    assert status == 2
    assert "apt-get install graphviz" in capsys.readouterr().err
    assert not (tmp_path / "t.png").exists()


@pytest.mark.parametrize("target", ["missing", "t.jpg"])
def test_usage_errors(
    launch_file: Path, tmp_path: Path, capsys: pytest.CaptureFixture[str], target: str
) -> None:
    if target == "missing":
        argv = ["graph", str(tmp_path / "no_such_folder")]
    else:
        argv = ["graph", str(launch_file), "-o", str(tmp_path / target)]
    assert main(argv) == 2
    assert "error" in capsys.readouterr().err


def test_a_workspace_folder_draws_one_cluster_per_distinct_tree(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    from tests.workspace_fixture import build_workspace

    monkeypatch.chdir(build_workspace(tmp_path))
    assert main(["graph", "--beliefs", "none", "."]) == 0
    dot = capsys.readouterr().out
    clusters = [line for line in dot.splitlines() if "subgraph cluster_" in line]
    # part.launch and sensors_launch.xml are included by main.launch and env.xml: no
    # cluster of their own. build/, install/, log/ and the ignored files are left out.
    titles = [line.split('label="', 1)[1].split(":", 1)[0]
              for line in dot.splitlines() if line.strip().startswith("label=")]
    assert titles == [
        "src/ros1_pkg/build/keep.launch",
        "src/ros1_pkg/launch/main.launch",
        "src/ros1_pkg/launch/robot.launch.xml",
        "src/ros2_pkg/launch/bringup_launch.py",
        "src/ros2_pkg/launch/env.xml",
    ]
    assert len(clusters) == 5
    # The unnamed ROS 2 nodes are named by executable and position, not "?".
    assert "static_transform_publisher #1" in dot and 'label="?\\n' not in dot
    assert main(["graph", "--beliefs", "none", ".", "-o", str(tmp_path / "t.mmd")]) == 0
    mermaid = (tmp_path / "t.mmd").read_text()
    assert mermaid.count("  subgraph c") == 5 and mermaid.count("  end") == 5


def test_the_legend_shows_only_what_the_picture_has(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    clean = tmp_path / "clean.launch"
    clean.write_text(
        '<launch><node pkg="tf2_ros" type="static_transform_publisher" name="a" '
        'args="0 0 0 0 0 0 base_link laser"/></launch>'
    )
    assert main(["graph", "--beliefs", "none", str(clean)]) == 0
    dot = capsys.readouterr().out
    assert "red:" not in dot and "dashed:" not in dot and "dotted:" not in dot
    flagged = tmp_path / "flagged.launch"
    # A warning-level finding (rot_degrees: a yaw of 90 read as radians).
    flagged.write_text(clean.read_text().replace("0 0 0 0 0 0 base_link", "0 0 0 90 0 0 base_link"))
    assert main(["graph", "--beliefs", "none", str(flagged)]) == 0
    dot = capsys.readouterr().out
    assert "red: errors or warnings" in dot and "dashed:" not in dot


WS = Path(__file__).resolve().parent / "fixtures" / "robot_ws"


def test_whole_tree_of_a_workspace_folder(capsys: pytest.CaptureFixture[str]) -> None:
    """URDF joints in blue with their joint in the label, movable ones dashed, findings red."""
    launch = WS / "src" / "demo_bringup" / "launch" / "robot.launch"
    assert main(["graph", "--beliefs", "none", "--package-path", str(WS), str(launch)]) == 0
    dot = capsys.readouterr().out
    lines = dot.splitlines()
    wheel = next(line for line in lines if "left_wheel_joint" in line)
    assert "style=dashed" in wheel and "#1565c0" in wheel
    base = next(line for line in lines if "base_joint (fixed)" in line)
    assert "style=dashed" not in base and "#1565c0" in base
    laser = next(line for line in lines if "laser_tf" in line)
    assert "#c62828" in laser and "multiple_parents" in laser
    assert main(["graph", "--beliefs", "none", "--package-path", str(WS),
                 str(WS / "src" / "demo_bringup")]) == 0
    assert "base_joint (fixed)" in capsys.readouterr().out


def _tf(parent: str, child: str, name: str) -> str:
    return (f'  <node pkg="tf2_ros" type="static_transform_publisher" name="{name}" '
            f'args="0 0 1 0 0 0 {parent} {child}"/>')


def _include(name: str) -> str:
    return f'<launch>\n  <include file="$(dirname)/{name}"/>\n</launch>\n'


def _cluster_blocks(dot: str) -> list[str]:
    return dot.split("subgraph cluster_")[1:]


def test_entry_points_with_the_same_tree_are_drawn_once(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.chdir(tmp_path)
    Path("robot_a.launch").write_text(
        "<launch>\n" + _tf("base_link", "laser", "laser_tf") + "\n</launch>\n")
    Path("robot_b.launch").write_text(
        "<launch>\n" + _tf("chassis", "camera", "cam_tf") + "\n</launch>\n")
    for name in ("sim.launch", "real.launch", "demo.launch"):
        Path(name).write_text(_include("robot_a.launch"))
    Path("other.launch").write_text(_include("robot_b.launch"))
    Path("nothing.launch").write_text('<launch>\n  <node pkg="rviz" type="rviz" name="v"/>\n'
                                      "</launch>\n")
    assert main(["graph", "--beliefs", "none"]) == 0  # the current folder by default
    dot = capsys.readouterr().out
    blocks = _cluster_blocks(dot)
    assert len(blocks) == 2
    first, second = blocks
    assert "3 entry points with this tree (1 static transform(s), 0 URDF joint(s)):" in first
    assert "demo.launch\\lreal.launch\\lsim.launch\\l" in first
    assert 'label="other.launch: 1 static transform(s), 0 URDF joint(s)\\l' in second
    # One edge per distinct tree, not one per entry point.
    assert len(dot_edges(dot)) == 2 and dot.count('label="laser"') == 1
    # The entry point that publishes nothing is not drawn; the caption says why.
    assert ("1 entry point(s) publish no transform:\\l  nothing.launch: no "
            "static_transform_publisher and no robot_description") in dot


def test_an_empty_picture_says_which_description_was_not_read(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    path = tmp_path / "robot.launch"
    path.write_text('<launch>\n  <param name="robot_description" command="$(find xacro)/xacro '
                    '$(arg model)"/>\n  <node pkg="robot_state_publisher" '
                    'type="robot_state_publisher" name="rsp"/>\n</launch>\n')
    assert main(["graph", "--beliefs", "none", str(path)]) == 0
    caption = capsys.readouterr().out.splitlines()[1].replace("\\l    ", " ")  # unwrapped
    assert "0 frame(s)" in caption and "robot_description at " in caption
    assert "not read" in caption and "$(arg model)" in caption


def test_a_large_tree_is_capped_with_a_summary(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    from launch_linter.graph import model

    monkeypatch.setattr(model, "MAX_DRAWN_EDGES", 5)
    chain = "\n".join(_tf(f"f{i}", f"f{i + 1}", f"t{i}") for i in range(12))
    path = tmp_path / "chain.launch"
    path.write_text(f"<launch>\n{chain}\n</launch>\n")
    graph = build_graph(lint_text(path.read_text(), str(path)))
    assert graph.left_out == 7 and len(graph.edges) == 5 and len(graph.frames) == 6
    # Breadth-first from the root: the top of the chain.
    assert [f.label for f in graph.frames] == ["f0", "f1", "f2", "f3", "f4", "f5"]
    assert any("too large for a readable picture: 5 of 12 edges" in n for n in graph.notes)
    assert main(["graph", "--beliefs", "none", str(path), "-o", str(tmp_path / "c.dot")]) == 0
    assert "5 edge(s) (of 12: too large for a readable picture" in capsys.readouterr().err


def test_layout_fits_the_shape_of_the_tree() -> None:
    from launch_linter.graph.render import rank_gaps, rankdir

    chain = "\n".join(_tf(f"f{i}", f"f{i + 1}", f"t{i}") for i in range(8))
    deep = graph_of(f"<launch>\n{chain}\n</launch>")
    assert rankdir(deep) == "TB" and "rankdir=TB" in to_dot(deep)
    fan = "\n".join(_tf("base_link", f"part{i}", f"t{i}") for i in range(30))
    wide = graph_of(f"<launch>\n{fan}\n</launch>")
    assert rankdir(wide) == "LR" and "rankdir=LR" in to_dot(wide)
    # Thirty leaves of one frame are dealt onto three ranks (of at most 14).
    gaps = rank_gaps(wide, "LR")
    assert sorted(set(gaps)) == [1, 2, 3] and gaps[:4] == [1, 2, 3, 1]
    assert to_dot(wide).count("minlen=") == 20
    assert "f0 --->|" in to_mermaid(wide)
