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
from launch_linter.report import json_report, text
from launch_linter.report.published import published


def add_parser(subparsers: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    transforms = subparsers.add_parser(
        "transforms", help="print every static transform and URDF edge found"
    )
    add_resolution_options(transforms)
    transforms.add_argument("--format", choices=("text", "json"), default="text")
    transforms.set_defaults(handler=run)


def run(ns: argparse.Namespace) -> int:
    config = load_config(ns)
    result = lint_command_paths(ns, lint_options(ns, config), config)
    if ns.format == "json":
        json_report.write(json_report.transforms_document(result), sys.stdout)
        return EXIT_OK
    edges = published(result)
    # The entry points are named only when there are several to tell apart.
    several = len({root for item in edges for root in item.entry_points}) > 1
    for item in sorted(edges, key=lambda item: isinstance(item.edge, RobotJoint)):
        roots = item.entry_points if several else ()
        if isinstance(item.edge, RobotJoint):
            sys.stdout.write(text.format_joint(item.edge, roots) + "\n")
        else:
            sys.stdout.write(text.format_transform(item.edge, roots) + "\n")
    return EXIT_OK
