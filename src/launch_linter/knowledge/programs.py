"""Knowledge of programs, not of their tf: what a package's release installs, which
programs give ROS 2 its ``/clock``, and the names programs give their nodes. Entries of
kinds ``installed``, ``clock`` and ``node_names`` in a
knowledge file of format 2 (the bundled ones in ``programs.json``, each citing the file,
branch and commit it was read from; docs/knowledge.md), read by the loader of
:mod:`launch_linter.knowledge` and extended by a user's files as the tf entries are.

- ``installed``: the executables a package's release for some distributions installs
  (its build file's install rules): a node of that package with another ``type`` or
  ``executable`` cannot start there (``node_executable_missing``).
- ``clock``: the programs and launch files that start Gazebo Sim without bridging its
  clock to ROS, those that publish or may bridge ``/clock``, and those known to publish
  none (``sim_clock_not_bridged``). ROS 2 nodes given ``use_sim_time`` true take their
  time from ``/clock`` alone (ros2/design, articles/130_ros_time.md: "the time will be
  zero until a message arrives on /clock"); Gazebo classic's ``gazebo_ros`` publishes it,
  Gazebo Sim publishes its clock on its own transport only, which ``ros_gz_bridge``
  bridges.
- ``node_names``: the names a ROS 2 program gives the nodes it runs when the launch file
  names none (relative to the namespace it is launched in; a ``*`` in the last part stands
  for text it makes up at run time): a parameter file given to such a node reaches it only
  under those names (``ros2_param_file_unmatched``).

Standard library only: the core reads it.
"""

from __future__ import annotations

import typing
from typing import Any

from launch_linter.knowledge.fields import (
    KnowledgeError,
    Source,
    _distributions,
    _sources,
    _text,
    _texts,
)

PROGRAM_KINDS = ("installed", "clock", "node_names")
"""Entry kinds of format 2 that describe programs (format 1 knows none of them)."""
CLOCK_ROLES = ("publishes", "may_bridge", "gz_sim", "none")
ANY = "*"


class Installed:
    """A package's executables in the releases of ``distros`` (ROS versions ``ros``)."""

    __slots__ = ("id", "package", "ros", "distros", "executables", "sources", "origin")

    def __init__(self, id: str, package: str, ros: tuple[int, ...], distros: tuple[str, ...],
                 executables: tuple[str, ...], sources: tuple[Source, ...],
                 origin: str) -> None:
        self.id = id
        self.package = package
        self.ros = ros
        self.distros = distros
        self.executables = executables
        self.sources = sources
        self.origin = origin


class NodeNames:
    """The names of the nodes a program (``executables`` of ``package``) runs in its
    process when the launch file gives it none."""

    __slots__ = ("id", "package", "ros", "executables", "names", "sources", "origin")

    def __init__(self, id: str, package: str, ros: tuple[int, ...],
                 executables: tuple[str, ...], names: tuple[str, ...],
                 sources: tuple[Source, ...], origin: str) -> None:
        self.id = id
        self.package = package
        self.ros = ros
        self.executables = executables
        self.names = names
        self.sources = sources
        self.origin = origin


class ClockFact:
    """Programs (``executables`` of ``package``, ``*`` any of them) or launch files
    (``launch_files``: paths in the package's share folder, ``*`` any) and what they do
    with ``/clock`` (``clock``): ``publishes`` (Gazebo classic), ``may_bridge`` (a bridge
    whose configuration may include /clock), ``gz_sim`` (starts or feeds Gazebo Sim and
    bridges nothing) or ``none`` (publishes no clock)."""

    __slots__ = ("id", "package", "ros", "executables", "launch_files", "clock", "sources",
                 "origin")

    def __init__(self, id: str, package: str, ros: tuple[int, ...],
                 executables: tuple[str, ...], launch_files: tuple[str, ...], clock: str,
                 sources: tuple[Source, ...], origin: str) -> None:
        self.id = id
        self.package = package
        self.ros = ros
        self.executables = executables
        self.launch_files = launch_files
        self.clock = clock
        self.sources = sources
        self.origin = origin



ProgramFact = typing.Union[Installed, ClockFact, NodeNames]
"""An entry about a program, of one of ``PROGRAM_KINDS``."""


def parse_program_entry(data: dict[str, Any], kind: str, ros: tuple[int, ...], where: str,
                        origin: str) -> ProgramFact:
    """An entry of one of ``PROGRAM_KINDS`` (its id, kind and ``ros`` already checked);
    :class:`KnowledgeError` names the fault."""
    entry_id = str(data.get("id"))
    match = data.get("match")
    if not isinstance(match, dict):
        raise KnowledgeError(f"{where}.match must be an object")
    package = _text(match.get("package"), f"{where}.match.package")
    if kind == "installed":
        distros = _distributions(data, ros, where)
        executables = _texts(data.get("installs"), f"{where}.installs")
        if not executables:
            raise KnowledgeError(f"{where}.installs must list the executables installed")
        return Installed(entry_id, package, ros, distros, executables,
                         _sources(data.get("sources"), f"{where}.sources"), origin)
    executables = _texts(match.get("executables"), f"{where}.match.executables")
    if kind == "node_names":
        names = _texts(data.get("names"), f"{where}.names")
        if not executables or not names:
            raise KnowledgeError(f"{where} needs match.executables and names for a "
                                 f"node_names entry")
        return NodeNames(entry_id, package, ros, executables, names,
                         _sources(data.get("sources"), f"{where}.sources"), origin)
    launch_files = _texts(match.get("launch_files"), f"{where}.match.launch_files")
    if not executables and not launch_files:
        raise KnowledgeError(f"{where}.match needs executables or launch_files for a "
                             f"clock entry")
    clock = data.get("clock")
    if clock not in CLOCK_ROLES:
        raise KnowledgeError(f"{where}.clock must be one of {', '.join(CLOCK_ROLES)}")
    return ClockFact(entry_id, package, ros, executables, launch_files, str(clock),
                     _sources(data.get("sources"), f"{where}.sources"), origin)


class Programs:
    """The facts about programs of a knowledge base, by package, in the base's order (a
    user's first): a look-up answers with the first that matches."""

    def __init__(self, facts: tuple[ProgramFact, ...]) -> None:
        self.facts = facts
        self._installed: dict[str, list[Installed]] = {}
        self._clock: dict[str, list[ClockFact]] = {}
        self._names: dict[str, list[NodeNames]] = {}
        for fact in facts:
            if isinstance(fact, Installed):
                self._installed.setdefault(fact.package, []).append(fact)
            elif isinstance(fact, ClockFact):
                self._clock.setdefault(fact.package, []).append(fact)
            else:
                self._names.setdefault(fact.package, []).append(fact)

    def installed(self, package: str, ros: int | None, distro: str | None
                  ) -> Installed | None:
        """What ``package`` installs in ``distro`` (None: not known)."""
        for fact in self._installed.get(package, ()):
            if ros in fact.ros and distro in fact.distros:
                return fact
        return None

    def clock_program(self, package: str, executable: str, ros: int) -> ClockFact | None:
        """What a node's program does with /clock, None when not known."""
        for fact in self._clock.get(package, ()):
            if ros in fact.ros and (executable in fact.executables
                                    or ANY in fact.executables):
                return fact
        return None

    def clock_launch(self, package: str, launch: str, ros: int) -> ClockFact | None:
        """What a package's launch file (its path in the share folder) does with /clock."""
        for fact in self._clock.get(package, ()):
            if ros in fact.ros and (launch in fact.launch_files or ANY in fact.launch_files):
                return fact
        return None

    def node_names(self, package: str, executable: str, ros: int) -> tuple[str, ...]:
        """The names of the nodes ``package``'s ``executable`` runs when the launch file
        names none; empty when not known."""
        for fact in self._names.get(package, ()):
            if ros in fact.ros and executable in fact.executables:
                return fact.names
        return ()
