"""The flags shared by the commands that lint (``check``, ``transforms``, ``graph``), and
how they combine with the configuration file into :class:`LintOptions`."""

from __future__ import annotations

import argparse
import os
import sys

from launch_linter import __version__
from launch_linter.beliefs_files import BeliefsNotFound
from launch_linter.beliefs_files import load_beliefs as _load
from launch_linter.commands.common import UsageError
from launch_linter.engine import AUTO_JOBS, LintOptions, LintResult, lint_bytes, lint_paths
from launch_linter.model.beliefs import BeliefSet
from launch_linter.results_cache import ResultsCache, results_cache_folder
from launch_linter.rules._profiles import PROFILES
from launch_linter.workspace.config import Config, ConfigError, check_rule_ids, config_for
from launch_linter.workspace.discovery import Exclusions
from launch_linter.workspace.environment import environment_places

TYPE_CHECKING = False  # typing is not imported at run time: start-up (docs/performance.md)
if TYPE_CHECKING:
    from launch_linter.knowledge import KnowledgeBase
    from launch_linter.workspace.discovery import Ignored


def split_ids(values: list[str] | None) -> list[str]:
    ids: list[str] = []
    for value in values or []:
        ids.extend(v.strip() for v in value.split(",") if v.strip())
    return ids


def check_ids(ids: list[str], where: str = "--select/--ignore") -> None:
    """A usage error naming each unknown id, with the closest rule or category."""
    try:
        check_rule_ids(ids, where)
    except ConfigError as exc:
        raise UsageError(str(exc)) from None


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
        "--profile",
        choices=PROFILES,
        default=None,
        help="default, or study: the study's checks and severities (docs/severity.md)",
    )
    parser.add_argument(
        "--ros-distro",
        default=None,
        metavar="NAME",
        help="target ROS distribution, for the rules and fixes that depend on it (default: "
        "the ros-distro key, else $ROS_DISTRO, else what the files show)",
    )
    parser.add_argument(
        "--jobs",
        type=int,
        default=None,
        metavar="N",
        help="lint files in N processes (default: chosen from the file count and free CPUs)",
    )
    add_discovery_options(parser)


def add_discovery_options(parser: argparse.ArgumentParser) -> None:
    """How folders are walked and XML is read: ruff's exclusions, .gitignore, ROS version."""
    parser.add_argument(
        "--exclude",
        action="append",
        metavar="GLOBS",
        help="globs of paths to leave out of folder walks, replacing the defaults "
        "(comma-separated, repeatable)",
    )
    parser.add_argument(
        "--extend-exclude",
        action="append",
        metavar="GLOBS",
        help="globs of paths to leave out in addition to the defaults",
    )
    parser.add_argument(
        "--no-respect-gitignore",
        dest="respect_gitignore",
        action="store_false",
        default=None,
        help="also lint files that .gitignore ignores",
    )
    parser.add_argument(
        "--ros",
        type=int,
        choices=(1, 2),
        default=None,
        help="read XML launch files as this ROS's (default: the package.xml, then content)",
    )
    parser.add_argument(
        "--stdin-filename",
        metavar="NAME",
        help="the file name of the text read from '-' (for paths, packages, config)",
    )


def load_beliefs(spec: str | None, min_z: float) -> BeliefSet:
    try:
        return _load(spec or "bundled", min_z)
    except BeliefsNotFound as exc:
        raise UsageError(str(exc)) from None


STDIN_NAME = "stdin.launch"
NO_CACHE_VARIABLE = "LAUNCH_LINTER_NO_CACHE"
"""An environment variable that turns the results cache off, as ``--no-cache`` does."""


def given_paths(ns: argparse.Namespace) -> list[str]:
    paths = getattr(ns, "paths", None)
    return list(paths) if paths is not None else [ns.path]


def input_paths(ns: argparse.Namespace) -> list[str]:
    """The paths to lint: those given (``-``: the stdin file name), else ``.``."""
    given = given_paths(ns)
    if not given:
        return [os.curdir]
    stdin_name = getattr(ns, "stdin_filename", None) or STDIN_NAME
    return [stdin_name if p == "-" else p for p in given]


def load_config(ns: argparse.Namespace) -> Config:
    """The configuration file for this command's paths (``--config`` or found)."""
    paths = input_paths(ns)
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
    if jobs is None:
        # check and transforms choose from the files and free CPUs (engine.auto_jobs).
        jobs = AUTO_JOBS if ns.command in ("check", "transforms") else 1
    elif jobs < 1:
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
        # A sourced ROS shell says where installed packages are (the order is documented
        # in workspace.environment and docs/workspace.md).
        environment=environment_places(os.environ),
        select=frozenset(select) if select else None,
        ignore=frozenset(ignore),
        severity=dict(config.severity),
        beliefs=beliefs,
        jobs=jobs,
        per_path_ignores=config.per_path_ignores,
        profile=getattr(ns, "profile", None) or config.profile or "default",
        ros=ns.ros if getattr(ns, "ros", None) is not None else config.ros,
        ros_distro=ros_distro(getattr(ns, "ros_distro", None), config.ros_distro),
        knowledge=load_knowledge(config.knowledge),
    )


def load_knowledge(files: tuple[str, ...]) -> KnowledgeBase | None:
    """The bundled knowledge base extended by the configuration's files (the later file
    first); None when there are none."""
    if not files:
        return None
    from launch_linter.knowledge import KnowledgeError, bundled
    from launch_linter.workspace.config import load_knowledge_file

    base = bundled()
    try:
        for path in files:
            base = base.extended(load_knowledge_file(path))
    except KnowledgeError as exc:
        raise UsageError(str(exc)) from None
    return base


def ros_distro(given: str | None, configured: str | None) -> str | None:
    """``--ros-distro``, else the configuration key, else ``ROS_DISTRO`` from the real
    environment (a sourced ROS setup names its distribution there); an unknown name on
    the command line is a usage error, an unknown ``ROS_DISTRO`` is passed over."""
    from launch_linter.model.distro import ROS1_DISTROS, ROS2_DISTROS, is_known, normalise

    name = normalise(given) or normalise(configured)
    if name is not None:
        if not is_known(name):
            known = ", ".join((*ROS1_DISTROS, *ROS2_DISTROS))
            raise UsageError(f"unknown ROS distribution {name!r} (known: {known})")
        return name
    from_env = normalise(os.environ.get("ROS_DISTRO"))
    return from_env if from_env is not None and is_known(from_env) else None


def discovery_for(ns: argparse.Namespace, config: Config) -> tuple[Exclusions, Ignored | None]:
    """Folder-walk exclusions and the ``.gitignore`` predicate, flags over the file."""
    exclude = split_ids(getattr(ns, "exclude", None)) or None
    if exclude is None and config.exclude is not None:
        exclude = list(config.exclude)
    extend = [*config.extend_exclude, *split_ids(getattr(ns, "extend_exclude", None))]
    base = os.path.dirname(os.path.abspath(config.path)) if config.path else os.curdir
    exclusions = Exclusions.of(exclude, extend, base)
    respect = getattr(ns, "respect_gitignore", None)
    if respect is None:
        respect = config.respect_gitignore if config.respect_gitignore is not None else True
    if not respect:
        return exclusions, None
    from launch_linter.workspace.gitignore import gitignore_predicate  # folder walks only

    return exclusions, gitignore_predicate().ignored


def read_stdin() -> bytes:
    """The bytes on stdin, as they are (an XML file's declared encoding is expat's to read)."""
    return sys.stdin.buffer.read() if hasattr(sys.stdin, "buffer") else sys.stdin.read().encode()


def lint_command_paths(
    ns: argparse.Namespace, options: LintOptions, config: Config, keep_trees: bool = True,
    cache: ResultsCache | None = None,
) -> LintResult:
    """Lint the command's paths (none: the current folder; ``-``: the text on stdin);
    ``keep_trees=False`` for a command that needs only the records and diagnostics, which
    may then come from ``cache`` (text read from stdin never does)."""
    given = given_paths(ns)
    if "-" in given:
        if len(given) > 1:
            raise UsageError("'-' (stdin) cannot be combined with other paths")
        name = getattr(ns, "stdin_filename", None) or STDIN_NAME
        return lint_bytes(read_stdin(), name, options)
    missing = [path for path in given if not os.path.lexists(path)]
    if missing:
        raise UsageError(f"{missing[0]}: no such file or folder")
    exclusions, ignored = discovery_for(ns, config)
    result = lint_paths(given or [os.curdir], options, exclusions, ignored, keep_trees, cache)
    if not result.files:
        # ruff's wording: an empty run is a silent success otherwise.
        sys.stderr.write("warning: No files found under the given path(s) (launch files: "
                         "*.launch, *.launch.xml/.py/.yaml, *_launch.py, .test, ...)\n")
    return result


def results_cache(
    ns: argparse.Namespace, options: LintOptions, config: Config
) -> ResultsCache | None:
    """The results cache for this run: None with ``--no-cache`` (or ``NO_CACHE_VARIABLE``
    set to anything but "") or for text on stdin."""
    if getattr(ns, "no_cache", False) or os.environ.get(NO_CACHE_VARIABLE) \
            or "-" in given_paths(ns):
        return None
    folder = results_cache_folder(getattr(ns, "cache_dir", None) or config.cache_dir, config.path)
    return ResultsCache.open(folder, __version__, options, config)
