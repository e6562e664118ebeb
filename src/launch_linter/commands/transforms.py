"""``launch-linter transforms``: every static transform found, as text or JSON."""

from __future__ import annotations

import argparse
import sys

from launch_linter.commands.common import EXIT_OK
from launch_linter.commands.options import (
    add_resolution_options,
    lint_command_paths,
    lint_options,
    load_config,
)
from launch_linter.report import json_report, node_edges, text


def add_parser(subparsers: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    transforms = subparsers.add_parser(
        "transforms", help="print every static transform, URDF edge and node-published edge found"
    )
    add_resolution_options(transforms)
    transforms.add_argument("--format", choices=("text", "json"), default="text")
    transforms.set_defaults(handler=run)


def run(ns: argparse.Namespace) -> int:
    config = load_config(ns)
    options = lint_options(ns, config)
    result = lint_command_paths(ns, options, config)
    if ns.format == "json":
        document = json_report.transforms_document(result)
        document.update(node_edges.document_part(result, options.knowledge))
        json_report.write(document, sys.stdout)
    else:
        for transform in result.transforms:
            sys.stdout.write(text.format_transform(transform) + "\n")
        for _, joint in result.joints:
            sys.stdout.write(text.format_joint(joint) + "\n")
        for line in node_edges.text_lines(result, options.knowledge):
            sys.stdout.write(line + "\n")
    return EXIT_OK
