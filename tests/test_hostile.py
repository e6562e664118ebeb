"""Hostile input: every bad file yields a diagnostic, and the run goes on.

Each file below is linted together with a good one: the good one's transform is still
reported, every input is listed once in ``files``, and the command line neither crashes
nor reports a usage error.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
import time
from pathlib import Path
from xml.sax.saxutils import escape

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from launch_linter.engine import LintResult, lint_paths
from launch_linter.frontends.dispatch import load_tree
from launch_linter.frontends.ros1 import LoadOptions

TF2 = 'pkg="tf2_ros" type="static_transform_publisher"'
SECRET = "S3CRET-CONTENT-0f9a"


def node(name: str, args: str = "0 0 0 0 0 0 base_link laser") -> bytes:
    return f'<node {TF2} name="{name}" args="{args}"/>'.encode()


def hostile_files(folder: Path) -> dict[str, tuple[bytes, str]]:
    """File name -> (content, rule expected on it)."""
    secret = folder / "secret.txt"
    secret.write_text(SECRET)
    laughs = b'<!ENTITY lol0 "lol">' + b"".join(
        f'<!ENTITY lol{i} "{("&lol" + str(i - 1) + ";") * 10}">'.encode() for i in range(1, 10)
    )
    deep = 10_000
    return {
        "malformed.launch": (b"<launch><node name='a'></launch>", "parse_error"),
        "non_utf8.launch": (b"<launch>" + node("cafe").replace(b"cafe", b"caf\xe9")
                            + b"</launch>", "parse_error"),
        "binary.launch": (bytes(range(256)) * 16, "parse_error"),
        "deep.launch": (
            b"<launch>" + b"<group>" * deep + node("deep") + b"</group>" * deep + b"</launch>",
            "parse_error",
        ),
        "bomb.launch": (
            b'<?xml version="1.0"?><!DOCTYPE launch [' + laughs + b"]>"
            b"<launch><node name='&lol9;'/></launch>",
            "parse_error",
        ),
        "external_entity.launch": (
            f'<?xml version="1.0"?><!DOCTYPE launch [<!ENTITY x SYSTEM "file://{secret}">]>'
            f"<launch><arg name='a' default='&x;'/></launch>".encode(),
            "parse_error",
        ),
        "eval_import.launch": (
            b"<launch>" + node("n", "$(eval __import__('os').system('touch PWNED'))")
            + b"</launch>",
            "roslaunch_error",
        ),
        "eval_power.launch": (b"<launch>" + node("n", "$(eval 9**9**9)") + b"</launch>",
                              "unresolved"),
        "cycle_a.launch": (
            b"<launch>" + node("in_a", "0 0 0 0 0 0 a b")
            + b'<include file="$(dirname)/cycle_b.launch"/></launch>',
            "roslaunch_error",
        ),
        "cycle_b.launch": (b'<launch><include file="$(dirname)/cycle_a.launch"/></launch>',
                           "roslaunch_error"),
    }


@pytest.fixture(scope="module")
def corpus(tmp_path_factory: pytest.TempPathFactory) -> tuple[Path, dict[str, str]]:
    folder = tmp_path_factory.mktemp("hostile")
    expected = {}
    for name, (content, rule) in hostile_files(folder).items():
        (folder / name).write_bytes(content)
        expected[name] = rule
    with open(folder / "huge.launch", "wb") as handle:
        handle.write(b"<launch><!-- ")
        chunk = b"x" * (1024 * 1024)
        for _ in range(50):
            handle.write(chunk)
        handle.write(b" --></launch>")
    expected["huge.launch"] = "parse_error"
    (folder / "good.launch").write_bytes(b"<launch>" + node("good") + b"</launch>")
    return folder, expected


def lint(folder: Path, names: list[str]) -> LintResult:
    return lint_paths([str(folder / n) for n in names])


def test_the_huge_file_really_is_50_mb(corpus: tuple[Path, dict[str, str]]) -> None:
    folder, _ = corpus
    assert (folder / "huge.launch").stat().st_size > 50 * 1024 * 1024


def test_each_hostile_file_gives_its_diagnostic(corpus: tuple[Path, dict[str, str]]) -> None:
    folder, expected = corpus
    for name, rule in expected.items():
        started = time.monotonic()
        result = lint(folder, [name, "good.launch"])
        assert time.monotonic() - started < 20, name
        path = str(folder / name)
        # (the cycle is reported in the file that closes it)
        rules = {d.rule for d in result.diagnostics if not d.path.endswith("good.launch")}
        assert rule in rules, (name, rules)
        assert [f.path for f in result.files] == [path, str(folder / "good.launch")]
        good = [t for t in result.transforms if t.name == "good"]
        assert len(good) == 1 and good[0].child == "laser", name


def test_all_at_once(corpus: tuple[Path, dict[str, str]]) -> None:
    folder, expected = corpus
    names = [*sorted(expected), "good.launch"]
    result = lint(folder, names)
    assert [f.path for f in result.files] == [str(folder / n) for n in names]
    statuses = {Path(f.path).name: f.status.value for f in result.files}
    assert statuses["good.launch"] == "ok"
    assert statuses["huge.launch"] == statuses["deep.launch"] == "parse_error"
    assert "good" in {t.name for t in result.transforms}


def test_nothing_from_the_file_is_executed_or_read(corpus: tuple[Path, dict[str, str]]) -> None:
    folder, _ = corpus
    result = lint(folder, ["external_entity.launch", "eval_import.launch"])
    text = json.dumps([d.message for d in result.diagnostics])
    assert SECRET not in text
    assert not (folder / "PWNED").exists() and not Path("PWNED").exists()


def test_cycle_is_reported_and_the_tree_is_kept(corpus: tuple[Path, dict[str, str]]) -> None:
    folder, _ = corpus
    result = lint(folder, ["cycle_a.launch"])
    assert [t.name for t in result.transforms] == ["in_a"]
    assert any("include cycle" in d.message for d in result.diagnostics)


@pytest.mark.parametrize("command", ["check", "transforms"])
def test_command_line_survives(corpus: tuple[Path, dict[str, str]], command: str) -> None:
    folder, expected = corpus
    paths = [str(folder / n) for n in [*sorted(expected), "good.launch"]]
    done = subprocess.run(
        [sys.executable, "-m", "launch_linter", command, *paths, "--format", "json"],
        capture_output=True, text=True, timeout=120, check=False,
        env={**os.environ, "PYTHONPATH": str(Path(__file__).resolve().parent.parent / "src")},
    )
    assert "Traceback" not in done.stderr
    assert done.returncode in (0, 1), done.stderr
    document = json.loads(done.stdout)
    assert [f["path"] for f in document["files"]] == paths
    assert SECRET not in done.stdout


# --- random launch files -------------------------------------------------------------------

_COMMON = ("if", "unless")
_TAGS = {
    "node": ("name", "pkg", "type", "args", "ns", "output", "respawn", "required",
             "respawn_delay", "cwd", "clear_params", *_COMMON),
    "test": ("test-name", "name", "pkg", "type", "args", "ns", "time-limit", *_COMMON),
    "group": ("ns", "clear_params", *_COMMON),
    "arg": ("name", "value", "default", "doc", *_COMMON),
    "include": ("file", "ns", "pass_all_args", "clear_params", *_COMMON),
    "param": ("name", "value", "type", "command", "textfile", *_COMMON),
    "rosparam": ("command", "param", "file", "subst_value", *_COMMON),
    "remap": ("from", "to", *_COMMON),
    "env": ("name", "value", *_COMMON),
    "machine": ("name", "address", "default", "ssh-port", "timeout", *_COMMON),
    "launch": ("if", "deprecated"),
    "bogus": ("name",),
}
# Hypothesis favours the first entries: the trickiest come first.
_PIECES = ("~", "$(", ")", "/", "$(arg a)", "$(eval arg('a') * 3)", "$(foo)", "yes", "true",
           "0 0 0 0 0 0 a b", "tf2_ros", "static_transform_publisher", "$(dirname)/t.launch",
           "$(anon n)", "a:=b", "'", "//", "$", "(", "$(arg b)", "$(arg)", "$(find p)",
           "$(find p)/x", "$(env E)", "$(optenv E d f)", "$(dirname)", "$(eval 1+1)",
           "$(eval )", "false", "1", "0", "tf", " ", "100", '"', "&", "<", "\u00e9", "\t", "a")
_VALUES = st.one_of(st.sampled_from(_PIECES),
                    st.lists(st.sampled_from(_PIECES), max_size=3).map("".join))


def _element(draw: st.DrawFn, depth: int) -> str:
    tag = draw(st.sampled_from(sorted(_TAGS)))
    names = draw(st.lists(st.sampled_from(_TAGS[tag]), max_size=6, unique=True))
    attributes = "".join(
        f' {name}="{escape(draw(_VALUES), {chr(34): "&quot;"})}"' for name in names
    )
    count = draw(st.integers(0, 3)) if depth < 4 else 0
    inner = "".join(_element(draw, depth + 1) for _ in range(count))
    return f"<{tag}{attributes}>{inner}</{tag}>"


@st.composite
def launch_files(draw: st.DrawFn) -> str:
    body = "".join(_element(draw, 1) for _ in range(draw(st.integers(0, 5))))
    return f"<launch>{body}</launch>"


@pytest.fixture(scope="module")
def scratch(tmp_path_factory: pytest.TempPathFactory) -> Path:
    return tmp_path_factory.mktemp("random")


@settings(max_examples=300, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(text=launch_files(), args=st.dictionaries(st.sampled_from(["a", "b", "_p", "__ns"]),
                                                 st.sampled_from(["1", "x", "", "/r", "~"])))
def test_random_launch_files_never_crash(scratch: Path, text: str, args: dict[str, str]) -> None:
    # The file is on disk so that "$(dirname)/t.launch" includes it (a cycle).
    path = scratch / "t.launch"
    path.write_text(text, encoding="utf-8")
    tree = load_tree(str(path), LoadOptions(args=args))
    assert tree.root
    for transform in tree.transforms:
        assert transform.line >= 1 and transform.column >= 1
