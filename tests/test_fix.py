"""Fixes: each edits only its words, every other byte is kept; --fix, --diff, stdin."""

from __future__ import annotations

import io
import json
from pathlib import Path

import pytest

from launch_linter.cli import main
from launch_linter.engine import LintOptions, lint_paths, lint_text
from launch_linter.fix import Source, apply_edits
from launch_linter.model.diagnostic import Applicability
from launch_linter.rules._fixes import distro_at_least

NODE = '<node pkg="{pkg}" type="static_transform_publisher" name="{name}"\n      args="{args}"/>'


def launch(*nodes: str) -> str:
    # Odd spacing, a comment and tabs: none of it may change.
    body = "\n  <!-- keep me -->\n\t".join(nodes)
    return f'<?xml version="1.0"?>\n<launch>\n\t{body}\n</launch>\n'


def fixed(text: str, rule: str, path: str = "robot.launch", **options: object) -> str:
    result = lint_text(text, path, LintOptions(**options))  # type: ignore[arg-type]
    fixes = [d.fix for d in result.diagnostics if d.rule == rule and d.fix is not None]
    assert fixes, f"no {rule} fix"
    out, applied = apply_edits(text.encode(), fixes)
    assert len(applied) == len(fixes)
    return out.decode()


def test_period_given_to_ros1_tf2_ros_is_dropped() -> None:
    text = launch(NODE.format(pkg="tf2_ros", name="a", args="0 0 0.2  0 0 0 base_link laser 100"))
    after = fixed(text, "bad_arity")
    assert after == text.replace("base_link laser 100", "base_link laser")
    assert lint_text(after, "robot.launch").diagnostics == ()


def test_no_period_fix_for_tf() -> None:
    text = launch(NODE.format(pkg="tf", name="a", args="0 0 0 0 0 0 base_link laser"))
    result = lint_text(text, "robot.launch")
    assert [d.fix for d in result.diagnostics if d.rule == "bad_arity"] == [None]


def test_one_leading_slash_is_stripped() -> None:
    text = launch(NODE.format(pkg="tf", name="a", args="0 0 0 0 0 0 //base_link /laser 100"))
    after = fixed(text, "leading_slash")
    assert after == text.replace("//base_link /laser", "/base_link laser")


def test_degrees_become_radians_unsafe() -> None:
    text = launch(NODE.format(pkg="tf", name="a", args="0 0 0 90 0 -180 base_link laser 100"))
    result = lint_text(text, "robot.launch")
    (diagnostic,) = [d for d in result.diagnostics if d.rule == "rot_degrees"]
    assert diagnostic.fix is not None
    assert diagnostic.fix.applicability is Applicability.UNSAFE
    after = fixed(text, "rot_degrees")
    assert after == text.replace("90 0 -180", "1.57079633 0 -3.14159265")


def test_quaternion_is_normalised_unsafe() -> None:
    text = launch(NODE.format(pkg="tf2_ros", name="a", args="0 0 0 0 0 0.7 0.7 base_link laser"))
    after = fixed(text, "bad_quaternion")
    assert "0 0 0 0 0 0.707106781 0.707106781 base_link laser" in after


def test_zero_quaternion_has_no_fix() -> None:
    text = launch(NODE.format(pkg="tf2_ros", name="a", args="0 0 0 0 0 0 0 base_link laser"))
    result = lint_text(text, "robot.launch")
    assert [d.fix for d in result.diagnostics if d.rule == "bad_quaternion"] == [None]


ROS2 = '<launch>\n  <node pkg="tf2_ros" exec="static_transform_publisher" args="{}"/>\n</launch>\n'


def test_ros2_positional_to_flags_safe_only_for_humble_and_newer() -> None:
    text = ROS2.format("1 0 0 0 0 0 map odom")
    # Foxy knows only the positional form: nothing is reported there (docs/severity.md).
    foxy = lint_text(text, "a.launch.xml", LintOptions(ros_distro="foxy")).diagnostics
    assert [d for d in foxy if d.rule == "ros2_positional_args"] == []
    for distro, expected in ((None, "unsafe"), ("humble", "safe"),
                             ("rolling", "safe"), ("noetic", "unsafe")):
        result = lint_text(text, "a.launch.xml", LintOptions(ros_distro=distro))
        (fix,) = [d.fix for d in result.diagnostics if d.rule == "ros2_positional_args"]
        assert fix is not None and fix.applicability.value == expected, distro
    after = fixed(text, "ros2_positional_args", "a.launch.xml")
    assert after == ROS2.format(
        "--x 1 --y 0 --z 0 --yaw 0 --pitch 0 --roll 0 --frame-id map --child-frame-id odom"
    )
    assert distro_at_least("jazzy", "humble") and not distro_at_least("galactic", "humble")


def test_substitutions_and_entities_are_never_fixed() -> None:
    for args in ("0 0 0 0 0 0 $(arg p) /laser 100", "0 0 0 0 0 0 /a&#32;b /laser 100"):
        text = launch(NODE.format(pkg="tf", name="a", args=args))
        result = lint_text(text, "robot.launch")
        assert all(d.fix is None for d in result.diagnostics if d.rule == "leading_slash")


PYTHON = """from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package="tf2_ros", executable="static_transform_publisher",
             arguments=["0", "0", "0",  "0", "0", "0", "/base_link", "laser"]),  # keep
    ])
"""


def test_python_arguments_are_fixed_item_by_item() -> None:
    after = fixed(PYTHON, "leading_slash", "robot.launch.py")
    assert after == PYTHON.replace('"/base_link"', '"base_link"')
    flags = fixed(PYTHON, "ros2_positional_args", "robot.launch.py")
    assert '["--x", "0", "--y", "0"' in flags and flags.endswith("]),  # keep\n    ])\n")


def test_json_carries_the_fix(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    path = tmp_path / "a.launch"
    path.write_text(launch(NODE.format(pkg="tf", name="a", args="0 0 0 0 0 0 a /b 100")))
    main(["check", str(path), "--format", "json", "--exit-zero"])
    (diagnostic,) = json.loads(capsys.readouterr().out)["diagnostics"]
    fix = diagnostic["fix"]
    assert fix["applicability"] == "safe"
    (edit,) = fix["edits"]
    assert path.read_bytes()[edit["start"] : edit["end"]] == b"/b" and edit["content"] == "b"


def test_fix_writes_relints_and_prints_what_remains(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.chdir(tmp_path)
    text = launch(
        NODE.format(pkg="tf2_ros", name="a", args="0 0 0 0 0 90 /base_link /laser 100"),
        NODE.format(pkg="tf", name="b", args="0 0 0 0 0 0 base_link base_link 100"),
    )
    Path("a.launch").write_text(text)
    assert main(["check", "a.launch", "--diff"]) == 1
    diff = capsys.readouterr().out
    assert diff.startswith("--- a/a.launch\n+++ b/a.launch\n") and "1.5707" not in diff
    assert Path("a.launch").read_text() == text  # --diff writes nothing
    status = main(["check", "a.launch", "--fix", "--select", "bad_arity,leading_slash,rot_degrees,"
                   "self_transform"])
    out, err = capsys.readouterr()
    assert "fixed 3 finding(s) (bad_arity 1, leading_slash 2)" in err
    assert Path("a.launch").read_text() == text.replace(
        "/base_link /laser 100", "base_link laser"
    )
    assert "[rot_degrees]" in out and "[self_transform]" in out and "[leading_slash]" not in out
    assert status == 1
    main(["check", "a.launch", "--fix", "--unsafe-fixes", "--select", "rot_degrees"])
    assert "0 0 0 0 0 1.57079633 base_link laser" in Path("a.launch").read_text()


def test_stdin_is_read_with_its_file_name(
    capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    text = launch(NODE.format(pkg="tf", name="a", args="0 0 0 0 0 0 a /b 100"))
    monkeypatch.setattr("sys.stdin", io.StringIO(text))
    assert main(["check", "-", "--stdin-filename", "pkg/robot.launch", "--fail-on", "info"]) == 1
    assert capsys.readouterr().out.startswith("pkg/robot.launch:3:2: info:")
    monkeypatch.setattr("sys.stdin", io.StringIO(text))
    assert main(["check", "-", "--fix"]) == 0
    assert capsys.readouterr().out == text.replace("a /b 100", "a b 100")


def test_statistics_exit_zero_quiet_output_file(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    path = tmp_path / "a.launch"
    path.write_text(launch(NODE.format(pkg="tf", name="a", args="0 0 0 0 0 0 /a /b 100")))
    assert main(["check", str(path), "--statistics", "--exit-zero"]) == 0
    out, err = capsys.readouterr()
    assert out.split() == ["2", "leading_slash", "info", "[2", "fixable]"]
    report = tmp_path / "report.txt"
    assert main(["check", str(path), "-q", "--output-file", str(report), "--fail-on", "info"]) == 1
    out, err = capsys.readouterr()
    assert out == "" and err == ""
    assert report.read_text().count("[leading_slash]") == 2


@pytest.mark.parametrize(
    ("argv", "hint"),
    [
        (["check", ".", "--select", "leading_slah"], "did you mean 'leading_slash'"),
        (["check", ".", "--ignore", "rot_degree"], "did you mean 'rot_degrees'"),
        (["explain", "dup_sgi"], "did you mean 'dup_sig'"),
    ],
)
def test_did_you_mean(argv: list[str], hint: str, capsys: pytest.CaptureFixture[str]) -> None:
    assert main(argv) == 2
    assert hint in capsys.readouterr().err


def test_rules_table_and_explain_say_the_fix_kind(capsys: pytest.CaptureFixture[str]) -> None:
    main(["rules"])
    rows = {line.split()[0]: line for line in capsys.readouterr().out.splitlines()}
    assert "[fix: safe;" in rows["leading_slash"] and "[fix: unsafe;" in rows["rot_degrees"]
    assert "fix:" not in rows["dup_sig"]
    main(["explain", "bad_arity"])
    assert capsys.readouterr().out.startswith("bad_arity (tf, error, safe fix)")


def test_unsafe_fixes_alone_is_a_usage_error() -> None:
    assert main(["check", ".", "--unsafe-fixes"]) == 2


def test_lint_paths_fix_edits_point_into_the_file(tmp_path: Path) -> None:
    path = tmp_path / "a.launch"
    path.write_text(launch(NODE.format(pkg="tf", name="a", args="0 0 0 0 0 0 a /b 100")))
    (diagnostic,) = lint_paths([str(path)]).diagnostics
    assert diagnostic.fix is not None
    (edit,) = diagnostic.fix.edits
    assert path.read_bytes()[edit.start : edit.end] == b"/b"


def test_sarif_carries_the_fix(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    path = tmp_path / "a.launch"
    path.write_text(launch(NODE.format(pkg="tf", name="a", args="0 0 0 0 0 0 a /b 100")))
    main(["check", str(path), "--format", "sarif", "--exit-zero"])
    (result,) = json.loads(capsys.readouterr().out)["runs"][0]["results"]
    ((change,),) = [fix["artifactChanges"] for fix in result["fixes"]]
    (replacement,) = change["replacements"]
    region = replacement["deletedRegion"]
    start, length = region["byteOffset"], region["byteLength"]
    assert path.read_bytes()[start : start + length] == b"/b"
    assert replacement["insertedContent"]["text"] == "b"
    assert result["properties"]["fixApplicability"] == "safe"


PYTHON_TWO_NODES = """from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package="tf2_ros", executable="static_transform_publisher", name="a",
             arguments=["0", "0", "0", "0", "0", "0", "/odom", "base"]),
        Node(package="tf2_ros", executable="static_transform_publisher",
             arguments=["0", "0", "0", "0", "0", "0", "/base_link", "laser"]),
    ])
"""


def test_every_python_fix_of_a_file_is_located() -> None:
    # One parse serves both: each search keeps to the lines of its own call.
    after = fixed(PYTHON_TWO_NODES, "leading_slash", "robot.launch.py")
    assert after == PYTHON_TWO_NODES.replace('"/odom"', '"odom"').replace(
        '"/base_link"', '"base_link"')


def test_source_finds_the_call_under_a_decorator() -> None:
    # A decorator lies above the first line of the function it decorates: searching by
    # lines must not skip it.
    text = b'@wrap(Node(arguments=["a", "b"]))\ndef f():\n    pass\n'
    spans = Source("x.launch.py", text).word_spans(1, 1)
    assert spans is not None and [text[a:b] for a, b in spans] == [b'"a"', b'"b"']
    assert Source("x.launch.py", text).word_spans(2, 1) is None
    assert Source("x.launch.py", b"def (:\n").word_spans(1, 1) is None


def test_locating_fixes_keeps_only_the_last_files_sources(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    # Keeping every file's bytes, line starts and syntax tree until the end of a run made
    # memory grow with the number of files.
    import weakref

    from launch_linter import fix

    alive: weakref.WeakSet[Source] = weakref.WeakSet()
    most = [0]

    class CountedSource(Source):
        def __init__(self, path: str, data: bytes) -> None:
            super().__init__(path, data)
            alive.add(self)
            most[0] = max(most[0], len(alive))

    monkeypatch.setattr(fix, "Source", CountedSource)
    paths = []
    for index in range(3 * fix.RECENT_SOURCES):
        path = tmp_path / f"f{index}.launch"
        path.write_text(launch(NODE.format(pkg="tf", name=f"n{index}", args="0 0 0 0 0 0 a /b 1")))
        paths.append(str(path))
    diagnostics = lint_paths(paths).diagnostics
    assert sum(d.fix is not None for d in diagnostics) == len(paths)  # every one located
    assert most[0] <= fix.RECENT_SOURCES + 1


MULTILINE_PYTHON = """from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([Node(
        package='tf2_ros', executable='static_transform_publisher',
        arguments=[
            '0', '0', '0.2',
            '0', '0', '0',
            'base_link', 'laser',
        ])])
"""


def test_a_multiline_python_list_gets_one_flag_pair_per_line() -> None:
    after = fixed(MULTILINE_PYTHON, "ros2_positional_args", "robot.launch.py")
    assert after == MULTILINE_PYTHON.replace(
        "'0', '0', '0.2',\n            '0', '0', '0',\n            'base_link', 'laser',",
        "'--x', '0',\n            '--y', '0',\n            '--z', '0.2',\n            '--yaw', '0',"
        "\n            '--pitch', '0',\n            '--roll', '0',\n"
        "            '--frame-id', 'base_link',\n            '--child-frame-id', 'laser',",
    )


def test_an_aligned_python_list_keeps_its_alignment_and_crlf() -> None:
    text = ("from launch import LaunchDescription\r\nfrom launch_ros.actions import Node\r\n"
            "def generate_launch_description():\r\n"
            "    return LaunchDescription([Node(arguments=['1', '0', '0', '0', '0', '0',\r\n"
            "                                             'map', 'odom'],\r\n"
            "        executable='static_transform_publisher', package='tf2_ros')])\r\n")
    after = fixed(text, "ros2_positional_args", "robot.launch.py")
    indent = " " * 45
    assert f"Node(arguments=['--x', '1',\r\n{indent}'--y', '0',\r\n" in after
    assert after.endswith(f"{indent}'--child-frame-id', 'odom'],\r\n"
                          "        executable='static_transform_publisher', package='tf2_ros')])"
                          "\r\n")


def test_a_multiline_xml_args_gets_one_flag_pair_per_line() -> None:
    text = ROS2.format("1 0 0\n          0 0 0\n          map odom")
    after = fixed(text, "ros2_positional_args", "a.launch.xml")
    assert after == ROS2.format(
        "--x 1\n          --y 0\n          --z 0\n          --yaw 0\n          --pitch 0\n"
        "          --roll 0\n          --frame-id map\n          --child-frame-id odom")
