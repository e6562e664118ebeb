"""The knowledge base of tf publishers and frame consumers: data (``tf_publishers.json``,
each entry citing the source file it was read from) and the model that reads it.

An entry says, for a node (ROS 1 ``pkg``/``type``, ROS 2 ``package``/``executable``, a
composable node's plugin), a Gazebo plugin (``filename``) or a ros2_control controller
(``type``), which tf edges it publishes as templates over its parameters (with the node's
defaults), which parameters switch publishing off (``when``), and which frames it looks up.
Format 2 adds entries about programs (``programs.json``, :mod:`.programs`): what a
package's release installs and what a program does with ``/clock``; and the sections
``values`` and ``launch_files`` (``param_values.json``, :mod:`.values`): the values nodes
refuse or replace, and launch files of installed packages that start known nodes. A file
of format 1 loads as before. Users add entries of the same forms in a JSON file named by the
configuration's ``knowledge`` key (docs/knowledge.md). Standard library only: the core
reads it.
"""

from __future__ import annotations

import json
import os
import re
from collections import Counter
from typing import Any, Callable, Mapping, Sequence

from launch_linter.knowledge.fields import MAX_KNOWLEDGE_BYTES as MAX_KNOWLEDGE_BYTES
from launch_linter.knowledge.fields import EntryError, _sources, _text, _texts, item_line
from launch_linter.knowledge.fields import KnowledgeError as KnowledgeError
from launch_linter.knowledge.fields import Source as Source
from launch_linter.knowledge.programs import (
    PROGRAM_KINDS,
    ClockFact,
    Installed,
    ProgramFact,
    Programs,
    parse_program_entry,
)
from launch_linter.knowledge.values import (
    ValueKnowledge,
    parse_launch,
    parse_value,
)
from launch_linter.model.record import Record, _set

FORMAT = 2
"""The format this version writes; it reads every one of ``FORMATS``."""
FORMATS = (1, 2)
DATA_FILE = "tf_publishers.json"
PROGRAMS_FILE = "programs.json"
"""The bundled entries about programs (format 2), beside the tf entries."""
VALUES_FILE = "param_values.json"
"""The bundled parameter values and known launch files (format 2's sections)."""
BUNDLED_FILES = (DATA_FILE, PROGRAMS_FILE, VALUES_FILE)
SECTIONS = ("entries", "values", "launch_files")
"""The lists a knowledge file holds (format 1: ``entries`` only)."""
KINDS = ("node", "gazebo_plugin", "controller")
"""The kinds of format 1; format 2 adds ``installed``, ``clock`` and ``node_names``
(:mod:`.programs`)."""
ROLES = ("localization", "odometry", "sensor", "robot")
ROS1_DISTROS = ("kinetic", "lunar", "melodic", "noetic")
"""ROS 1 distributions in release order (``ros1_tf2_from`` names one)."""
ANY = "*"
PLACEHOLDER = re.compile(r"\{([^{}]+)\}")
"""A ``{param}`` in a frame template (the parameter's value stands there)."""

TF_TOPIC = "/tf"
SCALARS = (str, bool, int, float)
PARAMETER_TYPES = ("bool", "integer", "double", "string")
"""The scalar types a ROS 2 node declares a parameter with (rclcpp's ``ParameterType``)."""


class EdgeSpec(Record):
    """One edge a publisher sends: parent and child as templates (``{param}`` replaced by
    the parameter's value), the conditions under which it does (``param`` true,
    ``!param`` false, ``a|b`` either true, ``a==b`` equal values, ``param=text`` the value
    is that text), and its REP 105 role."""

    parent: str
    child: str
    when: tuple[str, ...]
    role: str

    __slots__ = ("parent", "child", "when", "role")

    def __init__(self, parent: str, child: str, when: tuple[str, ...], role: str) -> None:
        _set(self, "parent", parent)
        _set(self, "child", child)
        _set(self, "when", when)
        _set(self, "role", role)


class Prefix(Record):
    """A parameter that prefixes every published frame (``tf_frame_prefix``); when
    ``empty_means_namespace``, an empty prefix is the node's namespace, and so it is in
    the ROS 1 distributions ``namespace_when_empty_in`` names (gazebo_plugins' GazeboRos
    up to melodic)."""

    param: str
    enabled_by: str | None
    empty_means_namespace: bool
    namespace_when_empty_in: tuple[str, ...]

    __slots__ = ("param", "enabled_by", "empty_means_namespace", "namespace_when_empty_in")

    def __init__(self, param: str, enabled_by: str | None, empty_means_namespace: bool,
                 namespace_when_empty_in: tuple[str, ...] = ()) -> None:
        _set(self, "param", param)
        _set(self, "enabled_by", enabled_by)
        _set(self, "empty_means_namespace", empty_means_namespace)
        _set(self, "namespace_when_empty_in", namespace_when_empty_in)


class Entry(Record):
    """What the knowledge base knows of one program."""

    id: str
    kind: str
    ros: tuple[int, ...]
    packages: tuple[str, ...]
    executables: tuple[str, ...]
    plugins: tuple[str, ...]
    filenames: tuple[str, ...]
    types: tuple[str, ...]
    parameters: tuple[tuple[str, object], ...]
    """Each parameter the entry reads, with its default (None: no static default)."""
    publishes: tuple[EdgeSpec, ...]
    looks_up: tuple[str, ...]
    camera_frames: tuple[str, ...]
    strips_leading_slash: bool
    publishes_joint_states: bool
    publishes_description: bool
    parameters_elsewhere: str | None
    unsure_defaults: tuple[str, ...]
    """Parameters whose default is not assumed when the node's parameter file is unread
    (robot_localization's ``world_frame``: the dual-filter setup sets it there)."""
    prefix: Prefix | None
    sources: tuple[Source, ...]
    origin: str
    header_frames: tuple[str, ...]
    """Frames the node stamps on the data it publishes (a map's ``frame_id``): its
    consumers look them up in tf."""
    ros1_tf2_from: str | None
    """ROS 1: the first distribution whose release hands the entry's frames to tf2 as
    written (a leading ``/`` then fails); None when not known to."""
    looks_up_listed: tuple[tuple[str, str], ...]
    """``(list, frame)`` pairs: each item of a parameter named like ``list`` (``*`` is any
    one name) names a sub-namespace whose ``frame`` parameter the node looks up (a
    costmap's observation sources and their ``sensor_frame``)."""
    inputs: tuple[str, ...]
    """Parameters that give the node the input it needs before it publishes anything
    (``#`` stands for a number: robot_localization's ``odom#``): with every parameter
    source of the node read and none of them set, it publishes no edge."""
    tf_listener: bool
    """It looks up transforms at its own clock's time between frames its own configuration
    names, not a parameter (RViz's fixed frame and displays): its clock matters to tf."""
    loads_controllers: bool
    """It loads the ros2_control controllers its parameter files name (a controller
    manager, a simulator's ros2_control plugin): a file it could not read leaves them
    unknown, and the tree open."""
    stream_frames: tuple[str, ...]
    """Frames it stamps the streams of sensors at different places with, one template
    each (a stereo pair's left and right camera): two of them given one frame put one
    sensor's data at the other's pose (``camera_streams_one_frame``)."""
    parameter_types: tuple[tuple[str, str], ...]
    """ROS 2: parameters the node declares with a typed default (``declare_parameter(name,
    30.0)``), each with its type (:data:`PARAMETER_TYPES`): rclcpp throws when the value
    given has another type, and the node dies."""
    tf_topic: str
    """The topic it sends its edges on: ``/tf``, or one of its own (``~/tf_odometry``: under
    the node's full name) that reaches the tree only when a remapping of its process, or a
    relay, brings it to ``/tf``."""

    __slots__ = (
        "id", "kind", "ros", "packages", "executables", "plugins", "filenames", "types",
        "parameters", "publishes", "looks_up", "camera_frames", "strips_leading_slash",
        "publishes_joint_states", "publishes_description", "parameters_elsewhere",
        "unsure_defaults", "prefix", "sources", "origin", "header_frames", "ros1_tf2_from",
        "looks_up_listed",
        "inputs", "tf_listener", "loads_controllers", "stream_frames",
        "parameter_types", "tf_topic",
    )

    def __init__(
        self,
        id: str,
        kind: str,
        ros: tuple[int, ...],
        packages: tuple[str, ...],
        executables: tuple[str, ...],
        plugins: tuple[str, ...],
        filenames: tuple[str, ...],
        types: tuple[str, ...],
        parameters: tuple[tuple[str, object], ...],
        publishes: tuple[EdgeSpec, ...],
        looks_up: tuple[str, ...],
        camera_frames: tuple[str, ...],
        strips_leading_slash: bool,
        publishes_joint_states: bool,
        publishes_description: bool,
        parameters_elsewhere: str | None,
        unsure_defaults: tuple[str, ...],
        prefix: Prefix | None,
        sources: tuple[Source, ...],
        origin: str,
        header_frames: tuple[str, ...] = (),
        ros1_tf2_from: str | None = None,
        looks_up_listed: tuple[tuple[str, str], ...] = (),
        inputs: tuple[str, ...] = (),
        tf_listener: bool = False,
        loads_controllers: bool = False,
        stream_frames: tuple[str, ...] = (),
        parameter_types: tuple[tuple[str, str], ...] = (),
        tf_topic: str = TF_TOPIC,
    ) -> None:
        _set(self, "id", id)
        _set(self, "kind", kind)
        _set(self, "ros", ros)
        _set(self, "packages", packages)
        _set(self, "executables", executables)
        _set(self, "plugins", plugins)
        _set(self, "filenames", filenames)
        _set(self, "types", types)
        _set(self, "parameters", parameters)
        _set(self, "publishes", publishes)
        _set(self, "looks_up", looks_up)
        _set(self, "camera_frames", camera_frames)
        _set(self, "strips_leading_slash", strips_leading_slash)
        _set(self, "publishes_joint_states", publishes_joint_states)
        _set(self, "publishes_description", publishes_description)
        _set(self, "parameters_elsewhere", parameters_elsewhere)
        _set(self, "unsure_defaults", unsure_defaults)
        _set(self, "prefix", prefix)
        _set(self, "sources", sources)
        _set(self, "origin", origin)
        _set(self, "header_frames", header_frames)
        _set(self, "ros1_tf2_from", ros1_tf2_from)
        _set(self, "looks_up_listed", looks_up_listed)
        _set(self, "inputs", inputs)
        _set(self, "tf_listener", tf_listener)
        _set(self, "loads_controllers", loads_controllers)
        _set(self, "stream_frames", stream_frames)
        _set(self, "parameter_types", parameter_types)
        _set(self, "tf_topic", tf_topic)

    def default(self, name: str) -> object:
        for key, value in self.parameters:
            if key == name:
                return value
        return None

    def names(self, program: str, executable: str) -> bool:
        return program in self.packages and (ANY in self.executables
                                              or executable in self.executables)


class KnowledgeBase:
    """Entries by what they match; a user's entry overrides a bundled one of its id.
    ``facts`` are the entries about programs (:mod:`.programs`), looked up through
    :meth:`installed`, :meth:`clock_program` and :meth:`clock_launch`; ``values`` the
    parameter values and known launch files (:mod:`.values`)."""

    def __init__(self, entries: Sequence[Entry],
                 facts: Sequence[ProgramFact] = (),
                 values: ValueKnowledge | None = None) -> None:
        self.entries = tuple(entries)
        self.programs: Programs = Programs(tuple(facts))
        self.values = ValueKnowledge() if values is None else values
        # Every launched node is looked up (several times per node, by several rules): the
        # node entries by package, in the base's order, so a lookup reads only those.
        self._nodes: dict[str, list[Entry]] = {}
        for entry in self.entries:
            if entry.kind == "node":
                for package in dict.fromkeys(entry.packages):
                    self._nodes.setdefault(package, []).append(entry)

    def node(self, package: str, executable: str, ros: int | None = None) -> Entry | None:
        """The entry of a launched node, preferring the one of ``ros``."""
        found = [e for e in self._nodes.get(package, ()) if e.names(package, executable)]
        return _of_version(found, ros)

    def plugin(self, kind: str, name: str, ros: int | None = None) -> Entry | None:
        """The entry of a composable node's plugin (``node``), a Gazebo plugin's
        filename (``gazebo_plugin``) or a controller's type (``controller``)."""
        found: list[Entry] = []
        for entry in self.entries:
            names = (entry.plugins if kind == "node" else entry.filenames
                     if kind == "gazebo_plugin" else entry.types)
            if entry.kind in (kind, "node") and any(_glob(n, name) for n in names):
                found.append(entry)
        return _of_version(found, ros)

    def installed(self, package: str, ros: int | None, distro: str | None
                  ) -> Installed | None:
        """What ``package``'s release for ``distro`` installs (None: not known)."""
        return self.programs.installed(package, ros, distro)

    def clock_program(self, package: str, executable: str, ros: int = 2) -> ClockFact | None:
        """What a node's program does with /clock, None when not known."""
        return self.programs.clock_program(package, executable, ros)

    def clock_launch(self, package: str, launch: str, ros: int = 2) -> ClockFact | None:
        """What a package's launch file (its path in the share folder) does with /clock."""
        return self.programs.clock_launch(package, launch, ros)

    def node_names(self, package: str, executable: str, ros: int = 2) -> tuple[str, ...]:
        """The names of the nodes a program runs when the launch file names none (empty:
        not known)."""
        return self.programs.node_names(package, executable, ros)

    def ids(self) -> set[str]:
        """The ids of every entry and fact (one name space: an id replaces its own)."""
        return ({e.id for e in self.entries} | {f.id for f in self.programs.facts}
                | {f.id for f in self.values.values} | {f.id for f in self.values.launch})

    def extended(self, other: KnowledgeBase) -> KnowledgeBase:
        """This base with ``other``'s entries first, replacing entries of the same id."""
        ids = other.ids()
        mine, theirs = self.values, other.values
        return KnowledgeBase(
            other.entries + tuple(e for e in self.entries if e.id not in ids),
            other.programs.facts + tuple(f for f in self.programs.facts if f.id not in ids),
            ValueKnowledge(theirs.values + tuple(f for f in mine.values if f.id not in ids),
                           theirs.launch + tuple(f for f in mine.launch if f.id not in ids)))


def _glob(pattern: str, name: str) -> bool:
    if pattern.endswith(ANY):
        return name.startswith(pattern[:-1])
    return pattern == name


def _of_version(found: list[Entry], ros: int | None) -> Entry | None:
    if not found:
        return None
    for entry in found:
        if ros is None or ros in entry.ros:
            return entry
    return found[0]


def _placeholders(template: str) -> list[str]:
    return PLACEHOLDER.findall(template)


def condition_parameters(condition: str) -> list[str]:
    """The parameters a ``when`` condition reads: ``p``, ``!p``, ``a==b``, ``a|b``, and
    ``p=text`` (the value of ``p`` is the text)."""
    bare = condition.lstrip("!")
    if "==" not in bare and "=" in bare:
        return [bare.split("=", 1)[0]]
    return re.split(r"==|\|", bare)


def _edge(data: Any, where: str, params: Mapping[str, object]) -> EdgeSpec:
    if not isinstance(data, dict):
        raise KnowledgeError(f"{where} must be an object")
    role = _text(data.get("role"), f"{where}.role")
    if role not in ROLES:
        raise KnowledgeError(f"{where}.role must be one of {', '.join(ROLES)}")
    edge = EdgeSpec(_text(data.get("parent"), f"{where}.parent"),
                    _text(data.get("child"), f"{where}.child"),
                    _texts(data.get("when"), f"{where}.when"), role)
    named = _placeholders(edge.parent) + _placeholders(edge.child)
    for condition in edge.when:
        named.extend(condition_parameters(condition))
    for name in named:
        if name not in params:
            raise KnowledgeError(f"{where} names parameter {name!r}, which the entry "
                                 f"does not declare in 'parameters'")
    return edge


def parse_entry(data: Any, where: str, origin: str, file_format: int = 1
                ) -> Entry | ProgramFact:
    """One entry of a file of ``file_format``, checked against it; :class:`KnowledgeError`
    names the fault."""
    if not isinstance(data, dict):
        raise KnowledgeError(f"{where} must be an object")
    entry_id = _text(data.get("id"), f"{where}.id")
    where = f"{where} ({entry_id})"
    kind = _text(data.get("kind"), f"{where}.kind")
    kinds = KINDS + (PROGRAM_KINDS if file_format >= 2 else ())
    if kind not in kinds:
        later = " (format 2 adds installed, clock, node_names)" if kind in PROGRAM_KINDS else ""
        raise KnowledgeError(f"{where}.kind must be one of {', '.join(kinds)}{later}")
    ros = data.get("ros")
    if not isinstance(ros, list) or not ros or any(v not in (1, 2) for v in ros):
        raise KnowledgeError(f"{where}.ros must be a list of 1 and/or 2")
    if kind in PROGRAM_KINDS:
        return parse_program_entry(data, kind, tuple(ros), where, origin)
    match = data.get("match")
    if not isinstance(match, dict):
        raise KnowledgeError(f"{where}.match must be an object")
    package = match.get("package")
    packages = (() if package is None else (_text(package, f"{where}.match.package"),)) + \
        _texts(match.get("also_packages"), f"{where}.match.also_packages")
    executables = _texts(match.get("executables"), f"{where}.match.executables")
    plugins = _texts(match.get("plugins"), f"{where}.match.plugins")
    filenames = _texts(match.get("filenames"), f"{where}.match.filenames")
    types = _texts(match.get("types"), f"{where}.match.types")
    if kind == "node" and not (packages and executables):
        raise KnowledgeError(f"{where}.match needs package and executables for a node")
    if kind == "gazebo_plugin" and not filenames:
        raise KnowledgeError(f"{where}.match needs filenames for a Gazebo plugin")
    if kind == "controller" and not types:
        raise KnowledgeError(f"{where}.match needs types for a controller")
    params = data.get("parameters", {})
    if not isinstance(params, dict) or not all(
            value is None or isinstance(value, SCALARS) for value in params.values()):
        raise KnowledgeError(f"{where}.parameters must map names to defaults "
                             f"(string, number, boolean or null)")
    publishes = data.get("publishes", [])
    if not isinstance(publishes, list):
        raise KnowledgeError(f"{where}.publishes must be a list")
    edges = tuple(_edge(item, f"{where}.publishes[{i}]", params)
                  for i, item in enumerate(publishes))
    looks_up = _texts(data.get("looks_up"), f"{where}.looks_up")
    cameras = _texts(data.get("camera_frames"), f"{where}.camera_frames")
    headers = _texts(data.get("header_frames"), f"{where}.header_frames")
    streams = _texts(data.get("stream_frames"), f"{where}.stream_frames")
    for template in looks_up + cameras + headers + streams:
        for name in _placeholders(template):
            if name not in params:
                raise KnowledgeError(f"{where} names parameter {name!r}, which the entry "
                                     f"does not declare in 'parameters'")
    prefix_data = data.get("prefix")
    prefix = None
    if prefix_data is not None:
        if not isinstance(prefix_data, dict):
            raise KnowledgeError(f"{where}.prefix must be an object")
        enabled = prefix_data.get("enabled_by")
        distros = _texts(prefix_data.get("namespace_when_empty_in", []),
                         f"{where}.prefix.namespace_when_empty_in")
        unknown = [d for d in distros if d not in ROS1_DISTROS]
        if unknown:
            raise KnowledgeError(f"{where}.prefix.namespace_when_empty_in names "
                                 f"{unknown[0]!r}, not one of {', '.join(ROS1_DISTROS)}")
        prefix = Prefix(_text(prefix_data.get("param"), f"{where}.prefix.param"),
                        None if enabled is None else _text(enabled, f"{where}.prefix.enabled_by"),
                        bool(prefix_data.get("empty_means_namespace", False)), distros)
    sources = _sources(data.get("sources"), f"{where}.sources")
    elsewhere = data.get("parameters_elsewhere")
    tf2_from = data.get("ros1_tf2_from")
    if tf2_from is not None and tf2_from not in ROS1_DISTROS:
        raise KnowledgeError(f"{where}.ros1_tf2_from must be one of {', '.join(ROS1_DISTROS)}")
    listed = data.get("looks_up_listed", [])
    if not isinstance(listed, list) or not all(isinstance(item, dict) for item in listed):
        raise KnowledgeError(f"{where}.looks_up_listed must be a list of objects")
    listed_pairs = tuple(
        (_text(item.get("list"), f"{where}.looks_up_listed[{i}].list"),
         _text(item.get("frame"), f"{where}.looks_up_listed[{i}].frame"))
        for i, item in enumerate(listed))
    types_data = data.get("parameter_types", {})
    if not isinstance(types_data, dict) or not all(
            isinstance(value, str) and value in PARAMETER_TYPES for value in types_data.values()):
        raise KnowledgeError(f"{where}.parameter_types must map names to one of "
                             f"{', '.join(PARAMETER_TYPES)}")
    tf_topic = _text(data.get("tf_topic", TF_TOPIC), f"{where}.tf_topic")
    if not tf_topic.startswith(("/", "~/")):
        raise KnowledgeError(f"{where}.tf_topic must be absolute (/tf) or the node's own (~/name)")
    return Entry(
        id=entry_id, kind=kind, ros=tuple(ros), packages=packages, executables=executables,
        plugins=plugins, filenames=filenames, types=types,
        parameters=tuple(params.items()), publishes=edges, looks_up=looks_up,
        camera_frames=cameras,
        strips_leading_slash=bool(data.get("strips_leading_slash", False)),
        publishes_joint_states=bool(data.get("publishes_joint_states", False)),
        publishes_description=bool(data.get("publishes_description", False)),
        parameters_elsewhere=None if elsewhere is None else _text(
            elsewhere, f"{where}.parameters_elsewhere"),
        unsure_defaults=_texts(data.get("unsure_defaults"), f"{where}.unsure_defaults"),
        prefix=prefix,
        sources=sources,
        origin=origin,
        header_frames=headers,
        ros1_tf2_from=tf2_from,
        looks_up_listed=listed_pairs,
        inputs=_texts(data.get("inputs"), f"{where}.inputs"),
        tf_listener=bool(data.get("tf_listener", False)),
        loads_controllers=bool(data.get("loads_controllers", False)),
        stream_frames=streams,
        parameter_types=tuple((str(k), v) for k, v in types_data.items()),
        tf_topic=tf_topic,
    )


def _section(data: dict[str, Any], name: str, origin: str, file_format: int) -> list[Any]:
    items = data.get(name)
    if items is None and (name != "entries" or file_format >= 2):
        return []
    if not isinstance(items, list):
        raise KnowledgeError(f"{origin}: {name!r} must be a list")
    if items and file_format < 2 and name != "entries":
        raise KnowledgeError(f"{origin}: {name!r} needs format 2")
    return items


def parse(data: Any, origin: str) -> KnowledgeBase:
    """A knowledge base from a decoded JSON document (``{"format": 2, "entries": [...],
    "values": [...], "launch_files": [...]}``, each list optional; format 1 as before:
    ``entries``, without the entries about programs). A fault of one item is an
    :class:`EntryError`."""
    file_format = data.get("format") if isinstance(data, dict) else None
    if not isinstance(data, dict) or file_format not in FORMATS:
        raise KnowledgeError(f"{origin}: not a knowledge file of format "
                             f"{' or '.join(map(str, FORMATS))}")
    readers: dict[str, Callable[[Any, str], Any]] = {
        "entries": lambda item, where: parse_entry(item, where, origin, file_format),
        "values": parse_value,
        "launch_files": parse_launch,
    }
    read: dict[str, list[Any]] = {}
    for name in SECTIONS:
        items = read[name] = []
        for index, item in enumerate(_section(data, name, origin, file_format)):
            try:
                items.append(readers[name](item, f"{origin}: {name}[{index}]"))
            except KnowledgeError as exc:
                raise EntryError(str(exc), name, index) from None
    parsed: list[Entry | ProgramFact] = read["entries"]
    facts = ValueKnowledge(tuple(read["values"]), tuple(read["launch_files"]))
    # Counted once: a file of tens of thousands of entries is checked in linear time.
    ids = Counter([e.id for e in parsed] + [f.id for f in facts.values]
                  + [f.id for f in facts.launch])
    duplicates = sorted(i for i, n in ids.items() if n > 1)
    if duplicates:
        shown = ", ".join(duplicates[:10]) + (" ..." if len(duplicates) > 10 else "")
        raise KnowledgeError(f"{origin}: entry ids used twice: {shown}")
    return KnowledgeBase([e for e in parsed if isinstance(e, Entry)],
                         [e for e in parsed if not isinstance(e, Entry)], facts)


def load(path: str) -> KnowledgeBase:
    """A bundled knowledge file. A user's files are read by the configuration layer
    (``workspace.config.load_knowledge_file``), which reads untrusted paths safely."""
    try:
        with open(path, "rb") as stream:
            raw = stream.read(MAX_KNOWLEDGE_BYTES + 1)
    except OSError as exc:
        raise KnowledgeError(f"{path}: cannot be read: {exc.strerror}") from None
    if len(raw) > MAX_KNOWLEDGE_BYTES:
        raise KnowledgeError(f"{path}: larger than {MAX_KNOWLEDGE_BYTES} bytes")
    return from_bytes(raw, path)


def from_bytes(raw: bytes, origin: str) -> KnowledgeBase:
    """A knowledge file's content (JSON); ``origin`` names it in messages, and the line
    where a faulty item begins (``user.json:12: entries[3] (my_node).match ...``)."""
    try:
        text = raw.decode("utf-8")
        data = json.loads(text)
    except (UnicodeDecodeError, ValueError, RecursionError) as exc:
        raise KnowledgeError(f"{origin}: not JSON: {exc}") from None
    try:
        return parse(data, origin)
    except EntryError as exc:
        line = item_line(text, exc.section, exc.index)
        message = str(exc)
        if line is not None and message.startswith(f"{origin}: "):
            message = f"{origin}:{line}: {message[len(origin) + 2:]}"
        raise KnowledgeError(message) from None


_BUNDLED: list[KnowledgeBase] = []


def bundled_path(name: str = DATA_FILE) -> str | None:
    """A bundled data file (the tf entries' unless named), None where the modules run
    without their files (the standalone linter, which installs its embedded copies with
    :func:`use_bundled`)."""
    here = globals().get("__file__")
    return None if here is None else os.path.join(os.path.dirname(os.path.abspath(here)),
                                                  name)


def _joined(bases: Sequence[KnowledgeBase]) -> KnowledgeBase:
    """The bundled files' entries as one base, in the files' order."""
    return KnowledgeBase([e for b in bases for e in b.entries],
                         [f for b in bases for f in b.programs.facts],
                         ValueKnowledge(tuple(f for b in bases for f in b.values.values),
                                        tuple(f for b in bases for f in b.values.launch)))


def use_bundled(*texts: str) -> None:
    """Make ``texts`` (the data files' JSON, those of ``BUNDLED_FILES`` in order) the
    bundled knowledge base."""
    _BUNDLED[:] = [_joined([parse(json.loads(text), "bundled") for text in texts])]


def bundled() -> KnowledgeBase:
    """The knowledge base shipped with the linter (read once per process)."""
    if not _BUNDLED:
        paths = [bundled_path(name) for name in BUNDLED_FILES]
        _BUNDLED.append(_joined([load(p) for p in paths if p is not None]))
    return _BUNDLED[0]
