"""Configuration files: ``[tool.launch-linter]`` in ``pyproject.toml`` or ``.launch-linter.toml``.

The file is ``--config FILE`` when given; otherwise the first of ``.launch-linter.toml`` or
a ``pyproject.toml`` with a ``[tool.launch-linter]`` table found by walking up from each
linted path (all paths must lead to the same file). Relative paths in the file (beliefs
file, package paths, per-path-ignores globs) are relative to the file's folder.
Command-line flags override the file key by key; for the tables ``args``, ``env`` and
``severity`` the command line overrides name by name.
"""

from __future__ import annotations

import importlib
import math
import os
from collections.abc import Iterable, Mapping, Sequence

from launch_linter.model.diagnostic import Severity
from launch_linter.model.paths import shown_path
from launch_linter.model.record import Record, _set
from launch_linter.resolve.xml_safe import read_file_within
from launch_linter.rules._catalog import CATALOG, CATEGORY_NAMES, CATEGORY_OF
from launch_linter.suppressions import PathIgnore

TYPE_CHECKING = False  # typing is not imported at run time: start-up (docs/performance.md)
if TYPE_CHECKING:
    from typing import Any

    from launch_linter.knowledge import KnowledgeBase

CONFIG_NAME = ".launch-linter.toml"
PYPROJECT = "pyproject.toml"
TABLE = "launch-linter"
KEYS = (
    "select",
    "ignore",
    "severity",
    "min-z",
    "beliefs",
    "args",
    "package-path",
    "env",
    "per-path-ignores",
    "fail-on",
    "profile",
    "exclude",
    "extend-exclude",
    "respect-gitignore",
    "ros",
    "ros-distro",
    "cache-dir",
    "knowledge",
)
BELIEF_KEYWORDS = ("bundled", "study", "none")
MAX_CONFIG_BYTES = 1024 * 1024


class ConfigError(ValueError):
    """The configuration file cannot be used; the message names the file and the key."""


class Config(Record):
    """What a configuration file sets; None (or empty) where it sets nothing."""

    path: str | None
    select: tuple[str, ...] | None
    ignore: tuple[str, ...] | None
    severity: dict[str, Severity]
    min_z: float | None
    beliefs: str | None
    args: dict[str, str]
    package_path: tuple[str, ...] | None
    env: dict[str, str]
    per_path_ignores: tuple[PathIgnore, ...]
    fail_on: str | None
    profile: str | None
    """``default`` or ``study`` (docs/severity.md)."""
    exclude: tuple[str, ...] | None
    extend_exclude: tuple[str, ...]
    respect_gitignore: bool | None
    ros: int | None
    ros_distro: str | None
    cache_dir: str | None
    """The results cache's folder (absolute; relative in the file to its folder)."""
    knowledge: tuple[str, ...]
    """Knowledge files (JSON, docs/knowledge.md) that extend the bundled knowledge base."""

    __slots__ = (
        "path", "select", "ignore", "severity", "min_z", "beliefs", "args", "package_path", "env",
        "per_path_ignores", "fail_on", "profile", "exclude", "extend_exclude", "respect_gitignore",
        "ros", "ros_distro", "cache_dir", "knowledge",
    )

    def __init__(
        self,
        path: str | None = None,
        select: tuple[str, ...] | None = None,
        ignore: tuple[str, ...] | None = None,
        severity: dict[str, Severity] | None = None,
        min_z: float | None = None,
        beliefs: str | None = None,
        args: dict[str, str] | None = None,
        package_path: tuple[str, ...] | None = None,
        env: dict[str, str] | None = None,
        per_path_ignores: tuple[PathIgnore, ...] = (),
        fail_on: str | None = None,
        profile: str | None = None,
        exclude: tuple[str, ...] | None = None,
        extend_exclude: tuple[str, ...] = (),
        respect_gitignore: bool | None = None,
        ros: int | None = None,
        ros_distro: str | None = None,
        cache_dir: str | None = None,
        knowledge: tuple[str, ...] = (),
    ) -> None:
        _set(self, "path", path)
        _set(self, "select", select)
        _set(self, "ignore", ignore)
        _set(self, "severity", {} if severity is None else severity)
        _set(self, "min_z", min_z)
        _set(self, "beliefs", beliefs)
        _set(self, "args", {} if args is None else args)
        _set(self, "package_path", package_path)
        _set(self, "env", {} if env is None else env)
        _set(self, "per_path_ignores", per_path_ignores)
        _set(self, "fail_on", fail_on)
        _set(self, "profile", profile)
        _set(self, "exclude", exclude)
        _set(self, "extend_exclude", extend_exclude)
        _set(self, "respect_gitignore", respect_gitignore)
        _set(self, "ros", ros)
        _set(self, "ros_distro", ros_distro)
        _set(self, "cache_dir", cache_dir)
        _set(self, "knowledge", knowledge)


def check_rule_ids(ids: Iterable[str], where: str) -> None:
    """Raise :class:`ConfigError` naming every id that is neither a rule nor a category."""
    unknown = [i for i in ids if i not in CATEGORY_OF and i not in CATEGORY_NAMES]
    if unknown:
        import difflib  # only for the message of a mistake: not at start-up

        known = sorted({*CATEGORY_OF, *CATEGORY_NAMES})
        hints = []
        for name in unknown:
            close = difflib.get_close_matches(name, known, n=1)
            hints.append(f"{name!r}" + (f" (did you mean {close[0]!r}?)" if close else ""))
        raise ConfigError(
            f"{where}: unknown rule id(s) {', '.join(hints)} (see 'launch-linter rules')"
        )


def _scalar_text(value: Any, where: str) -> str:
    # TOML gives booleans and numbers their own types; launch arguments are text, and
    # roslaunch writes booleans in lower case.
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, (str, int, float)):
        return str(value)
    raise ConfigError(f"{where} must be a string, number or boolean, not {type(value).__name__}")


def _string_list(value: Any, where: str) -> tuple[str, ...]:
    if isinstance(value, str):
        value = [value]
    if not isinstance(value, list) or not all(isinstance(v, str) for v in value):
        raise ConfigError(f"{where} must be a list of strings")
    return tuple(value)


def _table(value: Any, where: str) -> dict[str, Any]:
    if not isinstance(value, dict):
        raise ConfigError(f"{where} must be a table (name = value)")
    return value


def _relative_to(base: str, path: str) -> str:
    return os.path.normpath(os.path.join(base, os.path.expanduser(path)))


def parse_config(data: Mapping[str, Any], path: str) -> Config:
    """Check and convert the launch-linter table ``data`` read from ``path``."""
    shown = shown_path(path)  # as messages quote paths
    unknown = [k for k in data if k not in KEYS]
    if unknown:
        import difflib  # only for the message of a mistake: not at start-up

        hints = []
        for key in unknown:
            close = difflib.get_close_matches(key, KEYS, n=1)
            hints.append(f"{key!r}" + (f" (did you mean {close[0]!r}?)" if close else ""))
        raise ConfigError(
            f"{shown}: unknown key(s) {', '.join(hints)}; known keys: {', '.join(KEYS)}"
        )
    base = os.path.dirname(os.path.abspath(path))
    values: dict[str, Any] = {"path": path}
    for key in ("select", "ignore"):
        if key in data:
            ids = _string_list(data[key], f"{shown}: '{key}'")
            check_rule_ids(ids, f"{shown}: '{key}'")
            values[key] = ids
    if "severity" in data:
        values["severity"] = _severities(_table(data["severity"], f"{shown}: 'severity'"), shown)
    if "min-z" in data:
        z = data["min-z"]
        if isinstance(z, bool) or not isinstance(z, (int, float)) or not math.isfinite(z) \
                or abs(z) > 1e6:
            raise ConfigError(f"{shown}: 'min-z' must be a number, finite, not {z!r}")
        values["min_z"] = float(z)
    if "beliefs" in data:
        beliefs = data["beliefs"]
        if not isinstance(beliefs, str) or not beliefs:
            raise ConfigError(f"{shown}: 'beliefs' must be bundled, study, none or a file name")
        values["beliefs"] = beliefs if beliefs in BELIEF_KEYWORDS else _relative_to(base, beliefs)
    for key in ("args", "env"):
        if key in data:
            table = _table(data[key], f"{shown}: '{key}'")
            values[key] = {
                str(name): _scalar_text(v, f"{shown}: '{key}.{name}'") for name, v in table.items()
            }
    if "knowledge" in data:
        files = data["knowledge"]
        names = (files,) if isinstance(files, str) else _string_list(files, f"{shown}: 'knowledge'")
        values["knowledge"] = tuple(_relative_to(base, name) for name in names)
    if "package-path" in data:
        roots = _string_list(data["package-path"], f"{shown}: 'package-path'")
        values["package_path"] = tuple(_relative_to(base, r) for r in roots)
    if "per-path-ignores" in data:
        table = _table(data["per-path-ignores"], f"{shown}: 'per-path-ignores'")
        ignores = []
        for pattern, ids in table.items():
            where = f"{shown}: 'per-path-ignores' entry {pattern!r}"
            rule_ids = _string_list(ids, where)
            check_rule_ids(rule_ids, where)
            ignores.append(PathIgnore(base, pattern, frozenset(rule_ids)))
        values["per_path_ignores"] = tuple(ignores)
    if "fail-on" in data:
        fail_on = data["fail-on"]
        if fail_on not in ("error", "warning", "info"):
            raise ConfigError(f"{shown}: 'fail-on' must be error, warning or info")
        values["fail_on"] = fail_on
    if "profile" in data:
        from launch_linter.rules._profiles import PROFILES

        if data["profile"] not in PROFILES:
            raise ConfigError(f"{shown}: 'profile' must be one of {', '.join(PROFILES)}")
        values["profile"] = data["profile"]
    for key in ("exclude", "extend-exclude"):
        if key in data:
            values[key.replace("-", "_")] = _string_list(data[key], f"{shown}: '{key}'")
    if "respect-gitignore" in data:
        if not isinstance(data["respect-gitignore"], bool):
            raise ConfigError(f"{shown}: 'respect-gitignore' must be true or false")
        values["respect_gitignore"] = data["respect-gitignore"]
    if "ros" in data:
        if data["ros"] not in (1, 2) or isinstance(data["ros"], bool):
            raise ConfigError(f"{shown}: 'ros' must be 1 or 2")
        values["ros"] = int(data["ros"])
    if "ros-distro" in data:
        from launch_linter.model.distro import ROS1_DISTROS, ROS2_DISTROS, is_known, normalise

        name = normalise(data["ros-distro"]) if isinstance(data["ros-distro"], str) else None
        if name is None or not is_known(name):
            raise ConfigError(
                f"{shown}: 'ros-distro' must be one of {', '.join((*ROS1_DISTROS, *ROS2_DISTROS))}"
            )
        values["ros_distro"] = name
    if "cache-dir" in data:
        folder = data["cache-dir"]
        if not isinstance(folder, str) or not folder:
            raise ConfigError(f"{shown}: 'cache-dir' must be a folder name")
        values["cache_dir"] = _relative_to(base, folder)
    return Config(**values)


def _severities(table: Mapping[str, Any], shown: str) -> dict[str, Severity]:
    """Severity by rule id; a category sets its rules, and a rule named itself wins."""
    check_rule_ids(table, f"{shown}: 'severity'")
    levels: dict[str, Severity] = {}
    for name, level in table.items():
        if level not in ("error", "warning", "info"):
            raise ConfigError(
                f"{shown}: 'severity.{name}' must be error, warning or info, not {level!r}"
            )
    for name, level in table.items():
        if name not in CATEGORY_OF:
            levels.update({rule_id: Severity(level) for rule_id, category in CATALOG
                           if category.value == name})
    for name, level in table.items():
        if name in CATEGORY_OF:
            levels[name] = Severity(level)
    return levels


def _read_toml(path: str) -> dict[str, Any]:
    shown = shown_path(path)  # as messages quote paths
    try:
        data = read_file_within(path, MAX_CONFIG_BYTES)
    except OSError as exc:  # FileTooLarge included
        raise ConfigError(
            f"cannot read configuration file {shown}: {exc.strerror or exc}") from None

    try:
        text = data.decode("utf-8")
    except UnicodeDecodeError as exc:
        raise ConfigError(f"{shown}: not valid TOML: {exc}") from None
    parser = _toml_parser()
    if parser is None:
        from launch_linter.workspace.toml_fallback import NoTomlParser, loads_without_parser

        try:
            return loads_without_parser(text)
        except NoTomlParser as exc:
            raise ConfigError(f"{shown}: {exc}") from None
    try:
        document: dict[str, Any] = parser.loads(text)
    except parser.TOMLDecodeError as exc:
        raise ConfigError(f"{shown}: not valid TOML: {exc}") from None
    except RecursionError:
        raise ConfigError(f"{shown}: nested too deeply") from None
    return document


def _toml_parser() -> Any:
    """``tomllib`` (Python 3.11), else ``tomli`` (the package's dependency before 3.11), else
    ``None``: a standalone linter, which carries only the standard library, on an older Python.
    Both names are fixed here; nothing a configuration says is ever imported."""
    for name in ("tomllib", "tomli"):
        try:
            return importlib.import_module(name)
        except ImportError:
            continue
    return None


def _pyproject_table(document: Mapping[str, Any]) -> Any:
    tool = document.get("tool")
    return tool.get(TABLE) if isinstance(tool, dict) else None


def load_config(path: str) -> Config:
    """Read ``path``: the ``[tool.launch-linter]`` table of a ``pyproject.toml``, or the
    top level of any other TOML file."""
    shown = shown_path(path)  # as messages quote paths
    document = _read_toml(path)
    if os.path.basename(path) == PYPROJECT:
        table = _pyproject_table(document)
        if table is None:
            raise ConfigError(f"{shown}: no [tool.{TABLE}] table")
        return parse_config(_table(table, f"{shown}: [tool.{TABLE}]"), path)
    return parse_config(document, path)


def _config_in(directory: str) -> str | None:
    candidate = os.path.join(directory, CONFIG_NAME)
    if os.path.isfile(candidate):
        return candidate
    candidate = os.path.join(directory, PYPROJECT)
    if os.path.isfile(candidate) and _pyproject_table(_read_toml(candidate)) is not None:
        return candidate
    return None


def find_config(path: str) -> str | None:
    """The configuration file that governs ``path``, walking up from it."""
    directory = os.path.abspath(path)
    if not os.path.isdir(directory):
        directory = os.path.dirname(directory)
    while True:
        found = _config_in(directory)
        if found is not None:
            return found
        parent = os.path.dirname(directory)
        if parent == directory:
            return None
        directory = parent


def config_for(paths: Sequence[str], explicit: str | None = None) -> Config:
    """The configuration for linting ``paths``: ``explicit`` if given, else the one file
    found from every path, else an empty configuration."""
    if explicit is not None:
        return load_config(explicit)
    found = {find_config(p) for p in paths} if paths else {find_config(os.curdir)}
    if len(found) > 1:
        names = ", ".join(sorted(f or "(none)" for f in found))
        raise ConfigError(
            f"the paths are governed by different configuration files ({names}); "
            "lint them separately or name one with --config"
        )
    chosen = found.pop()
    return load_config(chosen) if chosen is not None else Config()


def load_knowledge_file(path: str) -> KnowledgeBase:
    """A knowledge file the configuration names (JSON, docs/knowledge.md). Its path comes
    from a repository's configuration, so it is read as any other untrusted file: a FIFO
    or device is refused rather than waited on, and at most its size limit is read."""
    from launch_linter.knowledge import MAX_KNOWLEDGE_BYTES, KnowledgeError, from_bytes

    try:
        raw = read_file_within(path, MAX_KNOWLEDGE_BYTES)
    except OSError as exc:  # NotRegularFile and FileTooLarge included
        raise KnowledgeError(f"{path}: cannot be read: {exc.strerror or exc}") from None
    return from_bytes(raw, path)
