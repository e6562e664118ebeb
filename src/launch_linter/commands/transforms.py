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
from launch_linter.report import json_report, text


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
    else:
        for transform in result.transforms:
            sys.stdout.write(text.format_transform(transform) + "\n")
        for _, joint in result.joints:
            sys.stdout.write(text.format_joint(joint) + "\n")
    return EXIT_OK
