#!/usr/bin/env python3
"""Validate ``check --format sarif`` output against the official SARIF 2.1.0 JSON schema.

    python scripts/validate_sarif.py [--schema FILE] [PATH ...]

The schema is read from ``../shared/research/schemas/sarif-schema-2.1.0.json`` relative
to the repository root unless ``--schema`` is given (it is not shipped with the project:
the file carries no licence statement). PATH defaults to ``examples/``. Besides the
linted paths, a generated launch file exercises related locations, every severity and a
suppression. Prints one line per document and exits 1 if any is invalid.
"""

from __future__ import annotations

import argparse
import json
import os
import sys
import tempfile

import jsonschema

from launch_linter import LintOptions, __version__, lint_paths
from launch_linter.model.beliefs import BeliefSet
from launch_linter.report.formats import render

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DEFAULT_SCHEMA = os.path.join(
    ROOT, "..", "shared", "research", "schemas", "sarif-schema-2.1.0.json"
)
NODE = '  <node pkg="{pkg}" type="static_transform_publisher" name="{name}" args="{args}"/>'
EXERCISE = "\n".join([
    "<launch>",
    NODE.format(pkg="tf2_ros", name="a", args="0 0 0 0 0 0 base_link laser"),
    NODE.format(pkg="tf2_ros", name="a", args="0 0 1 0 0 0 base_link laser"),
    NODE.format(pkg="tf", name="c", args="0 0 0 0 0 180 map /odom 100"),
    "  <!-- launch-linter: disable=dup_sig -->",
    NODE.format(pkg="tf2_ros", name="d", args="0 0 0 0 0 0 $(arg parent) x"),
    "</launch>",
])


def validate(validator: jsonschema.protocols.Validator, label: str, paths: list[str]) -> bool:
    result = lint_paths(paths, LintOptions())
    document = json.loads(render("sarif", result, BeliefSet.empty(), __version__))
    errors = sorted(validator.iter_errors(document), key=lambda e: list(e.absolute_path))
    results = len(document["runs"][0]["results"])
    related = sum(len(r.get("relatedLocations", ())) for r in document["runs"][0]["results"])
    status = "valid" if not errors else f"INVALID ({len(errors)} errors)"
    print(f"{label}: {results} results, {related} related locations: {status}")
    for error in errors[:10]:
        print(f"  at {'/'.join(map(str, error.absolute_path))}: {error.message}")
    return not errors


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[1])
    parser.add_argument("--schema", default=DEFAULT_SCHEMA)
    parser.add_argument("paths", nargs="*", default=[os.path.join(ROOT, "examples")])
    ns = parser.parse_args()
    try:
        with open(ns.schema, encoding="utf-8") as handle:
            schema = json.load(handle)
    except OSError as exc:
        print(f"cannot read the SARIF schema: {exc}", file=sys.stderr)
        return 2
    validator = jsonschema.Draft4Validator(
        schema, format_checker=jsonschema.Draft4Validator.FORMAT_CHECKER
    )
    ok = validate(validator, " ".join(ns.paths), ns.paths)
    with tempfile.TemporaryDirectory() as folder:
        path = os.path.join(folder, "exercise.launch")
        with open(path, "w", encoding="utf-8") as handle:
            handle.write(EXERCISE)
        ok = validate(validator, "generated exercise", [path]) and ok
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
