"""``launch-linter transforms``: every static transform and URDF edge found, each once
with the entry points that publish it, as text or JSON."""

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
from launch_linter.model.robot import RobotJoint
from launch_linter.report import json_report, node_edges, text
from launch_linter.report.published import nothing_published, published


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
        document = json_report.transforms_document(result, options.ros_distro)
        document.update(node_edges.document_part(result, options.knowledge,
                                                 options.ros_distro))
        json_report.write(document, sys.stdout)
        return EXIT_OK
    edges = published(result, options.ros_distro)
    # The entry points are named only when there are several to tell apart.
    several = len({root for item in edges for root in item.entry_points}) > 1
    for item in sorted(edges, key=lambda item: isinstance(item.edge, RobotJoint)):
        roots = item.entry_points if several else ()
        if isinstance(item.edge, RobotJoint):
            sys.stdout.write(text.format_joint(item.edge, roots) + "\n")
        else:
            sys.stdout.write(text.format_transform(item.edge, roots) + "\n")
    lines = list(node_edges.text_lines(result, options.knowledge, options.ros_distro))
    for line in lines:
        sys.stdout.write(line + "\n")
    if not edges and not lines:
        # Empty output would not say whether anything was read.
        sys.stderr.write(nothing_published(result) + "\n")
    return EXIT_OK
