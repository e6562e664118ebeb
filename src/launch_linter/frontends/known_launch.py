"""Launch files of packages the linter cannot read that start known nodes: nav2_bringup's
``bringup_launch.py`` runs AMCL with the parameter file its ``params_file`` argument names
(``knowledge/param_values.json``, ``launch_files``). An include of such a file that is not
followed (the package is not installed where the linter looks) still tells which of
those nodes run, under which namespace, and with which parameter file."""

from __future__ import annotations

import re
from collections.abc import Mapping

from launch_linter.knowledge import KnowledgeBase
from launch_linter.knowledge.publish import truth
from launch_linter.knowledge.values import LaunchFact
from launch_linter.model.robot import UNKNOWN_VALUE

MAX_TARGET_TEXT = 2_000
_PACKAGE = re.compile(
    r"(?:FindPackageShare|get_package_share_directory|find-pkg-share)\W{0,8}([A-Za-z0-9_]+)")
_WORD = re.compile(r"[A-Za-z0-9_.-]+")


def include_target(text: str) -> tuple[str, str] | None:
    """The package and the path in its share folder that an include's file names as
    written (``os.path.join(get_package_share_directory('p'), 'launch')/x.launch.py``,
    ``$(find-pkg-share p)/launch/x.launch.py``), None when it does not say."""
    text = text[:MAX_TARGET_TEXT]
    found = _PACKAGE.search(text)
    if found is None:
        return None
    words = _WORD.findall(text[found.end():])
    if not words:
        return None
    return found.group(1), "/".join(words)


class Started:
    """A known node a launch file starts: its program, name and namespace (None when the
    namespace argument is not known), the parameter file it is given, and the value each
    parameter the launch file may rewrite would be rewritten to (None: not resolved)."""

    __slots__ = ("package", "executable", "name", "namespace", "parameter_file", "fact",
                 "rewritten")

    def __init__(self, package: str, executable: str, name: str, namespace: str | None,
                 parameter_file: str, fact: LaunchFact,
                 rewritten: Mapping[str, str | None] | None = None) -> None:
        self.package = package
        self.executable = executable
        self.name = name
        self.namespace = namespace
        self.parameter_file = parameter_file
        self.fact = fact
        self.rewritten = dict(rewritten or {})

    def value(self, parameter: str, written: str) -> str:
        """The value the node gets for ``parameter``, which its file writes ``written``:
        that, unless the launch file may rewrite it to another value (then the target
        distribution decides, which the front end does not know: None)."""
        leaf = parameter.rsplit(".", 1)[-1]
        if leaf not in self.rewritten:
            return written
        other = self.rewritten[leaf]
        same = other is not None and (
            other == written or (truth(other) is not None and truth(other) == truth(written)))
        return written if same else UNKNOWN_VALUE


def started_by(text: str, ros: int, arguments: Mapping[str, str | None],
               knowledge: KnowledgeBase) -> list[Started]:
    """The known nodes the included file written ``text`` starts, given the include's
    ``arguments`` (None: an unresolved value); none when the file is not known, its
    parameter file is not given or not resolved, or it may start none of them."""
    target = include_target(text)
    fact = None if target is None else knowledge.values.launch_file(*target)
    if fact is None or fact.ros != ros:
        return []
    parameter_file = arguments.get(fact.parameter_file_argument)
    if not parameter_file:
        return []
    if fact.unless_argument is not None and fact.unless_argument in arguments:
        unless = arguments[fact.unless_argument]
        if unless is None or truth(unless) is not False:
            return []
    namespace: str | None = "/"
    if fact.namespace_argument is not None and fact.namespace_argument in arguments:
        given = arguments[fact.namespace_argument]
        namespace = None if given is None else "/" + given.strip("/")
    rewritten = {parameter: arguments.get(argument, default)
                 for parameter, argument, default in fact.rewrites}
    return [Started(package, executable, name, namespace, parameter_file, fact, rewritten)
            for package, executable, name in fact.nodes]
