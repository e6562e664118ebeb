"""Mutation fuzzing of every front-end, seeded from real launch files.

A case is a seed file (ROS 1 XML, ROS 2 XML, YAML or Python) changed by a few byte
mutations (flips, insertions, deletions, duplications, splices with another seed) and
structure mutations (launch-file tokens inserted at random places: substitutions, tags,
comments, entities, a BOM, NUL). Each case is loaded and linted as a file of its format;
the properties are those of the issue: no exception, a status, and output that stays one
line per diagnostic and valid JSON. Used by ``test_fuzz_frontends.py`` (seconds) and by
``scripts/fuzz_frontends.py`` (hours).
"""

from __future__ import annotations

import json
import os
from pathlib import Path

from hypothesis import strategies as st

from launch_linter import engine
from launch_linter.frontends.dispatch import load_tree
from launch_linter.frontends.ros1 import LoadOptions
from launch_linter.model.launch import FileStatus
from launch_linter.report import json_report, text

REPO = Path(__file__).resolve().parents[2]
SUFFIXES = {"xml": ".launch", "ros2": ".launch.xml", "yaml": ".launch.yaml", "py": ".launch.py"}

TOKENS = (
    b"$(arg a)", b"$(eval ", b"$(eval 9**9**9)", b"$(var a)", b"$(find p)", b"$(anon n)",
    b"$(", b")", b"<group>", b"</group>", b"<include file=\"$(dirname)/x.launch\"/>",
    b"<let name=\"a\" value=\"$(var a)$(var a)\"/>", b"<arg name=\"a\" default=\"$(arg a)\"/>",
    b"<!--", b"-->", b"<![CDATA[", b"]]>", b"&#10;", b"&amp;", b"&#xD800;", b"\xef\xbb\xbf",
    b"\x00", b"\x1b[2J", b"\r\n", b"\xff\xfe", b"<?xml version=\"1.0\" encoding=\"utf-7\"?>",
    b"<!DOCTYPE launch [<!ATTLIST node a CDATA \"x\">]>", b"nan", b"inf", b"-0", b"1e999",
    b"static_transform_publisher", b"tf2_ros", b"0 0 0 0 0 0 a b", b"'", b"\"", b"\\",
    b"- node: {pkg: tf2_ros, exec: static_transform_publisher, args: '0 0 0 0 0 0 a b'}\n",
    b"*a", b"&a ", b"!!python/object:os.system", b"{", b"[", b"]", b"}", b"\n  ",
    b"lambda: 0", b"__import__('os')", b"[x]*10**9", b"while True: pass\n", b"**", b"%s",
    b"LaunchConfiguration('a')", b"Node(", b"IncludeLaunchDescription(", b"\t", b"\\udcff",
    b"\xed\xb3\xbf",
)


def seeds() -> list[tuple[str, bytes]]:
    """(format, bytes) of the repository's own launch-file fixtures."""
    found: list[tuple[str, bytes]] = []
    for path in sorted((REPO / "tests").rglob("*")):
        name = path.name
        if not path.is_file() or path.stat().st_size > 64 * 1024:
            continue
        if name.endswith(".launch.py"):
            kind = "py"
        elif name.endswith((".launch.yaml", ".launch.yml")):
            kind = "yaml"
        elif name.endswith(".launch.xml"):
            kind = "ros2"
        elif name.endswith(".launch"):
            kind = "xml"
        else:
            continue
        found.append((kind, path.read_bytes()))
    return found


def corpus_seeds(folder: str, limit: int) -> list[tuple[str, bytes]]:
    """Seeds from a corpus of real files (``../shared/corpus/files``), for deep runs."""
    out: list[tuple[str, bytes]] = []
    for name in sorted(os.listdir(folder))[:limit]:
        kind = "py" if name.endswith(".py") else "ros2" if name.endswith(".xml") else "xml"
        with open(os.path.join(folder, name), "rb") as handle:
            out.append((kind, handle.read(256 * 1024)))
    return out


@st.composite
def mutated(draw: st.DrawFn, pool: list[tuple[str, bytes]]) -> tuple[str, bytes]:
    kind, data = draw(st.sampled_from(pool))
    buffer = bytearray(data)
    for _ in range(draw(st.integers(0, 8))):
        where = draw(st.integers(0, len(buffer)))
        operation = draw(st.integers(0, 6))
        if operation <= 1:
            buffer[where:where] = draw(st.sampled_from(TOKENS))
        elif operation == 2 and buffer:
            index = min(where, len(buffer) - 1)
            buffer[index] ^= 1 << draw(st.integers(0, 7))
        elif operation == 3:
            buffer[where:where + draw(st.integers(1, 64))] = b""
        elif operation == 4:
            span = bytes(buffer[where:where + draw(st.integers(1, 256))])
            buffer[where:where] = span * draw(st.integers(1, 50))
        elif operation == 5:
            buffer[where:where] = draw(st.binary(min_size=1, max_size=16))
        else:
            _, other = draw(st.sampled_from(pool))
            start = draw(st.integers(0, len(other)))
            buffer[where:where] = other[start:start + draw(st.integers(1, 512))]
    return kind, bytes(buffer)


def check_case(folder: Path, kind: str, data: bytes) -> None:
    """Load and lint one mutated file; raise AssertionError when a property fails."""
    path = folder / f"fuzz{SUFFIXES[kind]}"
    path.write_bytes(data)
    options = engine.LintOptions()
    tree = load_tree(str(path), LoadOptions(display_path=str), data)
    assert tree.status in FileStatus
    found = engine.check_tree(tree, engine.selected_rules(options), options)
    for problem in tree.problems:
        assert problem.line >= 1 and problem.column >= 1, problem
    for diagnostic in found:
        line = text.format_diagnostic(diagnostic)
        assert "\n" not in line and "\r" not in line and "\x1b" not in line, line
        assert diagnostic.line >= 1 and diagnostic.column >= 1, diagnostic
    for transform in tree.transforms:
        assert "\n" not in text.format_transform(transform)
    result = engine.LintResult((engine._file_record(engine.InputFile(str(path), str(path)),
                                                    tree),), (tree,), tuple(found))
    document = json_report.dumps(json_report.transforms_document(result))
    json.loads(document)
    document.encode("utf-8")
