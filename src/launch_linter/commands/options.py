"""The flags shared by the commands that lint (``check``, ``transforms``, ``graph``), and
how they combine with the configuration file into :class:`LintOptions`."""

from __future__ import annotations

import argparse

from launch_linter.beliefs_files import BeliefsNotFound
from launch_linter.beliefs_files import load_beliefs as _load
from launch_linter.commands.common import UsageError
from launch_linter.config import Config, ConfigError, config_for
from launch_linter.engine import LintOptions
from launch_linter.model.beliefs import BeliefSet
from launch_linter.rules import RULES, RULES_BY_ID


def split_ids(values: list[str] | None) -> list[str]:
    ids: list[str] = []
    for value in values or []:
        ids.extend(v.strip() for v in value.split(",") if v.strip())
    return ids


def check_ids(ids: list[str]) -> None:
    categories = {r.category.value for r in RULES}
    unknown = [i for i in ids if i not in RULES_BY_ID and i not in categories]
    if unknown:
        raise UsageError(f"unknown rule id(s): {', '.join(unknown)} (see 'launch-linter rules')")


def pairs(values: list[str] | None, separator: str, what: str) -> dict[str, str]:
    out: dict[str, str] = {}
    for value in values or []:
        name, sep, rest = value.partition(separator)
        if not sep or not name:
            raise UsageError(f"{what} must look like NAME{separator}VALUE, not {value!r}")
        out[name] = rest
    return out


def add_resolution_options(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("paths", nargs="*", metavar="PATH", help="launch files or folders")
    parser.add_argument(
        "--arg",
        action="append",
        metavar="NAME:=VALUE",
        help="set a launch argument, as on the roslaunch command line",
    )
    parser.add_argument(
        "--package-path",
        action="append",
        metavar="DIR",
        help="folder to search for packages for $(find) (repeatable)",
    )
    parser.add_argument(
        "--env",
        action="append",
        metavar="NAME=VALUE",
        help="environment variable for $(env)/$(optenv) (repeatable)",
    )
    parser.add_argument("--config", metavar="FILE", help="configuration file")
    parser.add_argument(
        "--jobs", type=int, default=None, metavar="N", help="lint files in N processes"
    )


def load_beliefs(spec: str | None, min_z: float) -> BeliefSet:
    try:
        return _load(spec or "bundled", min_z)
    except BeliefsNotFound as exc:
        raise UsageError(str(exc)) from None


def load_config(ns: argparse.Namespace) -> Config:
    """The configuration file for this command's paths (``--config`` or found)."""
    paths = getattr(ns, "paths", None) or [ns.path]
    try:
        return config_for(paths, getattr(ns, "config", None))
    except ConfigError as exc:
        raise UsageError(str(exc)) from None


def lint_options(ns: argparse.Namespace, config: Config | None = None) -> LintOptions:
    """Command-line flags over the configuration file, key by key."""
    config = config if config is not None else load_config(ns)
    select = split_ids(getattr(ns, "select", None))
    ignore = split_ids(getattr(ns, "ignore", None))
    check_ids(select + ignore)
    if not select:
        select = list(config.select or ())
    if not ignore:
        ignore = list(config.ignore or ())
    jobs = getattr(ns, "jobs", None)
    jobs = 1 if jobs is None else jobs
    if jobs < 1:
        raise UsageError("--jobs must be at least 1")
    beliefs = BeliefSet.empty()
    if ns.command in ("check", "graph"):
        min_z = getattr(ns, "min_z", None)
        if min_z is None:
            min_z = config.min_z if config.min_z is not None else 1.0
        beliefs = load_beliefs(getattr(ns, "beliefs", None) or config.beliefs, min_z)
    return LintOptions(
        args={**config.args, **pairs(ns.arg, ":=", "--arg")},
        env={**config.env, **pairs(ns.env, "=", "--env")},
        package_paths=tuple(ns.package_path) if ns.package_path else config.package_path,
        select=frozenset(select) if select else None,
        ignore=frozenset(ignore),
        severity=dict(config.severity),
        beliefs=beliefs,
        jobs=jobs,
        per_path_ignores=config.per_path_ignores,
    )
