"""Differential test: ROS 2 ``launch`` itself against launch-linter's ROS 2 front-ends.

The real ``launch`` is not on PyPI (the PyPI project of that name is unrelated), and
``launch_ros`` needs ``rclpy``, so this script runs what can run here: ``launch``,
``launch_xml`` and ``launch_yaml`` installed from their sources into a separate virtual
environment, a development tool only (see ``docs/agreement.md`` for the three commands).
Nothing is launched: the texts are only parsed (``Parser.load`` and
``parse_description``), which is where launch refuses a file.

The texts are (1) every XML and YAML launch text written in launch_xml's and
launch_yaml's own tests (string constants read from the test sources with ``ast``, never
run), and (2) probes made here: each launch action with every attribute and nested tag
our table accepts, then with one misspelled, without each required attribute, and with
an unknown nested tag; and ``<executable cmd="...">`` command lines
(fixed tricky ones and seeded random ones) whose argv items are compared item by item.

Agreement: launch refuses a text exactly when our front-end reports an error-level
problem for it (``ros2_schema``, ``parse_error``, ``roslaunch_error``), and every
executable's argv items are the same. Usage::

    python scripts/differential_ros2_launch.py --launch-python VENV/bin/python \\
        [--launch-src DIR] [--seed N] [--random N] [--verbose]
"""

from __future__ import annotations

import argparse
import ast
import json
import os
import random
import subprocess
import sys
import tempfile
import textwrap
from collections import Counter
from collections.abc import Sequence
from typing import Any

from launch_linter.frontends.ros2_schema import ACTIONS, LAUNCH
from launch_linter.frontends.ros2_xml import read_xml
from launch_linter.frontends.ros2_yaml import read_yaml
from launch_linter.resolve.ros2_substitution import (
    Call,
    CommandLineError,
    Text,
    parse,
    split_command_line,
)
from launch_linter.resolve.xml_safe import parse_xml

DEFAULT_SOURCES = "/work/.mirror/ros2+launch/repo"
ERRORS = ("ros2_schema", "parse_error", "roslaunch_error")

WORKER = r'''
import io, json, sys
from launch.frontend import Parser
from launch.actions import ExecuteProcess
from launch.substitutions import LaunchConfiguration, TextSubstitution

def render(item):
    out = []
    for sub in item:
        if isinstance(sub, TextSubstitution):
            out.append(sub.text)
        elif isinstance(sub, LaunchConfiguration):
            out.append("$(var " + "".join(s.text for s in sub.variable_name) + ")")
        else:
            out.append("$(" + type(sub).__name__ + ")")
    return "".join(out)

def executables(entities, found):
    for entity in entities:
        if isinstance(entity, ExecuteProcess):
            found.append([render(item) for item in entity.cmd])
        inner = list(entity.get_sub_entities() or [])
        if not inner and hasattr(type(entity), "actions"):  # TimerAction: after its period
            inner = list(entity.actions or [])
        executables(inner, found)
    return found

for line in sys.stdin:
    probe = json.loads(line)
    try:
        root, parser = Parser.load(io.StringIO(probe["text"]))
        description = parser.parse_description(root)
        row = {"id": probe["id"], "ok": True, "cmds": executables(description.entities, [])}
    except Exception as exc:
        row = {"id": probe["id"], "ok": False, "error": type(exc).__name__ + ": " + str(exc)}
    print(json.dumps(row), flush=True)
'''


def test_texts(sources: str) -> list[tuple[str, str, str]]:
    """(id, format, text) for each launch text in launch_xml's and launch_yaml's tests."""
    names = subprocess.run(["git", "-C", sources, "ls-tree", "-r", "--name-only", "HEAD"],
                           capture_output=True, text=True, check=True).stdout.split()
    found: list[tuple[str, str, str]] = []
    for name in names:
        if not name.startswith(("launch_xml/test/", "launch_yaml/test/")):
            continue
        blob = subprocess.run(["git", "-C", sources, "show", f"HEAD:{name}"],
                              capture_output=True, text=True, check=True).stdout
        if name.endswith(".xml") and "<launch" in blob:
            found.append((name, "xml", blob))
        if not name.endswith(".py"):
            continue
        for number, node in enumerate(ast.walk(ast.parse(blob))):
            if not isinstance(node, ast.Constant) or not isinstance(node.value, str):
                continue
            text = textwrap.dedent(node.value).strip() + "\n"
            if text.startswith("<launch"):
                found.append((f"{name}#{number}", "xml", text))
            elif text.startswith("launch:"):
                found.append((f"{name}#{number}", "yaml", text))
    return found


def _attribute_value(name: str) -> str:
    values = {"scoped": "true", "forwarding": "true", "period": "1.0", "prepend": "false",
              "respawn": "false", "respawn_delay": "1.0", "respawn_max_retries": "1",
              "sigkill_timeout": "1.0", "sigterm_timeout": "1.0", "shell": "false",
              "emulate_tty": "false", "cancel_on_shutdown": "false", "output": "screen",
              "if": "true", "unless": "false", "on_exit": "shutdown", "cmd": "ls -l"}
    return values.get(name, "x")


def schema_probes() -> list[tuple[str, str, str]]:
    """Each launch action (launch_ros needs rclpy) with what our table accepts, then with
    one attribute misspelled, and one unknown nested tag."""
    probes: list[tuple[str, str, str]] = []
    for tag, spec in sorted(ACTIONS.items()):
        if spec.repo != LAUNCH:
            continue
        attributes = sorted(spec.attributes - {"unless"})
        if tag == "executable":
            attributes = [a for a in attributes if a != "shell"]
        written = " ".join(f'{a}="{_attribute_value(a)}"' for a in attributes)
        nested = "".join(
            f'<{name} ' + " ".join(f'{a}="x"' for a in sorted(inner.attributes)) + "/>"
            for name, inner in spec.nested
        )
        probes.append((f"{tag}/accepted", "xml", f"<launch><{tag} {written}>{nested}</{tag}>"
                                                 f"</launch>\n"))
        probes.append((f"{tag}/misspelled", "xml",
                       f'<launch><{tag} {written} namespce="x">{nested}</{tag}></launch>\n'))
        for required in spec.required:
            without = " ".join(f'{a}="{_attribute_value(a)}"' for a in attributes
                               if a != required)
            probes.append((f"{tag}/without-{required}", "xml",
                           f"<launch><{tag} {without}>{nested}</{tag}></launch>\n"))
        if not spec.has_actions:
            probes.append((f"{tag}/unknown-nested", "xml",
                           f"<launch><{tag} {written}><remapp/></{tag}></launch>\n"))
    return probes


CMDLINES = [
    "ls -l", " $(var a) b", "$(var a)  $(var b)", "a$(var a)b c", "'a b' \"c d\"",
    "a\\ b", "x\\\\ $(var a)", "", "   ", "$(var a)", "a 'b", "a\\", "--x 1 --frame-id '' c",
    "a  b\tc", "'$(var a) b'", "a $(var a)' b'",
]


def random_cmdlines(seed: int, count: int) -> list[str]:
    rng = random.Random(seed)
    pieces = ["a", "b", " ", "  ", "'", '"', "\\", "\t", "$(var a)", "$(var b)", "x y", "''"]
    return ["".join(rng.choice(pieces) for _ in range(rng.randint(1, 7))) for _ in range(count)]


def _escape_xml(text: str) -> str:
    return (text.replace("&", "&amp;").replace('"', "&quot;").replace("<", "&lt;")
            .replace("\t", "&#9;"))


def cmd_probes(seed: int, count: int) -> list[tuple[str, str, str]]:
    probes = []
    for number, cmd in enumerate(CMDLINES + random_cmdlines(seed, count)):
        text = (f'<launch><arg name="a" default="1"/><arg name="b" default="2"/>'
                f'<executable cmd="{_escape_xml(cmd)}"/></launch>\n')
        probes.append((f"cmd#{number}:{cmd!r}", "xml", text))
    return probes


def ours(launch_format: str, text: str) -> tuple[bool, list[list[str]], str]:
    """(refused, executables' argv items, first error) as launch-linter reads the text."""
    read = (read_xml if launch_format == "xml" else read_yaml)("/probe.launch", text.encode())
    errors = [p for p in read.problems if p.rule in ERRORS]
    cmds = _executables(launch_format, text) if read.actions is not None else []
    return bool(errors) or read.actions is None, cmds, errors[0].message if errors else ""


def _executables(launch_format: str, text: str) -> list[list[str]]:
    """Our argv items for each ``<executable cmd=...>`` (XML probes only)."""
    if launch_format != "xml":
        return []
    found: list[list[str]] = []
    stack = [parse_xml(text.encode()).root]
    while stack:
        element = stack.pop(0)
        if element.tag == "executable" and "cmd" in element.attrib:
            try:
                items = split_command_line(parse(element.attrib["cmd"]))
            except CommandLineError:
                continue
            found.append(["".join(p.text if isinstance(p, Text) else
                                  p.written if isinstance(p, Call) else "" for p in item)
                          for item in items])
        stack.extend(element.children)
    return found


def run_launch(python: str, probes: list[tuple[str, str, str]], prefix: str
               ) -> dict[str, dict[str, Any]]:
    with tempfile.NamedTemporaryFile("w", suffix=".py", delete=False) as handle:
        handle.write(WORKER)
        worker = handle.name
    try:
        lines = "".join(json.dumps({"id": i, "text": t}) + "\n" for i, _, t in probes)
        env = {"AMENT_PREFIX_PATH": prefix, "PATH": os.environ.get("PATH", "")}
        done = subprocess.run([python, worker], input=lines, capture_output=True, text=True,
                              env=env, check=False, timeout=1800)
    finally:
        os.unlink(worker)
    if done.returncode != 0 and not done.stdout:
        raise SystemExit(f"the launch worker failed: {done.stderr[-800:]}")
    rows = [json.loads(line) for line in done.stdout.splitlines() if line.startswith("{")]
    return {row["id"]: row for row in rows}


def main(argv: Sequence[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--launch-python", required=True,
                        help="a python that imports launch, launch_xml and launch_yaml")
    parser.add_argument("--launch-src", default=DEFAULT_SOURCES,
                        help="a git copy of ros2/launch (its tests give the texts)")
    parser.add_argument("--seed", type=int, default=18)
    parser.add_argument("--random", type=int, default=300)
    parser.add_argument("--verbose", action="store_true")
    ns = parser.parse_args(argv)
    prefix = os.path.dirname(os.path.dirname(os.path.abspath(ns.launch_python)))
    groups = {
        "launch_xml/launch_yaml test texts": test_texts(ns.launch_src),
        "schema probes": schema_probes(),
        "command-line probes": cmd_probes(ns.seed, ns.random),
    }
    everything = [probe for probes in groups.values() for probe in probes]
    rows = run_launch(ns.launch_python, everything, prefix)
    status = 0
    for title, probes in groups.items():
        same = refused = 0
        classes: Counter[str] = Counter()
        examples: dict[str, str] = {}
        for probe_id, launch_format, text in probes:
            row = rows[probe_id]
            our_refusal, our_cmds, our_error = ours(launch_format, text)
            refused += not row["ok"]
            kind = ""
            if our_refusal != (not row["ok"]):
                kind = ("launch refuses, we report no error" if our_refusal is False
                        else "we report an error, launch accepts")
                example = f"{probe_id}: launch {row.get('error', 'ok')[:140]!r}; " \
                          f"ours {our_error[:100]!r}"
            elif row["ok"] and launch_format == "xml" and row["cmds"] != our_cmds:
                kind = "different argv items"
                example = f"{probe_id}: launch {row['cmds']}, ours {our_cmds}"
            if kind:
                classes[kind] += 1
                examples.setdefault(kind, example)
                if ns.verbose:
                    print(f"  {kind}: {example}")
            else:
                same += 1
        print(f"{title}: {same}/{len(probes)} agree (launch refuses {refused})")
        for kind, count in classes.most_common():
            print(f"  {count:5d}  {kind}\n         e.g. {examples[kind]}")
        status |= bool(classes)
    return status


if __name__ == "__main__":
    sys.exit(main())
