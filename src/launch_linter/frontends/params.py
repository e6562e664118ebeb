"""Node parameters read statically: YAML text (``<rosparam>``, parameter files of both ROS
versions) flattened to ``(name, value)`` pairs, and ros2_control controllers found in them.

PyYAML is imported on first use (the standalone linter's core is stdlib only): where it is
absent a parameter file is *unread*, and the node's defaults are then unknown. Files are
read bounded in size and parsed once per run.
"""

from __future__ import annotations

import os
import re
import textwrap
from collections.abc import Iterable, Sequence
from typing import Any, Dict, NamedTuple, Tuple

from launch_linter.model.record import replace
from launch_linter.model.robot import NodeRecord
from launch_linter.resolve import reads
from launch_linter.resolve.xml_safe import read_file_within

MAX_PARAM_FILE_BYTES = 512 * 1024
MAX_PARAMS = 5000
"""Parameters kept per file or per YAML text: what a real node is given is far less."""
MAX_CACHED = 512
ROS2_SECTION = "ros__parameters"
_CONTROLLER_TYPE = re.compile(r"^[A-Za-z_][\w]*/[A-Za-z_][\w]*$")

_cache: dict[str, tuple[Any, str | None, KeyPlaces]] = {}


_FLAT_LINE = re.compile(r"^([A-Za-z_~][\w/~]*)[ \t]*:[ \t]+(?:'([^']*)'|\"([^\"\\]*)\"|"
                        r"([^\s#'\"\[\]{}&*!|>%@`][^#]*?))[ \t]*(?:#.*)?$")


_BOOLEANS = {word: str(truth).lower() for truth, words in (
    (True, ("yes", "true", "on")), (False, ("no", "false", "off")))
    for base in words for word in (base, base.capitalize(), base.upper())}
"""YAML 1.1's booleans, as PyYAML reads them (written ``true``/``false``, like launch)."""
_NULLS = ("~", "null", "Null", "NULL")


def flat_yaml(text: str) -> dict[str, str] | None:
    """A YAML text that is only ``key: scalar`` lines (comments and blank lines aside),
    read without PyYAML; None when it is anything more (nesting, lists, anchors, tags)."""
    found: dict[str, str] = {}
    # A mapping indented as a whole (``<rosparam>`` text inside an element) is still flat.
    for line in textwrap.dedent(text).splitlines():
        stripped = line.strip()
        if not stripped or stripped.startswith("#") or stripped == "---":
            continue
        match = _FLAT_LINE.match(line)
        if match is None or len(found) >= MAX_PARAMS:
            return None
        quoted = match.group(4) is None
        value = next(v for v in match.groups()[1:] if v is not None).strip()
        if not quoted and value in _NULLS:
            continue
        found[match.group(1)] = value if quoted else _BOOLEANS.get(value, value)
    return found


def parse_yaml(text: str) -> tuple[Any, str | None]:
    """The YAML document (plain data, no tags run), or None and why it is not read.
    Without PyYAML, flat ``key: value`` text is still read (the same in both cases)."""
    document, why, _ = parse_yaml_placed(text)
    return document, why


def parse_yaml_placed(text: str) -> tuple[Any, str | None, KeyPlaces]:
    """:func:`parse_yaml`, and where each mapping key is written (see :data:`KeyPlaces`):
    from PyYAML's node marks, or the flat lines read without it."""
    try:
        # Imported on use: PyYAML stays out of the standard-library core.
        import yaml  # type: ignore[import-untyped]
    except ImportError:
        flat = flat_yaml(text)
        if flat is not None:
            return flat, None, _flat_places(text)
        return None, "reading YAML parameters needs PyYAML", {}
    if len(text) > MAX_PARAM_FILE_BYTES:
        return None, f"YAML larger than {MAX_PARAM_FILE_BYTES} bytes", {}
    # What yaml.load does (compose, then construct), keeping the composed nodes' marks.
    loader = getattr(yaml, "CSafeLoader", yaml.SafeLoader)(text)
    try:
        root = loader.get_single_node()
        document = None if root is None else loader.construct_document(root)
    except (yaml.YAMLError, RecursionError, ValueError) as exc:
        return None, f"not readable YAML: {str(exc)[:200]}", {}
    finally:
        loader.dispose()
    return document, None, _node_places(root, yaml.MappingNode, yaml.ScalarNode)


KeyPlaces = Dict[Tuple[str, ...], Tuple[int, int]]
"""Where a YAML text's mapping keys are written: the path of keys from the top (each key
as written) to its 1-based line and column."""
MAX_KEY_DEPTH = 32


def _node_places(root: object, mapping: type, scalar: type) -> KeyPlaces:
    """The keys of a composed YAML document (PyYAML nodes) with their marks; bounded in
    entries and visits (an alias reaches one mapping by many paths)."""
    out: KeyPlaces = {}
    stack: list[tuple[tuple[str, ...], object]] = [((), root)]
    visits = 0
    while stack and visits < 4 * MAX_PARAMS:
        path, node = stack.pop()
        if not isinstance(node, mapping) or len(path) >= MAX_KEY_DEPTH:
            continue
        for key, value in node.value:  # type: ignore[attr-defined]
            visits += 1
            if visits >= 4 * MAX_PARAMS:
                break
            if isinstance(key, scalar):
                here = (*path, str(key.value))  # type: ignore[attr-defined]
                mark = key.start_mark  # type: ignore[attr-defined]
                out[here] = (mark.line + 1, mark.column + 1)
                stack.append((here, value))
    return out


def _flat_places(text: str) -> KeyPlaces:
    """The keys of a flat ``key: value`` text (see :func:`flat_yaml`) with their lines."""
    out: KeyPlaces = {}
    for number, line in enumerate(text.splitlines(), 1):
        match = _FLAT_LINE.match(line.strip())
        if match is not None:
            out[(match.group(1),)] = (number, 1 + len(line) - len(line.lstrip()))
    return out


def read_yaml_file(path: str) -> tuple[Any, str | None]:
    """A parameter file's document, parsed once per version of the file (bounded)."""
    document, why, _ = read_yaml_file_placed(path)
    return document, why


def read_yaml_file_placed(path: str) -> tuple[Any, str | None, KeyPlaces]:
    """:func:`read_yaml_file`, and where the file's keys are written."""
    status: os.stat_result | None
    try:
        status = os.stat(path)
        key = f"{path}\x00{status.st_mtime_ns}\x00{status.st_size}"
    except OSError:
        status, key = None, path
    # A document reused is a read of the file for the results cache (resolve.reads); one
    # changed in the last moments is read again, since its time cannot vouch for it.
    if key in _cache and (status is None or not reads.too_recent(status)):
        if status is None:
            reads.note_path(path)
        else:
            reads.note_status(path, status)
        return _cache[key]
    try:
        data = read_file_within(path, MAX_PARAM_FILE_BYTES)
    except OSError as exc:  # FileTooLarge included
        found: tuple[Any, str | None, KeyPlaces] = (
            None, f"parameter file {path!r} not read: {exc.strerror or exc}", {})
    else:
        document, reason, places = parse_yaml_placed(data.decode("utf-8", "replace"))
        found = (document, None if reason is None else f"parameter file {path!r}: {reason}",
                 places)
    if len(_cache) >= MAX_CACHED:
        _cache.clear()
    _cache[key] = found
    return found


def scalar_text(value: object) -> str | None:
    """A YAML scalar as launch would pass it on; None for lists, maps and nulls."""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, (int, float)):
        return repr(value)
    if isinstance(value, str):
        return value
    return None


def flatten(data: object, separator: str, prefix: str = "") -> list[tuple[str, str]]:
    """``data``'s scalar leaves as ``(a<sep>b<sep>c, value)``, iteratively and bounded."""
    return [(name, text) for name, text, _ in flatten_keyed(data, separator, prefix)]


def flatten_keyed(data: object, separator: str, prefix: str = "",
                  keys: tuple[str, ...] = ()) -> list[tuple[str, str, tuple[str, ...]]]:
    """:func:`flatten`, each leaf with its path of keys below ``keys`` (to find where it
    is written in :data:`KeyPlaces`)."""
    out: list[tuple[str, str, tuple[str, ...]]] = []
    stack: list[tuple[str, tuple[str, ...], object]] = [(prefix, keys, data)]
    while stack and len(out) < MAX_PARAMS:
        name, path, value = stack.pop()
        if isinstance(value, dict):
            items = list(value.items())
            for key, child in reversed(items[:MAX_PARAMS]):
                here = (*path, str(key)) if len(path) < MAX_KEY_DEPTH else path
                stack.append((f"{name}{separator}{key}" if name else str(key), here, child))
            continue
        text = scalar_text(value)
        if text is not None and name:
            out.append((name, text, path))
    return out


def ros1_params(document: object, namespace: str = "") -> list[tuple[str, str]]:
    """A ``<rosparam>`` document's parameters, names joined with ``/`` under ``namespace``."""
    return [(key, value) for key, value, _ in ros1_params_keyed(document, namespace)]


def ros1_params_keyed(document: object, namespace: str = ""
                      ) -> list[tuple[str, str, tuple[str, ...]]]:
    """:func:`ros1_params`, each with its path of keys in the document."""
    prefix = namespace.strip("/")
    return [(key.lstrip("~"), value, path)
            for key, value, path in flatten_keyed(document, "/", prefix)]


def _section_pattern(key: str) -> re.Pattern[str]:
    """A ROS 2 parameter file's node key as a pattern over ``/namespace/name``, made as
    rclcpp makes it: a leading ``/`` added, each ``/*`` one ``/NAME`` and a ``*`` right
    after it a repeat (``/**``: any number of names, none included, so ``/**/amcl``
    matches ``/amcl``); any other ``*`` repeats the character before it, as in the
    ``std::regex`` rclcpp builds (``/lio_sam*`` is ``/lio_sa`` and any number of ``m``:
    it matches no ``/lio_sam_x``). A key std::regex would refuse matches everything
    (unknown, never a finding)."""
    text = "/" + key.lstrip("/")  # nested keys are joined with '/' by ros2_sections
    pieces = text.split("/*")
    pattern = _key_piece(pieces[0])
    for piece in pieces[1:]:
        pattern += "(/[A-Za-z0-9_]+)"
        if piece.startswith("*"):
            pattern += "*"
            piece = piece[1:]
        pattern += _key_piece(piece)
    try:
        return re.compile(f"^{pattern}$")
    except re.error:
        return re.compile("")


def _key_piece(piece: str) -> str:
    """Literal text of a node key, its ``*`` kept as the regex repeat rclcpp reads."""
    return "*".join(re.escape(part) for part in piece.split("*"))


def node_keys(document: object) -> list[tuple[str, tuple[str, ...]]]:
    """The node keys of a ROS 2 parameter file (nested keys joined with ``/``), each with
    its path of keys."""
    return [(key, path[:-1]) for key, _, path in _ros2_sections_keyed(document)]


def key_matches(key: str, full: str) -> bool:
    """Whether the node key ``key`` reaches the node ``full`` (rclcpp's matching)."""
    return _section_pattern(key).match(full) is not None


def ros2_sections(document: object) -> list[tuple[str, dict[Any, Any]]]:
    """Each ``ros__parameters`` mapping of a ROS 2 parameter file with its node key (nested
    namespace keys joined with ``/``)."""
    return [(key, section) for key, section, _ in _ros2_sections_keyed(document)]


def _ros2_sections_keyed(document: object
                         ) -> list[tuple[str, dict[Any, Any], tuple[str, ...]]]:
    """:func:`ros2_sections`, each with the path of keys down to its ``ros__parameters``."""
    out: list[tuple[str, dict[Any, Any], tuple[str, ...]]] = []
    stack: list[tuple[str, tuple[str, ...], object]] = [("", (), document)]
    while stack and len(out) < MAX_PARAMS:
        path, keys, value = stack.pop()
        if not isinstance(value, dict):
            continue
        for key, child in value.items():
            if key == ROS2_SECTION and isinstance(child, dict):
                out.append((path, child, (*keys, ROS2_SECTION)))
            elif isinstance(child, dict) and path.count("/") < 16:
                stack.append((f"{path}/{key}", (*keys, str(key)), child))
    return out


def ros2_file_params(document: object, name: str | None, namespace: str | None
                     ) -> list[tuple[str, str]]:
    """The parameters a ROS 2 parameter file gives the node ``namespace/name``: the
    sections whose key, with a leading ``/`` added, matches the node's full name (``/*``
    one name, ``/**`` any; later sections win): rclcpp's ``parameter_map_from``
    (rclcpp/src/rclcpp/parameter_map.cpp 52-68, ros2/rclcpp humble 99f1d8d). A bare
    ``name:`` key is ``/name``: it does not reach the node ``/ns/name``, and a key naming
    another node (``imu_filter_node:`` for the node ``imu_filter``) gives it nothing."""
    return [(key, value) for key, value, _ in ros2_file_params_keyed(document, name, namespace)]


def ros2_file_params_keyed(document: object, name: str | None, namespace: str | None
                           ) -> list[tuple[str, str, tuple[str, ...]]]:
    """:func:`ros2_file_params`, each with its path of keys in the file."""
    return ros2_file_params_and_misses(document, name, namespace)[0]


def ros2_file_params_and_misses(
    document: object, name: str | None, namespace: str | None,
) -> tuple[list[tuple[str, str, tuple[str, ...]]], list[tuple[str, tuple[str, ...]]] | None]:
    """:func:`ros2_file_params_keyed`, and the node keys of the file (each with its path of
    keys) when it has some and none matches the node (see :func:`ros2_file_params`): the
    node takes nothing from the file; None when one matches or it has no node key. One
    walk of the file's sections answers both (a front-end asks both of every parameter
    file it gives a node)."""
    full = node_full_name(name, namespace)
    out: list[tuple[str, str, tuple[str, ...]]] = []
    missed: list[tuple[str, tuple[str, ...]]] = []
    matched = False
    for key, section, keys in _ros2_sections_keyed(document):
        if _section_pattern(key).match(full):
            matched = True
            out.extend(flatten_keyed(section, ".", keys=keys))
        elif not matched:
            missed.append((key, keys[:-1]))
    return out, None if matched or not missed else missed


def node_full_name(name: str | None, namespace: str | None) -> str:
    """``/namespace/name`` as rclcpp's fully qualified name writes it."""
    return "/" + "/".join(p for p in ((namespace or "").strip("/"), name or "") if p)


class PlacedDocument(NamedTuple):
    """A parameter file's document with its path as shown and where its keys are written."""

    document: object
    shown: str
    keys: KeyPlaces
    substituted: bool = False
    """launch performs the file's ``$(...)`` before the node reads it (``allow_substs``)."""


MAX_SECTION_MATCHES = 200_000
"""Wildcard section keys tried against controller names, per controller manager: a file
of thousands of ``/**/NAME`` sections for thousands of controllers stays bounded (the
controllers past it are unread, their frames unknown)."""


class _Sections:
    """A parameter file's ``ros__parameters`` sections, indexed once for many node names:
    keys without a wildcard by the full name they match, the others compiled once."""

    def __init__(self, document: object) -> None:
        self.sections = _ros2_sections_keyed(document)
        self.exact: dict[str, list[int]] = {}
        self.wildcard: list[tuple[int, re.Pattern[str]]] = []
        for index, (key, _, _) in enumerate(self.sections):
            if "*" in key:
                self.wildcard.append((index, _section_pattern(key)))
            else:
                self.exact.setdefault("/" + key.lstrip("/"), []).append(index)

    def params_keyed(self, full: str) -> list[tuple[str, str, tuple[str, ...]]]:
        """:func:`ros2_file_params_keyed` for the node ``full``, sections in file order."""
        found = list(self.exact.get(full, ()))
        found.extend(index for index, pattern in self.wildcard if pattern.match(full))
        out: list[tuple[str, str, tuple[str, ...]]] = []
        for index in sorted(found):
            _, section, keys = self.sections[index]
            out.extend(flatten_keyed(section, ".", keys=keys))
        return out


def controllers_of(manager: NodeRecord, documents: Sequence[object],
                   placed: Sequence[PlacedDocument] = ()) -> list[NodeRecord]:
    """The ros2_control controllers a controller manager is given (``NAME.type`` set to a
    controller type), each with its own section of the same parameter files; with
    ``placed`` (the same files with their key places), each parameter at its key. Each
    file's sections are indexed once (a manager may name thousands of controllers)."""
    indexed: dict[int, _Sections] = {}

    def sections(document: object) -> _Sections:
        if id(document) not in indexed:
            indexed[id(document)] = _Sections(document)
        return indexed[id(document)]

    # One controller per name, of the type set last (a later file wins, as in rcl), where
    # it is first named: the same file given twice names its controllers twice.
    named: dict[str, str] = {}
    for key, value in manager.params:
        if key.endswith(".type") and "." not in key[:-len(".type")] \
                and _CONTROLLER_TYPE.match(value):
            named[key[:-len(".type")]] = value
    matches = 0
    out: list[NodeRecord] = []
    for controller, value in named.items():
        full = node_full_name(controller, manager.namespace)
        matches += sum(len(sections(d).wildcard) for d in documents)
        if matches > MAX_SECTION_MATCHES:
            out.append(replace(manager, executable="", name=controller, kind="controller",
                               plugin=value, params=(), param_lines=(),
                               unread=(*manager.unread, "too many parameter file sections "
                                       "to match for this controller manager")))
            continue
        params: list[tuple[str, str]] = []
        for document in documents:
            params.extend((name, text) for name, text, _ in sections(document).params_keyed(full))
        lines: list[tuple[str, str, int, int]] = []
        for each in placed:
            for name, _, at in sections(each.document).params_keyed(full):
                line_column = each.keys.get(at)
                if line_column is not None:
                    lines.append((name, each.shown, *line_column))
        out.append(replace(manager, executable="", name=controller, kind="controller",
                           plugin=value, params=tuple(params), param_lines=tuple(lines)))
    return out


EMBEDDED_COSTMAPS = {
    ("nav2_controller", "controller_server"): "local_costmap",
    ("nav2_planner", "planner_server"): "global_costmap",
}
"""nav2 servers that run a costmap node of their own in their process
(``Costmap2DROS(NAME, namespace, NAME)``: the node ``NAMESPACE/NAME/NAME``, navigation2
controller_server.cpp and planner_server.cpp, humble 3c3db59 and main a3a9704)."""
COSTMAP_PLUGIN = "nav2_costmap_2d::Costmap2DROS"


class ProcessParams:
    """A node's dictionary of parameters among its parameter files, in order: launch_ros
    writes each dictionary as a parameter file under ``/**`` (launch_ros node.py,
    ``_create_params_file_from_dict``), so every node of the process gets it."""

    __slots__ = ("params",)

    def __init__(self, params: tuple[tuple[str, str], ...]) -> None:
        self.params = params


def embedded_costmap(server: NodeRecord, process: Sequence[object],
                     scope_params: Sequence[tuple[str, str]] = ()) -> NodeRecord | None:
    """The costmap node a nav2 server runs, with what the server's process is given in
    order (``process``: parameter files' documents, whose section naming the costmap it
    reads, and :class:`ProcessParams`), after what ``SetParameter`` gives every node."""
    name = EMBEDDED_COSTMAPS.get((server.package, server.executable))
    if name is None:
        return None
    namespace = None if server.namespace is None else node_full_name(name, server.namespace)
    params = list(scope_params)
    for item in process:
        if isinstance(item, ProcessParams):
            params.extend(item.params)
        else:
            params.extend(ros2_file_params(item, name, namespace))
    return replace(server, package="nav2_costmap_2d", executable="", name=name,
                   plugin=COSTMAP_PLUGIN, params=tuple(params), namespace=namespace,
                   param_lines=())


CONTROLLER_MANAGER_NAME = "controller_manager"
"""The node name ros2_control_node takes when the launch file gives none."""
SPAWNERS = ("spawner", "spawner.py")
_SPAWNER_FILE_FLAGS = ("--param-file", "-p")
_SPAWNER_TYPE_FLAGS = ("--controller-type", "-t")
_SPAWNER_VALUE_FLAGS = ("-c", "--controller-manager", "-n", "--namespace",
                        "--controller-manager-timeout", "--switch-timeout",
                        "--service-call-timeout", "--controller-ros-args")


def spawner_words(words: Sequence[str | None]
                  ) -> tuple[list[str], list[str | None], str | None]:
    """The controllers a ``spawner`` loads (its positional words), the parameter files
    it gives them (``--param-file``, None when unresolved) and the type it names
    (``--controller-type``). An unresolved positional word is left out: it names a
    controller the linter cannot know."""
    names: list[str] = []
    files: list[str | None] = []
    kind: str | None = None
    skip: str | None = None
    for word in words:
        if skip is not None:
            if skip in _SPAWNER_FILE_FLAGS:
                files.append(word)
            elif skip in _SPAWNER_TYPE_FLAGS:
                kind = word
            skip = None
            continue
        if word is None:
            continue
        if word in _SPAWNER_FILE_FLAGS + _SPAWNER_TYPE_FLAGS + _SPAWNER_VALUE_FLAGS:
            skip = word
        elif word == "--ros-args":
            break
        elif not word.startswith("-"):
            names.append(word)
    return names, files, kind


CONTROL_VALUE_FLAGS = ("-c", "--controller-manager", "--spin-time", "--switch-timeout",
                       "--activate-timeout", "--set-state")
"""ros2controlcli's options that take a value (ros2_control humble 0941f73 and master
53b9999 ``ros2controlcli/api/__init__.py`` add_controller_mgr_parsers, the verbs'
``add_arguments``; ros2cli's ``--spin-time``)."""
ACTIVE_STATES = ("active", "start")
"""``--set-state``/``set_controller_state`` values that leave a controller active:
``active`` (humble on), ``start`` (foxy and galactic e3ae24b, ``load_controller.py``)."""
_CONTROL_STARTERS = ("--activate", "--start", "--start-controllers")
"""``switch_controllers``' lists of controllers to activate (foxy ``--start``, humble
``--activate``/``--start``)."""


def control_started(words: Sequence[str | None]) -> tuple[str, ...] | None:
    """The controllers a ``ros2 control VERB ...`` command (``words``: from the verb on,
    None where not resolved) leaves active: ``load_controller NAME --set-state active``
    (``start`` before humble), ``load_start_controller``/``configure_start_controller
    NAME`` (foxy), ``set_controller_state NAME active``, ``switch_controllers --activate
    NAME...``; () for any other verb or state. None when a word that decides is not
    resolved."""
    if not words or words[0] is None:
        return None
    verb = words[0]
    positional: list[str | None] = []
    activated: list[str | None] = []
    states: list[str | None] = []
    taking: list[str | None] | None = None
    skip: str | None = None
    for word in words[1:]:
        if skip is not None:
            if skip == "--set-state":
                states.append(word)
            skip = None
        elif word == "--ros-args":
            break
        elif word is not None and word in CONTROL_VALUE_FLAGS:
            skip, taking = word, None
        elif word is not None and word.startswith("-"):
            taking = activated if word in _CONTROL_STARTERS else None
        else:
            (positional if taking is None else taking).append(word)
    if verb == "switch_controllers":
        names = activated
    elif verb in ("load_start_controller", "configure_start_controller"):
        names = positional[:1]
    elif verb in ("load_controller", "set_controller_state"):
        # load_controller's state is --set-state's value; set_controller_state's its
        # second positional word (a parameter file is load_controller's second).
        if verb == "set_controller_state":
            states = positional[1:2]
        if None in states:
            return None
        names = positional[:1] if states and states[-1] in ACTIVE_STATES else []
    else:
        return ()
    if None in names:
        return None
    return tuple(name for name in names if name is not None)


def controller_remappings(words: Sequence[str | None]) -> tuple[tuple[str, str], ...] | None:
    """The remapping rules a spawner's ``--controller-ros-args`` give the controllers it
    loads (``-r``/``--remap`` ``from:=to``; spawner.py splits each value on spaces and the
    manager adds them to the controller node's arguments: ros2_control jazzy 9ffbf97
    spawner.py 494-505, controller_manager.cpp 5026-5035); None when a value is not
    resolved."""
    rules: list[tuple[str, str]] = []
    for index, word in enumerate(words[:-1]):
        if word != "--controller-ros-args":
            continue
        value = words[index + 1]
        if value is None:
            return None
        parts = value.split()
        for flag, rule in zip(parts, parts[1:]):
            if flag in ("-r", "--remap") and ":=" in rule:
                source, _, target = rule.partition(":=")
                rules.append((source, target))
    return tuple(rules)


def spawned_controllers(spawner: NodeRecord, names: Sequence[str], kind: str | None,
                        documents: Sequence[object],
                        remappings: tuple[tuple[str, str], ...] | None = ()
                        ) -> list[NodeRecord]:
    """The controllers a spawner loads with ``--param-file``, each with its section of
    the files (its own key or ``/**``) and the ``remappings`` its ``--controller-ros-args``
    give (the spawner's own remappings are its process's, not theirs). Its type:
    ``--controller-type``, else ``type`` in its section (jazzy's spawner sets it), else
    ``NAME.type`` in the file's controller manager section (what the manager is given
    when it reads the same file)."""
    out: list[NodeRecord] = []
    for name in names:
        params: list[tuple[str, str]] = []
        declared: str | None = None
        for document in documents:
            params.extend(ros2_file_params(document, name, spawner.namespace))
            for key, section in ros2_sections(document):
                if key.rstrip("/").endswith("/" + CONTROLLER_MANAGER_NAME):
                    declared = dict(flatten(section, ".")).get(name + ".type", declared)
        found = kind or dict(params).get("type") or declared or ""
        if _CONTROLLER_TYPE.match(found):
            out.append(replace(spawner, executable="", name=name, kind="controller",
                               plugin=found, params=tuple(params), param_lines=(),
                               remappings=remappings))
    return out


def spawner_records(spawner: NodeRecord, words: Sequence[str | None] | None
                    ) -> tuple[list[NodeRecord], tuple[str, ...] | None]:
    """What a ``spawner`` with the argument ``words`` loads: the controllers of its
    ``--param-file``s as records, and the names it loads (None when its words are not all
    resolved: a name may be missing)."""
    if words is None:
        return [], None
    names, files, kind = spawner_words(words)
    documents: list[object] = []
    for path in files:
        document, why = (None, "unresolved") if path is None else read_yaml_file(path)
        if why is None:
            documents.append(document)
    records = (spawned_controllers(spawner, names, kind, documents,
                                   controller_remappings(words))
               if names and documents else [])
    return records, None if None in words else tuple(names)


def ros1_controllers(global_params: Iterable[tuple[str, str]], manager: NodeRecord
                     ) -> list[NodeRecord]:
    """ROS 1 controllers loaded as parameters (``NAME/type`` set to a controller type),
    with the parameters under ``NAME/``, recorded at the controller manager's node."""
    pairs = list(global_params)
    out: list[NodeRecord] = []
    for key, value in pairs:
        if not key.endswith("/type") or not _CONTROLLER_TYPE.match(value):
            continue
        controller = key[:-len("/type")]
        head = controller + "/"
        params = tuple((k[len(head):], v) for k, v in pairs if k.startswith(head))
        out.append(replace(manager, executable="", name=controller.rsplit("/", 1)[-1],
                           kind="controller", plugin=value, params=params, param_lines=()))
    return out
