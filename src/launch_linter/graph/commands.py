"""``launch-linter graph PATH -o FILE.svg|.png|.dot|.mmd``."""

from __future__ import annotations

import argparse
import os
import shutil
import subprocess
import sys

from launch_linter.commands.common import EXIT_OK, UsageError
from launch_linter.commands.options import (
    add_discovery_options,
    lint_command_paths,
    lint_options,
    load_config,
)
from launch_linter.graph.model import build_graph
from launch_linter.graph.render import to_dot, to_mermaid

TEXT_FORMATS = {".dot": "dot", ".gv": "dot", ".mmd": "mermaid"}
IMAGE_FORMATS = {".svg": "svg", ".png": "png"}
DOT_TIMEOUT_S = 120
INSTALL_HINT = (
    "install Graphviz (Debian/Ubuntu: sudo apt-get install graphviz; Fedora: sudo dnf "
    "install graphviz; macOS: brew install graphviz), or write .dot or .mmd instead"
)


def _render_image(dot_text: str, image_format: str, output: str) -> None:
    dot = shutil.which("dot")
    if dot is None:
        raise UsageError(
            f"writing .{image_format} needs Graphviz's 'dot' program, which is not on PATH; "
            + INSTALL_HINT
        )
    try:
        done = subprocess.run(
            [dot, f"-T{image_format}", "-o", output],
            input=dot_text.encode("utf-8"),
            capture_output=True,
            timeout=DOT_TIMEOUT_S,
            check=False,
        )
    except (OSError, subprocess.TimeoutExpired) as exc:
        raise UsageError(f"running {dot} failed: {exc}") from None
    if done.returncode != 0:
        message = done.stderr.decode("utf-8", "replace").strip()
        raise UsageError(f"{dot} failed (status {done.returncode}): {message}")


def add_parser(subparsers: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    graph = subparsers.add_parser(
        "graph", help="draw the static transform trees of a launch file or a folder"
    )
    graph.add_argument(
        "path", nargs="?", default=os.curdir,
        help="a launch file or a folder (default: the current folder)",
    )
    add_discovery_options(graph)
    graph.add_argument("-o", "--output", metavar="FILE.svg|.png|.dot|.mmd")
    graph.add_argument("--arg", action="append", metavar="NAME:=VALUE")
    graph.add_argument("--package-path", action="append", metavar="DIR")
    graph.add_argument("--env", action="append", metavar="NAME=VALUE")
    graph.add_argument("--config", metavar="FILE", help="configuration file")
    graph.add_argument(
        "--beliefs",
        default=None,
        metavar="bundled|study|none|FILE",
        help="mined beliefs for the may_implied rules (default: bundled)",
    )
    graph.set_defaults(handler=run)


def run(ns: argparse.Namespace) -> int:
    if not os.path.exists(ns.path):
        raise UsageError(f"graph needs a launch file or a folder; {ns.path!r} does not exist")
    output: str | None = ns.output
    extension = os.path.splitext(output)[1].lower() if output else ".dot"
    if extension not in TEXT_FORMATS and extension not in IMAGE_FORMATS:
        known = ", ".join(sorted({*TEXT_FORMATS, *IMAGE_FORMATS}))
        raise UsageError(f"cannot tell the format of {output!r}: use one of {known}")
    config = load_config(ns)
    options = lint_options(ns, config)
    result = lint_command_paths(ns, options, config)
    graph = build_graph(result, options.knowledge)
    if output is None:
        sys.stdout.write(to_dot(graph))
        return EXIT_OK
    if extension in IMAGE_FORMATS:
        _render_image(to_dot(graph), IMAGE_FORMATS[extension], output)
    else:
        text = to_mermaid(graph) if TEXT_FORMATS[extension] == "mermaid" else to_dot(graph)
        try:
            with open(output, "w", encoding="utf-8") as handle:
                handle.write(text)
        except OSError as exc:
            raise UsageError(f"cannot write {output}: {exc.strerror or exc}") from None
    capped = (f" (of {len(graph.edges) + graph.left_out}: too large for a readable picture; "
              "`launch-linter transforms` lists them all)" if graph.left_out else "")
    sys.stderr.write(
        f"wrote {output}: {len(graph.edges)} edge(s){capped}, {len(graph.frames)} frame(s)\n"
    )
    return EXIT_OK
