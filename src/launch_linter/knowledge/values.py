"""What values nodes accept for their enumerated parameters, per distribution, and which
launch files of installed packages start which known nodes from a parameter file: data
(the ``values`` and ``launch_files`` of a knowledge file of format 2: the bundled ones in
``param_values.json``, each fact citing the file, branch, commit and lines it was read
from; docs/knowledge.md), read by the loader of :mod:`launch_linter.knowledge` and extended
by a user's files as the tf entries are.

- :class:`ValueFact`: a node's (or a ros2_control controller's) parameter, the values its
  release for ``distros`` accepts, and what it does with another: ``fails`` (it refuses
  and stops, or fails to configure) or ``falls_back`` (it uses ``fallback`` instead).
  ``closed``: the accepted values are all there are (a string compared in the node's
  code); else other packages may add values (pluginlib classes), and only a value with
  the package's own ``owned_prefix`` or listed in ``refuses`` is known to be refused.
- :class:`LaunchFact`: a launch file of an installed package that starts known nodes
  with the parameter file one of its arguments names (nav2_bringup's ``params_file``):
  an include of it the linter cannot follow still tells those nodes' parameters, and
  which of them the launch file rewrites from its own arguments (``rewrites``).

Standard library only: the core reads it.
"""

from __future__ import annotations

import re
from typing import Any

from launch_linter.knowledge.fields import (
    KnowledgeError,
    Source,
    _distributions,
    _sources,
    _text,
    _texts,
)

OUTCOMES = ("fails", "falls_back")


class ValueFact:
    """See the module's docstring. ``parameter`` may hold ``*`` for one name of a nested
    parameter (``*.plugin``: every costmap layer's plugin); ``controller`` matches a
    ros2_control controller, whose ``type`` is the value checked."""

    __slots__ = ("id", "ros", "packages", "executables", "plugins", "controller",
                 "parameter", "distros", "accepts", "closed", "owned_prefix", "refuses",
                 "outcome", "fallback", "effect", "sources", "_pattern")

    def __init__(self, id: str, ros: int, packages: tuple[str, ...],
                 executables: tuple[str, ...], plugins: tuple[str, ...], controller: bool,
                 parameter: str, distros: tuple[str, ...], accepts: tuple[str, ...],
                 closed: bool, owned_prefix: str | None, refuses: tuple[str, ...],
                 outcome: str, fallback: str | None, effect: str,
                 sources: tuple[Source, ...]) -> None:
        self.id = id
        self.ros = ros
        self.packages = packages
        self.executables = executables
        self.plugins = plugins
        self.controller = controller
        self.parameter = parameter
        self.distros = distros
        self.accepts = accepts
        self.closed = closed
        self.owned_prefix = owned_prefix
        self.refuses = refuses
        self.outcome = outcome
        self.fallback = fallback
        self.effect = effect
        self.sources = sources
        self._pattern = re.compile(
            "^" + "[^./]+".join(re.escape(part) for part in parameter.split("*")) + "$")

    def names(self, parameter: str) -> bool:
        """Whether ``parameter`` (a node's parameter name) is the fact's parameter."""
        return self._pattern.match(parameter) is not None

    def refused(self, value: str) -> bool:
        """Whether this release provably does not accept ``value``."""
        if value in self.accepts:
            return False
        if self.closed or value in self.refuses:
            return True
        return self.owned_prefix is not None and value.startswith(self.owned_prefix)


class LaunchFact:
    """A launch file (``package`` and its paths in the share folder) that starts
    ``nodes`` (package, executable, name) with the parameter file its argument
    ``parameter_file_argument`` names, under the namespace ``namespace_argument`` names,
    and starts none of them when ``unless_argument`` is true. ``rewrites``: (parameter,
    argument, the argument's default) for each parameter the launch file sets, where the
    parameter file has it, to its argument's value in some distributions and not in
    others (nav2_bringup's RewrittenYaml up to Humble; from Iron a ``SetParameter`` the
    file's own value overrides): where the two differ the value is the distribution's."""

    __slots__ = ("id", "ros", "package", "launch", "parameter_file_argument",
                 "namespace_argument", "unless_argument", "nodes", "sources", "rewrites")

    def __init__(self, id: str, ros: int, package: str, launch: tuple[str, ...],
                 parameter_file_argument: str, namespace_argument: str | None,
                 unless_argument: str | None, nodes: tuple[tuple[str, str, str], ...],
                 sources: tuple[Source, ...],
                 rewrites: tuple[tuple[str, str, str], ...] = ()) -> None:
        self.id = id
        self.ros = ros
        self.package = package
        self.launch = launch
        self.parameter_file_argument = parameter_file_argument
        self.namespace_argument = namespace_argument
        self.unless_argument = unless_argument
        self.nodes = nodes
        self.sources = sources
        self.rewrites = rewrites


def _ros(value: Any, where: str) -> int:
    if value not in (1, 2):
        raise KnowledgeError(f"{where} must be 1 or 2")
    return int(value)


def parse_value(data: Any, where: str) -> ValueFact:
    if not isinstance(data, dict):
        raise KnowledgeError(f"{where} must be an object")
    fact_id = _text(data.get("id"), f"{where}.id")
    where = f"{where} ({fact_id})"
    ros = _ros(data.get("ros"), f"{where}.ros")
    match = data.get("match")
    if not isinstance(match, dict):
        raise KnowledgeError(f"{where}.match must be an object")
    controller = match.get("controller") is True
    package = match.get("package")
    packages = () if package is None else (_text(package, f"{where}.match.package"),)
    executables = _texts(match.get("executables"), f"{where}.match.executables")
    plugins = _texts(match.get("plugins"), f"{where}.match.plugins")
    if not controller and not (packages and executables) and not plugins:
        raise KnowledgeError(f"{where}.match needs package and executables, plugins, or "
                             f"controller: true")
    distros = _distributions(data, (ros,), where)
    outcome = _text(data.get("otherwise"), f"{where}.otherwise")
    if outcome not in OUTCOMES:
        raise KnowledgeError(f"{where}.otherwise must be one of {', '.join(OUTCOMES)}")
    fallback = data.get("fallback")
    if (outcome == "falls_back") != (fallback is not None):
        raise KnowledgeError(f"{where}.fallback is given exactly when otherwise is "
                             f"falls_back")
    owned = data.get("owned_prefix")
    return ValueFact(
        fact_id, ros, packages, executables, plugins, controller,
        _text(data.get("parameter"), f"{where}.parameter"), distros,
        _texts(data.get("accepts"), f"{where}.accepts", required=True),
        data.get("closed") is True,
        None if owned is None else _text(owned, f"{where}.owned_prefix"),
        _texts(data.get("refuses"), f"{where}.refuses"), outcome,
        None if fallback is None else _text(fallback, f"{where}.fallback"),
        _text(data.get("effect"), f"{where}.effect"),
        _sources(data.get("sources"), f"{where}.sources"))


def parse_launch(data: Any, where: str) -> LaunchFact:
    if not isinstance(data, dict):
        raise KnowledgeError(f"{where} must be an object")
    fact_id = _text(data.get("id"), f"{where}.id")
    where = f"{where} ({fact_id})"
    nodes = data.get("nodes")
    if not isinstance(nodes, list) or not nodes or not all(isinstance(n, dict) for n in nodes):
        raise KnowledgeError(f"{where}.nodes must be a list of objects")
    namespace = data.get("namespace_argument")
    unless = data.get("unless_argument")
    rewrites = data.get("rewrites", [])
    if not isinstance(rewrites, list) or not all(isinstance(r, dict) for r in rewrites):
        raise KnowledgeError(f"{where}.rewrites must be a list of objects")
    return LaunchFact(
        fact_id, _ros(data.get("ros"), f"{where}.ros"),
        _text(data.get("package"), f"{where}.package"),
        _texts(data.get("launch"), f"{where}.launch", required=True, non_empty=True),
        _text(data.get("parameter_file_argument"), f"{where}.parameter_file_argument"),
        None if namespace is None else _text(namespace, f"{where}.namespace_argument"),
        None if unless is None else _text(unless, f"{where}.unless_argument"),
        tuple((_text(n.get("package"), f"{where}.nodes[{i}].package"),
               _text(n.get("executable"), f"{where}.nodes[{i}].executable"),
               _text(n.get("name"), f"{where}.nodes[{i}].name"))
              for i, n in enumerate(nodes)),
        _sources(data.get("sources"), f"{where}.sources"),
        tuple((_text(r.get("parameter"), f"{where}.rewrites[{i}].parameter"),
               _text(r.get("argument"), f"{where}.rewrites[{i}].argument"),
               _text(r.get("default"), f"{where}.rewrites[{i}].default"))
              for i, r in enumerate(rewrites)))


class ValueKnowledge:
    """The facts, by what they match, in the base's order (a user's first)."""

    def __init__(self, values: tuple[ValueFact, ...] = (),
                 launch: tuple[LaunchFact, ...] = ()) -> None:
        self.values = values
        self.launch = launch
        # Looked up once per launched node: by package, plugin and controller, so a user
        # file of thousands of facts costs each node only the facts of its program.
        self._by_package: dict[str, list[int]] = {}
        self._by_plugin: dict[str, list[int]] = {}
        self._controllers: list[int] = []
        for index, fact in enumerate(values):
            if fact.controller:
                self._controllers.append(index)
            for package in dict.fromkeys(fact.packages):
                self._by_package.setdefault(package, []).append(index)
            for plugin in dict.fromkeys(fact.plugins):
                self._by_plugin.setdefault(plugin, []).append(index)
        self._launch: dict[str, list[LaunchFact]] = {}
        for launch_fact in launch:
            self._launch.setdefault(launch_fact.package, []).append(launch_fact)

    def facts_for(self, ros: int | None, package: str, executable: str,
                  plugin: str | None, controller: bool) -> list[ValueFact]:
        """The value facts of a launched node (all distributions)."""
        if controller:
            candidates = self._controllers
        else:
            candidates = sorted(set(self._by_package.get(package, ())).union(
                () if plugin is None else self._by_plugin.get(plugin, ())))
        return [f for f in (self.values[i] for i in candidates) if f.ros == ros and (
            controller
            or (package in f.packages and executable in f.executables)
            or (plugin is not None and plugin in f.plugins))]

    def launch_file(self, package: str, path: str) -> LaunchFact | None:
        """The fact of the launch file ``path`` of ``package``'s share folder."""
        for fact in self._launch.get(package, ()):
            if path in fact.launch:
                return fact
        return None
