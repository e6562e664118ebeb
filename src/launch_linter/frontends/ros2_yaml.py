"""ROS 2 launch YAML to launch actions, with line numbers.

A YAML launch file is ``launch:`` followed by a list of one-key mappings, the key naming
the entity (``node``, ``arg``, ``group`` ...) and the value holding its attributes;
attributes that are lists of mappings are nested entities (``param``, the ``arg`` of an
``include``), and a group's children are its value when that is a list, or its
``children`` key. These become the same entities as XML, read by
:func:`launch_linter.frontends.ros2_xml.actions_of`.

PyYAML is only needed here, so it is imported when a YAML file is read; without it the
file gets a ``parse_error`` saying so. Only the composed node graph is used (safe: no
Python objects are built), and the walk is bounded so that aliases cannot multiply work.
"""

from __future__ import annotations

from typing import Any

from launch_linter.frontends.ros2_actions import FileRead, Problem
from launch_linter.frontends.ros2_xml import Entity, actions_of
from launch_linter.model.launch import DIRECTIVE_MARKER
from launch_linter.model.transform import LaunchFormat
from launch_linter.resolve.xml_safe import MAX_ELEMENTS

MAX_YAML_BYTES = 256 * 1024

FORMAT = LaunchFormat.ROS2_YAML


class _TooLarge(Exception):
    pass


class _Shape(Exception):
    def __init__(self, message: str, node: Any) -> None:
        super().__init__(message)
        self.message = message
        self.node = node


def _position(node: Any) -> tuple[int, int]:
    mark = node.start_mark
    return mark.line + 1, mark.column + 1


class _Converter:
    def __init__(self, yaml: Any) -> None:
        self.yaml = yaml
        self.count = 0
        self.lines: list[int] = []

    def tick(self) -> None:
        self.count += 1
        if self.count > MAX_ELEMENTS:
            raise _TooLarge(f"more than {MAX_ELEMENTS} YAML nodes")

    def entities(self, node: Any, owner: str) -> list[Entity]:
        if not isinstance(node, self.yaml.SequenceNode):
            raise _Shape(f"the entities of '{owner}' must be a list", node)
        out: list[Entity] = []
        for item in node.value:
            self.tick()
            if not isinstance(item, self.yaml.MappingNode) or len(item.value) != 1:
                raise _Shape("each entity must be a mapping with one key, its type", item)
            key, body = item.value[0]
            out.append(self.entity(str(key.value), key, body))
        return out

    def entity(self, tag: str, key: Any, body: Any) -> Entity:
        line, column = _position(key)
        self.lines.append(line)
        entity = Entity(tag, line, column)
        if isinstance(body, self.yaml.SequenceNode):
            entity.children = self.entities(body, tag)
        elif isinstance(body, self.yaml.MappingNode):
            self.attributes(entity, body)
        return entity

    def attributes(self, entity: Entity, body: Any) -> None:
        for key, value in body.value:
            self.tick()
            name = str(key.value)
            if name == "children":
                entity.children = self.entities(value, entity.tag)
            elif isinstance(value, self.yaml.ScalarNode) and (
                value.tag != "tag:yaml.org,2002:null"
            ):
                entity.attrs[name] = str(value.value)
            elif isinstance(value, self.yaml.SequenceNode) and value.value and all(
                isinstance(item, self.yaml.MappingNode) for item in value.value
            ):
                entity.lists[name] = [self.nested(name, item) for item in value.value]
            else:
                entity.other_keys.append(name)

    def nested(self, tag: str, body: Any) -> Entity:
        self.tick()
        line, column = _position(body)
        self.lines.append(line)
        entity = Entity(tag, line, column)
        self.attributes(entity, body)
        return entity


def _comments(text: str) -> tuple[tuple[int, str], ...]:
    """``#`` comments (outside quotes) with their line, for suppression directives."""
    found: list[tuple[int, str]] = []
    for number, line in enumerate(text.splitlines(), start=1):
        quote = ""
        for index, char in enumerate(line):
            if quote:
                if char == quote:
                    quote = ""
            elif char in "'\"":
                quote = char
            elif char == "#" and (index == 0 or line[index - 1].isspace()):
                found.append((number, line[index + 1:]))
                break
    return tuple(found)


def read_yaml(path: str, data: bytes) -> FileRead:
    """Read a ROS 2 launch YAML file (``path`` absolute, ``data`` its bytes)."""
    try:
        # Imported on use: PyYAML stays out of the standard-library core.
        import yaml  # type: ignore[import-untyped]
    except ImportError:
        return _error(1, 1, "reading ROS 2 YAML launch files needs PyYAML (pip install PyYAML)")
    if len(data) > MAX_YAML_BYTES:
        # PyYAML builds its node tree in Python: about 4 s per megabyte with libyaml and
        # 20 s without. Real YAML launch files are a few kilobytes.
        return _error(1, 1, f"YAML launch file is {len(data)} bytes, larger than the "
                            f"{MAX_YAML_BYTES}-byte limit")
    try:
        text = data.decode("utf-8")
    except UnicodeDecodeError as exc:
        return _error(1, 1, f"not UTF-8 text: {exc.reason}")
    # Comments only place suppression directives: not scanned for (a Python loop over
    # every character) in the many files that hold none.
    comments = _comments(text) if DIRECTIVE_MARKER in text else ()
    try:
        root = yaml.compose(text, Loader=getattr(yaml, "CSafeLoader", yaml.SafeLoader))
    except yaml.MarkedYAMLError as exc:
        mark = exc.problem_mark
        line, column = (mark.line + 1, mark.column + 1) if mark else (1, 1)
        return _error(line, column, f"not well-formed YAML: {exc.problem}", comments)
    except (yaml.YAMLError, RecursionError) as exc:
        return _error(1, 1, f"not readable YAML: {exc}", comments)
    if (
        not isinstance(root, yaml.MappingNode)
        or len(root.value) != 1
        or root.value[0][0].value != "launch"
    ):
        line, column = _position(root) if root is not None else (1, 1)
        return _error(line, column, "a YAML launch file is a mapping with the one key 'launch'",
                      comments)
    converter = _Converter(yaml)
    try:
        launch = Entity("launch", 1, 1, children=converter.entities(root.value[0][1], "launch"))
    except _Shape as exc:
        line, column = _position(exc.node)
        return _error(line, column, exc.message, comments)
    except (_TooLarge, RecursionError) as exc:
        return _error(1, 1, f"YAML launch file too large or too deep: {exc}", comments)
    actions, problems = actions_of(path, launch, "yaml")
    return FileRead(FORMAT, actions, comments, tuple(converter.lines), problems)


def _error(line: int, column: int, message: str,
           comments: tuple[tuple[int, str], ...] = ()) -> FileRead:
    return FileRead(FORMAT, None, comments, (), (Problem("parse_error", line, column, message),))


def _yaml_is_string(text: str) -> bool:
    """Whether launch's YAML typing keeps a parameter text as a string."""
    word = text.strip().lower()
    if word in ("true", "false", "yes", "no", "on", "off", ".inf", "-.inf", "+.inf", ".nan"):
        return False
    try:
        float(word.replace("_", ""))
    except ValueError:
        return True
    return False
