"""roslaunch's <test> and <rosparam> checks, with its messages (xmlloader.py, loader.py)."""

from __future__ import annotations

import textwrap
from pathlib import Path

import pytest

from launch_linter.frontends.dispatch import load_tree
from launch_linter.frontends.ros1 import LoadOptions, yaml_root_kind
from launch_linter.workspace.packages import PackageIndex


def errors(tmp_path: Path, body: str) -> list[str]:
    package = tmp_path / "src" / "robot"
    (package / "config").mkdir(parents=True, exist_ok=True)
    (package / "package.xml").write_text("<package><name>robot</name></package>\n")
    (package / "config" / "ok.yaml").write_text("a: 1\n")
    (package / "config" / "bad.yaml").write_text("c:\n  type: x\n  name: h rate: 10\n")
    (package / "config" / "tags.yaml").write_text("a: !degrees 90\nb: $(arg x)\n")
    path = package / "t.launch"
    path.write_text("<launch>\n" + textwrap.dedent(body).strip() + "\n</launch>\n")
    tree = load_tree(str(path), LoadOptions(packages=PackageIndex([str(tmp_path / "src")])))
    return [d.message for d in tree.problems if d.rule == "roslaunch_error"]


TEST = '<test test-name="t" pkg="rostest" type="x" {}/>'


@pytest.mark.parametrize(("attrs", "expected"), [
    ('time-limit="abc"', ["Invalid <node> tag: 'time-limit' must be a number: [abc]"]),
    ('time-limit="-1"', ["Invalid <node> tag: 'time-limit' must be a positive number"]),
    ('time-limit="0.0"', ["Invalid <node> tag: 'time-limit' must be a positive number"]),
    ('retry="2.5"', ["Invalid <node> tag: 'retry' must be a number: [2.5]"]),
    ('retry="x" time-limit="y"', ["Invalid <node> tag: 'time-limit' must be a number: [y]",
                                  "Invalid <node> tag: 'retry' must be a number: [x]"]),
    ('time-limit=" 60 " retry=" 3 "', []),
    ('time-limit="nan" retry=""', []),  # float('nan') <= 0 is false; empty is not checked
])
def test_test_limits(tmp_path: Path, attrs: str, expected: list[str]) -> None:
    assert errors(tmp_path, TEST.format(attrs)) == expected


@pytest.mark.parametrize(("body", "expected"), [
    ('<rosparam file=""/>', ["error loading <rosparam> tag: file does not exist []"]),
    ('<rosparam file="$(find robot)/config/nope.yaml"/>',
     ["error loading <rosparam> tag: file does not exist [{root}/src/robot/config/nope.yaml]"]),
    ('<rosparam file="$(dirname)/nope.yaml"/>',
     ["error loading <rosparam> tag: file does not exist [{root}/src/robot/nope.yaml]"]),
    ('<rosparam file="$(find robot)/config/ok.yaml"/>', []),
    ('<rosparam file="relative/nope.yaml"/>', []),  # depends on roslaunch's working folder
    ('<rosparam command="dump" file="$(find robot)/config/nope.yaml"/>', []),
    ("<rosparam>[1, 2]</rosparam>",
     ["error loading <rosparam> tag: 'param' attribute must be set for non-dictionary values"]),
    ("<rosparam>just text</rosparam>",
     ["error loading <rosparam> tag: 'param' attribute must be set for non-dictionary values"]),
    ('<rosparam param="gains">[1, 2]</rosparam>', []),
    ('<rosparam ns="gains">[1, 2]</rosparam>', []),
    ("<rosparam>a: !degrees 90\nb: deg(45)</rosparam>", []),
    ("<rosparam>   </rosparam>", []),
    ('<rosparam file="$(find robot)/config/ok.yaml">[1, 2]</rosparam>', []),  # text ignored
    # loader.py load_rosparam: yaml.safe_load, a MarkedYAMLError refuses the file.
    ('<rosparam file="$(find robot)/config/bad.yaml" command="load"/>',
     ["error loading <rosparam> tag: file {root}/src/robot/config/bad.yaml contains invalid "
      "YAML: mapping values are not allowed here line 3, column 15"]),
    ('<rosparam file="$(find robot)/config/tags.yaml"/>', []),  # rosparam's tags: syntax only
    ('<rosparam file="$(find robot)/config/bad.yaml" subst_value="true"/>', []),  # other text
    ('<rosparam command="delete" param="c"/>', []),
    ("<rosparam>a: [1, 2</rosparam>",
     ["error loading <rosparam> tag: Error within YAML block: while parsing a flow sequence "
      "line 1, column 4: a: [1, 2 ^ expected ',' or ']', but got '<stream end>'"]),
])
def test_rosparam(tmp_path: Path, body: str, expected: list[str]) -> None:
    # PyYAML's pure-Python parser words the message, as roslaunch's yaml.safe_load does.
    found = errors(tmp_path, body)
    wanted = [e.format(root=tmp_path) for e in expected]
    assert len(found) == len(wanted)
    assert all(f.startswith(w) for f, w in zip(found, wanted)), found


@pytest.mark.parametrize(("body", "kind"), [
    ("a: 1", "mapping"), ("- 1\n- 2", "other"), ("[1, 2]", "other"), ("{a: 1}", "mapping"),
    ("just text", "other"), ('"a: b"', "other"), ('"a": 1', "mapping"), ("a:1", "other"),
    ("# c\n\nfoo:\n  bar: 1", "mapping"), ("url: http://x", "mapping"),
    ("'it''s': 2", "mapping"), ("a #: b", "other"),
    ("!degrees 90", None), ("hello\nworld: 1", None), ("", None), ("---\na: 1", None),
])
def test_yaml_root_kind_without_pyyaml(body: str, kind: str | None) -> None:
    """Standard library only, so that the generated linter agrees on every Python."""
    assert yaml_root_kind(body) == kind


def test_rosparam_invalid_yaml_hostile(tmp_path: Path) -> None:
    """20,000 keys and the syntax error at the end: judged once, bounded by the file's size."""
    import time

    config = tmp_path / "src" / "robot" / "config"
    config.mkdir(parents=True)
    lines = "".join(f"k{i}: {i}\n" for i in range(20_000)) + "x: a b: c\n"
    (config / "big.yaml").write_text(lines)
    started = time.process_time()
    found = errors(tmp_path, '<rosparam file="$(find robot)/config/big.yaml"/>\n' * 3)
    assert time.process_time() - started < 60
    assert len(found) == 3 and all("line 20001" in message for message in found)
